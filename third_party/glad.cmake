# Generates the OpenGL 4.1 core function-pointer loader with Debian's python3-glad at configure
# time, into the build tree, and exposes it as the static library glint::glad.
# It does not create contexts or link libGL: platforms hand it a get-proc-address function.
set(GLINT_GLAD_DIR "${CMAKE_BINARY_DIR}/generated/glad")
set(GLINT_SYSTEM_PYTHON "/usr/bin/python3" CACHE FILEPATH "Python that has Debian's python3-glad")
if(NOT EXISTS "${GLINT_GLAD_DIR}/src/gl.c")
  message(STATUS "Generating the GL 4.1 core loader with glad")
  execute_process(
    COMMAND "${GLINT_SYSTEM_PYTHON}" -m glad --api gl:core=4.1 --out-path "${GLINT_GLAD_DIR}"
            --reproducible --quiet c
    RESULT_VARIABLE glad_result
    OUTPUT_VARIABLE glad_output ERROR_VARIABLE glad_output)
  if(NOT glad_result EQUAL 0)
    message(FATAL_ERROR "glad failed (is python3-glad installed? run third_party/install-deps.sh):\n${glad_output}")
  endif()
endif()
add_library(glint_glad STATIC "${GLINT_GLAD_DIR}/src/gl.c")
target_include_directories(glint_glad SYSTEM PUBLIC "${GLINT_GLAD_DIR}/include")
set_target_properties(glint_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
add_library(glint::glad ALIAS glint_glad)
