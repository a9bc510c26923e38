# SPDX-License-Identifier: Apache-2.0
# Tests of the installed package and of the ABI surface. Include this file from
# tests/CMakeLists.txt (after enable_testing()):
#   include(${CMAKE_CURRENT_SOURCE_DIR}/consumer/consumer.cmake)
# Do not add_subdirectory(consumer): its CMakeLists.txt is a stand-alone consumer project.
#
#   consumer_find_package  install into a staging prefix, build consumer.c with
#                          find_package(enteron CONFIG), run it; move the prefix; again
#   consumer_pkg_config    the same with cc $(pkg-config --cflags --libs enteron)
#   exports_only_ent       libenteron.so defines only ent_* dynamic symbols, all the
#                          header's functions, and has SONAME libenteron.so.<major>
set(_enteron_consumer_dir "${CMAKE_CURRENT_LIST_DIR}")

find_program(ENTERON_BASH bash REQUIRED)
find_program(ENTERON_PKG_CONFIG NAMES pkg-config pkgconf)
if(NOT CMAKE_NM)
  find_program(CMAKE_NM nm REQUIRED)
endif()
if(NOT CMAKE_READELF)
  find_program(CMAKE_READELF readelf REQUIRED)
endif()

foreach(_enteron_mode IN ITEMS cmake pkg-config)
  if(_enteron_mode STREQUAL "cmake")
    set(_enteron_test consumer_find_package)
  else()
    set(_enteron_test consumer_pkg_config)
  endif()
  if(_enteron_mode STREQUAL "pkg-config" AND NOT ENTERON_PKG_CONFIG)
    message(WARNING "pkg-config not found: test ${_enteron_test} is not registered")
    continue()
  endif()
  add_test(NAME ${_enteron_test}
    COMMAND ${ENTERON_BASH} ${_enteron_consumer_dir}/run_consumer_test.sh
            --build-dir ${CMAKE_BINARY_DIR}
            --work-dir ${CMAKE_CURRENT_BINARY_DIR}/${_enteron_test}
            --mode ${_enteron_mode}
            --libdir ${CMAKE_INSTALL_LIBDIR}
            --includedir ${CMAKE_INSTALL_INCLUDEDIR})
  set_tests_properties(${_enteron_test} PROPERTIES
    LABELS "install"
    TIMEOUT 300
    # Both write install_manifest.txt into the build tree: never at the same time.
    RESOURCE_LOCK enteron_install
    ENVIRONMENT "CMAKE=${CMAKE_COMMAND};CC=${CMAKE_C_COMPILER};PKG_CONFIG=${ENTERON_PKG_CONFIG};CMAKE_GENERATOR=${CMAKE_GENERATOR}")
endforeach()

add_test(NAME exports_only_ent
  COMMAND ${ENTERON_BASH} ${_enteron_consumer_dir}/check_exports.sh
          $<TARGET_FILE:enteron>
          libenteron.so.${PROJECT_VERSION_MAJOR}
          ${PROJECT_SOURCE_DIR}/include/enteron/enteron.h)
set_tests_properties(exports_only_ent PROPERTIES
  LABELS "abi"
  TIMEOUT 60
  ENVIRONMENT "NM=${CMAKE_NM};READELF=${CMAKE_READELF}")
