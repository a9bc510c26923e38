# SPDX-License-Identifier: Apache-2.0
# The C# binding's tests (label csharp), included from bindings/csharp/CMakeLists.txt:
#   csharp.example_minimal   examples/csharp/Minimal.cs prints the line examples/minimal.c prints
#   csharp.<Fixture>         each NUnit 2.6 fixture of bindings/csharp/tests/<Fixture>.cs (one
#                            fixture per file, named after it), run by nunit-console under Mono
# Debian: nunit-console and libnunit-cil-dev (scripts/install-deps).

# ---- the C# minimal example, compared with the C one --------------------------------------------
set(_enteron_minimal_exe "${ENTERON_CSHARP_DIR}/Minimal.exe")
enteron_csharp_assembly(TARGET enteron_csharp_minimal OUTPUT "${_enteron_minimal_exe}" EXECUTABLE
  SOURCES "${PROJECT_SOURCE_DIR}/examples/csharp/Minimal.cs" REFERENCES "${ENTERON_CSHARP_ASSEMBLY}")
if(ENTERON_BUILD_EXAMPLES)  # enteron_minimal is defined later (examples/), read at generation
  add_test(NAME csharp.example_minimal
    COMMAND ${CMAKE_COMMAND} -DC_PROGRAM=$<TARGET_FILE:enteron_minimal> -DMONO=${ENTERON_MONO}
            -DCSHARP_PROGRAM=${_enteron_minimal_exe} -P ${CMAKE_CURRENT_LIST_DIR}/same_line.cmake)
  set_tests_properties(csharp.example_minimal PROPERTIES LABELS "csharp;example" TIMEOUT 120)
endif()

# ---- NUnit -----------------------------------------------------------------------------------------
find_program(ENTERON_NUNIT_CONSOLE nunit-console)
file(GLOB _enteron_nunit_framework_candidates /usr/lib/cli/nunit.framework-2.6*/nunit.framework.dll)
find_file(ENTERON_NUNIT_FRAMEWORK nunit.framework.dll HINTS ${_enteron_nunit_framework_candidates})
if(_enteron_nunit_framework_candidates AND NOT ENTERON_NUNIT_FRAMEWORK)
  list(GET _enteron_nunit_framework_candidates 0 _enteron_nunit_framework)
  set(ENTERON_NUNIT_FRAMEWORK "${_enteron_nunit_framework}" CACHE FILEPATH "NUnit 2.6's nunit.framework.dll" FORCE)
endif()
if(NOT ENTERON_NUNIT_CONSOLE OR NOT ENTERON_NUNIT_FRAMEWORK)
  message(WARNING "nunit-console or nunit.framework.dll not found (Debian: nunit-console libnunit-cil-dev): "
                  "the C# binding's NUnit tests are not registered")
  return()
endif()

# The C struct layouts (the Python binding's program, also built here when Python's tests are off).
if(NOT TARGET enteron_struct_layout)
  add_executable(enteron_struct_layout "${PROJECT_SOURCE_DIR}/bindings/python/tests/struct_layout.c")
  target_link_libraries(enteron_struct_layout PRIVATE enteron)
  target_compile_options(enteron_struct_layout PRIVATE ${ENTERON_WARNINGS} -pedantic)
endif()

file(GLOB _enteron_csharp_test_sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_LIST_DIR}/*.cs")
set(ENTERON_CSHARP_TESTS_ASSEMBLY "${ENTERON_CSHARP_DIR}/Enteron.Tests.dll")
enteron_csharp_assembly(TARGET enteron_csharp_tests OUTPUT "${ENTERON_CSHARP_TESTS_ASSEMBLY}"
  SOURCES ${_enteron_csharp_test_sources} REFERENCES "${ENTERON_CSHARP_ASSEMBLY}" "${ENTERON_NUNIT_FRAMEWORK}")
add_dependencies(enteron_csharp_tests enteron_struct_layout enteron_exports)

# enteron_nunit_fixture(NAME ASSEMBLY NAMESPACE LABELS ENVIRONMENT): one ctest per fixture. A
# -run that matches nothing runs no test and succeeds: "Tests run: 0" fails instead.
function(enteron_nunit_fixture)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;ASSEMBLY;NAMESPACE;PREFIX" "LABELS;ENVIRONMENT")
  get_filename_component(directory "${arg_ASSEMBLY}" DIRECTORY)
  add_test(NAME ${arg_PREFIX}.${arg_NAME}
    COMMAND ${ENTERON_NUNIT_CONSOLE} "${arg_ASSEMBLY}" -run:${arg_NAMESPACE}.${arg_NAME}
            -nologo -noshadow -noresult -labels
    WORKING_DIRECTORY "${directory}")
  set_tests_properties(${arg_PREFIX}.${arg_NAME} PROPERTIES LABELS "${arg_LABELS}" TIMEOUT 300
    FAIL_REGULAR_EXPRESSION "Tests run: 0,"
    ENVIRONMENT "${arg_ENVIRONMENT}")
endfunction()

set(ENTERON_CSHARP_TEST_ENVIRONMENT
  "ENTERON_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
  "ENTERON_EXPORTS_FILE=${PROJECT_BINARY_DIR}/tests/enteron_exports.txt"
  "ENTERON_STRUCT_LAYOUT=$<TARGET_FILE:enteron_struct_layout>"
  "MONO_ENV_OPTIONS=--debug")  # file and line numbers in the stack traces of failures
foreach(source IN LISTS _enteron_csharp_test_sources)
  get_filename_component(fixture "${source}" NAME_WE)
  if(fixture MATCHES "Tests$")
    enteron_nunit_fixture(NAME ${fixture} PREFIX csharp ASSEMBLY "${ENTERON_CSHARP_TESTS_ASSEMBLY}"
      NAMESPACE Enteron.Tests LABELS csharp ENVIRONMENT ${ENTERON_CSHARP_TEST_ENVIRONMENT})
  endif()
endforeach()
if(TEST csharp.ThreadTests)
  set_tests_properties(csharp.ThreadTests PROPERTIES LABELS "csharp;threads")
endif()
