# The `stepwise` program end to end: exit codes and messages for good and bad input.
#
#   cmake -DSTEPWISE=<stepwise exe> -DCASES=<tests/cli dir> -DOUT=<scratch dir> -P run_cli_cases.cmake
#
# 1. Every line "file|code|text" of cases.txt runs `stepwise run FILE --frames 2 --quiet` from
#    the CASES directory and checks the exit code and that stderr contains the text. Every
#    bad/*.json must have a line, so a bad scene cannot sit there untested.
# 2. A good scene runs, writes a report that parses, and writes it byte-identically twice
#    outside timing_ms.
# 3. Unknown commands, unknown options and out-of-range values exit 2 with a usage message.
#
# Lines are split by hand (string(FIND)), not as CMake lists: messages contain ';' and '['.

cmake_minimum_required(VERSION 3.21)
foreach(required STEPWISE CASES OUT)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "run_cli_cases.cmake: -D${required}=... is required")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT}")
set(passed 0)
set(failed 0)

# Runs stepwise with the arguments after `name`; fills run_code, run_out and run_err.
macro(run_stepwise)
  execute_process(COMMAND "${STEPWISE}" ${ARGN} WORKING_DIRECTORY "${CASES}"
                  RESULT_VARIABLE run_code OUTPUT_VARIABLE run_out ERROR_VARIABLE run_err TIMEOUT 120)
endmacro()

macro(check condition_text name detail)
  if(${condition_text})
    math(EXPR passed "${passed} + 1")
  else()
    math(EXPR failed "${failed} + 1")
    message("FAILED ${name}: ${detail}")
  endif()
endmacro()

# Checks the exit code and that stderr contains `expected`.
macro(expect_failure name expected_code expected)
  string(FIND "${run_err}" "${expected}" found_at)
  set(ok FALSE)
  if(run_code STREQUAL "${expected_code}" AND NOT found_at EQUAL -1)
    set(ok TRUE)
  endif()
  check(ok "${name}" "expected exit ${expected_code} and stderr containing\n  ${expected}\ngot exit ${run_code}, stderr:\n${run_err}")
endmacro()

# --- 1. bad scene files --------------------------------------------------------------------
file(READ "${CASES}/cases.txt" cases_text)
set(listed_files "")
while(NOT cases_text STREQUAL "")
  string(FIND "${cases_text}" "\n" line_end)
  if(line_end EQUAL -1)
    set(line "${cases_text}")
    set(cases_text "")
  else()
    string(SUBSTRING "${cases_text}" 0 ${line_end} line)
    math(EXPR rest_start "${line_end} + 1")
    string(SUBSTRING "${cases_text}" ${rest_start} -1 cases_text)
  endif()
  string(STRIP "${line}" line)
  if(line STREQUAL "" OR line MATCHES "^#")
    continue()
  endif()
  string(FIND "${line}" "|" first_bar)
  string(SUBSTRING "${line}" 0 ${first_bar} case_file)
  math(EXPR after_first "${first_bar} + 1")
  string(SUBSTRING "${line}" ${after_first} -1 remainder)
  string(FIND "${remainder}" "|" second_bar)
  if(first_bar EQUAL -1 OR second_bar EQUAL -1)
    message(FATAL_ERROR "cases.txt: malformed line (want file|code|message): ${line}")
  endif()
  string(SUBSTRING "${remainder}" 0 ${second_bar} case_code)
  math(EXPR after_second "${second_bar} + 1")
  string(SUBSTRING "${remainder}" ${after_second} -1 case_message)
  string(APPEND listed_files "|${case_file}|")

  run_stepwise(run "${case_file}" --frames 2 --quiet)
  expect_failure("${case_file}" "${case_code}" "${case_message}")
endwhile()

file(GLOB bad_files RELATIVE "${CASES}" "${CASES}/bad/*.json")
foreach(bad_file IN LISTS bad_files)
  string(FIND "${listed_files}" "|${bad_file}|" listed_at)
  set(ok TRUE)
  if(listed_at EQUAL -1)
    set(ok FALSE)
  endif()
  check(ok "${bad_file}" "has no line in cases.txt")
endforeach()

# --- 2. a good run writes a report that parses, the same twice ------------------------------
get_filename_component(scene "${CASES}/../../scenes/ball-on-box.json" ABSOLUTE)
foreach(attempt 1 2)
  set(report "${OUT}/report-${attempt}.json")
  file(REMOVE "${report}")
  run_stepwise(run "${scene}" --frames 30 --report "${report}")
  set(ok FALSE)
  if(run_code EQUAL 0 AND EXISTS "${report}")
    set(ok TRUE)
  endif()
  check(ok "run ball-on-box (${attempt})" "exit ${run_code}, no report at ${report}\n${run_err}")
  if(NOT ok)
    continue()
  endif()
  file(READ "${report}" report_text)
  string(JSON report_format ERROR_VARIABLE json_error GET "${report_text}" format)
  string(JSON frames ERROR_VARIABLE json_error GET "${report_text}" frames)
  string(JSON scene_name ERROR_VARIABLE json_error GET "${report_text}" scene)
  string(JSON body_count ERROR_VARIABLE json_error LENGTH "${report_text}" bodies)
  string(JSON last_body ERROR_VARIABLE json_error GET "${report_text}" bodies 2 name)
  set(ok FALSE)
  # string(JSON) sorts members, so the contract's key order is checked on the text.
  set(in_order TRUE)
  set(previous -1)
  foreach(key format version scene engine frames dt pipeline timing_ms max_penetration max_contacts energy bodies)
    string(FIND "${report_text}" "\n  \"${key}\": " key_at)
    if(key_at LESS_EQUAL previous)
      set(in_order FALSE)
    endif()
    set(previous ${key_at})
  endforeach()
  if(NOT json_error AND report_format STREQUAL "stepwise-report" AND in_order AND
     frames EQUAL 30 AND scene_name STREQUAL "ball-on-box" AND body_count EQUAL 3 AND last_body STREQUAL "ball")
    set(ok TRUE)
  endif()
  check(ok "report of ball-on-box (${attempt})"
        "format=${report_format} keys-in-order=${in_order} frames=${frames} scene=${scene_name} bodies=${body_count} error=${json_error}")
  # Cut the timing_ms object out of the text: everything else must match byte for byte.
  string(FIND "${report_text}" "\n  \"timing_ms\": " timing_start)
  string(FIND "${report_text}" "\n  \"max_penetration\": " timing_end)
  string(SUBSTRING "${report_text}" 0 ${timing_start} before_timing)
  string(SUBSTRING "${report_text}" ${timing_end} -1 after_timing)
  set(report_${attempt} "${before_timing}${after_timing}")
endforeach()
if(DEFINED report_1 AND DEFINED report_2)
  set(ok FALSE)
  if(report_1 STREQUAL report_2)
    set(ok TRUE)
  endif()
  check(ok "deterministic report" "two runs of ball-on-box differ outside timing_ms")
endif()

# --- 3. usage errors -----------------------------------------------------------------------
run_stepwise(frobnicate)
expect_failure("unknown command" 2 "error: unknown command 'frobnicate'")
expect_failure("unknown command usage" 2 "Usage: stepwise")
run_stepwise(run "${scene}" --frmaes 3)
expect_failure("unknown option" 2 "--frmaes")
expect_failure("unknown option usage" 2 "Usage: stepwise run")
run_stepwise(run "${scene}" --frames -1)
expect_failure("out-of-range option" 2 "--frames")
run_stepwise(run)
expect_failure("missing scene" 2 "Usage: stepwise run")
run_stepwise(run no-such-builtin-scene)
expect_failure("unknown built-in scene" 2 "no-such-builtin-scene")

# --- 4. collide (chapter 3) ---------------------------------------------------------------
# expect(name detail CONDITION...): counts a check whose if() condition is given unquoted.
macro(expect name detail)
  if(${ARGN})
    set(ok TRUE)
  else()
    set(ok FALSE)
  endif()
  check(ok "${name}" "${detail}")
endmacro()

run_stepwise(collide --input collide/pairs.json --output "${OUT}/collide.json")
expect("collide runs" "exit ${run_code}: ${run_err}" run_code EQUAL 0)
if(EXISTS "${OUT}/collide.json")
  file(READ "${OUT}/collide.json" collide_text)
  string(JSON result_count LENGTH "${collide_text}" results)
  string(JSON first_depth GET "${collide_text}" results 0 depth)
  string(JSON second_intersect GET "${collide_text}" results 1 intersect)
  string(JSON second_depth GET "${collide_text}" results 1 depth)
  expect("collide: one result per pair" "got ${result_count}" result_count EQUAL 2)
  expect("collide: sphere pair depth" "got ${first_depth}" first_depth STREQUAL "0.5")
  expect("collide: separated boxes" "got ${second_intersect}" second_intersect STREQUAL "OFF")
  expect("collide: minus the distance" "got ${second_depth}" second_depth STREQUAL "-2")
endif()
run_stepwise(collide --input collide/bad_pairs.json)
expect_failure("collide bad input" 2 "error: pairs[0].b.shape.box.half_extents[1]: must be > 0")
run_stepwise(collide)
expect_failure("collide without input" 2 "--input")
# Every error of a query file at once, as for scenes.
run_stepwise(collide --input collide/many_bad_pairs.json)
expect_failure("collide: all errors (1)" 2 "error: pairs[0].a.shape.box.half_extents[1]: must be > 0")
expect_failure("collide: all errors (2)" 2 "error: pairs[0].b.position[1]: must be a number")
expect_failure("collide: all errors (3)" 2 "error: pairs[1]: missing required key \"b\"")
# A static body with a mass: rejected by collide with run's own message.
run_stepwise(collide --input collide/static_mass.json)
expect_failure("collide: static body with a mass" 2
               "error: pairs[0].a.mass: only dynamic bodies have mass (this body is static)")
run_stepwise(run bad/static_mass.json --frames 2 --quiet)
expect_failure("run: static body with a mass" 2
               "error: bodies[0].mass: only dynamic bodies have mass (this body is static)")
# A scene file given to collide is named as one.
run_stepwise(collide --input "${scene}")
expect_failure("collide: a scene file" 2
               "this is a scene file (format \"stepwise-scene\"); collide reads a query file: { \"pairs\": [")

# --- 5. benches -----------------------------------------------------------------------------
# --help names the files each suite writes.
run_stepwise(bench --help)
foreach(file out/integrators-dt.svg out/gjk-table.svg out/gjk-classification.csv out/epa.svg out/solver.csv
             out/resting.svg)
  string(FIND "${run_out}" "${file}" found_at)
  expect("bench --help names ${file}" "not in:\n${run_out}" NOT found_at EQUAL -1)
endforeach()
# Not on a terminal: no progress on stderr; the files written are listed at the end.
run_stepwise(bench resting --quick --csv "${OUT}/resting.csv" --plot "${OUT}/resting.svg")
string(FIND "${run_out}" "files written:" listed_at)
string(FIND "${run_out}" "${OUT}/resting.svg" plot_listed_at)
string(LENGTH "${run_err}" stderr_length)
expect("bench: exit 0, silent stderr" "exit ${run_code}, stderr:\n${run_err}" run_code EQUAL 0 AND stderr_length EQUAL 0)
expect("bench: lists the files written" "stdout:\n${run_out}" NOT listed_at EQUAL -1 AND NOT plot_listed_at EQUAL -1)
run_stepwise(bench resting --quick --quiet --csv "${OUT}/resting.csv")
string(FIND "${run_out}" "files written:" listed_at)
expect("bench --quiet: no list" "stdout:\n${run_out}" run_code EQUAL 0 AND listed_at EQUAL -1)
run_stepwise(bench resting --quick --csv "${OUT}/no/such/dir/resting.csv")
expect_failure("bench: unwritable output" 2 "error: bench resting: cannot write")

message("cli: ${passed} passed, ${failed} failed")
if(failed GREATER 0)
  message(FATAL_ERROR "cli: ${failed} check(s) failed")
endif()
