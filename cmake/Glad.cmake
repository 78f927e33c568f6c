# A glad 2 GL loader generated at BUILD time by Debian's python3-glad (toolchain.md):
# libOSMesa exports its own gl* symbols, so in one binary with libOpenGL the link order
# decides which stubs win. Loading every entry point through the context's own
# get-proc-address after each make-current (eglGetProcAddress / OSMesaGetProcAddress /
# glfwGetProcAddress) makes all three backends work together. The generated files live in
# the build tree only; never commit them.
#
# Puts out: static library zs_glad (include <glad/gl.h>).
if(TARGET zs_glad)
  return()
endif()

set(ZS_GLAD_PYTHON /usr/bin/python3 CACHE FILEPATH
    "Python that can import glad (pyenv's python3 cannot see Debian's python3-glad)")
set(_zs_glad_dir ${CMAKE_BINARY_DIR}/generated/glad)

add_custom_command(
  OUTPUT ${_zs_glad_dir}/src/gl.c ${_zs_glad_dir}/include/glad/gl.h
         ${_zs_glad_dir}/include/KHR/khrplatform.h
  COMMAND ${ZS_GLAD_PYTHON} -m glad --quiet --reproducible --api gl:core=4.5
          --extensions "" --out-path ${_zs_glad_dir} c
  COMMENT "Generating the glad GL 4.5 core loader"
  VERBATIM)

add_library(zs_glad STATIC ${_zs_glad_dir}/src/gl.c)
target_include_directories(zs_glad SYSTEM PUBLIC ${_zs_glad_dir}/include)
set_target_properties(zs_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(zs_glad PUBLIC ${CMAKE_DL_LIBS})
