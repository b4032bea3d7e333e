# The docs test a reader would run: every page of the built site opened in headless Chromium.
# Fails on a page whose formulas do not typeset (MathJax missing, a TeX error such as an
# unloaded AMS macro), an image or figure that is missing, or a link to a local file that
# does not exist, or a chapter page missing from the menu bar or from the side tree. With
# -DSCREENSHOTS=<dir> it also saves a screenshot of every page there.
# Usage: cmake -DCHROMIUM=<exe> -DHTML=<built html dir> [-DSCREENSHOTS=<dir>] -P check_site.cmake
if(NOT CHROMIUM OR NOT EXISTS "${CHROMIUM}")
  message(FATAL_ERROR "site check: Chromium not found (tools/setup-deps.sh installs Debian's "
                      "chromium; or pass -DSTEPWISE_CHROMIUM=<browser> to CMake)")
endif()
if(NOT EXISTS ${HTML}/index.html)
  message(FATAL_ERROR "site check: ${HTML}/index.html does not exist (build the docs first)")
endif()
get_filename_component(here ${CMAKE_CURRENT_LIST_FILE} DIRECTORY)
file(COPY ${here}/site_check.js DESTINATION ${HTML})
file(GLOB pages RELATIVE ${HTML} ${HTML}/*.html)
list(FILTER pages EXCLUDE REGEX "\\.sitecheck\\.html$")
set(chrome_flags --headless --no-sandbox --disable-gpu --disable-dev-shm-usage
    --allow-file-access-from-files --no-first-run --hide-scrollbars)
set(failures "")
# The navigation: every chapter page is in the menu bar (menudata.js) and in the side tree with
# its sections under it (navtreedata.js; build_docs.cmake adds the sections).
file(READ ${HTML}/menudata.js menu)
file(READ ${HTML}/navtreedata.js tree)
foreach(page IN LISTS pages)
  if(page MATCHES "^ch[0-9][0-9]_[a-z0-9_]+\\.html$")
    string(FIND "${menu}" "url:\"${page}\"" in_menu)
    string(FIND "${tree}" "\"${page}#" in_tree)
    if(in_menu EQUAL -1)
      string(APPEND failures "  ${page}: not in the menu bar (docs/DoxygenLayout.xml)\n")
    endif()
    if(in_tree EQUAL -1)
      string(APPEND failures "  ${page}: not in the side tree with its sections (docs/navtree_sections.cmake)\n")
    endif()
  endif()
endforeach()
set(copies "")
foreach(page IN LISTS pages)
  file(READ ${HTML}/${page} text)
  # Every local file the page points at must exist (images, figures, scripts, links).
  string(REGEX MATCHALL "(src|data|href)=\"[^\"]*\"" references "${text}")
  foreach(reference IN LISTS references)
    string(REGEX REPLACE "^[a-z]+=\"([^\"#?]*).*" "\\1" target "${reference}")
    if(target STREQUAL "" OR target MATCHES "^[a-z]+:")
      continue()  # an anchor in the page, or a web or javascript: address
    endif()
    if(NOT EXISTS ${HTML}/${target})
      string(APPEND failures "  ${page}: points at ${target}, which is not in the site\n")
    endif()
  endforeach()
  # A copy that carries the checker, which hands its verdict to the driver page framing it.
  string(REPLACE "</body>" "<script src=\"site_check.js\"></script></body>" checked "${text}")
  string(REGEX REPLACE "\\.html$" ".sitecheck.html" copy ${page})
  file(WRITE ${HTML}/${copy} "${checked}")
  list(APPEND copies ${HTML}/${copy})
endforeach()
# One browser for every page: the driver opens each copy in turn and lists the verdicts (starting
# Chromium costs more than checking a page). Each page has up to 60 s of virtual time.
list(LENGTH pages count)
string(REPLACE ";" "\", \"" page_list "${pages}")
set(driver ${HTML}/site_check_driver.sitecheck.html)
file(WRITE ${driver} "<!DOCTYPE html><html><body>\n<script>window.siteCheckPages = [\"${page_list}\"];</script>\n"
                     "<script src=\"site_check.js\"></script>\n</body></html>\n")
math(EXPR budget "(${count} + 1) * 60000")
execute_process(COMMAND ${CHROMIUM} ${chrome_flags} --virtual-time-budget=${budget} --dump-dom file://${driver}
                OUTPUT_VARIABLE dom ERROR_VARIABLE chrome_errors RESULT_VARIABLE status
                TIMEOUT 600)
file(REMOVE ${driver} ${copies})
if(NOT dom MATCHES "SITECHECK-BEGIN\n(.*)\nSITECHECK-END")
  string(APPEND failures "  the checker did not finish (Chromium exit ${status})\n")
else()
  string(REPLACE "\n" ";" verdicts "${CMAKE_MATCH_1}")
  foreach(page IN LISTS pages)
    list(FIND verdicts "OK ${page}" ok)
    if(ok EQUAL -1)
      set(found "")
      foreach(verdict IN LISTS verdicts)
        string(FIND "${verdict}" "${page}: " at)
        if(at EQUAL 0)
          string(APPEND found "  ${verdict}\n")
        endif()
      endforeach()
      if(found STREQUAL "")
        set(found "  ${page}: no verdict from the checker\n")
      endif()
      string(APPEND failures "${found}")
    endif()
  endforeach()
endif()
if(SCREENSHOTS)
  file(MAKE_DIRECTORY ${SCREENSHOTS})
  foreach(page IN LISTS pages)
    string(REGEX REPLACE "\\.html$" ".png" shot ${page})
    execute_process(COMMAND ${CHROMIUM} ${chrome_flags} --virtual-time-budget=60000 --window-size=1280,2400
                            --screenshot=${SCREENSHOTS}/${shot} file://${HTML}/${page}
                    OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
  endforeach()
endif()
file(REMOVE ${HTML}/site_check.js)
if(failures)
  message(FATAL_ERROR "site check: problems a reader would see:\n${failures}")
endif()
message(STATUS "site check: ${count} pages, every formula typeset, every image and link present")
