#pragma once
#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

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

// An input event as the window's owner gets it back from ImGuiLayer's queue.
struct WindowEvent {
  enum class Kind { Key, MouseButton, CursorMove, Wheel };
  Kind kind = Kind::Key;
  int code = 0;             // GLFW's key or mouse button
  int action = 0;           // GLFW_PRESS, GLFW_RELEASE or GLFW_REPEAT
  double x = 0.0, y = 0.0;  // where the pointer was
  double wheel = 0.0;       // vertical wheel steps
};

// Dear ImGui's context and its GLFW and OpenGL 3 backends for one window, with one queue for the window's input.
// It installs no GLFW callbacks: the window's owner passes every event on through the on...() functions, and
// takes its own share back from beginFrame in the same order and frame as ImGui takes them.
class ImGuiLayer {
 public:
  explicit ImGuiLayer(GLFWwindow* window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Hands ImGui the input events that fit in one frame (see InputEvent) and starts the frame. Returns that
  // frame's events other than typed characters, in order, those kept from ImGui included. io.WantCaptureKeyboard
  // and io.WantCaptureMouse now say whether ImGui takes them: ImGui decided after every earlier event, with the
  // pointer where this frame's mouse button event, if any, found it.
  std::vector<WindowEvent> beginFrame();
  void render();

  // Events of `key` never reach ImGui; they still wait in the queue with the others, and like every key press a
  // press of it is the last event of its frame, so that what the owner does for it follows exactly the events
  // before it.
  void keepFromImGui(int key) { keptKeys_.push_back(key); }

  void onKey(int key, int scancode, int action, int mods);
  void onChar(unsigned int codepoint);
  // (x, y): where the pointer was, as the cursor events before this one said.
  void onMouseButton(int button, int action, int mods, double x, double y);
  void onCursorMove(double x, double y);
  void onScroll(double dx, double dy, double x, double y);
  void onFocus(int focused);
  void onCursorEnter(int entered);

 private:
  // ImGui 1.86 reads the keyboard as one up/down state per key and frame, handles a frame's typed characters
  // before its key presses and a click before either, and takes the pointer's position when the frame starts, not
  // when a button went down. At a few frames per second a key pressed and released between two frames would never
  // be seen down, a key tapped twice would be seen pressed once, Ctrl+A whose Ctrl went up in the frame that A
  // went down would be a plain A, Backspace before typing would erase what was typed after it, text typed right
  // after a click on a field would be lost, and a click would land wherever the pointer had moved to since. So
  // these events wait in a queue, and each frame takes them in order only while the state ImGui reads stays true
  // to them: a key press ends the frame, so that ImGui reads the keyboard as it was right after that press (a
  // chord's modifier went down in an earlier frame and is still down); a key released in a frame is not pressed
  // again in it; a modifier press does not follow typing in its frame (a held Ctrl makes ImGui drop the frame's
  // characters); and a mouse button event follows no key, character or wheel event in its frame and ends it,
  // with the pointer where it was at the time. Pointer moves only go back to the owner (ImGui reads the pointer
  // itself) and end no frame.
  enum class EventKind { Key, Char, MouseButton, CursorMove, Wheel };
  struct InputEvent {
    EventKind kind;
    unsigned int codepoint;
    int key, scancode, action, mods;  // `key` is the button for MouseButton
    double x, y;                      // the pointer
    double dx, dy;                    // wheel steps
  };
  // Delivers one frame's events and adds those for the owner to `events`; returns the pointer position of the
  // mouse button event it delivered, if any.
  std::optional<ImVec2> deliverOneFramesEvents(std::vector<WindowEvent>& events);
  bool kept(int key) const;

  GLFWwindow* window_;
  std::vector<InputEvent> queue_;
  std::vector<int> keptKeys_;
};

}  // namespace candela
