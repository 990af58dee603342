# cmake --install: the public headers under include/zraster/, the libraries, the command, the
# CMake package (find_package(zraster)) and the pkg-config files zraster-core.pc and zraster.pc.
include(CMakePackageConfigHelpers)

set(ZRASTER_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/zraster)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/zraster ${PROJECT_BINARY_DIR}/include/zraster
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")

get_property(libraries GLOBAL PROPERTY ZRASTER_LIBRARIES)
if(TARGET zraster)
  list(APPEND libraries zraster)
endif()
install(TARGETS ${libraries} EXPORT zrasterTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET zraster_cli)
  install(TARGETS zraster_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT zrasterTargets NAMESPACE zraster:: DESTINATION ${ZRASTER_CMAKE_DIR})

# What zrasterConfig.cmake must find for consumers: static libraries carry their private
# dependencies to the consumer's link line.
set(ZRASTER_PACKAGE_SHARED ${BUILD_SHARED_LIBS})
set(ZRASTER_PACKAGE_IO ${ZRASTER_BUILD_IO})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/zrasterConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/zrasterConfig.cmake
                              INSTALL_DESTINATION ${ZRASTER_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/zrasterConfigVersion.cmake
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/zrasterConfig.cmake
              ${PROJECT_BINARY_DIR}/zrasterConfigVersion.cmake
        DESTINATION ${ZRASTER_CMAKE_DIR})

# pkg-config: Requires for what the headers need (GLM), Requires.private for what a static
# library adds to the link line.
set(ZRASTER_PC_CFLAGS "")
foreach(definition ${ZRASTER_GLM_DEFINITIONS})
  string(APPEND ZRASTER_PC_CFLAGS " -D${definition}")
endforeach()
if(BUILD_SHARED_LIBS)
  string(APPEND ZRASTER_PC_CFLAGS " -DZRASTER_SHARED")
endif()
# The prefix is found relative to the .pc file itself, so an installed tree can be moved (and
# `cmake --install --prefix P` gives files that are right for P).
file(RELATIVE_PATH ZRASTER_PC_UP "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
string(REGEX REPLACE "/$" "" ZRASTER_PC_UP "${ZRASTER_PC_UP}")
set(ZRASTER_PC_PREFIX "\${pcfiledir}/${ZRASTER_PC_UP}")
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(ZRASTER_PC_LIBDIR "${CMAKE_INSTALL_LIBDIR}")
else()
  set(ZRASTER_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
endif()
if(IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(ZRASTER_PC_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}")
else()
  set(ZRASTER_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/zraster-core.pc.in
               ${PROJECT_BINARY_DIR}/zraster-core.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/zraster-core.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(ZRASTER_BUILD_IO)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/zraster.pc.in ${PROJECT_BINARY_DIR}/zraster.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/zraster.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()
