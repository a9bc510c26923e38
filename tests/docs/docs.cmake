# SPDX-License-Identifier: Apache-2.0
# ---- the documentation says what the code does (label "docs"; tests/docs/check_docs.py) -----
#   docs.header          every exported function has a doc comment
#   docs.json_keys       every key of the scene's table (lib/scene/scene_table.h, which the
#                        JSON loader reads by) is in docs/scene-json.md, printed by
#                        enteron_scene_table
#   docs.links           every relative link of README.md and docs/*.md resolves
#   docs.doc_paths       every docs/*.md that a header, a source or a document names exists
#   docs.readme_example  the C program of README.md is examples/minimal.c
#   docs.example_outputs every output examples/README.md quotes is printed by a run of its
#                        example (registered in examples/CMakeLists.txt, which knows the
#                        examples and the Python binding's environment)
#   docs.unit_tests      every unit of lib/ has its tests/unit/<layer>/test_<unit>.cpp or a
#                        row in tests/unit/README.md saying why (tests/docs/check_unit_tests.py)
#   docs.cpp_api         every exported C function has its counterpart in enteron.hpp, or a
#                        reason in docs/cpp.md, and docs/cpp.md's table names it
#                        (tests/docs/check_cpp_api.py)
#   docs.spdx            every source file starts with its SPDX licence line
#                        (tests/docs/check_spdx.py; --fix adds it)
#   docs.unity_names     no two files of a target define functions of one name that a unity
#                        build would merge into one overload set (tests/docs/check_unity_names.py)
# Python 3's standard library only.
if(EXISTS /usr/bin/python3)
  set(_enteron_docs_python /usr/bin/python3)
else()
  find_program(_enteron_docs_python python3)
endif()
if(NOT _enteron_docs_python)
  message(WARNING "no python3: the documentation tests (label docs) are not registered")
  return()
endif()
set(_enteron_check_docs ${_enteron_docs_python} ${CMAKE_CURRENT_LIST_DIR}/check_docs.py --root ${PROJECT_SOURCE_DIR})
set(ENTERON_CHECK_DOCS ${_enteron_check_docs} CACHE INTERNAL "the documentation checks' command (examples/CMakeLists.txt)")
foreach(check IN ITEMS header links doc_paths readme_example)
  add_test(NAME docs.${check} COMMAND ${_enteron_check_docs} ${check})
endforeach()
add_test(NAME docs.unit_tests COMMAND ${_enteron_docs_python} ${CMAKE_CURRENT_LIST_DIR}/check_unit_tests.py
         --root ${PROJECT_SOURCE_DIR})
add_test(NAME docs.cpp_api COMMAND ${_enteron_docs_python} ${CMAKE_CURRENT_LIST_DIR}/check_cpp_api.py
         --root ${PROJECT_SOURCE_DIR})
add_test(NAME docs.spdx COMMAND ${_enteron_docs_python} ${CMAKE_CURRENT_LIST_DIR}/check_spdx.py
         --root ${PROJECT_SOURCE_DIR})
add_test(NAME docs.unity_names COMMAND ${_enteron_docs_python} ${CMAKE_CURRENT_LIST_DIR}/check_unity_names.py
         --root ${PROJECT_SOURCE_DIR})
add_executable(enteron_scene_table ${CMAKE_CURRENT_LIST_DIR}/print_scene_table.cpp)
target_link_libraries(enteron_scene_table PRIVATE enteron_core nlohmann_json::nlohmann_json)
target_compile_options(enteron_scene_table PRIVATE ${ENTERON_WARNINGS})
add_test(NAME docs.json_keys COMMAND ${_enteron_check_docs} --table $<TARGET_FILE:enteron_scene_table> json_keys)
set(_enteron_docs_tests docs.header docs.links docs.doc_paths docs.readme_example docs.unit_tests docs.cpp_api docs.spdx
    docs.json_keys docs.unity_names)
set_tests_properties(${_enteron_docs_tests} PROPERTIES LABELS docs TIMEOUT 60
  ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
