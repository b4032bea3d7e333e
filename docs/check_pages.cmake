# The rules every chapter page docs/chNN_*.md keeps, checked on the page's source:
#   (a) the course voice: no project-tracking words (issue, session, contract, target as a goal),
#       no host or CPU model names, no history ("first version", "was 22, now 6", "before this");
#   (b) an Exercises section with at least three items;
#   (c) at least two concept figures drawn by docs/figures (fig-*.svg; bench plots and
#       screenshots do not count);
#   (d) the page's line in the menu, DoxygenLayout.xml;
#   (e) the prev/next bar, pointing at the neighbouring chapter pages.
# Each problem names the page, the line and the word. Run by the docs build (build_docs.cmake)
# and as `ctest -L docs` (docs.pages); docs.pages.good and docs.pages.bad run it on the pages of
# docs/check_pages_fixtures/ to show it passes real uses and fails slips.
# Usage: cmake -DSOURCE=<repo> [-DPAGES_DIR=<dir>] [-DLAYOUT=<xml>] [-DPAGE_CHECK_EXEMPT=...]
#              -P check_pages.cmake
cmake_minimum_required(VERSION 3.20)  # under cmake -P: IN_LIST, empty list elements kept, POP_FRONT

# Pages the check reports without failing, while they are being rewritten. Empty it when they
# land: a page listed here that passes is named in the output.
if(NOT DEFINED PAGE_CHECK_EXEMPT)
  set(PAGE_CHECK_EXEMPT "")
endif()
if(NOT PAGES_DIR)
  set(PAGES_DIR ${SOURCE}/docs)
endif()
if(NOT LAYOUT)
  set(LAYOUT ${PAGES_DIR}/DoxygenLayout.xml)
endif()
# A concept figure, as docs/figures/main.cpp names what it draws.
set(FIGURE_REGEX "fig-[a-z0-9_-]+\\.svg")

# (a) The voice. Text is lower-cased and stripped of code spans, URLs, \ref labels, formulas and
# HTML tags first; then the allowed phrases are removed; then the flagged ones are looked for.
# Word edges: CMake's regex has no \b.
set(L "(^|[^a-z0-9_])")
set(R "([^a-z0-9_]|$)")
set(ALLOWED_PHRASES
    "debug sessions?"                   # chapter 9's DebugSession, the engine's own object
    "(libccd|fcl|bullet|box2d|jolt|github) (issue|pull request)s? #?[0-9]+"  # another project's tracker, cited
    "issues?/[0-9]+"
    "(fuzz|cmake|build|link) targets?"  # libFuzzer's and CMake's own terms
    "(compiler|gcc|clang|msvc) contracts"  # floating-point contraction (fused multiply-add)
    "--target")
set(VOICE_RULES  # pairs: regex ; what the report calls it
    "${L}issues?${R}" "'issue' (a project-tracking word)"
    "${L}sessions?${R}" "'session' (a project-tracking word)"
    "${L}contracts?${R}" "'contract' (a project-tracking word)"
    "${L}targets? (is|are|was|were|stays?) (all |now |still )?(met|missed|reached)${R}" "'target' as a goal"
    "${L}(meets?|met|missed|misses|reach|reaches|reached|set|sets|grades?|graded) (all |every |each |the |its |four |three |two |these |those |their )*([a-z0-9.'-]+ )?targets${R}" "'target' as a goal"
    "${L}(chapter|issue|page|stacking|performance)('s)? targets?${R}" "'target' as a goal"
    "[0-9]x targets?${R}" "'target' as a goal"
    "${L}targets? (scenes?|numbers?|ratios?)${R}" "'target' as a goal"
    "${L}the targets([,.:)]|$)" "'target' as a goal"
    "${L}first versions?${R}" "history ('first version')"
    "${L}earlier versions?${R}" "history ('earlier version')"
    "${L}earlier runs?${R}" "history ('earlier run')"
    "${L}the run before${R}" "history ('the run before')"
    "${L}was [-0-9.]+[a-z% ]*, now${R}" "history ('was N, now M')"
    "${L}before this([^a-z ]| *$| +[^a-z ])" "history ('before this')")
# Host and CPU model names are looked for everywhere, code and file names included.
set(HOST_REGEX "(^|[^a-z0-9])(epyc|xeon|ryzen|threadripper|opteron)([^a-z0-9]|$)")

# Reads a file into a list of lines, one element per line (empty lines kept), with the
# characters CMake's lists treat specially (; [ ]) replaced.
function(read_lines file out)
  file(READ ${file} text)
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "[" "(" text "${text}")
  string(REPLACE "]" ")" text "${text}")
  string(REPLACE "\\" "/" text "${text}")
  string(REPLACE "\n" ";" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# The visible prose of a line, lower-cased (backslashes already read as /).
function(prose_of line out)
  string(REGEX REPLACE "`[^`]*`" " " line "${line}")
  string(REGEX REPLACE "<https?://[^>]*>" " " line "${line}")
  string(REGEX REPLACE "https?://[^ )>]*" " " line "${line}")
  string(REGEX REPLACE "/(ref|subpage) +[A-Za-z0-9_]+" " " line "${line}")
  string(REGEX REPLACE "/f\\$[^$]*/f\\$" " " line "${line}")
  string(REGEX REPLACE "/f\\(.*/f\\)" " " line "${line}")
  string(REGEX REPLACE "\\{#[A-Za-z0-9_]+\\}" " " line "${line}")
  string(REGEX REPLACE "<[^>]*>" " " line "${line}")
  string(REGEX REPLACE "^/image +[a-z]+ +[^ ]+" " " line "${line}")
  string(TOLOWER "${line}" line)
  foreach(allowed IN LISTS ALLOWED_PHRASES)
    string(REGEX REPLACE "${allowed}" " " line "${line}")
  endforeach()
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

# Page labels ({#label} on the first line) of every page, for the menu's and the bar's links.
file(GLOB all_pages ${PAGES_DIR}/*.md)
set(labels "")
foreach(page IN LISTS all_pages)
  file(STRINGS ${page} first LIMIT_COUNT 1)
  if(first MATCHES "\\{#([A-Za-z0-9_]+)\\}")
    list(APPEND labels ${CMAKE_MATCH_1})
  endif()
endforeach()

# The menu, without XML comments (a commented-out line is not in the menu).
if(NOT EXISTS ${LAYOUT})
  message(FATAL_ERROR "page check: ${LAYOUT} does not exist")
endif()
file(READ ${LAYOUT} layout)
while(TRUE)
  string(FIND "${layout}" "<!--" open)
  if(open EQUAL -1)
    break()
  endif()
  string(SUBSTRING "${layout}" ${open} -1 rest)
  string(FIND "${rest}" "-->" close)
  if(close EQUAL -1)
    message(FATAL_ERROR "page check: ${LAYOUT}: a comment is never closed")
  endif()
  math(EXPR after "${open} + ${close} + 3")
  string(SUBSTRING "${layout}" 0 ${open} head)
  string(SUBSTRING "${layout}" ${after} -1 tail)
  set(layout "${head}${tail}")
endwhile()
string(REGEX MATCHALL "url=\"@ref [A-Za-z0-9_]+\"" menu_refs "${layout}")
set(menu "")
foreach(ref IN LISTS menu_refs)
  string(REGEX REPLACE "url=\"@ref ([A-Za-z0-9_]+)\"" "\\1" ref "${ref}")
  list(APPEND menu ${ref})
endforeach()
get_filename_component(layout_name ${LAYOUT} NAME)
set(failures "")
foreach(ref IN LISTS menu)
  if(NOT ref IN_LIST labels)
    string(APPEND failures "  ${layout_name}: the menu links @ref ${ref}, and no page has that label\n")
  endif()
endforeach()

file(GLOB chapter_pages ${PAGES_DIR}/ch[0-9][0-9]_*.md)
list(SORT chapter_pages)
set(chapter_labels "")
foreach(page IN LISTS chapter_pages)
  get_filename_component(name ${page} NAME_WE)
  list(APPEND chapter_labels ${name})
endforeach()
list(LENGTH chapter_labels chapter_count)

set(exempt_report "")
set(index 0)
foreach(page IN LISTS chapter_pages)
  get_filename_component(name ${page} NAME_WE)
  get_filename_component(file_name ${page} NAME)
  set(problems "")
  read_lines(${page} lines)

  # The page's own label must be its file name: the menu, the bar and the site link by it.
  list(GET lines 0 title)
  if(NOT title MATCHES "^# .*\\{#${name}\\}")
    string(APPEND problems "  ${file_name}:1: the title line must end in {#${name}}\n")
  endif()

  set(number 0)
  set(in_fence FALSE)
  set(in_math FALSE)
  set(in_comment FALSE)
  set(previous_blank TRUE)
  set(previous_code FALSE)
  set(exercise_level 0)
  set(exercise_items -1)
  set(figures "")
  set(nav_bars 0)
  list(LENGTH lines line_count)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    string(TOLOWER "${line}" lower)
    if(lower MATCHES "${HOST_REGEX}")
      string(APPEND problems "  ${file_name}:${number}: '${CMAKE_MATCH_2}' (a host or CPU model: name results by what they measure)\n")
    endif()
    # Where the line is: code, a formula block or a comment are not prose.
    set(blank FALSE)
    if(line MATCHES "^[ \t]*$")
      set(blank TRUE)
    endif()
    if(line MATCHES "^[ \t]*(```|~~~)")
      if(in_fence)
        set(in_fence FALSE)
      else()
        set(in_fence TRUE)
      endif()
      continue()
    endif()
    if(in_fence)
      continue()
    endif()
    if(line MATCHES "^[ \t]*/(code|verbatim)")
      set(in_fence TRUE)  # closed by /endcode or /endverbatim below
      continue()
    endif()
    if(line MATCHES "^[ \t]*/f\\(" AND NOT line MATCHES "/f\\)")
      set(in_math TRUE)
    endif()
    if(in_math)
      if(line MATCHES "/f\\)")
        set(in_math FALSE)
      endif()
      continue()
    endif()
    if(line MATCHES "<!--")
      set(in_comment TRUE)
    endif()
    if(in_comment)
      if(line MATCHES "-->")
        set(in_comment FALSE)
      endif()
      continue()
    endif()
    set(code FALSE)
    if(line MATCHES "^(    |\t)" AND (previous_blank OR previous_code))
      set(code TRUE)
    endif()
    if(NOT blank)
      set(previous_code ${code})
    endif()
    set(previous_blank ${blank})
    if(code OR line MATCHES "^[ \t]*/(snippet|verbinclude|include|dontinclude|htmlinclude)")
      continue()
    endif()

    # (a) the voice, on the prose; "before this" looks at the next line's first word.
    prose_of("${line}" prose)
    if(number LESS line_count)
      list(GET lines ${number} next)
      string(STRIP "${next}" next)
      string(REGEX REPLACE "[ \t].*" "" next_word "${next}")
      string(TOLOWER "${next_word}" next_word)
      if(prose MATCHES "before this *$" AND NOT next_word STREQUAL "")
        string(APPEND prose " ${next_word}")
      endif()
    endif()
    set(rules ${VOICE_RULES})
    while(rules)
      list(POP_FRONT rules regex what)
      if(prose MATCHES "${regex}")
        string(STRIP "${CMAKE_MATCH_0}" found)
        string(SUBSTRING "${line}" 0 90 context)
        string(STRIP "${context}" context)
        string(APPEND problems "  ${file_name}:${number}: ${what}, \"${found}\" in: ${context}\n")
      endif()
    endwhile()

    # (b) the exercises: the items of the section, up to the next heading as high as it.
    if(lower MATCHES "^(#+) +exercises")
      string(LENGTH "${CMAKE_MATCH_1}" exercise_level)
      set(exercise_items 0)
      set(exercise_line ${number})
    elseif(exercise_level GREATER 0 AND lower MATCHES "^(#+) ")
      string(LENGTH "${CMAKE_MATCH_1}" level)
      if(NOT level GREATER exercise_level)
        set(exercise_level 0)
      endif()
    elseif(exercise_level GREATER 0 AND line MATCHES "^([0-9]+\\.|[-*]) ")
      math(EXPR exercise_items "${exercise_items} + 1")
    endif()

    # (c) the concept figures shown.
    if(line MATCHES "^[ \t]*/image" OR line MATCHES "(src|data)=\"${FIGURE_REGEX}")
      string(REGEX MATCHALL "${FIGURE_REGEX}" shown "${line}")
      list(APPEND figures ${shown})
    endif()

    # (e) the prev/next bar: prev is the chapter before (any page before chapter 1), next the
    # chapter after (none after the last).
    if(line MATCHES "class=\"chapter-nav\"")
      math(EXPR nav_bars "${nav_bars} + 1")
      set(prev_ref "")
      set(next_ref "")
      if(line MATCHES "class=\"prev\">/ref +([A-Za-z0-9_]+)")
        set(prev_ref ${CMAKE_MATCH_1})
      endif()
      if(line MATCHES "class=\"next\">/ref +([A-Za-z0-9_]+)")
        set(next_ref ${CMAKE_MATCH_1})
      endif()
      if(index GREATER 0)
        math(EXPR before "${index} - 1")
        list(GET chapter_labels ${before} want)
        if(NOT prev_ref STREQUAL want)
          string(APPEND problems "  ${file_name}:${number}: the bar's prev link is '${prev_ref}', the chapter before is ${want}\n")
        endif()
      elseif(prev_ref STREQUAL "")
        string(APPEND problems "  ${file_name}:${number}: the bar has no prev link\n")
      endif()
      math(EXPR after "${index} + 1")
      if(after LESS chapter_count)
        list(GET chapter_labels ${after} want)
        if(NOT next_ref STREQUAL want)
          string(APPEND problems "  ${file_name}:${number}: the bar's next link is '${next_ref}', the chapter after is ${want}\n")
        endif()
      endif()
    endif()
  endforeach()

  if(exercise_items EQUAL -1)
    string(SUBSTRING "${name}" 0 4 prefix)
    string(APPEND problems "  ${file_name}: no Exercises section (a heading '# Exercises {#${prefix}_exercises}')\n")
  elseif(exercise_items LESS 3)
    string(APPEND problems "  ${file_name}:${exercise_line}: the Exercises section has ${exercise_items} items, at least 3 are needed\n")
  endif()
  list(REMOVE_DUPLICATES figures)
  list(LENGTH figures figure_count)
  if(figure_count LESS 2)
    string(APPEND problems "  ${file_name}: ${figure_count} concept figures (${FIGURE_REGEX} from docs/figures), at least 2 are needed\n")
  endif()
  if(NOT name IN_LIST menu)
    string(APPEND problems "  ${file_name}: not in the menu (${layout_name} has no url=\"@ref ${name}\")\n")
  endif()
  if(nav_bars EQUAL 0)
    string(APPEND problems "  ${file_name}: no prev/next bar (<div class=\"chapter-nav\">)\n")
  endif()

  if(name IN_LIST PAGE_CHECK_EXEMPT)
    if(problems)
      string(APPEND exempt_report "${problems}")
    else()
      message(STATUS "page check: ${file_name} passes; remove it from PAGE_CHECK_EXEMPT")
    endif()
  else()
    string(APPEND failures "${problems}")
  endif()
  math(EXPR index "${index} + 1")
endforeach()

if(exempt_report)
  message(STATUS "page check: pages in PAGE_CHECK_EXEMPT (docs/check_pages.cmake), reported, not failed:\n${exempt_report}")
endif()
if(failures)
  message(FATAL_ERROR "page check failed:\n${failures}")
endif()
message(STATUS "page check: ${chapter_count} chapter pages checked, ${PAGES_DIR}")
