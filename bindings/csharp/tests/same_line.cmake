# SPDX-License-Identifier: Apache-2.0
# ctest csharp.example_minimal: the C# minimal example prints exactly the line of the C one.
#   cmake -DC_PROGRAM=enteron_minimal -DMONO=mono -DCSHARP_PROGRAM=Minimal.exe -P same_line.cmake
execute_process(COMMAND ${C_PROGRAM} OUTPUT_VARIABLE c_line RESULT_VARIABLE c_status OUTPUT_STRIP_TRAILING_WHITESPACE)
execute_process(COMMAND ${MONO} --debug ${CSHARP_PROGRAM} OUTPUT_VARIABLE csharp_line ERROR_VARIABLE csharp_errors
                RESULT_VARIABLE csharp_status OUTPUT_STRIP_TRAILING_WHITESPACE)
message(STATUS "C:  ${c_line}")
message(STATUS "C#: ${csharp_line}")
if(NOT c_status EQUAL 0 OR NOT csharp_status EQUAL 0)
  message(FATAL_ERROR "exit status: C ${c_status}, C# ${csharp_status} ${csharp_errors}")
endif()
if(NOT c_line MATCHES "^minimal: t = 1\\.000 s, 100 axis points")
  message(FATAL_ERROR "the C example printed an unexpected line")
endif()
if(NOT csharp_line STREQUAL c_line)
  message(FATAL_ERROR "the C# example's line differs from the C example's")
endif()
message(STATUS "the same line")
