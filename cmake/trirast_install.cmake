# `cmake --install BUILD --prefix P`: the C++ model library as a CMake package and a pkg-config
# file, so that another project uses it with find_package(trirast) (docs/embedding.md):
#   P/lib/libtrirast_model.a                 trirast_model (model/, without the SystemC models)
#   P/lib/libtrirast_sc.a                    trirast_sc (the units' SystemC models, components of a
#                                            user's platform: trirast::systemc)
#   P/include/trirast/{common,scene,golden,improved,improved2,trad,halfspace}/*.hpp
#                                            its headers, laid out as under model/
#   P/lib/cmake/trirast/                     trirastConfig.cmake, trirastConfigVersion.cmake and
#                                            the exported targets trirast::model, trirast::systemc
#   P/lib/pkgconfig/trirast.pc               the same library for pkg-config
#   P/share/trirast/rtl/{common,UNIT}/       the SystemVerilog (*.sv, *.svh) and the units' file
#                                            lists (*.f), in rtl/'s layout so the lists' relative
#                                            paths still resolve
# Nothing of tb/, app/ or tools/ is installed: the libraries hold no CLI and no output formats. The folders are GNUInstallDirs' (included by the
# top-level CMakeLists.txt, before model/ names them).
include(CMakePackageConfigHelpers)

set(TRIRAST_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/trirast)
set(TRIRAST_INSTALL_RTLDIR ${CMAKE_INSTALL_DATADIR}/trirast/rtl)

# The installed targets are trirast::model and trirast::systemc; the same names work inside this
# build.
set_target_properties(trirast_model PROPERTIES EXPORT_NAME model)
add_library(trirast::model ALIAS trirast_model)
set_target_properties(trirast_sc PROPERTIES EXPORT_NAME systemc)
add_library(trirast::systemc ALIAS trirast_sc)

install(TARGETS trirast_model trirast_sc EXPORT trirastTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The headers of both: every model/ header, in model/'s layout (the SystemC models' are
# UNIT/UNIT_sc.hpp and common/sc_*.hpp).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/model/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/trirast
  FILES_MATCHING PATTERN "*.hpp")
install(EXPORT trirastTargets
  NAMESPACE trirast::
  FILE trirastTargets.cmake
  DESTINATION ${TRIRAST_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/trirastConfig.cmake.in
  ${CMAKE_BINARY_DIR}/trirastConfig.cmake
  INSTALL_DESTINATION ${TRIRAST_INSTALL_CMAKEDIR}
  PATH_VARS TRIRAST_INSTALL_RTLDIR)
# 0.x: a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/trirastConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/trirastConfig.cmake ${CMAKE_BINARY_DIR}/trirastConfigVersion.cmake
  DESTINATION ${TRIRAST_INSTALL_CMAKEDIR})

# pkg-config: the prefix is taken at install time (${pcfiledir}), so the file stays right for
# any --prefix. The library is static, so its dependencies are in Libs and Requires.
file(RELATIVE_PATH TRIRAST_PC_PREFIX_FROM_PCDIR /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)
string(REGEX REPLACE "/$" "" TRIRAST_PC_PREFIX_FROM_PCDIR "${TRIRAST_PC_PREFIX_FROM_PCDIR}")
configure_file(${CMAKE_SOURCE_DIR}/cmake/trirast.pc.in ${CMAKE_BINARY_DIR}/trirast.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/trirast.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The RTL and its file lists (the CMakeLists.txt there is the build's, not the RTL's).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/rtl/
  DESTINATION ${TRIRAST_INSTALL_RTLDIR}
  FILES_MATCHING PATTERN "*.sv" PATTERN "*.svh" PATTERN "*.f")
