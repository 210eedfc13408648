# Checks the command pages in DOCS against LUXEL's own --help, both ways: every long option a
# command's --help lists is named in the "## Options" section of DOCS/COMMAND.md, and every option
# that section names is one the command takes. Prints one line per difference, naming the page and
# the option, then fails.
#
# An option counts as named where a code span opens with it in the first column of a table, or
# anywhere in the section's prose (compare.md and cost.md list render's frame options there). A
# mention inside another option's meaning does not count, so a deleted row is noticed even when a
# neighbouring row still refers to its option (`--frames` ... excludes `--sequence`).
#
# The commands are taken from `luxel --help`, so a new command without a page fails too. A command
# with subcommands (report) has one page for all of them: its page is checked against their options
# together. --help and --version are everywhere and belong to no page.
#
#   cmake -DLUXEL=build/release/cli/luxel -DDOCS=docs -P tests/cli/docs_match_help.cmake
cmake_minimum_required(VERSION 3.25)  # a script starts with old policies: IN_LIST needs CMP0057
if(NOT DEFINED LUXEL OR NOT DEFINED DOCS)
  message(FATAL_ERROR "usage: cmake -DLUXEL=path/to/luxel -DDOCS=path/to/docs -P docs_match_help.cmake")
endif()
set(everywhere --help --version)

# TEXT as a list of its lines in OUT. In CMake's list syntax a ';' or a '\' before the newline's
# ';' would split or join lines, and so would an unbalanced '[' (brackets group list items), so
# they become characters no option name holds before the newlines become separators.
function(lines_of text out)
  string(REPLACE "\\" "/" text "${text}")
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "[" "(" text "${text}")
  string(REPLACE "]" ")" text "${text}")
  string(REPLACE "\n" ";" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# The long options and the subcommands `luxel WORDS... --help` lists, into OPTIONS and SUBCOMMANDS.
# Only the names that open an option's line count: the text after them ("Excludes: --frame",
# "Needs: --scene", the descriptions) names other options.
function(read_help options_out subcommands_out)
  execute_process(COMMAND "${LUXEL}" ${ARGN} --help RESULT_VARIABLE code OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    string(JOIN " " words luxel ${ARGN} --help)
    message(FATAL_ERROR "`${words}` exited with ${code}:\n${text}${err}")
  endif()
  lines_of("${text}" lines)
  set(section "")
  set(options "")
  set(subcommands "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^([A-Za-z]+):$")
      set(section "${CMAKE_MATCH_1}")
    elseif(section STREQUAL "Options" AND line MATCHES "^  (-[^ {]*)")
      # "-h,--help", "--no-bloom", and "--no-color-correction{false}": CLI11 shows the value a flag
      # sets in braces after its name.
      string(REPLACE "," ";" names "${CMAKE_MATCH_1}")
      foreach(name IN LISTS names)
        if(name MATCHES "^--" AND NOT name IN_LIST everywhere)
          list(APPEND options "${name}")
        endif()
      endforeach()
    elseif(section STREQUAL "Subcommands" AND line MATCHES "^  ([a-z][-a-z0-9_]*)( |$)")
      list(APPEND subcommands "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  set(${options_out} "${options}" PARENT_SCOPE)
  set(${subcommands_out} "${subcommands}" PARENT_SCOPE)
endfunction()

# The options the "## Options" section of PAGE names (see the top of this file), into OUT; FOUND is
# false when the page has no such section.
function(read_page page out found_out)
  file(READ "${page}" text)
  # An escaped '|' inside a cell (`--bake full\|quick`) must not end the cell.
  string(REPLACE "\\|" "/" text "${text}")
  lines_of("${text}" lines)
  set(inside FALSE)
  set(found FALSE)
  set(options "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^## ")
      if(line MATCHES "^## Options *$")
        set(inside TRUE)
        set(found TRUE)
      else()
        set(inside FALSE)
      endif()
    elseif(inside)
      if(line MATCHES "^ *\\|([^|]*)")
        set(named "${CMAKE_MATCH_1}")
      else()
        set(named "${line}")
      endif()
      string(REGEX MATCHALL "`--[A-Za-z0-9][-A-Za-z0-9_]*" spans "${named}")
      foreach(span IN LISTS spans)
        string(SUBSTRING "${span}" 1 -1 name)
        if(NOT name IN_LIST everywhere)
          list(APPEND options "${name}")
        endif()
      endforeach()
    endif()
  endforeach()
  list(REMOVE_DUPLICATES options)
  set(${out} "${options}" PARENT_SCOPE)
  set(${found_out} ${found} PARENT_SCOPE)
endfunction()

set(differences "")
read_help(unused commands)
if(NOT commands)
  message(FATAL_ERROR "`luxel --help` lists no commands")
endif()
foreach(command IN LISTS commands)
  read_help(help subcommands ${command})
  set(sources "luxel ${command} --help")
  if(subcommands)
    set(help "")
    set(sources "")
    foreach(subcommand IN LISTS subcommands)
      read_help(sub_help unused ${command} ${subcommand})
      list(APPEND help ${sub_help})
      list(APPEND sources "luxel ${command} ${subcommand} --help")
    endforeach()
    list(REMOVE_DUPLICATES help)
  endif()
  string(JOIN "` and `" sources ${sources})

  set(page "${command}.md")
  if(NOT EXISTS "${DOCS}/${page}")
    list(APPEND differences "${page}: missing, yet `luxel --help` lists the command ${command}")
    continue()
  endif()
  read_page("${DOCS}/${page}" documented found)
  if(NOT found)
    list(APPEND differences "${page}: no \"## Options\" section")
    continue()
  endif()
  foreach(option IN LISTS help)
    if(NOT option IN_LIST documented)
      list(APPEND differences "${page}: ${option} is in `${sources}` but the page does not name it")
    endif()
  endforeach()
  foreach(option IN LISTS documented)
    if(NOT option IN_LIST help)
      list(APPEND differences "${page}: ${option} is on the page but not in `${sources}`")
    endif()
  endforeach()
endforeach()

if(differences)
  # One line each: message(FATAL_ERROR) would rewrap them.
  foreach(difference IN LISTS differences)
    message(NOTICE "${difference}")
  endforeach()
  list(LENGTH differences count)
  message(FATAL_ERROR "${count} difference(s) between the pages in ${DOCS} and luxel's --help")
endif()
