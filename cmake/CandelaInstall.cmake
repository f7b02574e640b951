# What `cmake --install` lays out under the prefix, and `cpack -G DEB` packages:
#   bin/candela                          the command (its web page is inside it)
#   <libdir>/libcandela.so*              the public C++ interface, and include/candela/ its headers
#   <libdir>/cmake/candela/              the CMake package: find_package(candela), target candela::candela
#   lib/python3/dist-packages/candela*.so the Python module, where Debian's python3 looks for modules
#   share/doc/candela/                   README.md and docs/
include(CMakePackageConfigHelpers)

set(CANDELA_INSTALL_PYTHONDIR "lib/python3/dist-packages" CACHE STRING
    "Where the Python module goes, under the prefix (Debian's layout for python3)")
set(CANDELA_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/candela")

install(TARGETS candela RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS candela_shared EXPORT candelaTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/candela DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT candelaTargets NAMESPACE candela:: DESTINATION ${CANDELA_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/candelaConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/candelaConfig.cmake INSTALL_DESTINATION ${CANDELA_INSTALL_CMAKEDIR})
# The interface may change between minor versions until 1.0.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/candelaConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/candelaConfig.cmake ${PROJECT_BINARY_DIR}/candelaConfigVersion.cmake
        DESTINATION ${CANDELA_INSTALL_CMAKEDIR})

if(TARGET candela_python)
  # The module finds libcandela relative to itself, wherever the prefix is.
  file(RELATIVE_PATH module_to_lib /prefix/${CANDELA_INSTALL_PYTHONDIR} /prefix/${CMAKE_INSTALL_LIBDIR})
  set_target_properties(candela_python PROPERTIES INSTALL_RPATH "$ORIGIN/${module_to_lib}")
  install(TARGETS candela_python LIBRARY DESTINATION ${CANDELA_INSTALL_PYTHONDIR})
endif()

install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})

# cpack -G DEB: one package of all the above under /usr. Its dependencies are the Debian packages of the shared
# libraries it links, as dpkg-shlibdeps finds them (dpkg-dev, file), and NumPy for the module.
set(CPACK_PACKAGE_NAME candela)
set(CPACK_PACKAGE_VENDOR "candela")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "physically based path tracer: command, C++ library and Python module")
set(CANDELA_PACKAGE_MAINTAINER "candela maintainers" CACHE STRING "The Maintainer field of the Debian package")
set(CPACK_PACKAGE_CONTACT "${CANDELA_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${PROJECT_BINARY_DIR}/src/api)
if(TARGET candela_python)  # the module is built for one Python version
  set(python "python3 (>= ${CANDELA_PYTHON_VERSION}), python3 (<< ${CANDELA_PYTHON_VERSION_MAJOR}.${CANDELA_PYTHON_NEXT_MINOR})")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${python}, python3-numpy")
endif()
include(CPack)
