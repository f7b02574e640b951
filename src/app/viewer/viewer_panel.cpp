#include "app/viewer/viewer_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <optional>
#include <span>

#include "app/denoising/denoiser_choice.h"

namespace candela {

namespace {

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kOkColour{0.55f, 0.9f, 0.55f, 1.0f};
constexpr float kDenoiserComboWidth = 120.0f;

bool sliderUint(const char* label, uint32_t& value, int lo, int hi) {
  int v = int(value);
  bool changed = ImGui::SliderInt(label, &v, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
  if (changed) value = uint32_t(v);
  return changed;
}

void drawStatus(const PanelStatus& s) {
  ImGui::Text("Backend  %s", s.backend.c_str());
  ImGui::TextWrapped("Device   %s", s.device.c_str());
  ImGui::TextWrapped("Display  %s", s.imageTransfer.c_str());
  if (!s.starting.empty()) ImGui::TextColored(kOkColour, "%s", s.starting.c_str());
  ImGui::Text("%.1f fps, %.2f ms/frame", s.framesPerSecond, s.msPerFrame);
  ImGui::Text("Samples  %u per pixel", s.accumulatedSamples);
  ImGui::Text("Image    %u x %u%s", s.imageWidth, s.imageHeight, s.preview ? "  (moving: preview)" : "");
  ImGui::Separator();
  ImGui::Text("Scene    %s", s.sceneName.c_str());
  ImGui::Text("%zu vertices, %zu triangles", s.scene.vertices, s.scene.triangles);
  ImGui::Text("%zu meshes (%zu instances)", s.scene.meshes, s.scene.instances);
  ImGui::Text("%zu materials, %zu textures", s.scene.materials, s.scene.textures);
  ImGui::Separator();
  ImGui::Text("Camera   %.3f %.3f %.3f", s.cameraPosition.x, s.cameraPosition.y, s.cameraPosition.z);
  ImGui::Text("Looking  %.3f %.3f %.3f", s.cameraDirection.x, s.cameraDirection.y, s.cameraDirection.z);
}

void drawRenderSettings(ViewerControls& c, PanelRequests& requests) {
  sliderUint("Max depth", c.maxDepth, 1, 64);
  sliderUint("Samples/frame", c.samplesPerFrame, 1, 64);
  ImGui::Checkbox("Accumulate", &c.accumulate);
  // Backends take a new environment or new materials without rebuilding the geometry, so sliders apply while
  // they are dragged.
  const bool intensity = ImGui::SliderFloat("Env intensity", &c.environmentScale, 0.0f, 16.0f, "x %.3f",
                                            ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  const bool rotation = ImGui::SliderFloat("Env rotation", &c.environmentRotation, -180.0f, 180.0f, "%.1f deg",
                                           ImGuiSliderFlags_AlwaysClamp);
  requests.applyEnvironment = intensity || rotation;
}

void drawMaterials(ViewerControls& c, PanelRequests& requests) {
  int model = int(c.materials.shading);
  if (ImGui::Combo("Shading", &model, "Each material's own\0Blinn-Phong\0PBR\0Disney\0")) {
    c.materials.shading = ShadingModel(model);
    requests.applyMaterials = true;
  }
  const std::span<const OverrideParameter> parameters = overrideParameters();
  for (size_t i = c.overrideSliders.size(); i < parameters.size(); ++i)
    c.overrideSliders.push_back(0.5f * (parameters[i].min + parameters[i].max));
  for (size_t i = 0; i < parameters.size(); ++i) {
    const OverrideParameter& p = parameters[i];
    std::optional<float>& value = c.materials.*(p.field);
    bool on = value.has_value();
    ImGui::PushID(int(i));
    if (ImGui::Checkbox("##override", &on)) {
      value = on ? std::optional<float>(c.overrideSliders[i]) : std::nullopt;
      requests.applyMaterials = true;
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(!on);
    const bool dragged =
        ImGui::SliderFloat(p.name, &c.overrideSliders[i], p.min, p.max, "%.3f", ImGuiSliderFlags_AlwaysClamp);
    if (dragged && on) {
      value = c.overrideSliders[i];
      requests.applyMaterials = true;
    }
    ImGui::EndDisabled();
    ImGui::PopID();
  }
}

void drawPost(PostSettings& post) {
  int mapper = int(post.display.toneMapper);
  if (ImGui::Combo("Tone mapper", &mapper, "ACES filmic\0Clamp\0Reinhard\0"))
    post.display.toneMapper = ToneMapper(mapper);
  ImGui::SliderFloat("Exposure", &post.display.exposure, -10.0f, 10.0f, "%.2f stops");
  // One row, so that the panel still fits a short window.
  int denoiser = int(post.denoiser);
  ImGui::SetNextItemWidth(kDenoiserComboWidth);
  const char* const choices =
      inThisBuild(DenoiserChoice::Optix) ? "No denoiser\0A-trous\0OptiX AI\0" : "No denoiser\0A-trous\0";
  if (ImGui::Combo("##denoiser", &denoiser, choices)) post.denoiser = DenoiserChoice(denoiser);
  ImGui::SameLine();
  ImGui::BeginDisabled(post.denoiser != DenoiserChoice::Atrous);
  ImGui::SliderInt("Passes", &post.atrousParams.passes, 1, kMaxAtrousPasses, "%d", ImGuiSliderFlags_AlwaysClamp);
  ImGui::EndDisabled();
  ImGui::Checkbox("Bilateral filter", &post.bilateral);
  ImGui::BeginDisabled(!post.bilateral);
  ImGui::SliderInt("Radius", &post.bilateralParams.radius, 1, kMaxBilateralRadius, "%d px",
                   ImGuiSliderFlags_AlwaysClamp);
  ImGui::SliderFloat("Spatial sigma", &post.bilateralParams.spatialSigma, 0.25f, 32.0f, "%.2f px",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  ImGui::SliderFloat("Range sigma", &post.bilateralParams.rangeSigma, 0.001f, 10.0f, "%.3f",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  ImGui::EndDisabled();
}

// Play/pause, the time (dragging it pauses) and, where the scene has several, the animation that plays.
void drawAnimation(const PanelStatus& s, AnimationControls& a) {
  const size_t clip = size_t(a.clip) < s.animationRanges.size() ? size_t(a.clip) : 0;
  if (ImGui::Button(a.playing ? "Pause" : "Play")) a.playing = !a.playing;
  ImGui::SameLine();
  const auto [start, end] = s.animationRanges[clip];
  if (ImGui::SliderFloat("Time", &a.time, start, end, "%.2f s", ImGuiSliderFlags_AlwaysClamp)) a.playing = false;
  if (s.animationClips.size() < 2) return;
  if (ImGui::BeginCombo("Animation", s.animationClips[clip].c_str())) {
    for (size_t i = 0; i < s.animationClips.size(); ++i)
      if (ImGui::Selectable(s.animationClips[i].c_str(), i == clip)) {
        a.clip = int(i);
        a.time = s.animationRanges[i].first;
      }
    ImGui::EndCombo();
  }
}

void drawActions(ViewerControls& c, PanelRequests& requests) {
  ImGui::InputText("##shot", &c.screenshotBase);
  ImGui::SameLine();
  requests.saveScreenshot = ImGui::Button("Save PNG+EXR");
  ImGui::InputText("##file", &c.sceneFilePath);
  ImGui::SameLine();
  requests.saveSceneFile = ImGui::Button("Save camera");
  const bool entered =
      ImGui::InputTextWithHint("##open", "scene name or file", &c.openSpec, ImGuiInputTextFlags_EnterReturnsTrue);
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  requests.openSceneField = {0.5f * (lo.x + hi.x), 0.5f * (lo.y + hi.y)};
  requests.openSceneFieldActive = ImGui::IsItemActive();
  ImGui::SameLine();
  requests.openScene = ImGui::Button("Open scene") || entered;
}

}  // namespace

PanelRequests drawPanel(const PanelStatus& status, ViewerControls& controls, float x, float width, float height) {
  PanelRequests requests;
  ImGui::SetNextWindowPos(ImVec2(x, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, height));
  ImGui::Begin("candela", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushItemWidth(-110.0f);
  if (ImGui::CollapsingHeader("Status", ImGuiTreeNodeFlags_DefaultOpen)) drawStatus(status);
  if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) drawRenderSettings(controls, requests);
  if (!status.animationClips.empty() && ImGui::CollapsingHeader("Animation", ImGuiTreeNodeFlags_DefaultOpen))
    drawAnimation(status, controls.animation);
  if (ImGui::CollapsingHeader("Materials")) drawMaterials(controls, requests);
  if (ImGui::CollapsingHeader("Post", ImGuiTreeNodeFlags_DefaultOpen)) drawPost(controls.post);
  if (ImGui::CollapsingHeader("Actions", ImGuiTreeNodeFlags_DefaultOpen)) drawActions(controls, requests);
  if (!status.message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, status.messageIsError ? kErrorColour : kOkColour);
    ImGui::TextWrapped("%s", status.message.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::Separator();
  ImGui::TextDisabled("Drag: left/right orbit, middle pan; wheel dolly");
  ImGui::TextDisabled("WASD/QE fly, F frame, R reset, F12 state, Esc quit");
  ImGui::PopItemWidth();
  ImGui::End();
  return requests;
}

}  // namespace candela
