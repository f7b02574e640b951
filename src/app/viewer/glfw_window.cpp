#include "app/viewer/glfw_window.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace candela {

namespace {

std::string lastGlfwError;

void rememberGlfwError(int, const char* description) { lastGlfwError = description ? description : ""; }

std::string displayName() {
  const char* display = std::getenv("DISPLAY");
  return display ? display : "";
}

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
  glfwSetErrorCallback(rememberGlfwError);
  if (displayName().empty())
    throw std::runtime_error(
        "cannot open a window: no display (DISPLAY is not set); run candela view on a desktop or under Xvfb, "
        "or use candela render to write images without a window");
  if (!glfwInit())
    throw std::runtime_error("cannot open a window on display '" + displayName() + "': " + lastGlfwError);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    std::string why = lastGlfwError;
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 core context on display '" + displayName() + "': " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // the renderer, not the display's refresh, sets the pace
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::string GlfwWindow::glRenderer() const {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "unknown renderer") + ", OpenGL " + (version ? version : "?");
}

ImGuiLayer::ImGuiLayer(GLFWwindow* window) : window_(window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; nothing to remember between runs
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, /*install_callbacks=*/false);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  // A window that opens under the pointer gets no enter event, and without a window manager no focus either;
  // ImGui would then not see the pointer until it left and came back.
  if (glfwGetWindowAttrib(window, GLFW_HOVERED)) ImGui_ImplGlfw_CursorEnterCallback(window, GLFW_TRUE);
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

std::vector<WindowEvent> ImGuiLayer::beginFrame() {
  std::vector<WindowEvent> events;
  std::optional<ImVec2> pointerAtClick = deliverOneFramesEvents(events);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (pointerAtClick) ImGui::GetIO().MousePos = *pointerAtClick;
  ImGui::NewFrame();
  return events;
}

namespace {

bool isModifier(int key) { return key >= GLFW_KEY_LEFT_SHIFT && key <= GLFW_KEY_RIGHT_SUPER; }

}  // namespace

bool ImGuiLayer::kept(int key) const { return std::find(keptKeys_.begin(), keptKeys_.end(), key) != keptKeys_.end(); }

std::optional<ImVec2> ImGuiLayer::deliverOneFramesEvents(std::vector<WindowEvent>& events) {
  std::optional<ImVec2> pointer;
  bool typed = false;
  bool imguiTookInput = false;  // a key, character or wheel event
  std::vector<int> released;
  size_t next = 0;
  for (; next < queue_.size(); ++next) {
    const InputEvent& e = queue_[next];
    if (e.kind == EventKind::CursorMove) {
      events.push_back({WindowEvent::Kind::CursorMove, 0, 0, e.x, e.y, 0.0});
      continue;
    }
    if (e.kind == EventKind::MouseButton) {
      if (imguiTookInput) break;
      ImGui_ImplGlfw_MouseButtonCallback(window_, e.key, e.action, e.mods);
      events.push_back({WindowEvent::Kind::MouseButton, e.key, e.action, e.x, e.y, 0.0});
      pointer = ImVec2(float(e.x), float(e.y));
      ++next;
      break;
    }
    if (e.kind == EventKind::Wheel) {
      ImGui_ImplGlfw_ScrollCallback(window_, e.dx, e.dy);
      events.push_back({WindowEvent::Kind::Wheel, 0, 0, e.x, e.y, e.dy});
      imguiTookInput = true;
      continue;
    }
    if (e.kind == EventKind::Char) {
      ImGui_ImplGlfw_CharCallback(window_, e.codepoint);
      typed = imguiTookInput = true;
      continue;
    }
    const bool press = e.action == GLFW_PRESS;
    if (press && typed && isModifier(e.key)) break;
    if (press && std::find(released.begin(), released.end(), e.key) != released.end()) break;
    if (!kept(e.key)) {
      ImGui_ImplGlfw_KeyCallback(window_, e.key, e.scancode, e.action, e.mods);
      imguiTookInput = true;
    }
    events.push_back({WindowEvent::Kind::Key, e.key, e.action, 0.0, 0.0, 0.0});
    if (press) {
      ++next;
      break;
    }
    if (e.action == GLFW_RELEASE) released.push_back(e.key);
  }
  queue_.erase(queue_.begin(), queue_.begin() + ptrdiff_t(next));
  return pointer;
}

void ImGuiLayer::onKey(int key, int scancode, int action, int mods) {
  queue_.push_back({EventKind::Key, 0, key, scancode, action, mods, 0.0, 0.0, 0.0, 0.0});
}

void ImGuiLayer::onChar(unsigned int codepoint) {
  queue_.push_back({EventKind::Char, codepoint, 0, 0, 0, 0, 0.0, 0.0, 0.0, 0.0});
}

void ImGuiLayer::onMouseButton(int button, int action, int mods, double x, double y) {
  queue_.push_back({EventKind::MouseButton, 0, button, 0, action, mods, x, y, 0.0, 0.0});
}

void ImGuiLayer::onCursorMove(double x, double y) {
  queue_.push_back({EventKind::CursorMove, 0, 0, 0, 0, 0, x, y, 0.0, 0.0});
}

void ImGuiLayer::onScroll(double dx, double dy, double x, double y) {
  queue_.push_back({EventKind::Wheel, 0, 0, 0, 0, 0, x, y, dx, dy});
}

void ImGuiLayer::onFocus(int focused) { ImGui_ImplGlfw_WindowFocusCallback(window_, focused); }
void ImGuiLayer::onCursorEnter(int entered) { ImGui_ImplGlfw_CursorEnterCallback(window_, entered); }

void ImGuiLayer::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace candela
