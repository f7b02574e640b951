#pragma once
#include <string>

#include "app/viewer/gl.h"

namespace candela {

// The process's one GLFW window, with an OpenGL 3.3 core context current on this thread. Throws
// std::runtime_error with one sentence when there is no display or the display offers no such context.
class GlfwWindow {
 public:
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  std::string glRenderer() const;  // e.g. "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5"

 private:
  GLFWwindow* window_ = nullptr;
};

// Dear ImGui's context and its GLFW and OpenGL 3 backends for one window.
class ImGuiLayer {
 public:
  explicit ImGuiLayer(GLFWwindow* window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void beginFrame();
  void render();
};

}  // namespace candela
