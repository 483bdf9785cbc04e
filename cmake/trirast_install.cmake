# `cmake --install BUILD --prefix P`: the C++ model library as a CMake package and a pkg-config
# file, so that another project uses it with find_package(trirast) (docs/embedding.md):
#   P/lib/libtrirast_model.a                 trirast_model (model/, without the SystemC models)
#   P/include/trirast/{common,scene,golden,improved,improved2,trad,halfspace}/*.hpp
#                                            its headers, laid out as under model/
#   P/lib/cmake/trirast/                     trirastConfig.cmake, trirastConfigVersion.cmake and
#                                            the exported target trirast::model
#   P/lib/pkgconfig/trirast.pc               the same library for pkg-config
#   P/share/trirast/rtl/{common,UNIT}/       the SystemVerilog (*.sv, *.svh) and the units' file
#                                            lists (*.f), in rtl/'s layout so the lists' relative
#                                            paths still resolve
# Nothing of tb/, app/ or tools/ is installed, and neither are the SystemC models (trirast_sc):
# the library holds no CLI and no output formats. The folders are GNUInstallDirs' (included by the
# top-level CMakeLists.txt, before model/ names them).
include(CMakePackageConfigHelpers)

set(TRIRAST_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/trirast)
set(TRIRAST_INSTALL_RTLDIR ${CMAKE_INSTALL_DATADIR}/trirast/rtl)

# The installed target is trirast::model; the same name works inside this build.
set_target_properties(trirast_model PROPERTIES EXPORT_NAME model)
add_library(trirast::model ALIAS trirast_model)

install(TARGETS trirast_model EXPORT trirastTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The headers of trirast_model: every model/ header but the SystemC models' (UNIT_sc.hpp and
# common/sc_*.hpp, which belong to trirast_sc).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/model/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/trirast
  FILES_MATCHING PATTERN "*.hpp"
  PATTERN "sc_*.hpp" EXCLUDE
  PATTERN "*_sc.hpp" EXCLUDE)
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
