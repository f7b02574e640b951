#include "app/viewer/viewer.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "app/interactive/interactive_renderer.h"
#include "app/interactive/viewer_files.h"
#include "app/viewer/glfw_window.h"
#include "app/viewer/image_display.h"
#include "app/viewer/image_transfer.h"
#include "app/viewer/viewer_panel.h"
#include "app/viewer/window_capture.h"

namespace candela {

namespace {

constexpr int kPanelWidth = 380;
constexpr double kTimingSmoothing = 0.1;

// candela view: the interactive renderer's frames in a window, beside a panel of its controls.
class Viewer : private FrontEnd {
 public:
  explicit Viewer(const ViewerOptions& options);
  int run();

 private:
  static Viewer& of(GLFWwindow* window) { return *static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }
  void installCallbacks();
  bool cursorOverImage(double x) const;
  void handleInput(const std::vector<WindowEvent>& events);
  void handleMouseButton(const WindowEvent& e);
  void handleKey(const WindowEvent& e);
  FlyKeys heldFlyKeys() const;

  // FrontEnd
  FlyKeys takeInput() override;
  void present(FrameImages& frame) override;
  void report(const std::string& message, bool isError) override;

  void sceneShown();
  // The backend's name and device, and how its image reaches the screen: again after the session's handover.
  void backendShown();
  void frame(double now, double seconds);
  void updateStatus(double seconds);
  void handle(const PanelRequests& requests);
  void writeState();
  void writeExitFiles();

  ViewerOptions options_;
  GlfwWindow window_;
  ImGuiLayer imgui_;
  ImageDisplay display_;
  InteractiveRenderer renderer_;
  std::optional<ImageTransfer> transfer_;
  uint64_t transferBackendChanges_ = 0;  // the session's backendChanges() that transfer_ was chosen for
  PanelStatus status_;
  FlyKeys flyKeys_;  // held, as the events taken from the input queue so far say
  FramePlan lastPlan_;
  bool stateRequested_ = false;
  double pointerX_ = 0.0, pointerY_ = 0.0;  // as of the last cursor event GLFW reported
  Vec2 openSceneField_;
  bool openSceneFieldActive_ = false;
  int framebufferWidth_ = 0;
  int framebufferHeight_ = 0;
};

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      window_(int(options.interactive.width) + kPanelWidth, int(options.interactive.height), "candela"),
      imgui_(window_.handle()),
      renderer_(options.interactive) {
  std::fprintf(stderr, "window: %s\n", window_.glRenderer().c_str());
  sceneShown();
  backendShown();
  glfwSetWindowSizeLimits(window_.handle(), kPanelWidth + int(kMinImageSide), int(kMinImageSide), GLFW_DONT_CARE,
                          GLFW_DONT_CARE);
  glfwGetCursorPos(window_.handle(), &pointerX_, &pointerY_);
  imgui_.keepFromImGui(GLFW_KEY_F12);  // text fields have no use for it
  installCallbacks();
}

void Viewer::installCallbacks() {
  // Input waits in ImGui's queue; the viewer takes its share from there (handleInput), in the same order and frame
  // as ImGui takes its own, so that what ImGui wants (a click on the panel, a key typed into a text field) never
  // also moves the camera.
  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  // Where the pointer was at a click or a wheel step is where the cursor events before it had taken it.
  glfwSetCursorPosCallback(w, [](GLFWwindow* window, double x, double y) {
    Viewer& v = of(window);
    v.pointerX_ = x;
    v.pointerY_ = y;
    v.imgui_.onCursorMove(x, y);
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* window, int button, int action, int mods) {
    Viewer& v = of(window);
    v.imgui_.onMouseButton(button, action, mods, v.pointerX_, v.pointerY_);
  });
  glfwSetScrollCallback(w, [](GLFWwindow* window, double dx, double dy) {
    Viewer& v = of(window);
    v.imgui_.onScroll(dx, dy, v.pointerX_, v.pointerY_);
  });
  glfwSetKeyCallback(w, [](GLFWwindow* window, int key, int scancode, int action, int mods) {
    of(window).imgui_.onKey(key, scancode, action, mods);
  });
  glfwSetCharCallback(w, [](GLFWwindow* window, unsigned int c) { of(window).imgui_.onChar(c); });
  glfwSetWindowFocusCallback(w, [](GLFWwindow* window, int focused) { of(window).imgui_.onFocus(focused); });
  glfwSetCursorEnterCallback(w, [](GLFWwindow* window, int entered) { of(window).imgui_.onCursorEnter(entered); });
}

// Over the image, not over the panel or an ImGui popup.
bool Viewer::cursorOverImage(double x) const {
  int windowWidth = 0, windowHeight = 0;
  glfwGetWindowSize(window_.handle(), &windowWidth, &windowHeight);
  const double scale = framebufferWidth_ > 0 ? double(windowWidth) / framebufferWidth_ : 1.0;
  return x < (framebufferWidth_ - kPanelWidth) * scale && !ImGui::GetIO().WantCaptureMouse;
}

namespace {

// The FlyKeys entry that `key` holds, if it is a fly key.
bool* flyKey(FlyKeys& keys, int key) {
  switch (key) {
    case GLFW_KEY_W: return &keys.forward;
    case GLFW_KEY_S: return &keys.back;
    case GLFW_KEY_A: return &keys.left;
    case GLFW_KEY_D: return &keys.right;
    case GLFW_KEY_Q: return &keys.down;
    case GLFW_KEY_E: return &keys.up;
    default: return nullptr;
  }
}

}  // namespace

// Called after ImGui has started the frame that takes `events`: io.WantCaptureMouse and io.WantCaptureKeyboard
// are ImGui's decisions for them.
void Viewer::handleInput(const std::vector<WindowEvent>& events) {
  for (const WindowEvent& e : events) {
    switch (e.kind) {
      case WindowEvent::Kind::CursorMove: renderer_.input().cursorMoved(e.x, e.y); break;
      case WindowEvent::Kind::Wheel: renderer_.input().wheel(e.wheel, cursorOverImage(e.x)); break;
      case WindowEvent::Kind::MouseButton: handleMouseButton(e); break;
      case WindowEvent::Kind::Key: handleKey(e); break;
    }
  }
}

void Viewer::handleMouseButton(const WindowEvent& e) {
  if (e.code > GLFW_MOUSE_BUTTON_MIDDLE) return;
  const MouseButton b = e.code == GLFW_MOUSE_BUTTON_MIDDLE  ? MouseButton::Middle
                        : e.code == GLFW_MOUSE_BUTTON_RIGHT ? MouseButton::Right
                                                            : MouseButton::Left;
  if (e.action == GLFW_PRESS)
    renderer_.input().buttonPressed(b, e.x, e.y, cursorOverImage(e.x));
  else if (e.action == GLFW_RELEASE)
    renderer_.input().buttonReleased(b);
}

void Viewer::handleKey(const WindowEvent& e) {
  bool* fly = flyKey(flyKeys_, e.code);
  if (e.action == GLFW_RELEASE && fly) *fly = false;
  if (e.action != GLFW_PRESS) return;
  if (e.code == GLFW_KEY_F12) stateRequested_ = true;
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  if (fly) *fly = true;
  if (e.code == GLFW_KEY_F) renderer_.frameScene();
  if (e.code == GLFW_KEY_R) renderer_.resetCamera();
  if (e.code == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window_.handle(), GLFW_TRUE);
}

FlyKeys Viewer::heldFlyKeys() const { return ImGui::GetIO().WantCaptureKeyboard ? FlyKeys{} : flyKeys_; }

// The panel's scene status and the window's title for the scene the renderer shows now.
void Viewer::sceneShown() {
  const Scene& scene = renderer_.session().scene();
  status_.sceneName = scene.name;
  status_.animationClips.clear();
  status_.animationRanges.clear();
  if (!scene.animation.empty())
    for (const AnimationClip& clip : scene.animation.clips) {
      status_.animationClips.push_back(clip.name);
      status_.animationRanges.push_back({clip.start, clip.end});
    }
  glfwSetWindowTitle(window_.handle(), ("candela - " + status_.sceneName).c_str());
}

void Viewer::backendShown() {
  const RenderSession& session = renderer_.session();
  transfer_.emplace(session, options_.interop);
  transferBackendChanges_ = session.backendChanges();
  status_.backend = session.backend().name();
  status_.device = session.backend().deviceName();
  status_.imageTransfer = transfer_->description();
  std::fprintf(stderr, "display: %s\n", status_.imageTransfer.c_str());
}

void Viewer::report(const std::string& message, bool isError) {
  status_.message = message;
  status_.messageIsError = isError;
  std::fprintf(stderr, "%s\n", message.c_str());
}

void Viewer::handle(const PanelRequests& requests) {
  if (requests.applyEnvironment) renderer_.applyEnvironmentControls();
  if (requests.applyMaterials) renderer_.applyMaterialControls();
  ViewerControls& controls = renderer_.controls();
  try {
    if (requests.saveScreenshot) {
      const Image image = renderer_.accumulatedImage(), emission = renderer_.recordedEmission();
      saveScreenshot(controls.screenshotBase + ".png", image, emission, controls.post);
      saveScreenshot(controls.screenshotBase + ".exr", image, emission, controls.post);
      report("saved " + controls.screenshotBase + ".png and .exr", false);
    }
    if (requests.saveSceneFile) {
      const RenderSession& session = renderer_.session();
      std::string note = writeViewFile(controls.sceneFilePath, renderer_.sceneSpec(), session.scene(),
                                       renderer_.camera().description(), session.appliedSettings(), controls);
      report("saved " + controls.sceneFilePath + (note.empty() ? "" : " (" + note + ")"), false);
    }
  } catch (const std::exception& e) {
    report(e.what(), true);
  }
  if (requests.openScene) {
    try {
      renderer_.openScene(controls.openSpec);
      sceneShown();
      report("opened " + controls.openSpec, false);
    } catch (const std::exception& e) {
      report("could not open '" + controls.openSpec + "': " + e.what(), true);
    }
  }
}

void Viewer::frame(double now, double seconds) {
  glfwGetFramebufferSize(window_.handle(), &framebufferWidth_, &framebufferHeight_);
  const int imageWidth = std::max(framebufferWidth_ - kPanelWidth, 1);
  const int imageHeight = std::max(framebufferHeight_, 1);
  lastPlan_ = renderer_.step({uint32_t(imageWidth), uint32_t(imageHeight), now, seconds}, *this).plan;

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, framebufferWidth_, framebufferHeight_);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  display_.draw(renderer_.controls().post, 0, 0, imageWidth, imageHeight);

  updateStatus(seconds);
  // The panel's edits take effect from the next frame on; its actions act on this frame's image.
  // ImGui lays out in window coordinates, which differ from framebuffer pixels on high-density displays.
  const float scale = ImGui::GetIO().DisplayFramebufferScale.x > 0.0f ? ImGui::GetIO().DisplayFramebufferScale.x : 1.0f;
  PanelRequests requests = drawPanel(status_, renderer_.controls(), float(imageWidth) / scale,
                                     float(kPanelWidth) / scale, float(framebufferHeight_) / scale);
  openSceneField_ = requests.openSceneField;
  openSceneFieldActive_ = requests.openSceneFieldActive;
  handle(requests);
  imgui_.render();
}

// ImGui takes this frame's share of the queued input first; the camera takes what ImGui does not want.
FlyKeys Viewer::takeInput() {
  handleInput(imgui_.beginFrame());
  return heldFlyKeys();
}

// The denoised or filtered image is made on the host side of the backend, and the emission the bilateral pass
// keeps apart is read from there; otherwise the image may stay on the device (interop).
void Viewer::present(FrameImages& frame) {
  if (frame.session().backendChanges() != transferBackendChanges_) backendShown();
  if (frame.needsHost())
    display_.upload(frame.image(), frame.emission());
  else
    transfer_->transfer(frame.session(), display_);
}

void Viewer::updateStatus(double seconds) {
  status_.accumulatedSamples = renderer_.session().accumulatedSamples();
  status_.starting = meanwhileNote(renderer_.session());
  status_.imageWidth = lastPlan_.width;
  status_.imageHeight = lastPlan_.height;
  status_.preview = lastPlan_.preview;
  status_.scene = renderer_.session().summary();
  status_.cameraPosition = renderer_.camera().position();
  status_.cameraDirection = renderer_.camera().forward();
  if (seconds > 0.0) {
    const double ms = seconds * 1000.0;
    status_.msPerFrame =
        status_.msPerFrame == 0.0 ? ms : (1.0 - kTimingSmoothing) * status_.msPerFrame + kTimingSmoothing * ms;
    status_.framesPerSecond = 1000.0 / status_.msPerFrame;
  }
}

void Viewer::writeState() {
  const RenderSession& session = renderer_.session();
  const OrbitCamera& camera = renderer_.camera();
  ViewerState state;
  state.frame = session.frames();
  state.restarts = session.restarts();
  state.accumulatedSamples = session.accumulatedSamples();
  state.imageWidth = lastPlan_.width;
  state.imageHeight = lastPlan_.height;
  state.preview = lastPlan_.preview;
  state.scene = status_.sceneName;
  state.backend = status_.backend;
  state.cameraPosition = camera.position();
  state.cameraForward = camera.forward();
  state.cameraTarget = camera.target();
  state.cameraDistance = camera.distance();
  state.denoiser = denoiserName(renderer_.controls().post.denoiser);
  state.message = status_.message;
  state.messageIsError = status_.messageIsError;
  state.openSceneField = openSceneField_;
  state.openSceneText = renderer_.controls().openSpec;
  state.openSceneFieldActive = openSceneFieldActive_;
  try {
    writeStateFile(options_.stateFile, state);
  } catch (const std::exception& e) {
    report(e.what(), true);
  }
}

void Viewer::writeExitFiles() {
  if (!options_.windowCapture.empty()) captureWindow(options_.windowCapture, framebufferWidth_, framebufferHeight_);
  if (!options_.interactive.screenshot.empty()) renderer_.writeScreenshot(options_.interactive.screenshot);
}

int Viewer::run() {
  double last = glfwGetTime();
  while (!glfwWindowShouldClose(window_.handle())) {
    glfwPollEvents();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_.handle(), &w, &h);
    if (w == 0 || h == 0) {  // minimised
      glfwWaitEvents();
      continue;
    }
    const double now = glfwGetTime();
    frame(now, now - last);
    last = now;
    if (stateRequested_) {
      writeState();
      stateRequested_ = false;
    }
    const uint32_t frames = options_.interactive.frames;
    if (frames > 0 && renderer_.session().frames() >= frames) break;
    glfwSwapBuffers(window_.handle());
  }
  writeExitFiles();
  std::fprintf(stderr, "viewer: %llu frames; the panel showed %.1f fps, %.2f ms/frame\n",
               static_cast<unsigned long long>(renderer_.session().frames()), status_.framesPerSecond,
               status_.msPerFrame);
  return 0;
}

}  // namespace

int runViewer(const ViewerOptions& options) {
  Viewer viewer(options);
  return viewer.run();
}

}  // namespace candela
