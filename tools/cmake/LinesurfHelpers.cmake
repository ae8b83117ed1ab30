# linesurf_enable_sanitizers(<list>)
#   Instruments everything built after this call (our code and the tests; Debian's prebuilt
#   libraries stay uninstrumented) with the given sanitizers, e.g. "address,undefined". UBSan
#   findings abort the test (-fno-sanitize-recover) so that CTest sees them; -O1 keeps the suite
#   fast enough for CI, for the tests too (the linker keeps one copy of an inline function, so
#   -O0 tests would hand the modules unoptimised Eigen); -g1 (line tables) is all a report's
#   stack needs, at a quarter less compile time than -g (docs/design/sanitizers_and_fuzzing.md).
function(linesurf_enable_sanitizers sanitizers)
  if(sanitizers STREQUAL "")
    return()
  endif()
  set(flags -fsanitize=${sanitizers} -fno-omit-frame-pointer -g1 -O1)
  if(sanitizers MATCHES "undefined")
    list(APPEND flags -fno-sanitize-recover=undefined)
  endif()
  # Third-party header code that reports on every run (each entry says why it is harmless);
  # clang only (g++ has no ignore list).
  set(ignorelist ${PROJECT_SOURCE_DIR}/tools/cmake/sanitizer_ignorelist.txt)
  set(clang "$<OR:$<COMPILE_LANG_AND_ID:CXX,Clang>,$<COMPILE_LANG_AND_ID:C,Clang>>")
  list(APPEND flags "$<${clang}:-fsanitize-ignorelist=${ignorelist}>")
  add_compile_options(${flags})
  add_link_options(-fsanitize=${sanitizers})
endfunction()

# linesurf_add_module(NAME <target> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
#   One static, position-independent library per module with the project's warnings.
function(linesurf_add_module)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${ARG_NAME} STATIC ${ARG_SOURCES})
  target_include_directories(${ARG_NAME} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/engine/include>)
  target_link_libraries(${ARG_NAME} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  linesurf_set_warnings(${ARG_NAME})
endfunction()

# Our own targets only: third-party headers come in as SYSTEM through imported targets.
function(linesurf_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
endfunction()

# linesurf_add_test(MODULE <name> SOURCES ... DEPS ... [LABELS ...] [SLOW <gtest filter>])
#   One GoogleTest executable per module; tests are named <module>/Suite.Case and labelled
#   LABELS (default `unit`: seconds for the whole label, `ctest -L unit`). The tests SLOW matches
#   (a gtest filter, `Suite.Case:Suite.*`) are labelled `slow` instead.
#   LINESURF_SHARED_DIR points at ../shared (real data); tests skip when it is absent.
#   LINESURF_SOURCE_DIR points at the repository (bundled examples: docs/examples/house). Test
#   executables sit in bin/ beside linesurf, which is how CLI tests find it (BinDir()).
function(linesurf_add_test)
  cmake_parse_arguments(ARG "" "MODULE;SLOW" "SOURCES;DEPS;LABELS" ${ARGN})
  if(NOT LINESURF_BUILD_TESTS)
    return()
  endif()
  set(target linesurf_test_${ARG_MODULE})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS} linesurf_testing GTest::gtest GTest::gmock)
  linesurf_set_warnings(${target})
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  set(filter "*")
  if(ARG_SLOW)
    set(filter "-${ARG_SLOW}")
  endif()
  set(common
    TEST_PREFIX "${ARG_MODULE}/"
    DISCOVERY_TIMEOUT 60)
  set(environment
    ENVIRONMENT "LINESURF_SHARED_DIR=${PROJECT_SOURCE_DIR}/../shared"
    ENVIRONMENT_MODIFICATION "LINESURF_SOURCE_DIR=set:${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(${target} ${common} TEST_FILTER "${filter}"
    PROPERTIES LABELS "${ARG_LABELS}" ${environment})
  if(ARG_SLOW)
    gtest_discover_tests(${target} ${common} TEST_FILTER "${ARG_SLOW}"
      PROPERTIES LABELS slow ${environment})
  endif()
endfunction()

# linesurf_add_benchmark(MODULE <name> SOURCES ... DEPS ...)
function(linesurf_add_benchmark)
  cmake_parse_arguments(ARG "" "MODULE" "SOURCES;DEPS" ${ARGN})
  if(NOT LINESURF_BUILD_BENCHMARKS)
    return()
  endif()
  set(target linesurf_bench_${ARG_MODULE})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS} benchmark::benchmark)
  linesurf_set_warnings(${target})
endfunction()
