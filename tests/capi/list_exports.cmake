# SPDX-License-Identifier: Apache-2.0
# Writes the functions libenteron exports, one per line, for BadInputs.EveryExportedFunctionHasRows.
#   cmake -DNM=nm -DLIBRARY=libenteron.so -DOUTPUT=enteron_exports.txt -P list_exports.cmake
execute_process(COMMAND ${NM} -D --defined-only ${LIBRARY} OUTPUT_VARIABLE symbols RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${NM} -D --defined-only ${LIBRARY} failed: ${result}")
endif()
string(REGEX MATCHALL " T ent_[A-Za-z0-9_]+" functions "${symbols}")
list(TRANSFORM functions REPLACE " T " "")
list(SORT functions)
list(JOIN functions "\n" text)
file(WRITE ${OUTPUT} "${text}\n")
