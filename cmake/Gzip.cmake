# cmake -DIN=file -DOUT=file.gz -P Gzip.cmake: gzip -9n (no name or time stamp in the header,
# so the output depends on the content only).
find_program(ZS_GZIP gzip REQUIRED)
execute_process(COMMAND ${ZS_GZIP} -9 -n -c ${IN} OUTPUT_FILE ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip ${IN} failed: ${rc}")
endif()
