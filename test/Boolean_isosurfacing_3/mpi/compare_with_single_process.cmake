# Runs a tool once in one process and once under mpirun with --distributed,
# and fails unless the two output files are byte-identical.
#   -DSINGLE="tool~arg~..."   the single-process command (~ separates words: expressions use |)
#   -DDISTRIBUTED="tool~arg~..." the distributed command, without mpirun
#   -DMPIEXEC=... -DNP=K -DMPIEXEC_FLAGS="flag~flag"
#   -DSINGLE_OUTPUT=file -DDISTRIBUTED_OUTPUT=file
#   -DPREPARE="cmd~arg~..." optional, run first (makes the input)
foreach(var SINGLE DISTRIBUTED PREPARE MPIEXEC_FLAGS)
  string(REPLACE "~" ";" ${var} "${${var}}")
endforeach()
file(REMOVE "${SINGLE_OUTPUT}" "${DISTRIBUTED_OUTPUT}")
if(PREPARE)
  execute_process(COMMAND ${PREPARE} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "preparing the input failed (${status})")
  endif()
endif()
execute_process(COMMAND ${SINGLE} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the single-process run failed (${status}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${MPIEXEC} -np ${NP} ${MPIEXEC_FLAGS} ${DISTRIBUTED} RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
message("${out}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the distributed run on ${NP} ranks failed (${status}):\n${err}")
endif()
file(SIZE "${SINGLE_OUTPUT}" single_size)
file(SIZE "${DISTRIBUTED_OUTPUT}" distributed_size)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${SINGLE_OUTPUT}" "${DISTRIBUTED_OUTPUT}" RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "${DISTRIBUTED_OUTPUT} (${distributed_size} bytes, ${NP} ranks) differs from the "
                      "single-process ${SINGLE_OUTPUT} (${single_size} bytes)")
endif()
if(single_size LESS 1000)
  message(FATAL_ERROR "${SINGLE_OUTPUT} has only ${single_size} bytes: the test case is degenerate")
endif()
message("identical: ${single_size} bytes on ${NP} ranks")
