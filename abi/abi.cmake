# SPDX-License-Identifier: Apache-2.0
# Registers the ABI tests (included from tests/CMakeLists.txt), label "abi":
#   abi_check        the built library against the committed baseline abi/libenteron.abi
#   abi_check_bites  abi/check refuses deliberately broken copies of the library (a removed
#                    function, a field inserted mid-struct) and accepts a field appended at
#                    the end of a struct_size struct (tests/abi/check_bites.sh)
find_program(ENTERON_ABIDW abidw)
find_program(ENTERON_ABIDIFF abidiff)
if(ENTERON_ABIDW AND ENTERON_ABIDIFF)
  add_test(NAME abi_check COMMAND ${PROJECT_SOURCE_DIR}/abi/check $<TARGET_FILE:enteron>)
  set_tests_properties(abi_check PROPERTIES LABELS abi)

  find_program(ENTERON_NINJA NAMES ninja ninja-build)
  if(ENTERON_NINJA)
    add_test(NAME abi_check_bites
      COMMAND ${PROJECT_SOURCE_DIR}/tests/abi/check_bites.sh
              ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR}/abi_check_bites $<TARGET_FILE:enteron_core>)
    set_tests_properties(abi_check_bites PROPERTIES
      LABELS abi
      TIMEOUT 600
      ENVIRONMENT "CMAKE=${CMAKE_COMMAND};NINJA=${ENTERON_NINJA};JOBS=2")
  else()
    message(WARNING "ninja not found: the test abi_check_bites is not registered")
  endif()
else()
  message(WARNING "abidw/abidiff not found (Debian: abigail-tools): the ABI checks are not registered")
endif()
