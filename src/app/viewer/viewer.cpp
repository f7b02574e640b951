#include "app/viewer/viewer.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "app/backend_factory.h"
#include "app/interactive/camera_input.h"
#include "app/interactive/interactive_policy.h"
#include "app/interactive/orbit_camera.h"
#include "app/interactive/render_session.h"
#include "app/interactive/viewer_denoiser.h"
#include "app/interactive/viewer_files.h"
#include "app/scene_loading.h"
#include "app/viewer/glfw_window.h"
#include "app/viewer/image_display.h"
#include "app/viewer/image_transfer.h"
#include "app/viewer/viewer_panel.h"
#include "app/viewer/window_capture.h"

namespace candela {

namespace {

constexpr int kPanelWidth = 380;
constexpr int kMinImageSide = 64;
constexpr double kMaxFlyStep = 0.1;  // seconds: a slow frame does not throw the camera far
constexpr double kTimingSmoothing = 0.1;

class Viewer {
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

  void showScene(Scene scene, const std::string& spec);
  void frame(double now, double seconds);
  void updateStatus(double seconds);
  void handle(const PanelRequests& requests);
  void writeState();
  void writeExitFiles();
  void report(const std::string& message, bool isError);
  void prepareDenoiser();
  Image accumulatedImage();
  // The emission for saveScreenshot: empty where the backend does not record it (no AOVs).
  Image screenshotEmission() const;

  ViewerOptions options_;
  GlfwWindow window_;
  ImGuiLayer imgui_;
  ImageDisplay display_;
  RenderSession session_;
  ImageTransfer transfer_;
  ViewerDenoiser denoiser_;
  std::unique_ptr<OrbitCamera> camera_;
  std::string sceneSpec_;
  CameraInput input_;
  InteractivePolicy policy_;
  ViewerControls controls_;
  PanelStatus status_;
  FlyKeys flyKeys_;  // held, as the events taken from the input queue so far say
  FramePlan lastPlan_;
  Camera lastCamera_;
  bool stateRequested_ = false;
  double pointerX_ = 0.0, pointerY_ = 0.0;  // as of the last cursor event GLFW reported
  Vec2 openSceneField_;
  bool openSceneFieldActive_ = false;
  bool sceneJustShown_ = true;
  bool followsSceneCamera_ = false;  // the view is the scene's animated camera, moved with each pose
  int framebufferWidth_ = 0;
  int framebufferHeight_ = 0;
};

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      window_(int(options.width) + kPanelWidth, int(options.height), "candela"),
      imgui_(window_.handle()),
      session_([&] {
        std::string why;
        std::unique_ptr<Backend> backend = createBackend(options.backend, why, options.devices);
        std::fprintf(stderr, "%s\n", why.c_str());
        return backend;
      }()),
      transfer_(session_, options.interop) {
  controls_.maxDepth = options.maxDepth;
  controls_.samplesPerFrame = options.samplesPerFrame;
  controls_.post = options.post;
  std::fprintf(stderr, "window: %s\n", window_.glRenderer().c_str());
  showScene(loadScene(options.sceneSpec, {options.environmentPath, options.sceneCache, options.outsidePaths,
                                          options.camera, options.textureLimits}),
            options.sceneSpec);
  status_.backend = session_.backend().name();
  status_.device = session_.backend().deviceName();
  status_.imageTransfer = transfer_.description();
  std::fprintf(stderr, "display: %s\n", status_.imageTransfer.c_str());
  glfwSetWindowSizeLimits(window_.handle(), kPanelWidth + kMinImageSide, kMinImageSide, GLFW_DONT_CARE, GLFW_DONT_CARE);
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
      case WindowEvent::Kind::CursorMove: input_.cursorMoved(e.x, e.y); break;
      case WindowEvent::Kind::Wheel: input_.wheel(e.wheel, cursorOverImage(e.x)); break;
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
    input_.buttonPressed(b, e.x, e.y, cursorOverImage(e.x));
  else if (e.action == GLFW_RELEASE)
    input_.buttonReleased(b);
}

void Viewer::handleKey(const WindowEvent& e) {
  bool* fly = flyKey(flyKeys_, e.code);
  if (e.action == GLFW_RELEASE && fly) *fly = false;
  if (e.action != GLFW_PRESS) return;
  if (e.code == GLFW_KEY_F12) stateRequested_ = true;
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  if (fly) *fly = true;
  if (e.code == GLFW_KEY_F) {
    camera_->frameScene();
    followsSceneCamera_ = false;
  }
  if (e.code == GLFW_KEY_R) {
    // Back to the scene's camera, where the animation has it now; an animated one is followed again.
    camera_ = std::make_unique<OrbitCamera>(session_.scene().camera, session_.summary().bounds);
    followsSceneCamera_ = sceneCameraAnimated(session_.scene());
  }
  if (e.code == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window_.handle(), GLFW_TRUE);
}

FlyKeys Viewer::heldFlyKeys() const { return ImGui::GetIO().WantCaptureKeyboard ? FlyKeys{} : flyKeys_; }

void Viewer::showScene(Scene scene, const std::string& spec) {
  validateScene(scene);
  SceneSummary summary = summarizeScene(scene);
  camera_ = std::make_unique<OrbitCamera>(scene.camera, summary.bounds);
  followsSceneCamera_ = sceneCameraAnimated(scene);
  status_.sceneName = scene.name;
  status_.animationClips.clear();
  status_.animationRanges.clear();
  if (!scene.animation.empty())
    for (const AnimationClip& clip : scene.animation.clips) {
      status_.animationClips.push_back(clip.name);
      status_.animationRanges.push_back({clip.start, clip.end});
    }
  controls_.animation = {};
  if (!scene.animation.empty()) controls_.animation.time = scene.animation.clips[0].start;
  sceneSpec_ = spec;
  sceneJustShown_ = true;
  session_.setScene(std::move(scene));
  glfwSetWindowTitle(window_.handle(), ("candela - " + status_.sceneName).c_str());
}

void Viewer::report(const std::string& message, bool isError) {
  status_.message = message;
  status_.messageIsError = isError;
  std::fprintf(stderr, "%s\n", message.c_str());
}

void Viewer::handle(const PanelRequests& requests) {
  if (requests.applyEnvironment) session_.setEnvironment(controls_.environmentScale, controls_.environmentRotation);
  if (requests.applyMaterials) session_.setMaterialOverrides(controls_.materials);
  try {
    if (requests.saveScreenshot) {
      const Image image = accumulatedImage(), emission = screenshotEmission();
      saveScreenshot(controls_.screenshotBase + ".png", image, emission, controls_.post);
      saveScreenshot(controls_.screenshotBase + ".exr", image, emission, controls_.post);
      report("saved " + controls_.screenshotBase + ".png and .exr", false);
    }
    if (requests.saveSceneFile) {
      std::string note = writeViewFile(controls_.sceneFilePath, sceneSpec_, session_.scene(), camera_->description(),
                                       session_.appliedSettings(), controls_);
      report("saved " + controls_.sceneFilePath + (note.empty() ? "" : " (" + note + ")"), false);
    }
  } catch (const std::exception& e) {
    report(e.what(), true);
  }
  if (requests.openScene) {
    try {
      showScene(loadScene(controls_.openSpec,
                          {{}, options_.sceneCache, options_.outsidePaths, {}, options_.textureLimits}),
                controls_.openSpec);
      report("opened " + controls_.openSpec, false);
    } catch (const std::exception& e) {
      report("could not open '" + controls_.openSpec + "': " + e.what(), true);
    }
  }
}

void Viewer::frame(double now, double seconds) {
  glfwGetFramebufferSize(window_.handle(), &framebufferWidth_, &framebufferHeight_);
  const int imageWidth = std::max(framebufferWidth_ - kPanelWidth, 1);
  const int imageHeight = std::max(framebufferHeight_, 1);

  // A playing animation moves on with the wall clock; a new pose restarts the accumulation like a camera move.
  bool posed = false;
  if (const SceneAnimation& animation = session_.scene().animation; !animation.empty()) {
    advanceAnimation(controls_.animation, animation, seconds);
    posed = session_.poseAnimation(controls_.animation.clip, controls_.animation.time);
  }
  // The view follows an animated scene camera until the user moves it (R goes back to it).
  if (posed && followsSceneCamera_)
    camera_ = std::make_unique<OrbitCamera>(session_.scene().camera, session_.summary().bounds);
  // ImGui takes this frame's share of the queued input first; the camera takes what ImGui does not want.
  handleInput(imgui_.beginFrame());
  const float aspect = float(imageWidth) / float(imageHeight);
  const Camera beforeInput = camera_->camera(aspect);
  input_.apply(*camera_, heldFlyKeys(), float(std::min(seconds, kMaxFlyStep)), float(imageHeight));
  const Camera camera = camera_->camera(aspect);
  if (!sameCamera(camera, beforeInput)) followsSceneCamera_ = false;
  // A scene's first camera is where the view starts, not a motion.
  const bool moved = (!sceneJustShown_ && !sameCamera(camera, lastCamera_)) || (posed && controls_.animation.playing);
  lastCamera_ = camera;
  sceneJustShown_ = false;
  lastPlan_ = policy_.plan(uint32_t(imageWidth), uint32_t(imageHeight), controls_.samplesPerFrame, moved, now);

  RenderSettings settings;
  settings.width = lastPlan_.width;
  settings.height = lastPlan_.height;
  settings.maxDepth = controls_.maxDepth;
  settings.seed = options_.seed;
  settings.sampler = options_.sampler;
  settings.lightSampler = options_.lightSampler;
  auto start = std::chrono::steady_clock::now();
  prepareDenoiser();
  // The bilateral pass keeps the emission apart, which the backend records with the AOVs.
  session_.setAovsEnabled(controls_.post.denoiser != DenoiserChoice::None || controls_.post.bilateral);
  session_.renderFrame(camera, settings, lastPlan_.samplesPerPixel, controls_.accumulate);
  // The denoised image is made on the host side of the backend, and the emission the bilateral pass needs is read
  // from there; otherwise the image may stay on the device (interop).
  if (controls_.post.bilateral) {
    const Image emission = session_.emission();
    display_.upload(accumulatedImage(), &emission);
  } else if (controls_.post.denoiser != DenoiserChoice::None) {
    display_.upload(accumulatedImage());
  } else {
    transfer_.transfer(session_, display_);
  }
  policy_.recordFrame(lastPlan_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, framebufferWidth_, framebufferHeight_);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  display_.draw(controls_.post, 0, 0, imageWidth, imageHeight);

  updateStatus(seconds);
  // The panel's edits take effect from the next frame on; its actions act on this frame's image.
  // ImGui lays out in window coordinates, which differ from framebuffer pixels on high-density displays.
  const float scale = ImGui::GetIO().DisplayFramebufferScale.x > 0.0f ? ImGui::GetIO().DisplayFramebufferScale.x : 1.0f;
  PanelRequests requests = drawPanel(status_, controls_, float(imageWidth) / scale, float(kPanelWidth) / scale,
                                     float(framebufferHeight_) / scale);
  openSceneField_ = requests.openSceneField;
  openSceneFieldActive_ = requests.openSceneFieldActive;
  handle(requests);
  imgui_.render();
}

// The OptiX AI denoiser is made when first chosen; where it cannot run the panel says why and denoising goes off,
// before any frame is rendered for it.
void Viewer::prepareDenoiser() {
  const std::string why = denoiser_.prepareOrTurnOff(controls_.post.denoiser);
  if (!why.empty()) report(why, true);
}

// What the window shows before its GPU passes: the film, through the chosen denoiser.
Image Viewer::screenshotEmission() const { return session_.backend().aovsEnabled() ? session_.emission() : Image(); }

Image Viewer::accumulatedImage() {
  return denoiser_.apply(session_, controls_.post.denoiser, controls_.post.atrousParams);
}

void Viewer::updateStatus(double seconds) {
  status_.accumulatedSamples = session_.accumulatedSamples();
  status_.imageWidth = lastPlan_.width;
  status_.imageHeight = lastPlan_.height;
  status_.preview = lastPlan_.preview;
  status_.scene = session_.summary();
  status_.cameraPosition = camera_->position();
  status_.cameraDirection = camera_->forward();
  if (seconds > 0.0) {
    const double ms = seconds * 1000.0;
    status_.msPerFrame =
        status_.msPerFrame == 0.0 ? ms : (1.0 - kTimingSmoothing) * status_.msPerFrame + kTimingSmoothing * ms;
    status_.framesPerSecond = 1000.0 / status_.msPerFrame;
  }
}

void Viewer::writeState() {
  ViewerState state;
  state.frame = session_.frames();
  state.restarts = session_.restarts();
  state.accumulatedSamples = session_.accumulatedSamples();
  state.imageWidth = lastPlan_.width;
  state.imageHeight = lastPlan_.height;
  state.preview = lastPlan_.preview;
  state.scene = status_.sceneName;
  state.backend = status_.backend;
  state.cameraPosition = camera_->position();
  state.cameraForward = camera_->forward();
  state.cameraTarget = camera_->target();
  state.cameraDistance = camera_->distance();
  state.denoiser = denoiserName(controls_.post.denoiser);
  state.message = status_.message;
  state.messageIsError = status_.messageIsError;
  state.openSceneField = openSceneField_;
  state.openSceneText = controls_.openSpec;
  state.openSceneFieldActive = openSceneFieldActive_;
  try {
    writeStateFile(options_.stateFile, state);
  } catch (const std::exception& e) {
    report(e.what(), true);
  }
}

void Viewer::writeExitFiles() {
  if (!options_.windowCapture.empty()) captureWindow(options_.windowCapture, framebufferWidth_, framebufferHeight_);
  if (!options_.screenshot.empty())
    saveScreenshot(options_.screenshot, accumulatedImage(), screenshotEmission(), controls_.post);
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
    if (options_.frames > 0 && session_.frames() >= options_.frames) break;
    glfwSwapBuffers(window_.handle());
  }
  writeExitFiles();
  std::fprintf(stderr, "viewer: %llu frames; the panel showed %.1f fps, %.2f ms/frame\n",
               static_cast<unsigned long long>(session_.frames()), status_.framesPerSecond, status_.msPerFrame);
  return 0;
}

}  // namespace

int runViewer(const ViewerOptions& options) {
  if (options.post.denoiser == DenoiserChoice::Optix && !ViewerDenoiser::optixInThisBuild())
    throw std::runtime_error(
        "--denoise optix needs the OptiX backend, which is not in this build (see README, "
        "'GPU backend')");
  Viewer viewer(options);
  return viewer.run();
}

}  // namespace candela
