# Checks the include arrows of the layers (docs/design/layers.md). Run with `cmake -P`:
#   -DROOT=<repository>                       every source under engine/, partition/, solver/,
#                                             tools/ and tests/ includes only headers of its own
#                                             folder's layer or of a lower one; test sources
#                                             (*_test.cpp and tests/) may also
#                                             include the test fixtures and the tools
#   -DROOT=<repository> -DFACADE_ONLY=<a.cpp,b.h,...>
#                                             instead: the listed sources (relative to ROOT; '*'
#                                             globs) include no engine/, partition/ or solver/
#                                             header, directly or through a tools/ header they
#                                             include (followed transitively)
#   -DSELF_TEST_DIR=<scratch dir>             instead: checks that both checks find what they
#                                             must, in a scratch tree written there
# Fails naming file:line and the include.

cmake_minimum_required(VERSION 3.20)  # IN_LIST, list(POP_FRONT) in script mode

# Bottom to top: a folder prefix and its rank. A source may include its own folder and folders
# of a lower rank; folders of one rank (partition/ and solver/) do not see each other.
set(LINESURF_LAYERS
  "engine/include/linesurf=0" "engine/core=1" "engine/io=2" "partition=3" "solver=3"
  "engine/detect=4" "engine/pipeline=5" "engine/api=6" "tools=7" "tests=8")
# What test sources may include besides their layer and the ones below it.
set(LINESURF_TEST_ONLY_INCLUDE "^(tests/support|tools/gen|tools/eval)/")
set(LINESURF_FACADE_FORBIDDEN_INCLUDE "^(engine|partition|solver)/")

# The layer (prefix;rank) of a repository path or an include spelling; empty when it has none.
function(linesurf_layer_of path out_prefix out_rank)
  if(path MATCHES "^linesurf/")
    set(path "engine/include/${path}")
  endif()
  set(best "")
  set(rank "")
  foreach(layer IN LISTS LINESURF_LAYERS)
    string(REPLACE "=" ";" parts "${layer}")
    list(GET parts 0 prefix)
    list(GET parts 1 prefix_rank)
    string(LENGTH "${prefix}/" length)
    string(LENGTH "${best}/" best_length)
    string(SUBSTRING "${path}/" 0 ${length} head)
    if(head STREQUAL "${prefix}/" AND length GREATER best_length)
      set(best "${prefix}")
      set(rank "${prefix_rank}")
    endif()
  endforeach()
  set(${out_prefix} "${best}" PARENT_SCOPE)
  set(${out_rank} "${rank}" PARENT_SCOPE)
endfunction()

# The 1-based line of `path` holding `#include "header"` (read only when a violation is found).
function(linesurf_include_line path header out)
  file(READ "${path}" text)
  string(FIND "${text}" "${header}" at)
  string(SUBSTRING "${text}" 0 ${at} before)
  string(REGEX MATCHALL "\n" newlines "${before}")
  list(LENGTH newlines count)
  math(EXPR number "${count} + 1")
  set(${out} "${number}" PARENT_SCOPE)
endfunction()

# The headers `path` includes (commented-out includes are not include lines).
function(linesurf_includes path out)
  file(STRINGS "${path}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  set(headers "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"]")
      list(APPEND headers "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  set(${out} "${headers}" PARENT_SCOPE)
endfunction()

# Sets `out` to one "file:line: #include "x" (layer a includes layer b above it)" entry per
# upward include among the sources under `root`.
function(linesurf_upward_includes root out)
  file(GLOB_RECURSE sources RELATIVE "${root}"
    "${root}/engine/*.h" "${root}/engine/*.cpp" "${root}/partition/*.h" "${root}/partition/*.cpp"
    "${root}/solver/*.h" "${root}/solver/*.cpp" "${root}/tools/*.h" "${root}/tools/*.cpp"
    "${root}/tests/*.h" "${root}/tests/*.cpp")
  list(SORT sources)
  set(found "")
  foreach(source IN LISTS sources)
    linesurf_layer_of("${source}" layer rank)
    set(is_test FALSE)
    if(source MATCHES "_test\\.cpp$" OR source MATCHES "${LINESURF_TEST_ONLY_INCLUDE}")
      set(is_test TRUE)
    endif()
    linesurf_includes("${root}/${source}" headers)
    foreach(header IN LISTS headers)
      linesurf_layer_of("${header}" header_layer header_rank)
      if(header_layer STREQUAL "" OR header_layer STREQUAL layer)
        continue()
      endif()
      if(is_test AND header MATCHES "${LINESURF_TEST_ONLY_INCLUDE}")
        continue()
      endif()
      if(header_rank LESS rank)
        continue()
      endif()
      linesurf_include_line("${root}/${source}" "${header}" number)
      list(APPEND found
        "${source}:${number}: #include \"${header}\" (${layer} includes ${header_layer}, not below it)")
    endforeach()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# Sets `out` to one "file:line: #include "x" (reached from source)" entry per engine/,
# partition/ or solver/ include in `sources` and the tools/ headers they include, transitively.
function(linesurf_non_facade_includes root sources out)
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
      linesurf_includes("${root}/${file}" headers)
      foreach(header IN LISTS headers)
        if(header MATCHES "${LINESURF_FACADE_FORBIDDEN_INCLUDE}")
          linesurf_include_line("${root}/${file}" "${header}" number)
          list(APPEND found "${file}:${number}: #include \"${header}\" (reached from ${source})")
        elseif(header MATCHES "^tools/" AND EXISTS "${root}/${header}")
          list(APPEND queue "${header}")
        endif()
      endforeach()
    endwhile()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# Fails unless `found` holds exactly the entries given after it.
function(linesurf_expect what found)
  set(expected "${ARGN}")
  list(SORT found)
  list(SORT expected)
  if(NOT found STREQUAL expected)
    message(FATAL_ERROR "${what}: the check found:\n  ${found}\nexpected:\n  ${expected}")
  endif()
endfunction()

if(SELF_TEST_DIR)
  # A scratch tree: an io header that includes the pipeline (upward), a partition source that
  # includes the solver (a peer), a pipeline source that includes core and io (downward), a test
  # that includes a fixture and a production source that includes the same fixture.
  file(REMOVE_RECURSE "${SELF_TEST_DIR}")
  file(WRITE "${SELF_TEST_DIR}/engine/io/up.h"
    "#pragma once\n// #include \"engine/api/commented.h\"\n#include \"engine/core/scene.h\"\n"
    "\n  #  include <engine/pipeline/reconstruct.h>\n")
  file(WRITE "${SELF_TEST_DIR}/partition/voxel/peer.cpp"
    "#include \"partition/voxel/own.h\"\n#include \"solver/lp/lp_backend.h\"\n")
  file(WRITE "${SELF_TEST_DIR}/engine/pipeline/down.cpp"
    "#include \"linesurf/options.h\"\n#include \"engine/io/up.h\"\n#include <vector>\n")
  file(WRITE "${SELF_TEST_DIR}/engine/detect/detect_test.cpp"
    "#include \"engine/detect/own.h\"\n#include \"tests/support/fixture.h\"\n")
  file(WRITE "${SELF_TEST_DIR}/engine/detect/uses_fixture.cpp"
    "#include \"tools/gen/city.h\"\n")
  linesurf_upward_includes("${SELF_TEST_DIR}" found)
  linesurf_expect("layers" "${found}"
    "engine/detect/uses_fixture.cpp:1: #include \"tools/gen/city.h\" (engine/detect includes tools, not below it)"
    "engine/io/up.h:5: #include \"engine/pipeline/reconstruct.h\" (engine/io includes engine/pipeline, not below it)"
    "partition/voxel/peer.cpp:2: #include \"solver/lp/lp_backend.h\" (partition includes solver, not below it)")

  # A command that includes a clean helper, a helper that includes the engine and a facade
  # header: exactly the two engine lines, one of them reached through the helper.
  file(WRITE "${SELF_TEST_DIR}/tools/cli/cmd_x.cpp"
    "#include \"linesurf/linesurf.h\"\n#include \"tools/cli/bad.h\"\n#include <vector>\n"
    "  #  include <solver/lp/lp_backend.h>\n")
  file(WRITE "${SELF_TEST_DIR}/tools/cli/bad.h"
    "#pragma once\n// #include \"engine/core/commented.h\"\n#include \"engine/core/scene.h\"\n"
    "int a[2];\n#include \"tools/cli/good.h\"\n")
  file(WRITE "${SELF_TEST_DIR}/tools/cli/good.h" "#pragma once\n#include <string>\n")
  linesurf_non_facade_includes("${SELF_TEST_DIR}" "tools/cli/cmd_x.cpp" found)
  linesurf_expect("facade" "${found}"
    "tools/cli/cmd_x.cpp:4: #include \"solver/lp/lp_backend.h\" (reached from tools/cli/cmd_x.cpp)"
    "tools/cli/bad.h:3: #include \"engine/core/scene.h\" (reached from tools/cli/cmd_x.cpp)")
  linesurf_non_facade_includes("${SELF_TEST_DIR}" "tools/cli/good.h" clean)
  linesurf_expect("facade, clean file" "${clean}")
  message(STATUS "the checks find upward, peer and non-facade includes, and only those")
  return()
endif()

if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<repository> [-DFACADE_ONLY=<a.cpp,b.h,...>] -P ${CMAKE_CURRENT_LIST_FILE}")
endif()

if(FACADE_ONLY)
  string(REPLACE "," ";" patterns "${FACADE_ONLY}")
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
  linesurf_non_facade_includes("${ROOT}" "${sources}" found)
  if(found)
    list(JOIN found "\n  " listed)
    message(FATAL_ERROR "headers outside the facade (engine/, partition/, solver/):\n  ${listed}")
  endif()
  list(LENGTH sources count)
  message(STATUS "${count} files and the tools/ headers they include use the facade only")
  return()
endif()

linesurf_upward_includes("${ROOT}" found)
if(found)
  list(JOIN found "\n  " listed)
  message(FATAL_ERROR "includes against the layer order (docs/design/layers.md):\n  ${listed}")
endif()
message(STATUS "every source includes only its own layer and the layers below it")
