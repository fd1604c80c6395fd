# cmake -DDOXYGEN=... -DDOXYFILE=... -DOUTPUT_DIR=... [-DFIG_DIR=...] -P run_doxygen.cmake
#
# Builds the HTML manual and fails when Doxygen fails or writes any warning to its log.

foreach(var DOXYGEN DOXYFILE OUTPUT_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "run_doxygen.cmake: ${var} is not set")
  endif()
endforeach()

set(log "${OUTPUT_DIR}/doxygen_warnings.log")
file(REMOVE_RECURSE "${OUTPUT_DIR}/html")
file(REMOVE "${log}")

execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}"
                WORKING_DIRECTORY "${OUTPUT_DIR}"
                RESULT_VARIABLE status
                OUTPUT_VARIABLE output
                ERROR_VARIABLE errors)

set(warnings "")
if(EXISTS "${log}")
  file(READ "${log}" warnings)
endif()
string(STRIP "${warnings}" warnings)
string(STRIP "${errors}" errors)

if(NOT status EQUAL 0 OR NOT warnings STREQUAL "" OR NOT errors STREQUAL "")
  message(FATAL_ERROR "Doxygen failed (exit status ${status}); warnings (${log}):\n${warnings}\n${errors}")
endif()
if(NOT EXISTS "${OUTPUT_DIR}/html/index.html")
  message(FATAL_ERROR "Doxygen wrote no ${OUTPUT_DIR}/html/index.html")
endif()
# The manual's pictures (doc/Surface_mesh_parameterization/fig, made by
# scripts/make_figures.sh): the manual links them as fig/NAME, relative to the page.
if(FIG_DIR AND IS_DIRECTORY "${FIG_DIR}")
  file(COPY "${FIG_DIR}" DESTINATION "${OUTPUT_DIR}/html")
endif()
message(STATUS "Doxygen: ${OUTPUT_DIR}/html/index.html, no warnings")
