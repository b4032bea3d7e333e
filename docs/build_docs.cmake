# Builds the course site: plots from quick bench runs, the figures, the headless runs the pages
# include, the snippet check, then Doxygen and MathJax.
cmake_policy(SET CMP0057 NEW)  # IN_LIST under cmake -P
file(MAKE_DIRECTORY ${IMAGES})
# The chapter pages' own rules (voice, exercises, figures, menu, prev/next) first: cheap, and a
# page that breaks them fails the build before the benches run.
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE=${SOURCE} -P ${SOURCE}/docs/check_pages.cmake
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "page check failed (docs/check_pages.cmake)")
endif()
execute_process(COMMAND ${STEPWISE} bench --list OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "stepwise bench --list failed (${status})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
foreach(line IN LISTS lines)
  if(line MATCHES "^([a-z0-9_-]+)")
    set(suite ${CMAKE_MATCH_1})
    # A bench whose test ran it quick in this ctest run (BENCH_RUNS, docs/CMakeLists.txt): its
    # files, written by the same code with the same options, and what it printed (written last).
    if(BENCH_RUNS AND EXISTS ${BENCH_RUNS}/bench-${suite}.txt)
      file(GLOB kept ${BENCH_RUNS}/bench-${suite}.* ${BENCH_RUNS}/bench-${suite}-*)
      file(COPY ${kept} DESTINATION ${IMAGES})
      message(STATUS "bench ${suite}: plot from its test's run")
      continue()
    endif()
    execute_process(COMMAND ${STEPWISE} bench ${suite} --quick --csv ${IMAGES}/bench-${suite}.csv
                            --plot ${IMAGES}/bench-${suite}.svg
                    OUTPUT_FILE ${IMAGES}/bench-${suite}.txt RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "stepwise bench ${suite} --quick failed (${status})")
    endif()
    message(STATUS "bench ${suite}: plot written")
  endif()
endforeach()
# The figures, drawn by the engine's own code (docs/figures/).
execute_process(COMMAND ${FIGURES} ${IMAGES} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "stepwise_figures failed (${status})")
endif()
# The extremes tables of docs/reliability.md, quick form (bench/extremes.cpp).
execute_process(COMMAND ${EXTREMES} --quick OUTPUT_FILE ${IMAGES}/extremes.txt RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "stepwise_extremes --quick failed (${status})")
endif()
# "What you should see": a page that includes run-chNN-SCENE.txt gets what a headless run of
# SCENE with chapter NN's engine prints over 600 frames (10 s), from this build's program.
file(GLOB pages ${SOURCE}/docs/*.md)
foreach(page IN LISTS pages)
  file(STRINGS ${page} includes REGEX "run-ch[0-9]+-[a-z0-9-]+\\.txt")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "run-ch([0-9]+)-([a-z0-9-]+)\\.txt" output "${line}")
    set(scene ${CMAKE_MATCH_2})
    math(EXPR chapter "${CMAKE_MATCH_1}")
    execute_process(COMMAND ${STEPWISE} run ${scene} --chapter ${chapter} --frames 600
                    OUTPUT_FILE ${IMAGES}/${output} RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "stepwise run ${scene} --chapter ${chapter} failed (${status}), for ${page}")
    endif()
  endforeach()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE=${SOURCE} -P ${SOURCE}/docs/check_snippets.cmake
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "snippet check failed")
endif()
get_filename_component(doxyfile_dir ${DOXYFILE} DIRECTORY)
file(REMOVE_RECURSE ${doxyfile_dir}/html)  # no page of an older build survives
execute_process(COMMAND ${DOXYGEN} ${DOXYFILE} WORKING_DIRECTORY ${doxyfile_dir} RESULT_VARIABLE status)
# MathJax 2.7 (Debian's libjs-mathjax) goes next to the pages: formulas render offline. Only
# what the configuration loads is copied: TeX input, the AMS extensions, SVG output, TeX font.
set(mathjax ${doxyfile_dir}/html/mathjax)
file(REMOVE_RECURSE ${mathjax})
foreach(part MathJax.js extensions jax/input/TeX jax/element jax/output/SVG/jax.js
             jax/output/SVG/config.js jax/output/SVG/autoload jax/output/SVG/fonts/TeX localization/en)
  get_filename_component(parent ${mathjax}/${part} DIRECTORY)
  file(COPY ${MATHJAX}/${part} DESTINATION ${parent})
endforeach()
if(EXISTS ${doxyfile_dir}/warnings.log)
  file(READ ${doxyfile_dir}/warnings.log warnings)
endif()
if(NOT status EQUAL 0 OR warnings)
  message(FATAL_ERROR "Doxygen reported warnings (the docs build fails on any):\n${warnings}")
endif()
# The side tree: each page's sections under its entry (docs/navtree_sections.cmake).
execute_process(COMMAND ${CMAKE_COMMAND} -DHTML=${doxyfile_dir}/html -DPAGES=${SOURCE}/docs
                        -P ${SOURCE}/docs/navtree_sections.cmake RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "navtree_sections.cmake failed (${status})")
endif()
message(STATUS "docs: ${doxyfile_dir}/html/index.html")
