# `cmake --install`: headers, the two libraries, the tactus program and its helpers, presets and
# actuator profiles, a CMake package (find_package(tactus): tactus::dsp, tactus::files) and
# pkg-config files (tactus-dsp.pc, tactus.pc).
include(CMakePackageConfigHelpers)

install(TARGETS tactus_dsp tactus_files EXPORT tactusTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS tactus_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The live and studio commands' helper programs, where `tactus` looks for them
# (apps/tactus/helper_programs.hpp).
foreach(helper tactus_live_program tactus_studio_program)
  if(TARGET ${helper})
    install(TARGETS ${helper} RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/tactus)
  endif()
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/tactus DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/presets ${PROJECT_SOURCE_DIR}/actuators
                  ${PROJECT_SOURCE_DIR}/layouts DESTINATION ${CMAKE_INSTALL_DATADIR}/tactus)

set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/tactus)
install(EXPORT tactusTargets NAMESPACE tactus:: DESTINATION ${package_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/tactusConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/tactusConfig.cmake
                              INSTALL_DESTINATION ${package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tactusConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tactusConfig.cmake
              ${PROJECT_BINARY_DIR}/tactusConfigVersion.cmake DESTINATION ${package_dir})

# The .pc files find the prefix from their own folder: the tree can be installed anywhere.
file(RELATIVE_PATH pc_to_prefix /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
foreach(pc tactus-dsp tactus)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()
