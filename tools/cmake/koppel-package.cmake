# The CMake package of an installed koppel: the export set of every library (koppel_add_library),
# koppel::koppel for all of it, a config file and a version file, so that another project writes
#   find_package(koppel 0.1 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE koppel::koppel)   # or koppel::analysis, ...
# Only Eigen is a public dependency (core's headers use it). The private ones (Ceres, glog,
# yaml-cpp, fmt, nlohmann_json) live inside koppel's shared libraries; a static build has to hand
# them on to the consumer's link, so its config finds them too. Ceres and muparser are in the
# modules libkoppel_ceres.so and libkoppel_muparser.so (installed in LIBDIR/koppel), never linked.
include(CMakePackageConfigHelpers)

# koppel::koppel: the library API (koppel/koppel.hpp) and, through it, every part.
add_library(koppel_all INTERFACE)
add_library(koppel::koppel ALIAS koppel_all)
set_target_properties(koppel_all PROPERTIES EXPORT_NAME koppel)
target_link_libraries(koppel_all INTERFACE koppel::api)
install(TARGETS koppel_all EXPORT koppelTargets)

set(KOPPEL_PRIVATE_DEPENDENCIES "")
if(NOT BUILD_SHARED_LIBS)
  foreach(dependency yaml-cpp fmt nlohmann_json nanoflann)
    string(APPEND KOPPEL_PRIVATE_DEPENDENCIES "find_dependency(${dependency})\n")
  endforeach()
endif()

set(KOPPEL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/koppel)
install(EXPORT koppelTargets NAMESPACE koppel:: DESTINATION ${KOPPEL_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/koppelConfig.cmake.in ${CMAKE_BINARY_DIR}/koppelConfig.cmake
  INSTALL_DESTINATION ${KOPPEL_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/koppelConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/koppelConfig.cmake ${CMAKE_BINARY_DIR}/koppelConfigVersion.cmake
  DESTINATION ${KOPPEL_CMAKE_DIR})
