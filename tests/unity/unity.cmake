# SPDX-License-Identifier: Apache-2.0
# The Unity package (bindings/unity) where Unity cannot run: its components compiled against
# a stand-in of the few UnityEngine types they use (UnityEngineStandIn.cs, here and never in
# the package), then run by NUnit (label unity). Included from bindings/csharp/CMakeLists.txt.
#   UnityEngineStandIn.dll      the stand-in
#   Enteron.Unity.dll           bindings/unity/Runtime, as Unity would compile it (unsafe code on)
#   Enteron.Unity.Samples.dll   bindings/unity/Samples~ (the abdomen sample)
#   unity.<Fixture>             each fixture of tests/unity/<Fixture>.cs, under nunit-console
set(_enteron_unity_dir "${PROJECT_SOURCE_DIR}/bindings/unity")
set(_enteron_standin "${ENTERON_CSHARP_DIR}/UnityEngineStandIn.dll")
set(_enteron_unity_runtime "${ENTERON_CSHARP_DIR}/Enteron.Unity.dll")
set(_enteron_unity_samples "${ENTERON_CSHARP_DIR}/Enteron.Unity.Samples.dll")
enteron_csharp_assembly(TARGET enteron_unity_standin OUTPUT "${_enteron_standin}"
  SOURCES "${CMAKE_CURRENT_LIST_DIR}/UnityEngineStandIn.cs")
file(GLOB _enteron_unity_runtime_sources CONFIGURE_DEPENDS "${_enteron_unity_dir}/Runtime/*.cs")
enteron_csharp_assembly(TARGET enteron_unity_runtime OUTPUT "${_enteron_unity_runtime}"
  SOURCES ${_enteron_unity_runtime_sources} REFERENCES "${ENTERON_CSHARP_ASSEMBLY}" "${_enteron_standin}")
file(GLOB_RECURSE _enteron_unity_sample_sources CONFIGURE_DEPENDS "${_enteron_unity_dir}/Samples~/*.cs")
enteron_csharp_assembly(TARGET enteron_unity_samples OUTPUT "${_enteron_unity_samples}"
  SOURCES ${_enteron_unity_sample_sources}
  REFERENCES "${ENTERON_CSHARP_ASSEMBLY}" "${_enteron_standin}" "${_enteron_unity_runtime}")

if(NOT ENTERON_NUNIT_CONSOLE OR NOT ENTERON_NUNIT_FRAMEWORK)
  return()  # csharp_tests.cmake said why
endif()
file(GLOB _enteron_unity_test_sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_LIST_DIR}/*Tests.cs")
set(_enteron_unity_tests "${ENTERON_CSHARP_DIR}/Enteron.Unity.Tests.dll")
enteron_csharp_assembly(TARGET enteron_unity_tests OUTPUT "${_enteron_unity_tests}"
  SOURCES ${_enteron_unity_test_sources} "${PROJECT_SOURCE_DIR}/bindings/csharp/tests/TestSupport.cs"
  REFERENCES "${ENTERON_CSHARP_ASSEMBLY}" "${_enteron_standin}" "${_enteron_unity_runtime}" "${_enteron_unity_samples}"
             "${ENTERON_NUNIT_FRAMEWORK}")
add_dependencies(enteron_unity_tests enteron_unity_package)
foreach(source IN LISTS _enteron_unity_test_sources)
  get_filename_component(fixture "${source}" NAME_WE)
  enteron_nunit_fixture(NAME ${fixture} PREFIX unity ASSEMBLY "${_enteron_unity_tests}" NAMESPACE Enteron.Unity.Tests
    LABELS "csharp;unity" ENVIRONMENT ${ENTERON_CSHARP_TEST_ENVIRONMENT}
    "ENTERON_UNITY_PACKAGE=${ENTERON_UNITY_PACKAGE_DIR}" "ENTERON_UNITY_TARBALL=${ENTERON_UNITY_TARBALL}"
    "ENTERON_VERSION=${PROJECT_VERSION}")
endforeach()
