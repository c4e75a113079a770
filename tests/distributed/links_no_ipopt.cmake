# Fails when PROGRAM's dynamic section needs IPOPT or the sequential MUMPS (src/CMakeLists.txt: they clash
# with MPI and PETSc in one process), or when it cannot be read.
find_program(READELF readelf REQUIRED)
execute_process(COMMAND ${READELF} -d ${PROGRAM} OUTPUT_VARIABLE dynamic RESULT_VARIABLE code)
if(NOT code EQUAL 0 OR NOT dynamic MATCHES "NEEDED")
  message(FATAL_ERROR "cannot read the dynamic section of ${PROGRAM}")
endif()
if(dynamic MATCHES "libipopt|mumps_seq|libmpiseq")
  message(FATAL_ERROR "${PROGRAM} needs IPOPT or the sequential MUMPS:\n${dynamic}")
endif()
if(NOT dynamic MATCHES "libpetsc")
  message(FATAL_ERROR "${PROGRAM} does not need PETSc: not the distributed program")
endif()
