# Dear ImGui from Debian's libimgui-dev 1.86: the core library from the package, the GLFW and
# OpenGL3 backends compiled here from the sources the package ships (loaded through glad).
# Exposes glint::imgui. Nothing of ImGui is copied into the repository.
find_package(PkgConfig REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
set(GLINT_IMGUI_BACKENDS "/usr/share/doc/libimgui-dev/examples/backends")
foreach(backend_source imgui_impl_glfw.cpp imgui_impl_opengl3.cpp)
  if(NOT EXISTS "${GLINT_IMGUI_BACKENDS}/${backend_source}")
    message(FATAL_ERROR "${GLINT_IMGUI_BACKENDS}/${backend_source} is missing: install libimgui-dev")
  endif()
endforeach()
add_library(glint_imgui STATIC
  "${GLINT_IMGUI_BACKENDS}/imgui_impl_glfw.cpp"
  "${GLINT_IMGUI_BACKENDS}/imgui_impl_opengl3.cpp")
# The OpenGL3 backend takes its GL declarations from glad instead of its own gl3w loader.
target_compile_definitions(glint_imgui PUBLIC IMGUI_IMPL_OPENGL_LOADER_CUSTOM GLFW_INCLUDE_NONE)
target_compile_options(glint_imgui PRIVATE -include glad/gl.h -w)
target_include_directories(glint_imgui SYSTEM PUBLIC /usr/include/imgui /usr/include/imgui/backends)
find_package(glfw3 REQUIRED)
target_link_libraries(glint_imgui PUBLIC PkgConfig::IMGUI glint::glad glfw)
# libimgui.a uses stb; pkg-config lists it only in the static libs.
target_link_libraries(glint_imgui PUBLIC stb)
add_library(glint::imgui ALIAS glint_imgui)
