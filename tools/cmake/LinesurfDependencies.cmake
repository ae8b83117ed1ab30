# Finds every third-party dependency (Debian 12 packages; see tools/install_deps.sh).
# Order matters: oneTBB in CONFIG mode before OpenVDB, whose Find module would otherwise
# define an incomplete TBB::tbb (see shared/reference/deps.md, pitfall 2).
find_package(TBB 2021 CONFIG REQUIRED COMPONENTS tbb tbbmalloc)
find_package(Eigen3 3.4 CONFIG REQUIRED)
find_package(Threads REQUIRED)

find_path(LINESURF_OPENVDB_MODULE_DIR FindOpenVDB.cmake
  PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB /usr/local/lib/cmake/OpenVDB
  NO_DEFAULT_PATH REQUIRED)
list(APPEND CMAKE_MODULE_PATH ${LINESURF_OPENVDB_MODULE_DIR})
find_package(OpenVDB REQUIRED COMPONENTS openvdb)

find_package(CGAL 5.5 CONFIG REQUIRED)

# CHOLMOD: only the solver benchmark's analysis of what a barrier would factor
# (BM_CholmodAnalyze, docs/design/lp_backend.md); no library source calls it.
# SuiteSparse 5.12 ships neither a CMake config nor pkg-config files.
if(LINESURF_BUILD_BENCHMARKS)
  find_path(LINESURF_SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
  set(_linesurf_ss_libs)
  foreach(_ss cholmod amd colamd camd ccolamd suitesparseconfig)
    find_library(LINESURF_SUITESPARSE_${_ss}_LIBRARY NAMES ${_ss} REQUIRED)
    list(APPEND _linesurf_ss_libs ${LINESURF_SUITESPARSE_${_ss}_LIBRARY})
  endforeach()
  if(NOT TARGET SuiteSparse::cholmod)
    add_library(SuiteSparse::cholmod INTERFACE IMPORTED)
    target_include_directories(SuiteSparse::cholmod SYSTEM INTERFACE
      ${LINESURF_SUITESPARSE_INCLUDE_DIR})
    target_link_libraries(SuiteSparse::cholmod INTERFACE ${_linesurf_ss_libs})
  endif()
endif()

find_package(PkgConfig REQUIRED)
pkg_check_modules(CLP REQUIRED IMPORTED_TARGET clp)
# COIN-OR Cbc (branch and cut): optional, for the `cbc` backend only (solver/CMakeLists.txt).
pkg_check_modules(CBC IMPORTED_TARGET cbc)

# libmaxflow (Boykov-Kolmogorov max-flow, GPL-3+): pkg-config module "maxflow".
pkg_check_modules(MAXFLOW REQUIRED IMPORTED_TARGET maxflow)

find_package(nlohmann_json 3.11 CONFIG REQUIRED)

# Only the tools, tests and benchmarks need these: a library-only build
# (-DLINESURF_BUILD_TESTS=OFF -DLINESURF_BUILD_BENCHMARKS=OFF -DLINESURF_BUILD_CLI=OFF) does not.
if(LINESURF_BUILD_TOOLS)
  find_package(PNG REQUIRED)
endif()
if(LINESURF_BUILD_CLI)
  find_package(CLI11 2.1 CONFIG REQUIRED)
endif()
if(LINESURF_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)
endif()
if(LINESURF_BUILD_BENCHMARKS)
  find_package(benchmark CONFIG REQUIRED)
endif()
