# The project speaks of itself: its code, build files, scripts and documentation name no work
# sessions or issue numbers (history is git log) and point at no file outside the repository
# (the shared folder beside it). Run as: cmake -DROOT=<source dir> -P speaks_of_itself.cmake
file(GLOB_RECURSE files RELATIVE ${ROOT}
     ${ROOT}/*.cpp ${ROOT}/*.hpp ${ROOT}/*.h ${ROOT}/*.cmake ${ROOT}/*CMakeLists.txt ${ROOT}/*.md ${ROOT}/*.txt
     ${ROOT}/*.json ${ROOT}/scripts/* ${ROOT}/.ci/*)
set(offences "")
foreach(f IN LISTS files)
  # Build trees, fetched dependencies and third-party test data are not the project's words.
  # This file names what it looks for.
  if(f MATCHES "^(build|_deps|\\.git)/|/build/|^tests/data/(gltf|gltf-bad|fuzz|hostile)/|^fuzz/corpus/|^tests/project/")
    continue()
  endif()
  file(STRINGS ${ROOT}/${f} lines)
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    if(line MATCHES "[Ss]ession[s]? [0-9]|[Ii]ssue #?[0-9]|\\(#[0-9]+\\)|\\.\\./shared/|SOURCE_FACTS|SDK_AUDIT")
      string(APPEND offences "${f}:${n}: ${line}\n")
    endif()
  endforeach()
endforeach()
if(offences)
  message(FATAL_ERROR "the project names sessions, issues or files outside itself:\n${offences}")
endif()
list(LENGTH files count)
message(STATUS "speaks_of_itself: ${count} files read")
