#include "app/serve/serve_loop.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "app/denoising/denoiser_choice.h"
#include "app/interactive/viewer_files.h"

namespace candela {

namespace {

constexpr double kTimingSmoothing = 0.1;
constexpr std::chrono::milliseconds kIdleWait{50};

using Json = nlohmann::json;

Json vec(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

// The frame header's `starting`: how the GPU programs' compile goes while the frames render on the CPU meanwhile
// (RenderSession); null otherwise.
Json startingJson(const RenderSession& session) {
  const std::optional<ProgramCompileStatus> compile = session.startingCompile();
  if (!compile) return nullptr;
  return {{"tasks_done", compile->tasksDone},
          {"tasks_known", compile->tasksKnown},
          {"seconds", compile->seconds},
          {"note", meanwhileNote(session)}};
}

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

}  // namespace

ServeLoop::ServeLoop(const InteractiveOptions& options, ClientHub& hub)
    : options_(options), hub_(hub), renderer_(options), viewWidth_(options.width), viewHeight_(options.height) {}

void ServeLoop::greet(uint64_t client) {
  const RenderSession& session = renderer_.session();
  const SceneSummary& s = session.summary();
  Json overrides = Json::array();
  for (const OverrideParameter& p : overrideParameters())
    overrides.push_back({{"name", p.name}, {"min", p.min}, {"max", p.max}});
  Json denoisers = Json::array({"none", "atrous"});
  if (inThisBuild(DenoiserChoice::Optix)) denoisers.push_back("optix");
  // The page's animation controls: one entry per clip, none where nothing is animated.
  Json animations = Json::array();
  if (const SceneAnimation& animation = session.scene().animation; !animation.empty())
    for (const AnimationClip& clip : animation.clips)
      animations.push_back({{"name", clip.name}, {"start", clip.start}, {"end", clip.end}});
  const Json hello = {
      {"type", "hello"},
      {"backend", session.backend().name()},
      {"device", session.backend().deviceName()},
      {"scene", session.scene().name},
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
      {"streams", hub_.videoOffered() ? Json::array({"jpeg", "h264"}) : Json::array({"jpeg"})},
      {"animations", animations},
      {"controls", controlsJson()},
  };
  hub_.send(client, std::make_shared<const std::string>(hello.dump()), false);
}

Json ServeLoop::controlsJson() const {
  const ViewerControls& controls = renderer_.controls();
  Json overrides = Json::object();
  for (const OverrideParameter& p : overrideParameters())
    if (const std::optional<float>& v = controls.materials.*(p.field)) overrides[p.name] = *v;
  return {
      {"max_depth", controls.maxDepth},
      {"samples_per_frame", controls.samplesPerFrame},
      {"accumulate", controls.accumulate},
      {"env_intensity", controls.environmentScale},
      {"env_rotation", controls.environmentRotation},
      {"shading", shadingModelName(controls.materials.shading)},
      {"overrides", overrides},
      {"exposure", controls.post.display.exposure},
      {"tonemap", toneMapperName(controls.post.display.toneMapper)},
      {"denoiser", denoiserName(controls.post.denoiser)},
      {"atrous_passes", controls.post.atrousParams.passes},
      {"bilateral", controls.post.bilateral},
      {"playing", controls.animation.playing},
      {"animation", controls.animation.clip},
      {"animation_time", controls.animation.time},
  };
}

void ServeLoop::report(const std::string& message, bool isError) {
  std::fprintf(stderr, "candela serve: %s\n", message.c_str());
  hub_.broadcast(Json{{"type", "message"}, {"text", message}, {"error", isError}}.dump());
}

void ServeLoop::handle(const IncomingMessage& incoming) {
  inputSinceVideo_ = true;
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, PointerMessage>) {
          CameraInput& input = renderer_.input();
          if (m.action == PointerMessage::Action::Down) input.buttonPressed(m.button, m.x, m.y, true);
          if (m.action == PointerMessage::Action::Up) input.buttonReleased(m.button);
          if (m.action == PointerMessage::Action::Move) input.cursorMoved(m.x, m.y);
        } else if constexpr (std::is_same_v<T, WheelMessage>) {
          renderer_.input().wheel(m.steps, true);
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
  ViewerControls& controls = renderer_.controls();
  if (m.maxDepth) controls.maxDepth = *m.maxDepth;
  if (m.samplesPerFrame) controls.samplesPerFrame = *m.samplesPerFrame;
  if (m.accumulate) controls.accumulate = *m.accumulate;
  if (m.environmentScale) controls.environmentScale = *m.environmentScale;
  if (m.environmentRotation) controls.environmentRotation = *m.environmentRotation;
  environmentEdited_ = environmentEdited_ || m.environmentScale || m.environmentRotation;
  if (m.shading) controls.materials.shading = *m.shading;
  for (const auto& [name, value] : m.overrides)
    for (const OverrideParameter& p : overrideParameters())
      if (name == p.name) controls.materials.*(p.field) = value;
  materialsEdited_ = materialsEdited_ || m.shading || !m.overrides.empty();
  if (m.exposure) controls.post.display.exposure = *m.exposure;
  if (m.toneMapper) controls.post.display.toneMapper = *m.toneMapper;
  if (m.denoiser) controls.post.denoiser = *m.denoiser;
  if (m.atrousPasses) controls.post.atrousParams.passes = *m.atrousPasses;
  if (m.bilateral) controls.post.bilateral = *m.bilateral;
  // As in the viewer's panel: choosing an animation plays it from its start, moving the time pauses.
  const SceneAnimation& animation = renderer_.session().scene().animation;
  if (m.animationClip) selectClip(controls.animation, animation, int(*m.animationClip));
  if (m.animationTime) seekAnimation(controls.animation, animation, *m.animationTime);
  if (m.playing) controls.animation.playing = *m.playing;
}

void ServeLoop::act(uint64_t client, ActionMessage::Kind kind) {
  switch (kind) {
    case ActionMessage::Kind::Frame: renderer_.frameScene(); break;
    case ActionMessage::Kind::Reset: renderer_.resetCamera(); break;
    case ActionMessage::Kind::TakeControl: hub_.giveControl(client); break;
    case ActionMessage::Kind::Screenshot:
      try {
        const std::string png = encodePng(displayImage(renderer_.postImage(), renderer_.controls().post.display));
        hub_.send(client, binaryMessage({{"kind", "screenshot"}, {"name", "candela-view.png"}}, png), true);
      } catch (const std::exception& e) {
        report(std::string("no screenshot: ") + e.what(), true);
      }
      break;
    case ActionMessage::Kind::SaveView: {
      const RenderSession& session = renderer_.session();
      const ViewFile file = makeViewFile(renderer_.sceneSpec(), session.scene(), renderer_.camera().description(),
                                         session.appliedSettings(), renderer_.controls());
      const Json message = {
          {"type", "view_file"}, {"name", "candela-view.json"}, {"text", file.text}, {"note", file.note}};
      hub_.send(client, std::make_shared<const std::string>(message.dump()), false);
      break;
    }
  }
}

// A slow connection shrinks the preview further (stream_quality.h); the video's rate holds at the frame rate sent.
// At rest the video's frames come StreamQuality::kRestFrameRate a second at most; a client that needs a key frame
// gets one at once.
void ServeLoop::adjustPlan(FramePlan& plan) {
  const uint32_t divisor = quality_.resolutionDivisor(plan.preview);
  plan.width = std::max(plan.width / divisor, kMinViewSide);
  plan.height = std::max(plan.height / divisor, kMinViewSide);
  jpegQuality_ = quality_.jpegQuality(plan.preview);
  const double ms = plan.preview ? msPerMovingFrame_ : msPerFrame_;
  videoSettings_ = quality_.videoSettings(plan.preview, ms > 0.0 ? 1000.0 / ms : 0.0);
  holdVideo_ = needs_.video && !plan.preview && !needs_.videoKey && !inputSinceVideo_ && lastVideoTime_ &&
               frameTime_ - *lastVideoTime_ < 1.0 / StreamQuality::kRestFrameRate;
}

void ServeLoop::present(FrameImages& frame) {
  presented_ = {};
  const bool video = needs_.video && !holdVideo_;
  if (!needs_.jpeg && !video) return;  // the samples accumulate for the next frame sent
  const DisplayFrame pixels = frame.display();
  presented_.postMilliseconds = pixels.milliseconds;
  if (needs_.jpeg) presented_.jpeg = jpegEncoder_.encode(pixels.rgb, pixels.width, pixels.height, jpegQuality_);
  if (!video) return;
  try {
    presented_.video = videoEncoder_.encode(pixels.rgb, pixels.width, pixels.height, videoSettings_, needs_.videoKey);
  } catch (const std::exception& e) {
    // The browsers that took video get JPEG stripes from this frame on.
    report(std::string("the video stream stopped (") + e.what() + "): JPEG frames from now on", true);
    hub_.stopVideo();
    if (!presented_.jpeg) presented_.jpeg = jpegEncoder_.encode(pixels.rgb, pixels.width, pixels.height, jpegQuality_);
  }
}

void ServeLoop::renderFrame(double now) {
  needs_ = hub_.frameNeeds(lastVideoFrame_);
  frameTime_ = now;
  const double sinceLast = firstFrame_ ? 0.0 : now - lastFrameTime_;
  const FrameOutcome outcome = renderer_.step({viewWidth_, viewHeight_, now, sinceLast}, *this);
  const FramePlan& plan = outcome.plan;
  lastFrameTime_ = now;
  firstFrame_ = false;
  ++framesRendered_;
  if (!presented_.jpeg && !presented_.video) return;  // held back (adjustPlan)

  const auto smooth = [](double& average, double ms) {
    average = average == 0.0 ? ms : (1.0 - kTimingSmoothing) * average + kTimingSmoothing * ms;
  };
  if (lastSentTime_) {
    const double ms = 1000.0 * (now - *lastSentTime_);
    smooth(msPerFrame_, ms);
    if (plan.preview && lastSentMoving_) smooth(msPerMovingFrame_, ms);
  }
  lastSentTime_ = now;
  lastSentMoving_ = plan.preview;
  ++framesSent_;
  const RenderSession& session = renderer_.session();
  const Json header = {
      {"kind", "frame"},
      {"frame", framesSent_},
      {"preview", plan.preview},
      {"samples", session.accumulatedSamples()},
      {"fps", msPerFrame_ > 0.0 ? 1000.0 / msPerFrame_ : 0.0},
      {"ms_per_frame", msPerFrame_},
      // Where a frame's time went: the backend's render, then the filters, tone mapping and read-back of its
      // pixels, then their encoding (encode_ms: of the stream the message carries); frame_ms is all of the step.
      {"render_ms", 1000.0 * outcome.renderSeconds},
      {"post_ms", presented_.postMilliseconds},
      {"frame_ms", 1000.0 * outcome.seconds},
      {"bytes_per_second", quality_.bytesPerSecond()},
      {"clients", hub_.clientCount()},
      // The backend that rendered the frame: the CPU's while the GPU programs compile (`starting`), then the GPU's.
      {"backend", session.backend().name()},
      {"device", session.backend().deviceName()},
      {"starting", startingJson(session)},
      {"camera", {{"position", vec(renderer_.camera().position())}, {"forward", vec(renderer_.camera().forward())}}},
      {"applied", {{"max_depth", session.appliedSettings().maxDepth}, {"samples_per_frame", plan.samplesPerPixel}}},
      {"controls", controlsJson()},
  };
  std::shared_ptr<const std::string> jpegMessage, videoMessage;
  if (const std::optional<StripedJpeg>& jpeg = presented_.jpeg) {
    Json h = header;
    h.update({{"format", "jpeg-stripes"},
              {"width", jpeg->width},
              {"height", jpeg->height},
              {"stripes", jpeg->stripes.size()},
              {"quality", jpegQuality_},
              {"encode_ms", jpeg->milliseconds}});
    jpegMessage = binaryMessage(h, packStripedJpeg(*jpeg));
  }
  if (const std::optional<H264Frame>& video = presented_.video) {
    Json h = header;
    h.update({{"format", "h264"},
              {"width", video->width},
              {"height", video->height},
              {"key", video->key},
              {"codec", video->codec},
              {"kilobits_per_second", videoSettings_.maxKilobitsPerSecond},
              {"rate_factor", videoSettings_.rateFactor},
              {"encode_ms", video->milliseconds}});
    videoMessage = binaryMessage(h, video->bytes);
    lastVideoFrame_ = framesSent_;
    lastVideoTime_ = now;
    inputSinceVideo_ = false;
  }
  hub_.publishFrame(framesSent_, {jpegMessage, videoMessage}, plan.preview);
}

void ServeLoop::run(const std::atomic<bool>& stop) {
  while (!stop) {
    hub_.waitForWork(kIdleWait);
    if (const uint64_t changes = hub_.controlChanges(); changes != controlChanges_) {
      // A new controller starts with no buttons or keys held.
      renderer_.input() = CameraInput();
      flyKeys_ = FlyKeys();
      controlChanges_ = changes;
    }
    for (uint64_t client : hub_.takeJoined()) greet(client);
    for (const IncomingMessage& m : hub_.takeMessages())
      if (!stop) handle(m);  // a stop need not wait for the screenshots asked for
    // Once for all the messages that came since the last frame: a slider dragged quickly (or a flood of
    // edits) costs one update of the backend's materials or environment, not one for each message.
    if (environmentEdited_) renderer_.applyEnvironmentControls();
    if (materialsEdited_) renderer_.applyMaterialControls();
    environmentEdited_ = materialsEdited_ = false;
    for (const FrameDelivery& d : hub_.takeDeliveries()) quality_.recordDelivery(d.bytes, d.seconds, d.moving);
    if (stop || !hub_.anyReady()) continue;
    renderFrame(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    if (options_.frames > 0 && framesRendered_ >= options_.frames) break;
  }
}

void ServeLoop::writeExitFiles() {
  if (options_.screenshot.empty()) return;
  if (renderer_.session().frames() == 0)
    throw std::runtime_error("no frame was rendered (no browser connected), so there is no --screenshot to write");
  renderer_.writeScreenshot(options_.screenshot);
}

}  // namespace candela
