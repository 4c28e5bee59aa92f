# `cmake --install build --prefix DIR`: the `medusa` binary, the static libraries with their public
# headers and a CMake package (find_package(medusa): medusa::core, medusa::kinetic, medusa::medusa,
# medusa::persistence, medusa::io), the Python module, the documentation and the examples with the
# bundled run.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(MEDUSA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/medusa)
set(MEDUSA_INSTALL_DOCDIR ${CMAKE_INSTALL_DATADIR}/doc/medusa)
set(MEDUSA_INSTALL_EXAMPLESDIR ${CMAKE_INSTALL_DATADIR}/medusa/examples)

# Short names in the package: medusa::core ... medusa::io. The INTERFACE targets that carry the
# third-party flags (CGAL_NO_CORE, MPFI, GMP, HDF5 and PHAT paths) go with them: the libraries'
# interfaces name them.
foreach(lib core kinetic medusa persistence io)
  set_target_properties(medusa_${lib} PROPERTIES EXPORT_NAME ${lib})
endforeach()
install(TARGETS medusa_core medusa_kinetic medusa_medusa medusa_persistence medusa_io
                medusa_cgal medusa_gmp medusa_mpfi medusa_hdf5 medusa_phat
        EXPORT medusaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS medusa RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The Python module goes where Debian's /usr/bin/python3 looks for a prefix's modules:
# <prefix>/lib/python3.X/dist-packages is on its default sys.path for the prefixes /usr/local and /usr;
# for any other prefix, PYTHONPATH=<prefix>/lib/python3.X/dist-packages (README, "Install").
if(TARGET medusa_python)
  set(Python3_EXECUTABLE /usr/bin/python3)
  find_package(Python3 COMPONENTS Interpreter REQUIRED)
  set(MEDUSA_INSTALL_PYTHONDIR lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages
      CACHE STRING "where `cmake --install` puts the Python module medusa, relative to the prefix")
  install(TARGETS medusa_python LIBRARY DESTINATION ${MEDUSA_INSTALL_PYTHONDIR})
endif()

foreach(dir libcore/include libkinetic/include libmedusa/include libpersistence/include pipeline/io/include)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(DIRECTORY ${PROJECT_BINARY_DIR}/libcore/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

install(EXPORT medusaTargets NAMESPACE medusa:: DESTINATION ${MEDUSA_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/medusaConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/medusaConfig.cmake
                              INSTALL_DESTINATION ${MEDUSA_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the interfaces.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/medusaConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/medusaConfig.cmake ${PROJECT_BINARY_DIR}/medusaConfigVersion.cmake
        DESTINATION ${MEDUSA_INSTALL_CMAKEDIR})

install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${MEDUSA_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${MEDUSA_INSTALL_DOCDIR}/docs FILES_MATCHING PATTERN "*.md")
foreach(name LICENSE LICENSE.md LICENSE.txt COPYING CHANGELOG.md CHANGELOG)
  if(EXISTS ${PROJECT_SOURCE_DIR}/${name})
    install(FILES ${PROJECT_SOURCE_DIR}/${name} DESTINATION ${MEDUSA_INSTALL_DOCDIR})
  endif()
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${MEDUSA_INSTALL_EXAMPLESDIR} USE_SOURCE_PERMISSIONS)
