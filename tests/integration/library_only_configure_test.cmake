# A library-only configure (no tests, benchmarks or CLI) must not look for GoogleTest, Google
# Benchmark, CLI11 or libpng: each is disabled, so any find_package of them fails the configure.
# Run by CTest with -DSOURCE_DIR= -DWORK=.
file(REMOVE_RECURSE ${WORK})
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK} -DCMAKE_BUILD_TYPE=Release
    -DLINESURF_BUILD_TESTS=OFF -DLINESURF_BUILD_BENCHMARKS=OFF -DLINESURF_BUILD_CLI=OFF
    -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON -DCMAKE_DISABLE_FIND_PACKAGE_PNG=ON
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(REMOVE_RECURSE ${WORK})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "library-only configure failed:\n${out}\n${err}")
endif()
