# install() and an exported CMake package (the four layer libraries, the runner piezocontact::runner, the
# headers, piezocontact_add_plugin()), so that another project can
#   find_package(piezocontact REQUIRED)
#   target_link_libraries(app PRIVATE piezocontact::piezocontact)   # or one layer, e.g. piezocontact::piezocontact_bricks
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS piezocontact piezocontact_assembly piezocontact_bricks piezocontact_models piezocontact_scene
                piezocontact_warnings EXPORT piezocontactTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(dir assembly bricks models)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/piezocontact/${dir}
    FILES_MATCHING PATTERN "*.hpp" PATTERN "gmsh_module" EXCLUDE)  # gmsh_module/: a module, no headers
endforeach()
include(ForwardingHeaders)
install(EXPORT piezocontactTargets NAMESPACE piezocontact::
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/piezocontact)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/piezocontactConfig.cmake.in
  ${PROJECT_BINARY_DIR}/piezocontactConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/piezocontact)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/piezocontactConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/piezocontactConfig.cmake
  ${PROJECT_BINARY_DIR}/piezocontactConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/PiezocontactDependencies.cmake
  ${PROJECT_SOURCE_DIR}/cmake/PiezocontactPlugin.cmake
  ${PROJECT_SOURCE_DIR}/cmake/piezocontact_plugin_entry.cpp
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/piezocontact)
