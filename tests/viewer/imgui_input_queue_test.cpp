// The viewer's ImGui input queue: key, character and key-chord events that arrive between two frames, as they do
// at a few frames per second, reach a text field with the meaning they had. Runs on an X display (CTest starts
// Xvfb); the events are handed to the queue directly, so the frames they fall into are exactly those given here.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <memory>
#include <string>
#include <vector>

#include "app/viewer/glfw_window.h"

namespace candela {
namespace {

class ImGuiInputQueue : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { window_ = std::make_unique<GlfwWindow>(320, 200, "candela input test"); }
  static void TearDownTestSuite() { window_.reset(); }

  void SetUp() override { layer_ = std::make_unique<ImGuiLayer>(window_->handle()); }
  void TearDown() override { layer_.reset(); }

  // One frame with a text field; returns the events the queue handed back.
  std::vector<WindowEvent> frame() {
    std::vector<WindowEvent> keys = layer_->beginFrame();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::Begin("input", nullptr, ImGuiWindowFlags_NoSavedSettings);
    if (focusNextFrame_) ImGui::SetKeyboardFocusHere();
    focusNextFrame_ = false;
    entered_ = ImGui::InputText("##text", &text_, ImGuiInputTextFlags_EnterReturnsTrue) || entered_;
    active_ = ImGui::IsItemActive();
    ImGui::End();
    layer_->render();
    return keys;
  }
  // The field takes the keyboard with "abc" in it, the cursor at its end and nothing selected.
  void typeIntoAFocusedField() {
    text_ = "abc";
    focusNextFrame_ = true;
    settle();  // focuses the field, which selects all of it
    tap(GLFW_KEY_END);
    settle();
    ASSERT_TRUE(active_);
    ASSERT_EQ(text_, "abc");
  }
  // Frames until every queued event has reached ImGui.
  void settle() {
    for (int i = 0; i < 16; ++i) frame();
  }
  void key(int key, int action, int mods = 0) { layer_->onKey(key, 0, action, mods); }
  void tap(int k) {
    key(k, GLFW_PRESS);
    key(k, GLFW_RELEASE);
  }
  // A printable key as GLFW reports it: the press, its character, the release.
  void type(char c) {
    const int k = c >= 'a' && c <= 'z' ? GLFW_KEY_A + (c - 'a') : GLFW_KEY_MINUS;
    key(k, GLFW_PRESS);
    layer_->onChar(static_cast<unsigned char>(c));
    key(k, GLFW_RELEASE);
  }

  static std::unique_ptr<GlfwWindow> window_;
  std::unique_ptr<ImGuiLayer> layer_;
  std::string text_;
  bool focusNextFrame_ = false;
  bool entered_ = false;
  bool active_ = false;
};
std::unique_ptr<GlfwWindow> ImGuiInputQueue::window_;

// The order xdotool sends `key ctrl+a BackSpace` in, with a frame starting after the Ctrl press: ImGui must still
// see Ctrl down when A goes down, although Ctrl's release arrived in the same batch.
TEST_F(ImGuiInputQueue, ChordWhoseModifierIsReleasedInTheSameBatchStillSelectsAll) {
  typeIntoAFocusedField();
  key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS);
  frame();
  key(GLFW_KEY_A, GLFW_PRESS, GLFW_MOD_CONTROL);
  key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE, GLFW_MOD_CONTROL);
  key(GLFW_KEY_A, GLFW_RELEASE);
  tap(GLFW_KEY_BACKSPACE);
  settle();
  EXPECT_EQ(text_, "");
}

TEST_F(ImGuiInputQueue, TypingAndBackspaceBetweenTwoFramesKeepTheirOrder) {
  typeIntoAFocusedField();
  type('x');
  tap(GLFW_KEY_BACKSPACE);
  tap(GLFW_KEY_BACKSPACE);
  type('y');
  type('-');
  type('z');
  settle();
  EXPECT_EQ(text_, "aby-z");
}

TEST_F(ImGuiInputQueue, AKeyTappedBetweenTwoFramesIsSeenDown) {
  typeIntoAFocusedField();
  tap(GLFW_KEY_ENTER);
  settle();
  EXPECT_TRUE(entered_);
  EXPECT_FALSE(active_);
}

// A key kept from ImGui comes back in order and ends its frame: what the owner does for it sees exactly the
// events before it.
TEST_F(ImGuiInputQueue, AKeptKeyEndsItsFrame) {
  layer_->keepFromImGui(GLFW_KEY_F12);
  typeIntoAFocusedField();
  type('x');
  tap(GLFW_KEY_F12);
  type('y');
  std::vector<WindowEvent> keys;
  for (int i = 0; i < 16 && (keys.empty() || keys.back().code != GLFW_KEY_F12); ++i) keys = frame();
  ASSERT_FALSE(keys.empty());
  EXPECT_EQ(keys.back().code, GLFW_KEY_F12);
  EXPECT_EQ(keys.back().action, GLFW_PRESS);
  EXPECT_EQ(text_, "abcx");
  settle();
  EXPECT_EQ(text_, "abcxy");
}

// The camera follows pointer moves and buttons from the same queue; moves before a click do not hold it back.
TEST_F(ImGuiInputQueue, PointerMovesComeBackInOrderWithTheClicks) {
  layer_->onCursorMove(10.0, 20.0);
  layer_->onMouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 0, 10.0, 20.0);
  layer_->onCursorMove(30.0, 40.0);
  layer_->onMouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_RELEASE, 0, 30.0, 40.0);
  const std::vector<WindowEvent> first = frame(), second = frame();
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].kind, WindowEvent::Kind::CursorMove);
  EXPECT_EQ(first[0].x, 10.0);
  EXPECT_EQ(first[1].kind, WindowEvent::Kind::MouseButton);
  EXPECT_EQ(first[1].action, GLFW_PRESS);
  ASSERT_EQ(second.size(), 2u);
  EXPECT_EQ(second[0].kind, WindowEvent::Kind::CursorMove);
  EXPECT_EQ(second[0].y, 40.0);
  EXPECT_EQ(second[1].kind, WindowEvent::Kind::MouseButton);
  EXPECT_EQ(second[1].action, GLFW_RELEASE);
}

}  // namespace
}  // namespace candela
