# Run EXE with ARGS (a ;-list); check the exit status CODE, that standard
# output matches STDOUT and standard error STDERR (regexes, if given), and
# that no Fortran runtime error or backtrace reached the user.
execute_process(COMMAND ${EXE} ${ARGS}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc STREQUAL "${CODE}")
  message(FATAL_ERROR "exit status ${rc}, expected ${CODE}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(STDOUT AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match \"${STDOUT}\":\n${out}")
endif()
if(STDERR AND NOT err MATCHES "${STDERR}")
  message(FATAL_ERROR "stderr does not match \"${STDERR}\":\n${err}")
endif()
foreach(bad "Fortran runtime" "Backtrace" "Error termination" "ERROR STOP" "Segmentation" "Program received")
  if(err MATCHES "${bad}" OR out MATCHES "${bad}")
    message(FATAL_ERROR "\"${bad}\" reached the user:\n${err}")
  endif()
endforeach()
