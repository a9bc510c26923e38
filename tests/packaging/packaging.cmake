# SPDX-License-Identifier: Apache-2.0
# ctest packaging.debs (label "package"): cpack makes the Debian packages of this build
# tree into a scratch directory, then check_packages.sh checks their names, dependencies
# and lintian, and builds the C consumer against them unpacked. Included from
# cmake/EnteronPackaging.cmake, which knows the packages (ENTERON_DEBIAN_PACKAGES).
# Not in sanitized or fuzzing builds: the packages are the library as released.
if(ENTERON_SANITIZE OR ENTERON_FUZZ)
  return()
endif()
find_program(ENTERON_BASH bash REQUIRED)
find_program(ENTERON_PKG_CONFIG NAMES pkg-config pkgconf)
set(_enteron_packaging_work "${PROJECT_BINARY_DIR}/tests/packaging")
list(JOIN ENTERON_DEBIAN_PACKAGES " " _enteron_packaging_expect)
add_test(NAME packaging.debs
  COMMAND ${ENTERON_BASH} -c "rm -rf \"$1\" && \"$2\" -G DEB --config \"$3\" -B \"$1\" && exec \"$4\" --packages \"$1\" --work-dir \"$5\" --expect \"$6\""
          packaging.debs
          "${_enteron_packaging_work}/packages" "${CMAKE_CPACK_COMMAND}" "${PROJECT_BINARY_DIR}/CPackConfig.cmake"
          "${CMAKE_CURRENT_LIST_DIR}/check_packages.sh" "${_enteron_packaging_work}/check"
          "${_enteron_packaging_expect}")
set_tests_properties(packaging.debs PROPERTIES
  LABELS "package;install"
  TIMEOUT 600
  # cpack installs every component of the build tree, as the consumer tests do.
  RESOURCE_LOCK enteron_install
  ENVIRONMENT "CMAKE=${CMAKE_COMMAND};CC=${CMAKE_C_COMPILER};PKG_CONFIG=${ENTERON_PKG_CONFIG};CMAKE_GENERATOR=${CMAKE_GENERATOR}")

# ctest packaging.bindings (label "package"): the packages packaging.debs made, python3-enteron
# and libenteron-cil with libenteron0, installed into a scratch root laid over /usr in a mount
# namespace of its own and used there (check_bindings.sh); skipped where no mount namespace
# can be made.
if(ENTERON_PYTHON_BINDING AND ENTERON_CSHARP_BINDING)
  set_tests_properties(packaging.debs PROPERTIES FIXTURES_SETUP enteron_debs)
  add_test(NAME packaging.bindings
    COMMAND ${ENTERON_BASH} "${CMAKE_CURRENT_LIST_DIR}/check_bindings.sh"
            --packages "${_enteron_packaging_work}/packages" --work-dir "${_enteron_packaging_work}/bindings")
  set_tests_properties(packaging.bindings PROPERTIES
    LABELS "package;install;python;csharp"
    TIMEOUT 300
    FIXTURES_REQUIRED enteron_debs
    SKIP_RETURN_CODE 77)
endif()
