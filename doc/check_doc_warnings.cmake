# Runs Doxygen on a copy of the Doxyfile that writes to OUTPUT_DIR, and fails
# when Doxygen warns (or fails).  Used by the test doc_builds_without_warnings.
#   cmake -DDOXYGEN=... -DDOXYFILE=... -DOUTPUT_DIR=... -DSOURCE_DIR=... -P check_doc_warnings.cmake

file(REMOVE_RECURSE "${OUTPUT_DIR}")
file(MAKE_DIRECTORY "${OUTPUT_DIR}")
set(log "${OUTPUT_DIR}/doxygen_warnings.log")
file(READ "${DOXYFILE}" config)
# Later assignments override earlier ones in a Doxyfile.
string(APPEND config "\nOUTPUT_DIRECTORY = \"${OUTPUT_DIR}\"\nWARN_LOGFILE = \"${log}\"\n")
file(WRITE "${OUTPUT_DIR}/Doxyfile" "${config}")

execute_process(COMMAND "${DOXYGEN}" "${OUTPUT_DIR}/Doxyfile"
                WORKING_DIRECTORY "${SOURCE_DIR}"
                RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "doxygen failed (exit ${status}):\n${out}\n${err}")
endif()
if(NOT EXISTS "${log}")
  message(FATAL_ERROR "doxygen wrote no warning log ${log}")
endif()
file(READ "${log}" warnings)
string(STRIP "${warnings}" warnings)
if(NOT warnings STREQUAL "")
  string(REGEX MATCHALL "warning:" count "${warnings}")
  list(LENGTH count n)
  message(FATAL_ERROR "the manual has ${n} Doxygen warning(s):\n${warnings}")
endif()
if(NOT EXISTS "${OUTPUT_DIR}/html/index.html")
  message(FATAL_ERROR "doxygen wrote no ${OUTPUT_DIR}/html/index.html")
endif()
message(STATUS "the manual builds without warnings")
