# Registers the ABI check of the built library against abi/libenteron.abi (included from
# tests/CMakeLists.txt).
find_program(ENTERON_ABIDW abidw)
if(ENTERON_ABIDW)
  add_test(NAME abi_check COMMAND ${PROJECT_SOURCE_DIR}/abi/check $<TARGET_FILE:enteron>)
  set_tests_properties(abi_check PROPERTIES LABELS abi)
else()
  message(WARNING "abidw not found (Debian: abigail-tools): the ABI check is not registered")
endif()
