# `cmake --install build --prefix P` installs graspsim as a CMake package:
#   P/include/graspsim/...                 public headers
#   P/lib/libgraspsim_*.a                  one static library per layer
#   P/bin/graspsim                         the command-line tool
#   P/share/graspsim/{models,anthropometry} model files, scenarios and the anthropometric tables
#   P/lib/cmake/graspsim/                  graspsimConfig.cmake, its version file, exported targets
# so that find_package(graspsim) and target_link_libraries(app graspsim::graspsim) work.
# The exported targets carry what using graspsim requires (include paths, the dependencies'
# libraries, Simbody's ABI setting below) and none of the project's own choices: no warning
# flags, no sanitizers, no build type.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GRASPSIM_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/graspsim)
set(graspsim_layers graspsim_io graspsim_anthropometry graspsim_model graspsim_system graspsim_integration
    graspsim_contact graspsim_control graspsim_grasp graspsim_scenario graspsim_planning graspsim_simulation graspsim_results
    graspsim_viewer graspsim_capacity graspsim_opensim graspsim_validation graspsim_study)

# graspsim::graspsim is the one library target (every layer); the layers keep their names.
set_target_properties(graspsim_api PROPERTIES EXPORT_NAME graspsim)
foreach(layer IN LISTS graspsim_layers ITEMS graspsim_core graspsim_simbody graspsim_urdfdom)
  string(REPLACE "graspsim_" "" short ${layer})
  set_target_properties(${layer} PROPERTIES EXPORT_NAME ${short})
endforeach()

install(TARGETS graspsim_api graspsim_core graspsim_simbody graspsim_urdfdom ${graspsim_layers}
  EXPORT graspsimTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS graspsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/graspsim DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/ DESTINATION ${CMAKE_INSTALL_DATADIR}/graspsim/models)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/anthropometry/ DESTINATION ${CMAKE_INSTALL_DATADIR}/graspsim/anthropometry)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CITATION.cff DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/graspsim)

install(EXPORT graspsimTargets NAMESPACE graspsim:: DESTINATION ${GRASPSIM_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/graspsimConfig.cmake.in
  ${PROJECT_BINARY_DIR}/graspsimConfig.cmake INSTALL_DESTINATION ${GRASPSIM_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/graspsimConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/graspsimConfig.cmake ${PROJECT_BINARY_DIR}/graspsimConfigVersion.cmake
  DESTINATION ${GRASPSIM_INSTALL_CMAKEDIR})
