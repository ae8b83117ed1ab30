# The installed package for C++ and C hosts: installs linesurf into a fresh prefix, builds the
# out-of-tree hosts docs/examples/host_cpp and host_c against it with find_package(linesurf 3),
# runs them on the bundled house and checks their meshes are byte for byte the CLI's.
# Run by CTest (tests/integration/CMakeLists.txt) with -DBUILD_DIR= -DSOURCE_DIR= -DCLI= -DWORK=
# -DCXX= -DCC= -DCC_ID= (CMAKE_C_COMPILER_ID) -DPKG_CONFIG= (may be empty) -DSANITIZE=
# (LINESURF_SANITIZE, may be empty: a sanitized library needs hosts linked with the same
# sanitizer runtime).

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
endfunction()

set(prefix ${WORK}/prefix)
set(host_flags "")
set(c_host_link_flags "")
if(DEFINED SANITIZE AND NOT SANITIZE STREQUAL "")
  set(host_flags "-fsanitize=${SANITIZE}")
  if(CC_ID STREQUAL "Clang")
    # clang links a C program with the C part of the UBSan runtime only; the library's C++ code
    # needs the rest (__ubsan_vptr_type_cache, the dynamic-type handlers) and its libstdc++.
    set(c_host_link_flags "-fsanitize-link-c++-runtime -lstdc++")
  endif()
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f include/linesurf/linesurf.h include/linesurf/linesurf_c.h include/linesurf/version.h
    lib/cmake/linesurf/linesurfConfig.cmake lib/cmake/linesurf/linesurfConfigVersion.cmake
    lib/pkgconfig/linesurf.pc)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${prefix}/${f}")
  endif()
endforeach()
# Only public headers are installed: no engine/, partition/ or solver/ include, no Eigen/CGAL/TBB.
file(GLOB installed_headers ${prefix}/include/linesurf/*.h)
foreach(h ${installed_headers})
  file(STRINGS ${h} includes REGEX "#include")
  foreach(line ${includes})
    if(NOT line MATCHES "#include <[a-z_]+(\\.h)?>" AND NOT line MATCHES "#include \"linesurf/")
      message(FATAL_ERROR "${h} includes a non-public header: ${line}")
    endif()
  endforeach()
endforeach()

set(house ${SOURCE_DIR}/docs/examples/house/lines.json)
run(${CLI} --quiet reconstruct ${house} --scene exterior -o ${WORK}/cli.ply)

foreach(host host_cpp host_c)
  set(link_flags "")
  if(host STREQUAL "host_c" AND NOT c_host_link_flags STREQUAL "")
    set(link_flags "-DCMAKE_EXE_LINKER_FLAGS=${c_host_link_flags}")
  endif()
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/docs/examples/${host} -B ${WORK}/${host}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_C_COMPILER=${CC}
    -DCMAKE_CXX_FLAGS=${host_flags} -DCMAKE_C_FLAGS=${host_flags} ${link_flags})
  run(${CMAKE_COMMAND} --build ${WORK}/${host})
  run(${WORK}/${host}/${host} ${house} ${WORK}/${host}.ply)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/cli.ply ${WORK}/${host}.ply
    RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "${host}.ply differs from the CLI's mesh (${WORK})")
  endif()
  message(STATUS "${host}: same mesh bytes as linesurf reconstruct")
endforeach()

if(PKG_CONFIG)
  set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
  run(${PKG_CONFIG} --exists --print-errors "linesurf >= 2")
  execute_process(COMMAND ${PKG_CONFIG} --libs --cflags linesurf OUTPUT_VARIABLE flags
    OUTPUT_STRIP_TRAILING_WHITESPACE)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  separate_arguments(c_link_flags UNIX_COMMAND "${c_host_link_flags}")
  run(${CC} ${host_flags} ${SOURCE_DIR}/docs/examples/host_c/main.c ${flags} ${c_link_flags}
    -o ${WORK}/host_c_pkgconfig)
  message(STATUS "host_c also builds with pkg-config: ${flags}")
endif()
