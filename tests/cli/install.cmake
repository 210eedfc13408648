# Installs the build BUILD into PREFIX (emptied first), checks that the prefix holds bin/luxel and
# nothing else, and runs the installed command from another folder: a small render written there.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${PREFIX}" RESULT_VARIABLE code
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${code}):\n${out}${err}")
endif()
file(GLOB_RECURSE installed RELATIVE "${PREFIX}" "${PREFIX}/*")
if(NOT installed STREQUAL "bin/luxel")
  message(FATAL_ERROR "the prefix should hold bin/luxel alone, it holds: ${installed}")
endif()
file(MAKE_DIRECTORY "${PREFIX}/elsewhere")
execute_process(COMMAND "${PREFIX}/bin/luxel" render --scene builtin:demo --width 32 --height 24 --out demo.png
                WORKING_DIRECTORY "${PREFIX}/elsewhere" RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT EXISTS "${PREFIX}/elsewhere/demo.png")
  message(FATAL_ERROR "the installed luxel did not render from another folder (${code}):\n${err}")
endif()
