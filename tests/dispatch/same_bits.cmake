# SPDX-License-Identifier: Apache-2.0
# ctest dispatch.same_bits: runs PROGRAM on this build's library and, through
# LD_LIBRARY_PATH, on the baseline-only build in BASELINE; the hashes must be equal.
# Without a library in BASELINE the loader would quietly take this build's again.
if(NOT EXISTS "${BASELINE}/libenteron.so.0")
  message(FATAL_ERROR "no baseline library: ${BASELINE}/libenteron.so.0 does not exist")
endif()
foreach(which this baseline)
  if(which STREQUAL "this")
    execute_process(COMMAND "${PROGRAM}" OUTPUT_VARIABLE out_${which} RESULT_VARIABLE rc)
  else()
    execute_process(COMMAND ${CMAKE_COMMAND} -E env "LD_LIBRARY_PATH=${BASELINE}" "${PROGRAM}"
                    OUTPUT_VARIABLE out_${which} RESULT_VARIABLE rc)
  endif()
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the trajectory on the ${which} library failed (exit ${rc})")
  endif()
  string(STRIP "${out_${which}}" out_${which})
endforeach()
message(STATUS "trajectory hash: this build ${out_this}, baseline ${out_baseline}")
if(NOT out_this STREQUAL out_baseline)
  message(FATAL_ERROR "the CPU-dispatched kernels changed the trajectory: ${out_this} != ${out_baseline}")
endif()
