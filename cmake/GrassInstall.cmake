# `cmake --install`: the public headers, libgrass.so (soname: the header's major version), a
# CMake package (find_package(grass) -> grass::grass) and a pkg-config file (grass.pc).
# The library links no GL or Vulkan library (the host hands over its loaders), so neither
# the package nor grass.pc names one.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS grass EXPORT grassTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/api/include/grass" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  COMPONENT development FILES_MATCHING PATTERN "*.h")

set(GRASS_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/grass)
install(EXPORT grassTargets NAMESPACE grass:: DESTINATION ${GRASS_CMAKE_DIR} COMPONENT development)
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/grassConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/grassConfig.cmake" INSTALL_DESTINATION ${GRASS_CMAKE_DIR})
# A newer minor runs binaries built against an older one of the same major (grass.h, "ABI").
write_basic_package_version_file("${PROJECT_BINARY_DIR}/grassConfigVersion.cmake"
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES "${PROJECT_BINARY_DIR}/grassConfig.cmake" "${PROJECT_BINARY_DIR}/grassConfigVersion.cmake"
  DESTINATION ${GRASS_CMAKE_DIR} COMPONENT development)

# pkg-config: paths relative to the .pc file's prefix, so the tree can be moved.
set(GRASS_PC_HAS_GL ${GRASS_BUILD_GL})
set(GRASS_PC_HAS_VULKAN ${GRASS_BUILD_VULKAN})
configure_file("${PROJECT_SOURCE_DIR}/cmake/grass.pc.in" "${PROJECT_BINARY_DIR}/grass.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/grass.pc" DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT development)
