# `cmake --install`: the libraries with their headers, the unfurl command,
# the built-in scenes and meshes (share/unfurl), and a CMake package:
#   find_package(unfurl REQUIRED COMPONENTS sim)   ->  unfurl::sim
# (also unfurl::studies, and unfurl::render when it was built).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(UNFURL_INSTALLED_LIBRARIES unfurl_input unfurl_sim unfurl_studies)
set(UNFURL_INSTALLED_COMPONENTS input sim studies)
install(DIRECTORY input/include/ sim/include/ studies/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(UNFURL_BUILD_RENDER)
  list(APPEND UNFURL_INSTALLED_LIBRARIES unfurl_mesh_files unfurl_render)
  list(APPEND UNFURL_INSTALLED_COMPONENTS mesh_files render)
  install(DIRECTORY render/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
list(APPEND UNFURL_INSTALLED_LIBRARIES unfurl_io)
list(APPEND UNFURL_INSTALLED_COMPONENTS io)
if(UNFURL_BUILD_RENDER)
  list(APPEND UNFURL_INSTALLED_LIBRARIES unfurl_io_pictures)
  list(APPEND UNFURL_INSTALLED_COMPONENTS io_pictures)
endif()
install(DIRECTORY io/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ${UNFURL_INSTALLED_LIBRARIES} EXPORT unfurlTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS unfurl RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(UNFURL_BUILD_RENDER)
  # What the command loads to draw (app/graphics), found from bin/ as ../lib/unfurl.
  install(TARGETS unfurl_graphics LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/unfurl)
endif()
install(DIRECTORY assets/scenes assets/meshes assets/studies DESTINATION ${CMAKE_INSTALL_DATADIR}/unfurl)

set(UNFURL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/unfurl)
install(EXPORT unfurlTargets NAMESPACE unfurl:: DESTINATION ${UNFURL_CMAKE_DIR})
set(UNFURL_RENDER_WITH_EGL ${EGL_FOUND})
set(UNFURL_RENDER_WITH_OSMESA ${OSMESA_FOUND})
configure_package_config_file(cmake/unfurlConfig.cmake.in ${PROJECT_BINARY_DIR}/unfurlConfig.cmake
                              INSTALL_DESTINATION ${UNFURL_CMAKE_DIR} PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/unfurlConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/unfurlConfig.cmake ${PROJECT_BINARY_DIR}/unfurlConfigVersion.cmake
        DESTINATION ${UNFURL_CMAKE_DIR})
