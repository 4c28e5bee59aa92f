# Finds every third-party dependency. Each one that is missing stops configuration with a message
# naming the Debian 12 package to install (scripts/setup installs them all).

macro(medusa_require found package what)
  if(NOT ${found})
    message(FATAL_ERROR "medusa needs ${what}: install the Debian package '${package}' "
                        "(or run: sudo bash scripts/setup)")
  endif()
endmacro()

find_package(CGAL QUIET)
medusa_require(CGAL_FOUND libcgal-dev "CGAL 5.5")
# CGAL as medusa uses it. CGAL_NO_CORE: with GMP present, CGAL 5.5 enables its header-only CORE
# library, and <CGAL/Polynomial.h> (through the default Arithmetic_kernel) then compiles CORE's
# non-template inline functions and vtables into every translation unit, about half of each one's
# compile time. medusa never uses CORE: its exact types are GMP's (Gmpz, mpq_class, Mpzf), whose
# selection does not depend on CORE (CGAL/Number_types/internal/Exact_type_selector.h). One
# definition for every target, since it changes CGAL::Arithmetic_kernel.
add_library(medusa_cgal INTERFACE)
target_link_libraries(medusa_cgal INTERFACE CGAL::CGAL)
target_compile_definitions(medusa_cgal INTERFACE CGAL_NO_CORE=1)

find_path(GMPXX_INCLUDE_DIR gmpxx.h)
find_library(GMPXX_LIBRARY gmpxx)
find_library(GMP_LIBRARY gmp)
medusa_require(GMPXX_LIBRARY libgmp-dev "GMP with C++ bindings (gmpxx)")
find_library(MPFR_LIBRARY mpfr)
medusa_require(MPFR_LIBRARY libmpfr-dev "MPFR")

# CGAL 5.5 has no CGAL::MPFI_support target; its FindMPFI.cmake is on the module path (TOOLCHAIN.md).
find_package(MPFI QUIET)
medusa_require(MPFI_FOUND libmpfi-dev "MPFI (for CGAL's Algebraic_kernel_d_1)")
add_library(medusa_mpfi INTERFACE)
target_include_directories(medusa_mpfi SYSTEM INTERFACE ${MPFI_INCLUDE_DIR})
target_link_libraries(medusa_mpfi INTERFACE ${MPFI_LIBRARIES} ${MPFR_LIBRARY} ${GMP_LIBRARY})
target_compile_definitions(medusa_mpfi INTERFACE CGAL_USE_MPFI)

add_library(medusa_gmp INTERFACE)
target_include_directories(medusa_gmp SYSTEM INTERFACE ${GMPXX_INCLUDE_DIR})
target_link_libraries(medusa_gmp INTERFACE ${GMPXX_LIBRARY} ${GMP_LIBRARY})

find_path(PHAT_INCLUDE_DIR phat/compute_persistence_pairs.h)
medusa_require(PHAT_INCLUDE_DIR libphat-dev "PHAT")
add_library(medusa_phat INTERFACE)
target_include_directories(medusa_phat SYSTEM INTERFACE ${PHAT_INCLUDE_DIR})

find_package(Boost 1.74 QUIET COMPONENTS graph)
medusa_require(Boost_FOUND libboost-graph-dev "Boost.Graph")

find_package(HDF5 QUIET COMPONENTS C)
medusa_require(HDF5_FOUND libhdf5-dev "HDF5 (C library)")
add_library(medusa_hdf5 INTERFACE)
target_include_directories(medusa_hdf5 SYSTEM INTERFACE ${HDF5_INCLUDE_DIRS})
target_link_libraries(medusa_hdf5 INTERFACE ${HDF5_C_LIBRARIES})
target_compile_definitions(medusa_hdf5 INTERFACE ${HDF5_DEFINITIONS})

find_package(ZLIB QUIET)
medusa_require(ZLIB_FOUND zlib1g-dev "zlib")

find_package(CLI11 QUIET)
medusa_require(CLI11_FOUND libcli11-dev "CLI11")

find_package(nlohmann_json 3 QUIET)
medusa_require(nlohmann_json_FOUND nlohmann-json3-dev "nlohmann-json")

find_package(Threads REQUIRED)

if(MEDUSA_BUILD_TESTS)
  find_package(Catch2 2 QUIET)
  medusa_require(Catch2_FOUND catch2 "Catch2 version 2")
endif()

# Python with Debian's modules (GUDHI, h5py) for the oracle tests: always /usr/bin/python3.
set(MEDUSA_PYTHON /usr/bin/python3 CACHE FILEPATH "Python interpreter with python3-gudhi and python3-h5py")
