# SPDX-License-Identifier: Apache-2.0
# Debian packages with CPack (docs/building.md, "Debian packages"): one package per install
# component, named after the SONAME where it holds a shared library (Debian policy 8.1).
# Included last from the top-level CMakeLists.txt, once every install rule is known.
#
#   component    package           holds
#   Runtime      libenteron0       libenteron.so.0 and libenteron.so.<version>
#   Development  libenteron-dev    enteron.h, enteron.hpp, libenteron.so, the CMake package, enteron.pc
#   Viewer       enteron-viewer    bin/enteron-viewer, when it is built
#   with the LCM bridge (ENTERON_WITH_LCM, docs/lcm.md):
#   LcmRuntime      libenteron-lcm0     libenteron_lcm.so.0 and libenteron_lcm.so.<version>
#   LcmDevelopment  libenteron-lcm-dev  enteron_lcm.h, libenteron_lcm.so, the CMake package's
#                                       component lcm, enteron_lcm.pc, the .lcm types
#   LcmPrograms     enteron-lcm         bin/enteron-lcm-server, bin/enteron-lcm-replay
#   with the bindings (ENTERON_PYTHON_BINDING, ENTERON_CSHARP_BINDING), architecture all:
#   Python          python3-enteron     the package enteron in /usr/lib/python3/dist-packages
#   CSharp          libenteron-cil      Enteron.dll (+ .config, .xml) in /usr/lib/cli/enteron,
#                                       enteron-sharp.pc (Debian's CLI policy names it -cil)
#
# `scripts/package` configures a tree for the prefix /usr and runs cpack; tests/packaging
# unpacks the packages and builds a consumer against them, and installs the bindings'
# packages into a scratch root to use them (check_bindings.sh). Every package carries
# /usr/share/doc/<package>/copyright and changelog.Debian.gz, as Debian policy asks.
# The maintainer is a placeholder (the .invalid domain never resolves) until the owners
# name one: give ENTERON_PACKAGE_MAINTAINER in the build tree's cache (cmake
# -DENTERON_PACKAGE_MAINTAINER="Name <address>" build/package, then scripts/package). It
# fills the Maintainer field, the Debian changelog's signature and the copyright file's
# Upstream-Contact.
set(ENTERON_PACKAGE_MAINTAINER "Enteron developers <dev@enteron.invalid>"
    CACHE STRING "The Maintainer field of the Debian packages (name <address>)")
set(ENTERON_PACKAGE_RELEASE "1" CACHE STRING "The Debian revision of the packages (version <project version>-<this>)")
mark_as_advanced(ENTERON_PACKAGE_MAINTAINER ENTERON_PACKAGE_RELEASE)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME enteron)
set(CPACK_PACKAGE_VENDOR "Enteron developers")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
# Each package has its own synopsis (the first line of its description). CPack's DEB
# generator would put this summary above it, unless it is CPack's own default: keep that.
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_NAME} built using CMake")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)  # lintian: unstripped-binary-or-object is an error
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <package>_<version>-<release>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_RELEASE "${ENTERON_PACKAGE_RELEASE}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${ENTERON_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SOURCE enteron)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Dependencies on system libraries from dpkg-shlibdeps; on our own packages from the
# components' DEPENDS, pinned to this exact version (they are built together).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
# dpkg-shlibdeps must find our own libraries, which no installed package provides yet:
# where the build put them (then --ignore-missing-info, which CPack passes, skips them).
get_target_property(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS enteron BINARY_DIR)
if(TARGET enteron_lcm)
  get_target_property(_enteron_lcm_library_dir enteron_lcm BINARY_DIR)
  list(APPEND CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${_enteron_lcm_library_dir}")
endif()
# A shlibs control file for each library package, so that packages built against it get
# "Depends: libenteron0 (>= <version>)" from dpkg-shlibdeps.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")

# The files every package must carry in /usr/share/doc/<package>/: the copyright notice and
# a Debian changelog, compressed with gzip -9n (no name, no time stamp: reproducible).
set(_enteron_debian_dir "${PROJECT_BINARY_DIR}/debian")
set(ENTERON_PACKAGE_VERSION "${PROJECT_VERSION}-${ENTERON_PACKAGE_RELEASE}")
string(TIMESTAMP ENTERON_PACKAGE_DATE "%a, %d %b %Y %H:%M:%S +0000" UTC)  # honours SOURCE_DATE_EPOCH
configure_file("${PROJECT_SOURCE_DIR}/cmake/debian/changelog.in" "${_enteron_debian_dir}/changelog" @ONLY)
# The copyright file, machine-readable (DEP-5): the project's licence (ENTERON_LICENSE,
# Apache-2.0) and what the packages carry of others' (docs/building.md, "Licences").
configure_file("${PROJECT_SOURCE_DIR}/cmake/debian/copyright.in" "${_enteron_debian_dir}/copyright" @ONLY)
find_program(ENTERON_GZIP gzip REQUIRED)
execute_process(COMMAND "${ENTERON_GZIP}" -9nc "${_enteron_debian_dir}/changelog"
                OUTPUT_FILE "${_enteron_debian_dir}/changelog.Debian.gz" COMMAND_ERROR_IS_FATAL ANY)

# A library package activates dpkg's ldconfig trigger (lintian: lacks-ldconfig-trigger).
file(WRITE "${_enteron_debian_dir}/triggers" "activate-noawait ldconfig\n")

# _enteron_wrap(out text): text in lines of at most 79 characters, as a Debian package's
# long description wants them.
function(_enteron_wrap out text)
  string(REGEX REPLACE " +" ";" words "${text}")
  set(lines "")
  set(line "")
  foreach(word IN LISTS words)
    string(LENGTH "${line} ${word}" length)
    if(line AND length GREATER 79)
      string(APPEND lines "${line}\n")
      set(line "${word}")
    elseif(line)
      string(APPEND line " ${word}")
    else()
      set(line "${word}")
    endif()
  endforeach()
  set(${out} "${lines}${line}" PARENT_SCOPE)
endfunction()

set(CPACK_COMPONENTS_ALL "")
set(ENTERON_DEBIAN_PACKAGES "")
# enteron_debian_package(COMPONENT NAME SECTION SUMMARY DESCRIPTION [LIBRARY] [ARCHITECTURE_ALL]
#                        [DEPENDS component...] [EXTRA_DEPENDS text] [RECOMMENDS text]):
# the component becomes the package NAME. LIBRARY: it holds a shared library (an ldconfig
# trigger). ARCHITECTURE_ALL: nothing in it depends on the processor (Python, C#).
# DESCRIPTION is the long description, one paragraph; DEPENDS are other components of this
# project, EXTRA_DEPENDS what dpkg-shlibdeps cannot see (libraries opened with dlopen, the
# interpreter of a binding).
macro(enteron_debian_package)
  cmake_parse_arguments(_package "LIBRARY;ARCHITECTURE_ALL" "COMPONENT;NAME;SECTION;SUMMARY;DESCRIPTION;EXTRA_DEPENDS;RECOMMENDS"
                        "DEPENDS" ${ARGN})
  string(TOUPPER "${_package_COMPONENT}" _package_upper)
  list(APPEND CPACK_COMPONENTS_ALL ${_package_COMPONENT})
  list(APPEND ENTERON_DEBIAN_PACKAGES ${_package_NAME})
  set(CPACK_DEBIAN_${_package_upper}_PACKAGE_NAME ${_package_NAME})
  set(CPACK_DEBIAN_${_package_upper}_PACKAGE_SECTION ${_package_SECTION})
  _enteron_wrap(_package_long "${_package_DESCRIPTION}")
  set(CPACK_DEBIAN_${_package_upper}_DESCRIPTION "${_package_SUMMARY}\n${_package_long}")
  set(CPACK_COMPONENT_${_package_upper}_DEPENDS ${_package_DEPENDS})
  set(CPACK_DEBIAN_${_package_upper}_PACKAGE_DEPENDS "${_package_EXTRA_DEPENDS}")
  set(CPACK_DEBIAN_${_package_upper}_PACKAGE_RECOMMENDS "${_package_RECOMMENDS}")
  if(_package_ARCHITECTURE_ALL)
    set(CPACK_DEBIAN_${_package_upper}_PACKAGE_ARCHITECTURE all)
  endif()
  if(_package_LIBRARY)
    set(CPACK_DEBIAN_${_package_upper}_PACKAGE_CONTROL_EXTRA "${_enteron_debian_dir}/triggers")
    set(CPACK_DEBIAN_${_package_upper}_PACKAGE_CONTROL_STRICT_PERMISSION ON)
  endif()
  # Only in the package: a plain `cmake --install` does not put these into the prefix.
  install(FILES "${_enteron_debian_dir}/copyright" "${_enteron_debian_dir}/changelog.Debian.gz"
    DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/${_package_NAME}"
    COMPONENT ${_package_COMPONENT} EXCLUDE_FROM_ALL)
endmacro()

set(_enteron_about "Enteron simulates the human small intestine in real time for laparoscopic surgery simulators: an elastic tube around a spline axis, stepped at 1 kHz, with tools that push and grasp it and surfaces to draw from any thread.")

enteron_debian_package(COMPONENT Runtime NAME libenteron${PROJECT_VERSION_MAJOR} SECTION libs LIBRARY
  SUMMARY "real-time small intestine model for surgery simulators (library)"
  DESCRIPTION "${_enteron_about} This package holds the shared library, libenteron.so.${PROJECT_VERSION_MAJOR}, behind a stable C ABI.")
enteron_debian_package(COMPONENT Development NAME libenteron-dev SECTION libdevel DEPENDS Runtime
  SUMMARY "real-time small intestine model for surgery simulators (development files)"
  DESCRIPTION "${_enteron_about} This package holds the C header enteron/enteron.h, the header-only C++17 layer enteron/enteron.hpp, the CMake package (find_package(enteron), target enteron::enteron) and the pkg-config file enteron.pc.")
if(TARGET enteron-viewer)
  # With the bridge built, the viewer's --lcm mode links libenteron_lcm.
  set(_enteron_viewer_needs Runtime)
  if(TARGET enteron_lcm)
    list(APPEND _enteron_viewer_needs LcmRuntime)
  endif()
  enteron_debian_package(COMPONENT Viewer NAME enteron-viewer SECTION science DEPENDS ${_enteron_viewer_needs}
    # libepoxy opens libGL and libEGL at run time; ffmpeg only writes --video.
    EXTRA_DEPENDS "libgl1, libegl1" RECOMMENDS "fonts-dejavu-core, ffmpeg"
    SUMMARY "real-time small intestine model for surgery simulators (viewer)"
    DESCRIPTION "${_enteron_about} This package holds enteron-viewer, which shows a scene in a window, moves a tool with the mouse and plots the forces, or renders frames and videos without a display (--headless); with --lcm it shows a running enteron-lcm-server session.")
endif()
if(TARGET enteron_lcm)
  enteron_debian_package(COMPONENT LcmRuntime NAME libenteron-lcm${PROJECT_VERSION_MAJOR} SECTION libs LIBRARY
    DEPENDS Runtime
    SUMMARY "real-time small intestine model for surgery simulators (LCM bridge)"
    DESCRIPTION "${_enteron_about} This package holds the LCM bridge, libenteron_lcm.so.${PROJECT_VERSION_MAJOR}: haptic drivers, viewers and loggers talk to a running scene over LCM, with safety rules on the tool commands and a journal that replays bit for bit.")
  enteron_debian_package(COMPONENT LcmDevelopment NAME libenteron-lcm-dev SECTION libdevel
    DEPENDS LcmRuntime Development
    SUMMARY "real-time small intestine model for surgery simulators (LCM bridge, development)"
    DESCRIPTION "${_enteron_about} This package holds the C header enteron/enteron_lcm.h, the CMake package's component lcm (target enteron::enteron_lcm), the pkg-config file enteron_lcm.pc and the LCM message types (/usr/share/enteron/lcm).")
  enteron_debian_package(COMPONENT LcmPrograms NAME enteron-lcm SECTION science DEPENDS LcmRuntime Runtime
    SUMMARY "real-time small intestine model for surgery simulators (LCM server)"
    DESCRIPTION "${_enteron_about} This package holds enteron-lcm-server, which runs a scene at 1 kHz and serves it over LCM, and enteron-lcm-replay, which replays a server's journal and checks it bit for bit.")
endif()

if(ENTERON_PYTHON_BINDING)
  enteron_debian_package(COMPONENT Python NAME python3-enteron SECTION python ARCHITECTURE_ALL DEPENDS Runtime
    EXTRA_DEPENDS "python3, python3-numpy"
    SUMMARY "real-time small intestine model for surgery simulators (Python 3)"
    DESCRIPTION "${_enteron_about} This package holds the Python 3 package enteron, a ctypes binding of libenteron that gives numpy arrays: import enteron works without PYTHONPATH.")
endif()
if(ENTERON_CSHARP_BINDING)
  enteron_debian_package(COMPONENT CSharp NAME libenteron-cil SECTION cli-mono ARCHITECTURE_ALL DEPENDS Runtime
    EXTRA_DEPENDS "mono-runtime (>= 6.8), libmono-corlib4.5-cil (>= 6.8)"
    SUMMARY "real-time small intestine model for surgery simulators (C#)"
    DESCRIPTION "${_enteron_about} This package holds Enteron.dll, the C# binding of libenteron for Mono and .NET (P/Invoke, SafeHandles, no garbage on the 1 kHz path), in /usr/lib/cli/enteron, and enteron-sharp.pc: mcs -pkg:enteron-sharp.")
endif()

include(CPack)
# The names, for scripts/package to check that cpack made exactly these.
list(JOIN ENTERON_DEBIAN_PACKAGES " " _enteron_package_names)
file(WRITE "${_enteron_debian_dir}/packages" "${_enteron_package_names}\n")

if(ENTERON_BUILD_TESTS)
  include(${PROJECT_SOURCE_DIR}/tests/packaging/packaging.cmake)
endif()
