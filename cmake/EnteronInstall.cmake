# SPDX-License-Identifier: Apache-2.0
# Install rules for libenteron: the shared library (with its SONAME symlink and namelink),
# the public header, a CMake package (enteron::enteron) and a relocatable pkg-config file.
# Included from lib/CMakeLists.txt after the `enteron` target is defined.
#
# Layout under the prefix (GNUInstallDirs; "lib" below is CMAKE_INSTALL_LIBDIR):
#   lib/libenteron.so.<version>, lib/libenteron.so.<major> (SONAME), lib/libenteron.so
#   include/enteron/enteron.h, enteron.hpp (the header-only C++ layer)
#   lib/cmake/enteron/enteronConfig.cmake, enteronConfigVersion.cmake, enteronTargets*.cmake
#   lib/pkgconfig/enteron.pc
#
# Only the shared library is exported. enteron_core is a static library linked PRIVATE
# into it, so it is not part of the link interface of a shared library and need not (and
# must not) be installed or exported.
include(CMakePackageConfigHelpers)

set(ENTERON_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/enteron"
    CACHE STRING "Where to install the CMake package files, relative to the prefix")
set(ENTERON_INSTALL_PKGCONFIGDIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig"
    CACHE STRING "Where to install enteron.pc, relative to the prefix")
mark_as_advanced(ENTERON_INSTALL_CMAKEDIR ENTERON_INSTALL_PKGCONFIGDIR)

install(TARGETS enteron
  EXPORT enteronTargets
  LIBRARY
    DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    COMPONENT Runtime
    NAMELINK_COMPONENT Development
  RUNTIME
    DESTINATION "${CMAKE_INSTALL_BINDIR}"
    COMPONENT Runtime
  PUBLIC_HEADER
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/enteron"
    COMPONENT Development)

install(EXPORT enteronTargets
  NAMESPACE enteron::
  FILE enteronTargets.cmake
  DESTINATION "${ENTERON_INSTALL_CMAKEDIR}"
  COMPONENT Development)

configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/enteronConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/cmake/enteronConfig.cmake"
  INSTALL_DESTINATION "${ENTERON_INSTALL_CMAKEDIR}")

# A program built against 0.x keeps working with any later 0.y: the SONAME changes with
# the major version only (SOVERSION = PROJECT_VERSION_MAJOR).
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/cmake/enteronConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMajorVersion)

install(FILES
  "${PROJECT_BINARY_DIR}/cmake/enteronConfig.cmake"
  "${PROJECT_BINARY_DIR}/cmake/enteronConfigVersion.cmake"
  DESTINATION "${ENTERON_INSTALL_CMAKEDIR}"
  COMPONENT Development)

# pkg-config: every path is relative to ${pcfiledir}, so the installed tree can be moved.
# An absolute CMAKE_INSTALL_LIBDIR/INCLUDEDIR cannot be expressed that way and is kept
# as given (that install is then not relocatable).
function(_enteron_pc_path out_var dir)
  if(IS_ABSOLUTE "${dir}")
    set(${out_var} "${dir}" PARENT_SCOPE)
  else()
    set(${out_var} "\${prefix}/${dir}" PARENT_SCOPE)
  endif()
endfunction()
if(IS_ABSOLUTE "${ENTERON_INSTALL_PKGCONFIGDIR}")
  set(ENTERON_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  # From <prefix>/<pkgconfigdir> back up to <prefix>: one ".." per path component.
  file(RELATIVE_PATH _enteron_pc_up "/enteron-prefix/${ENTERON_INSTALL_PKGCONFIGDIR}"
       "/enteron-prefix")
  string(REGEX REPLACE "/+$" "" _enteron_pc_up "${_enteron_pc_up}")
  set(ENTERON_PC_PREFIX "\${pcfiledir}/${_enteron_pc_up}")
endif()
_enteron_pc_path(ENTERON_PC_LIBDIR "${CMAKE_INSTALL_LIBDIR}")
_enteron_pc_path(ENTERON_PC_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}")
configure_file("${PROJECT_SOURCE_DIR}/cmake/enteron.pc.in"
               "${PROJECT_BINARY_DIR}/enteron.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/enteron.pc"
  DESTINATION "${ENTERON_INSTALL_PKGCONFIGDIR}"
  COMPONENT Development)
