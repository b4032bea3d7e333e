# The page check checked (ctest docs.pages.selftest): the pages of good/ use every flagged word
# in a legitimate way and keep every rule, so the check must pass them; the pages of bad/ break
# each rule once, so it must fail, naming each page, line and word below.
# Usage: cmake -DSOURCE=<repo> -P selftest.cmake
set(check ${SOURCE}/docs/check_pages.cmake)
set(here ${SOURCE}/docs/check_pages_fixtures)
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE=${SOURCE} -DPAGES_DIR=${here}/good
                        -DPAGE_CHECK_EXEMPT= -P ${check}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT out MATCHES "2 chapter pages checked")
  message(FATAL_ERROR "the check fails pages that keep the rules:\n${out}${err}")
endif()
# An exempt page that passes is named, so the list can be emptied.
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE=${SOURCE} -DPAGES_DIR=${here}/good
                        -DPAGE_CHECK_EXEMPT=ch01_alpha -P ${check}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT out MATCHES "ch01_alpha.md passes; remove it from PAGE_CHECK_EXEMPT")
  message(FATAL_ERROR "an exempt page that passes is not named:\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE=${SOURCE} -DPAGES_DIR=${here}/bad
                        -DPAGE_CHECK_EXEMPT= -P ${check}
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE status)
if(status EQUAL 0)
  message(FATAL_ERROR "the check passes pages that break the rules:\n${out}${err}")
endif()
set(expected
    "ch01_slips.md:3: 'issue'"
    "ch01_slips.md:4: 'session'"
    "ch01_slips.md:5: 'contract'"
    "ch01_slips.md:6: 'target' as a goal"
    "ch01_slips.md:7: history ('first version')"
    "ch01_slips.md:8: history ('was N, now M')"
    "ch01_slips.md:9: history ('before this')"
    "ch01_slips.md:10: 'epyc'"
    "ch01_slips.md:11: 'xeon'"
    "ch01_slips.md:17: the Exercises section has 2 items"
    "ch01_slips.md: 1 concept figures"
    "ch01_slips.md: not in the menu"
    "ch01_slips.md: no prev/next bar"
    "ch02_gaps.md: no Exercises section"
    "ch02_gaps.md: 0 concept figures"
    "ch03_wrong_bar.md:1: the title line must end in {#ch03_wrong_bar}"
    "ch03_wrong_bar.md:3: the bar's prev link is 'ch01_slips', the chapter before is ch02_gaps"
    "the menu links @ref ch03_missing, and no page has that label")
set(missing "")
foreach(line IN LISTS expected)
  string(FIND "${err}" "${line}" at)
  if(at EQUAL -1)
    string(APPEND missing "  ${line}\n")
  endif()
endforeach()
string(REGEX MATCHALL "\n    [a-zA-Z0-9_.]+(:[0-9]+)?: " reported "${err}")
list(LENGTH reported count)
if(missing OR NOT count EQUAL 23)
  message(FATAL_ERROR "the check's report of bad/ is not the expected one; missing:\n${missing}"
                      "${count} problems reported (23 expected):\n${err}")
endif()
message(STATUS "page check self-test: good/ passes, bad/ fails with each of its ${count} problems named")
