# `cmake --install`: the plantsim program and, for plugins, the robot side's interfaces and their
# value types as a header-only CMake package (find_package(plantsim CONFIG), target
# plantsim::plugin_api). Only these headers are installed: a plugin sees readings, the map and
# the estimate, never the simulator. PLANTSIM_PLUGIN_ABI_VERSION (plugins/plugin_api.h) changes
# whenever one of them changes layout.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PLANTSIM_PLUGIN_HEADERS
  plugins/plugin_api.h
  controller/local_controller.h controller/diff_drive.h controller/moving_box.h
  robot/estimator_registry.h robot/pose_estimator.h robot/readings.h robot/dock_detector.h
  planner/registry.h planner/planner.h planner/planner_options.h planner/search_budget.h
  worlds/world.h worlds/tunnel_maze.h util/c_number.h
  util/component_info.h util/component_registry.h util/param_spec.h
  geometry/vec2.h)
set(PLANTSIM_INCLUDE_DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/plantsim)
foreach(header ${PLANTSIM_PLUGIN_HEADERS})
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${header} DESTINATION ${PLANTSIM_INCLUDE_DESTINATION}/${folder})
endforeach()

add_library(plantsim_plugin_api INTERFACE)
target_include_directories(plantsim_plugin_api INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}> $<INSTALL_INTERFACE:${PLANTSIM_INCLUDE_DESTINATION}>)
target_link_libraries(plantsim_plugin_api INTERFACE Eigen3::Eigen)
target_compile_features(plantsim_plugin_api INTERFACE cxx_std_20)
set_target_properties(plantsim_plugin_api PROPERTIES EXPORT_NAME plugin_api)

install(TARGETS plantsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS plantsim_plugin_api EXPORT plantsimTargets)
set(PLANTSIM_CMAKE_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/plantsim)
install(EXPORT plantsimTargets NAMESPACE plantsim:: DESTINATION ${PLANTSIM_CMAKE_DESTINATION})
file(STRINGS plugins/plugin_api.h abi_line REGEX "^#define PLANTSIM_PLUGIN_ABI_VERSION ")
string(REGEX REPLACE ".* ([0-9]+)$" "\\1" PLANTSIM_PLUGIN_ABI_VERSION "${abi_line}")
configure_package_config_file(cmake/plantsimConfig.cmake.in
  ${PROJECT_BINARY_DIR}/plantsimConfig.cmake INSTALL_DESTINATION ${PLANTSIM_CMAKE_DESTINATION})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/plantsimConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY ExactVersion)
install(FILES ${PROJECT_BINARY_DIR}/plantsimConfig.cmake
  ${PROJECT_BINARY_DIR}/plantsimConfigVersion.cmake DESTINATION ${PLANTSIM_CMAKE_DESTINATION})
