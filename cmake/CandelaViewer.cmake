# The interactive viewer (candela view): GLFW, OpenGL 3.3 core and Dear ImGui, all from the system's packages.
# It is built when they are all found, unless CANDELA_BUILD_VIEWER is OFF; CANDELA_VIEWER_ENABLED says which.
option(CANDELA_BUILD_VIEWER "Build the interactive viewer when GLFW, OpenGL and Dear ImGui are found" ON)
set(CANDELA_VIEWER_ENABLED OFF)
if(NOT CANDELA_BUILD_VIEWER)
  message(STATUS "viewer: off (CANDELA_BUILD_VIEWER=OFF)")
  return()
endif()

set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL QUIET)
find_package(glfw3 3.3 QUIET CONFIG)
pkg_check_modules(IMGUI QUIET IMPORTED_TARGET imgui)
if(NOT OpenGL_FOUND OR NOT glfw3_FOUND OR NOT IMGUI_FOUND)
  message(STATUS "viewer: off (needs OpenGL, GLFW 3.3 and Dear ImGui: libgl-dev libglfw3-dev libimgui-dev)")
  return()
endif()

# Debian's libimgui.a already holds the GLFW and OpenGL 3 backends; where a distribution ships only their
# sources (in libimgui-dev's examples folder), compile them from there.
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_INCLUDES ${IMGUI_INCLUDE_DIRS})
set(CMAKE_REQUIRED_LIBRARIES ${IMGUI_LINK_LIBRARIES} glfw OpenGL::GL ${CMAKE_DL_LIBS})
check_cxx_source_compiles([[
  #include <backends/imgui_impl_glfw.h>
  #include <backends/imgui_impl_opengl3.h>
  int main() { return ImGui_ImplGlfw_InitForOpenGL(nullptr, true) && ImGui_ImplOpenGL3_Init(nullptr); }
]] CANDELA_IMGUI_LIBRARY_HAS_BACKENDS)
unset(CMAKE_REQUIRED_INCLUDES)
unset(CMAKE_REQUIRED_LIBRARIES)

add_library(candela_imgui INTERFACE)
target_link_libraries(candela_imgui INTERFACE PkgConfig::IMGUI glfw OpenGL::GL ${CMAKE_DL_LIBS})
if(NOT CANDELA_IMGUI_LIBRARY_HAS_BACKENDS)
  find_path(CANDELA_IMGUI_BACKEND_SOURCES imgui_impl_glfw.cpp
            PATHS /usr/share/doc/libimgui-dev/examples/backends /usr/share/imgui/backends NO_DEFAULT_PATH)
  if(NOT CANDELA_IMGUI_BACKEND_SOURCES)
    message(STATUS "viewer: off (Dear ImGui's GLFW and OpenGL 3 backends are neither in its library nor found as sources)")
    return()
  endif()
  add_library(candela_imgui_backends STATIC ${CANDELA_IMGUI_BACKEND_SOURCES}/imgui_impl_glfw.cpp
                                            ${CANDELA_IMGUI_BACKEND_SOURCES}/imgui_impl_opengl3.cpp)
  target_include_directories(candela_imgui_backends PUBLIC ${IMGUI_INCLUDEDIR}/backends)
  target_link_libraries(candela_imgui_backends PUBLIC PkgConfig::IMGUI glfw OpenGL::GL ${CMAKE_DL_LIBS})
  target_link_libraries(candela_imgui INTERFACE candela_imgui_backends)
endif()

set(CANDELA_VIEWER_ENABLED ON)
message(STATUS "viewer: on (GLFW ${glfw3_VERSION}, Dear ImGui ${IMGUI_VERSION})")
