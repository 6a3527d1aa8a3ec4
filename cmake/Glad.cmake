# The GL loader is generated at build time by glad2 (Debian's python3-glad) from the Khronos
# XML it ships, so GL entry points are resolved through whichever context backend is current
# (OSMesaGetProcAddress or eglGetProcAddress): one loader for both.
set(LPVLAB_GLAD_DIR "${CMAKE_BINARY_DIR}/glad")
set(LPVLAB_GL_EXTENSIONS "GL_ARB_gl_spirv,GL_ARB_spirv_extensions,GL_NV_shader_atomic_float")
add_custom_command(
  OUTPUT "${LPVLAB_GLAD_DIR}/src/gl.c" "${LPVLAB_GLAD_DIR}/include/glad/gl.h"
  COMMAND /usr/bin/python3 -m glad --quiet --reproducible --api gl:core=4.5
          --extensions ${LPVLAB_GL_EXTENSIONS} --out-path "${LPVLAB_GLAD_DIR}" c
  COMMENT "Generating the GL 4.5 core loader with glad"
  VERBATIM)
add_library(lpvlab_glad STATIC "${LPVLAB_GLAD_DIR}/src/gl.c")
target_include_directories(lpvlab_glad SYSTEM PUBLIC "$<BUILD_INTERFACE:${LPVLAB_GLAD_DIR}/include>"
                                                     "$<INSTALL_INTERFACE:include/lpvlab>")
set_target_properties(lpvlab_glad PROPERTIES EXPORT_NAME glad)
set_target_properties(lpvlab_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
