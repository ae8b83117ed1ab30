# The installed Python module: installs linesurf into a fresh prefix, runs
# docs/examples/host_python/reconstruct_house.py with the installed module only (PYTHONPATH =
# the prefix's site-packages, run outside the build tree) and checks that its mesh of the
# bundled house is byte for byte the CLI's.
# Run by CTest (tools/python/tests/CMakeLists.txt) with -DBUILD_DIR= -DSOURCE_DIR= -DCLI=
# -DWORK= -DPYTHON= -DSITE_DIR= (relative to the prefix) -DPRELOAD= (a sanitized build: the
# sanitizer runtime python needs, preloaded into python only; may be empty).

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
    WORKING_DIRECTORY ${WORK})
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK}/prefix)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
set(site ${prefix}/${SITE_DIR})
file(GLOB extension ${site}/linesurf/_linesurf*.so)
if(NOT EXISTS ${site}/linesurf/__init__.py OR NOT extension)
  message(FATAL_ERROR "the Python module is not installed in ${site}/linesurf")
endif()

set(house ${SOURCE_DIR}/docs/examples/house/lines.json)
run(${CLI} reconstruct ${house} --scene exterior -o ${WORK}/cli.ply)

set(ENV{PYTHONPATH} ${site})
set(python ${PYTHON})
if(DEFINED PRELOAD AND NOT PRELOAD STREQUAL "")
  set(python ${CMAKE_COMMAND} -E env LD_PRELOAD=${PRELOAD}
    ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:strict_string_checks=1 ${PYTHON})
endif()
run(${python} -c "print(__import__('linesurf._linesurf', fromlist=['_']).__file__)")
string(STRIP "${run_output}" loaded)
if(NOT loaded STREQUAL extension)
  message(FATAL_ERROR "python loaded ${loaded}, not the installed ${extension}")
endif()
run(${python} ${SOURCE_DIR}/docs/examples/host_python/reconstruct_house.py ${house}
  ${WORK}/python.ply)
message(STATUS "${run_output}")
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/cli.ply ${WORK}/python.ply
  RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "python.ply differs from the CLI's mesh (${WORK})")
endif()
message(STATUS "host_python: same mesh bytes as linesurf reconstruct")
