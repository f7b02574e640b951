#include "app/serve/serve_loop.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "app/backend_factory.h"
#include "app/interactive/viewer_files.h"
#include "app/scene_loading.h"
#include "app/serve/frame_encoding.h"

namespace candela {

namespace {

constexpr double kMaxFlyStep = 0.1;  // seconds: a slow frame does not throw the camera far
constexpr double kTimingSmoothing = 0.1;
constexpr std::chrono::milliseconds kIdleWait{50};

using Json = nlohmann::json;

Json vec(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

// A binary message: the header's length (4 bytes, little-endian), the JSON header, the payload.
std::shared_ptr<const std::string> binaryMessage(const Json& header, const std::string& payload) {
  const std::string text = header.dump();
  auto message = std::make_shared<std::string>();
  const uint32_t length = uint32_t(text.size());
  for (int i = 0; i < 4; ++i) message->push_back(char((length >> (8 * i)) & 0xffu));
  *message += text;
  *message += payload;
  return message;
}

std::unique_ptr<Backend> makeBackend(const std::string& name, const DeviceRequest& devices) {
  std::string why;
  std::unique_ptr<Backend> backend = createBackend(name, why, devices);
  std::fprintf(stderr, "%s\n", why.c_str());
  return backend;
}

}  // namespace

ServeLoop::ServeLoop(const ServeOptions& options, ClientHub& hub)
    : options_(options),
      hub_(hub),
      session_(makeBackend(options.backend, options.devices)),
      viewWidth_(options.width),
      viewHeight_(options.height) {
  controls_.maxDepth = options.maxDepth;
  controls_.samplesPerFrame = options.samplesPerFrame;
  controls_.post = options.post;
  Scene scene = loadScene(options.sceneSpec, {options.environmentPath, options.sceneCache, options.outsidePaths});
  validateScene(scene);
  camera_ = std::make_unique<OrbitCamera>(scene.camera, summarizeScene(scene).bounds);
  session_.setScene(std::move(scene));
  backendName_ = session_.backend().name();
}

void ServeLoop::greet(uint64_t client) {
  const SceneSummary& s = session_.summary();
  Json overrides = Json::array();
  for (const OverrideParameter& p : overrideParameters())
    overrides.push_back({{"name", p.name}, {"min", p.min}, {"max", p.max}});
  Json denoisers = Json::array({"none", "atrous"});
  if (ViewerDenoiser::optixInThisBuild()) denoisers.push_back("optix");
  const Json hello = {
      {"type", "hello"},
      {"backend", session_.backend().name()},
      {"device", session_.backend().deviceName()},
      {"scene", session_.scene().name},
      {"stats",
       {{"vertices", s.vertices},
        {"triangles", s.triangles},
        {"meshes", s.meshes},
        {"instances", s.instances},
        {"materials", s.materials},
        {"textures", s.textures}}},
      {"override_parameters", overrides},
      {"denoisers", denoisers},
      {"max_atrous_passes", kMaxAtrousPasses},
      {"controls", controlsJson()},
  };
  hub_.send(client, std::make_shared<const std::string>(hello.dump()), false);
}

Json ServeLoop::controlsJson() const {
  Json overrides = Json::object();
  for (const OverrideParameter& p : overrideParameters())
    if (const std::optional<float>& v = controls_.materials.*(p.field)) overrides[p.name] = *v;
  return {
      {"max_depth", controls_.maxDepth},
      {"samples_per_frame", controls_.samplesPerFrame},
      {"accumulate", controls_.accumulate},
      {"env_intensity", controls_.environmentScale},
      {"env_rotation", controls_.environmentRotation},
      {"shading", shadingName(controls_.materials.shading)},
      {"overrides", overrides},
      {"exposure", controls_.post.display.exposure},
      {"tonemap", toneMapperName(controls_.post.display.toneMapper)},
      {"denoiser", denoiserName(controls_.post.denoiser)},
      {"atrous_passes", controls_.post.atrousParams.passes},
      {"bilateral", controls_.post.bilateral},
  };
}

void ServeLoop::report(const std::string& message, bool isError) {
  std::fprintf(stderr, "candela serve: %s\n", message.c_str());
  hub_.broadcast(Json{{"type", "message"}, {"text", message}, {"error", isError}}.dump());
}

void ServeLoop::handle(const IncomingMessage& incoming) {
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, PointerMessage>) {
          if (m.action == PointerMessage::Action::Down) input_.buttonPressed(m.button, m.x, m.y, true);
          if (m.action == PointerMessage::Action::Up) input_.buttonReleased(m.button);
          if (m.action == PointerMessage::Action::Move) input_.cursorMoved(m.x, m.y);
        } else if constexpr (std::is_same_v<T, WheelMessage>) {
          input_.wheel(m.steps, true);
        } else if constexpr (std::is_same_v<T, KeysMessage>) {
          flyKeys_ = m.held;
        } else if constexpr (std::is_same_v<T, ResizeMessage>) {
          viewWidth_ = m.width;
          viewHeight_ = m.height;
        } else if constexpr (std::is_same_v<T, ActionMessage>) {
          act(incoming.client, m.kind);
        } else if constexpr (std::is_same_v<T, SettingsMessage>) {
          applySettings(m);
        }
      },
      incoming.message);
}

void ServeLoop::applySettings(const SettingsMessage& m) {
  if (m.maxDepth) controls_.maxDepth = *m.maxDepth;
  if (m.samplesPerFrame) controls_.samplesPerFrame = *m.samplesPerFrame;
  if (m.accumulate) controls_.accumulate = *m.accumulate;
  if (m.environmentScale) controls_.environmentScale = *m.environmentScale;
  if (m.environmentRotation) controls_.environmentRotation = *m.environmentRotation;
  environmentEdited_ = environmentEdited_ || m.environmentScale || m.environmentRotation;
  if (m.shading) controls_.materials.shading = *m.shading;
  for (const auto& [name, value] : m.overrides)
    for (const OverrideParameter& p : overrideParameters())
      if (name == p.name) controls_.materials.*(p.field) = value;
  materialsEdited_ = materialsEdited_ || m.shading || !m.overrides.empty();
  if (m.exposure) controls_.post.display.exposure = *m.exposure;
  if (m.toneMapper) controls_.post.display.toneMapper = *m.toneMapper;
  if (m.denoiser) controls_.post.denoiser = *m.denoiser;
  if (m.atrousPasses) controls_.post.atrousParams.passes = *m.atrousPasses;
  if (m.bilateral) controls_.post.bilateral = *m.bilateral;
}

void ServeLoop::act(uint64_t client, ActionMessage::Kind kind) {
  switch (kind) {
    case ActionMessage::Kind::Frame: camera_->frameScene(); break;
    case ActionMessage::Kind::Reset: camera_->reset(); break;
    case ActionMessage::Kind::TakeControl: hub_.giveControl(client); break;
    case ActionMessage::Kind::Screenshot:
      try {
        const std::string png = encodePng(displayImage(accumulatedImage(), controls_.post));
        hub_.send(client, binaryMessage({{"kind", "screenshot"}, {"name", "candela-view.png"}}, png), true);
      } catch (const std::exception& e) {
        report(std::string("no screenshot: ") + e.what(), true);
      }
      break;
    case ActionMessage::Kind::SaveView: {
      const ViewFile file = makeViewFile(options_.sceneSpec, session_.scene(), camera_->description(),
                                         session_.appliedSettings(), controls_);
      const Json message = {
          {"type", "view_file"}, {"name", "candela-view.json"}, {"text", file.text}, {"note", file.note}};
      hub_.send(client, std::make_shared<const std::string>(message.dump()), false);
      break;
    }
  }
}

// The OptiX AI denoiser is made when first chosen; where it cannot run the page says why and denoising goes off.
void ServeLoop::prepareDenoiser() {
  const std::string why = denoiser_.prepareOrTurnOff(controls_.post.denoiser);
  if (!why.empty()) report(why, true);
}

Image ServeLoop::accumulatedImage() {
  return denoiser_.apply(session_, controls_.post.denoiser, controls_.post.atrousParams);
}

void ServeLoop::renderFrame(double now) {
  const double sinceLast = firstFrame_ ? 0.0 : now - lastFrameTime_;
  input_.apply(*camera_, flyKeys_, float(std::min(sinceLast, kMaxFlyStep)), float(viewHeight_));
  const Camera camera = camera_->camera(float(viewWidth_) / float(viewHeight_));
  const bool moved = !firstFrame_ && !sameCamera(camera, lastCamera_);
  lastCamera_ = camera;
  FramePlan plan = policy_.plan(viewWidth_, viewHeight_, controls_.samplesPerFrame, moved, now);
  // A slow connection shrinks the preview further (stream_quality.h).
  const uint32_t divisor = quality_.resolutionDivisor(plan.preview);
  plan.width = std::max(plan.width / divisor, kMinViewSide);
  plan.height = std::max(plan.height / divisor, kMinViewSide);

  RenderSettings settings;
  settings.width = plan.width;
  settings.height = plan.height;
  settings.maxDepth = controls_.maxDepth;
  settings.seed = options_.seed;
  settings.sampler = options_.sampler;
  settings.lightSampler = options_.lightSampler;
  const auto renderStart = std::chrono::steady_clock::now();
  prepareDenoiser();
  session_.setAovsEnabled(controls_.post.denoiser != DenoiserChoice::None);
  session_.renderFrame(camera, settings, plan.samplesPerPixel, controls_.accumulate);
  const DisplayImage image = displayImage(accumulatedImage(), controls_.post);
  const double renderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - renderStart).count();
  policy_.recordFrame(plan, renderSeconds);
  const int jpegQuality = quality_.jpegQuality(plan.preview);
  const std::string jpeg = encodeJpeg(image, jpegQuality);

  if (!firstFrame_) {
    const double ms = 1000.0 * sinceLast;
    msPerFrame_ = msPerFrame_ == 0.0 ? ms : (1.0 - kTimingSmoothing) * msPerFrame_ + kTimingSmoothing * ms;
  }
  ++framesSent_;
  const Json header = {
      {"kind", "frame"},
      {"frame", framesSent_},
      {"width", image.width},
      {"height", image.height},
      {"preview", plan.preview},
      {"quality", jpegQuality},
      {"samples", session_.accumulatedSamples()},
      {"fps", msPerFrame_ > 0.0 ? 1000.0 / msPerFrame_ : 0.0},
      {"ms_per_frame", msPerFrame_},
      {"render_ms", 1000.0 * renderSeconds},
      {"bytes_per_second", quality_.bytesPerSecond()},
      {"clients", hub_.clientCount()},
      {"camera", {{"position", vec(camera_->position())}, {"forward", vec(camera_->forward())}}},
      {"applied", {{"max_depth", session_.appliedSettings().maxDepth}, {"samples_per_frame", plan.samplesPerPixel}}},
      {"controls", controlsJson()},
  };
  hub_.publishFrame(framesSent_, binaryMessage(header, jpeg), plan.preview);
  lastFrameTime_ = now;
  firstFrame_ = false;
}

void ServeLoop::run(const std::atomic<bool>& stop) {
  while (!stop) {
    hub_.waitForWork(kIdleWait);
    if (const uint64_t changes = hub_.controlChanges(); changes != controlChanges_) {
      // A new controller starts with no buttons or keys held.
      input_ = CameraInput();
      flyKeys_ = FlyKeys();
      controlChanges_ = changes;
    }
    for (uint64_t client : hub_.takeJoined()) greet(client);
    for (const IncomingMessage& m : hub_.takeMessages()) handle(m);
    // Once for all the messages that came since the last frame: a slider dragged quickly (or a flood of
    // edits) costs one update of the backend's materials or environment, not one for each message.
    if (environmentEdited_) session_.setEnvironment(controls_.environmentScale, controls_.environmentRotation);
    if (materialsEdited_) session_.setMaterialOverrides(controls_.materials);
    environmentEdited_ = materialsEdited_ = false;
    for (const FrameDelivery& d : hub_.takeDeliveries()) quality_.recordDelivery(d.bytes, d.seconds, d.moving);
    if (!hub_.anyReady()) continue;
    renderFrame(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    if (options_.frames > 0 && framesSent_ >= options_.frames) break;
  }
}

}  // namespace candela
