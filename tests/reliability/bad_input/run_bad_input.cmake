# Bad input end to end: every malformed scene or query must end in exit code 2 and one message
# naming the JSON path, an unstable run in exit code 3 naming the body and the frame; never a
# crash, a hang (each run has 60 s) or an allocation that exhausts memory.
#
#   cmake -DSTEPWISE=<stepwise exe> -DCASES=<this dir> -DOUT=<scratch dir> -P run_bad_input.cmake
#
# cases.txt: one line per case, "exit code|text stderr must contain|arguments of stepwise".
# Every *.json of this folder must be named by some line. Cases too large to keep in the repo
# (100,001 bodies, 4 million values, a 65 MiB file, 100,000 nested arrays) are written to OUT
# first and named there as ${OUT}/<name>.json.
cmake_minimum_required(VERSION 3.21)
foreach(required STEPWISE CASES OUT)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "run_bad_input.cmake: -D${required}=... is required")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT}")

# --- generated cases -----------------------------------------------------------------------
string(REPEAT "{}," 100000 bodies)
file(WRITE "${OUT}/many_bodies.json" "{ \"bodies\": [${bodies}{}] }")
string(REPEAT "0," 2000000 zeros)
file(WRITE "${OUT}/many_values.json" "{ \"description\": [${zeros}${zeros}0] }")
string(REPEAT "[" 100000 open)
string(REPEAT "]" 100000 close)
file(WRITE "${OUT}/deep_nesting.json" "{ \"bodies\": ${open}${close} }")
string(REPEAT "[0, 0, 0]," 128 points)
file(WRITE "${OUT}/many_hull_points.json"
     "{ \"bodies\": [ { \"shape\": { \"convex\": { \"vertices\": [${points}[1, 1, 1]] } } } ] }")
string(REPEAT "{}," 1000000 pairs)
file(WRITE "${OUT}/many_pairs.json" "{ \"pairs\": [${pairs}{}] }")
# 65 MiB: sparse where `truncate` exists (no disk used), written out otherwise.
find_program(TRUNCATE truncate)
file(REMOVE "${OUT}/huge_file.json")
if(TRUNCATE)
  execute_process(COMMAND ${TRUNCATE} -s 65M "${OUT}/huge_file.json")
else()
  string(REPEAT " " 1048576 mebibyte)
  foreach(i RANGE 1 65)
    file(APPEND "${OUT}/huge_file.json" "${mebibyte}")
  endforeach()
endif()

# --- the cases -----------------------------------------------------------------------------
set(passed 0)
set(failed 0)
file(STRINGS "${CASES}/cases.txt" lines)
set(named "")
foreach(line IN LISTS lines)
  if(line STREQUAL "" OR line MATCHES "^#")
    continue()
  endif()
  string(FIND "${line}" "|" first_bar)
  string(FIND "${line}" "|" last_bar REVERSE)
  if(first_bar EQUAL -1 OR first_bar EQUAL last_bar)
    message(FATAL_ERROR "cases.txt: want code|message|arguments, got: ${line}")
  endif()
  string(SUBSTRING "${line}" 0 ${first_bar} code)
  math(EXPR message_start "${first_bar} + 1")
  math(EXPR message_length "${last_bar} - ${message_start}")
  string(SUBSTRING "${line}" ${message_start} ${message_length} expected)
  math(EXPR arguments_start "${last_bar} + 1")
  string(SUBSTRING "${line}" ${arguments_start} -1 arguments)
  string(REPLACE "\${OUT}" "${OUT}" arguments "${arguments}")
  string(REPLACE "\${OUT}" "${OUT}" expected "${expected}")
  separate_arguments(arguments UNIX_COMMAND "${arguments}")
  string(REPLACE ";" " " spaced "${arguments}")
  string(APPEND named " ${spaced} ")
  execute_process(COMMAND "${STEPWISE}" ${arguments} WORKING_DIRECTORY "${CASES}" TIMEOUT 60
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "${expected}" found)
  if(result STREQUAL code AND NOT found EQUAL -1)
    math(EXPR passed "${passed} + 1")
  else()
    math(EXPR failed "${failed} + 1")
    message("FAILED stepwise ${arguments}\n  expected exit ${code} and stderr containing: ${expected}\n"
            "  got exit ${result}, stderr: ${err}")
  endif()
endforeach()

file(GLOB files RELATIVE "${CASES}" "${CASES}/*.json")
foreach(file IN LISTS files)
  string(FIND "${named}" " ${file} " at)
  if(at EQUAL -1)
    math(EXPR failed "${failed} + 1")
    message("FAILED ${file} has no line in cases.txt")
  endif()
endforeach()

message("bad input: ${passed} passed, ${failed} failed")
if(failed GREATER 0)
  message(FATAL_ERROR "bad input: ${failed} case(s) failed")
endif()
