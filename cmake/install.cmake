# `cmake --install` and the CMake package: headers, the static libraries, the configured version
# header and shadowvolConfig.cmake, so that an outside project can
#   find_package(shadowvol CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE shadowvol::core shadowvol::embree)
# Targets: shadowvol::core, ::embree, ::cgal, ::validate, ::gl (when built with GL). The shaders are
# compiled into shadowvol::gl, so nothing else is needed at run time.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(sv_exported shadowvol_core shadowvol_embree shadowvol_cgal shadowvol_validate)
if(SHADOWVOL_BUILD_GL)
  list(APPEND sv_exported shadowvol_gl)
endif()
foreach(t ${sv_exported})
  string(REPLACE "shadowvol_" "" short ${t})
  # INSTALL_RPATH: with BUILD_SHARED_LIBS each library finds its siblings beside itself.
  set_target_properties(${t} PROPERTIES EXPORT_NAME ${short} POSITION_INDEPENDENT_CODE ON INSTALL_RPATH "$ORIGIN")
  add_library(shadowvol::${short} ALIAS ${t})
endforeach()
# Linked privately by every target; exported because static libraries carry their link interface.
set_target_properties(shadowvol_warnings PROPERTIES EXPORT_NAME warnings)

install(TARGETS ${sv_exported} shadowvol_warnings EXPORT shadowvolTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/include/shadowvol DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/generated/shadowvol/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadowvol)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/shadowvol)
if(SHADOWVOL_BUILD_APPS)
  # With BUILD_SHARED_LIBS the installed command finds the installed libraries relative to itself.
  file(RELATIVE_PATH sv_bin_to_lib /p/${CMAKE_INSTALL_BINDIR} /p/${CMAKE_INSTALL_LIBDIR})
  set_target_properties(shadowvol PROPERTIES INSTALL_RPATH "$ORIGIN/${sv_bin_to_lib}")
  install(TARGETS shadowvol RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(sv_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/shadowvol)
install(EXPORT shadowvolTargets NAMESPACE shadowvol:: DESTINATION ${sv_cmake_dir})
set(SHADOWVOL_PACKAGE_WITH_GL ${SHADOWVOL_BUILD_GL})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/shadowvolConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/shadowvolConfig.cmake INSTALL_DESTINATION ${sv_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/shadowvolConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/shadowvolConfig.cmake ${PROJECT_BINARY_DIR}/shadowvolConfigVersion.cmake
        DESTINATION ${sv_cmake_dir})
