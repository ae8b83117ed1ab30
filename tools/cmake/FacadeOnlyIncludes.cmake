# Checks that sources include only the facade (linesurf/...), third-party and standard headers
# and headers of tools/: no engine/, partition/ or solver/ header, directly or through a tools/
# header they include (followed transitively). Run by CTest (`cmake -P`):
#   -DROOT=<repository> -DSOURCES=<a.cpp,b.cpp,...>  paths relative to ROOT, comma-separated; a
#                                                     path with '*' is a glob
#   -DSELF_TEST_DIR=<scratch dir>                     instead: checks that the check finds a
#                                                     forbidden include, direct and transitive
# Fails naming file:line, the include and the source that reached it.

cmake_minimum_required(VERSION 3.20)  # IN_LIST, list(POP_FRONT) in script mode

set(LINESURF_FORBIDDEN_INCLUDE "^(engine|partition|solver)/")

# The lines of `path` as a list, empty lines kept (file(STRINGS) drops them, which would shift
# the line numbers); characters CMake lists treat specially are masked.
function(linesurf_read_lines path out)
  file(READ "${path}" text)
  string(REPLACE "\\" "/" text "${text}")
  string(REPLACE "[" "(" text "${text}")
  string(REPLACE "]" ")" text "${text}")
  string(REPLACE ";" "," text "${text}")
  string(REPLACE "\n" ";" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# Sets `out` to one "file:line: #include \"x\" (reached from source)" entry per forbidden include
# in `sources` (relative to `root`) and the tools/ headers they include, transitively.
function(linesurf_forbidden_includes root sources out)
  set(found "")
  set(seen "")
  foreach(source IN LISTS sources)
    set(queue "${source}")
    while(queue)
      list(POP_FRONT queue file)
      if("${file}" IN_LIST seen)
        continue()
      endif()
      list(APPEND seen "${file}")
      if(NOT EXISTS "${root}/${file}")
        list(APPEND found "${file}: no such file (reached from ${source})")
        continue()
      endif()
      linesurf_read_lines("${root}/${file}" lines)
      list(LENGTH lines count)
      if(count EQUAL 0)
        continue()
      endif()
      math(EXPR last "${count} - 1")
      foreach(i RANGE ${last})
        list(GET lines ${i} line)
        if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"]")
          continue()
        endif()
        set(header "${CMAKE_MATCH_1}")
        if(header MATCHES "${LINESURF_FORBIDDEN_INCLUDE}")
          math(EXPR number "${i} + 1")
          list(APPEND found "${file}:${number}: #include \"${header}\" (reached from ${source})")
        elseif(header MATCHES "^tools/" AND EXISTS "${root}/${header}")
          list(APPEND queue "${header}")
        endif()
      endforeach()
    endwhile()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

if(SELF_TEST_DIR)
  # A command that includes a clean helper, a helper with a forbidden include (line 3, after an
  # empty line and a commented-out include) and a facade header: exactly the two bad lines.
  file(REMOVE_RECURSE "${SELF_TEST_DIR}")
  file(WRITE "${SELF_TEST_DIR}/tools/cli/cmd_x.cpp"
    "#include \"linesurf/linesurf.h\"\n#include \"tools/cli/bad.h\"\n#include <vector>\n"
    "  #  include <solver/lp/lp_backend.h>\n")
  file(WRITE "${SELF_TEST_DIR}/tools/cli/bad.h"
    "#pragma once\n// #include \"engine/core/commented.h\"\n#include \"engine/core/scene.h\"\n"
    "int a[2];\n#include \"tools/cli/good.h\"\n")
  file(WRITE "${SELF_TEST_DIR}/tools/cli/good.h" "#pragma once\n#include <string>\n")
  linesurf_forbidden_includes("${SELF_TEST_DIR}" "tools/cli/cmd_x.cpp" found)
  set(expected
    "tools/cli/cmd_x.cpp:4: #include \"solver/lp/lp_backend.h\" (reached from tools/cli/cmd_x.cpp)"
    "tools/cli/bad.h:3: #include \"engine/core/scene.h\" (reached from tools/cli/cmd_x.cpp)")
  list(SORT found)
  list(SORT expected)
  if(NOT found STREQUAL expected)
    message(FATAL_ERROR "the check found:\n  ${found}\nexpected:\n  ${expected}")
  endif()
  linesurf_forbidden_includes("${SELF_TEST_DIR}" "tools/cli/good.h" clean)
  if(clean)
    message(FATAL_ERROR "the check found forbidden includes in a clean file: ${clean}")
  endif()
  message(STATUS "the check finds direct and transitive forbidden includes, and only those")
  return()
endif()

if(NOT ROOT OR NOT SOURCES)
  message(FATAL_ERROR "usage: cmake -DROOT=<repository> -DSOURCES=<a.cpp,b.h,...> -P ${CMAKE_CURRENT_LIST_FILE}")
endif()
string(REPLACE "," ";" patterns "${SOURCES}")
set(sources "")
foreach(pattern IN LISTS patterns)
  if(pattern MATCHES "\\*")
    file(GLOB matched RELATIVE "${ROOT}" "${ROOT}/${pattern}")
    if(NOT matched)
      message(FATAL_ERROR "no file matches ${pattern}")
    endif()
    list(SORT matched)
    list(APPEND sources ${matched})
  else()
    list(APPEND sources "${pattern}")
  endif()
endforeach()
linesurf_forbidden_includes("${ROOT}" "${sources}" found)
if(found)
  list(JOIN found "\n  " listed)
  message(FATAL_ERROR "headers outside the facade (engine/, partition/, solver/):\n  ${listed}")
endif()
list(LENGTH sources count)
message(STATUS "${count} files and the tools/ headers they include use the facade only")
