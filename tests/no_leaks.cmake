# Runs CMD (a |-separated command) in WORKDIR; fails on a non-zero exit or
# when PETSc's -malloc_dump reports unfreed memory (lines "[rank] N bytes ...").
string(REPLACE "|" ";" cmd "${CMD}")
execute_process(COMMAND ${cmd} WORKING_DIRECTORY ${WORKDIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "command failed with ${rc}")
endif()
if("${out}${err}" MATCHES "\\[ *[0-9]+\\] *[0-9]+ bytes")
  message(FATAL_ERROR "unfreed PETSc memory reported by -malloc_dump")
endif()
