# One example test: render SCENE small with a depth map, then check that the PNG exists and
# that enough depth pixels are finite (the picture is not blank).
# cmake -DZEROSET=... -DCHECK=... -DSCENE=... -DOUT=<prefix> -P run_example.cmake
foreach(var ZEROSET CHECK SCENE OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_example.cmake: ${var} is not set")
  endif()
endforeach()
file(REMOVE "${OUT}.png" "${OUT}.pfm")
execute_process(
  COMMAND "${ZEROSET}" render "${SCENE}" -o "${OUT}.png" --depth "${OUT}.pfm" --size 96x72
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "zeroset render ${SCENE} failed (${rc})")
endif()
if(NOT EXISTS "${OUT}.png")
  message(FATAL_ERROR "zeroset render wrote no ${OUT}.png")
endif()
file(READ "${OUT}.png" signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "${OUT}.png is not a PNG")
endif()
execute_process(COMMAND "${CHECK}" "${OUT}.pfm" 0.02 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SCENE}: the picture is blank or broken")
endif()
