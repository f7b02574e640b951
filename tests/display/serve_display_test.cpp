// The CPU backend's display frames are the serve page's frames (app/serve/frame_encoding.h's displayImage), byte for
// byte, with and without its bilateral display pass.
#include <gtest/gtest.h>

#include <vector>

#include "app/serve/frame_encoding.h"
#include "backends/cpu/cpu_backend.h"
#include "backends/film_display.h"
#include "scene/builtin_scenes.h"

namespace candela {
namespace {

TEST(ServeDisplay, CpuFramesAreTheServeFrames) {
  const Scene scene = makeCornellBox();
  RenderSettings settings;
  settings.width = 72;
  settings.height = 40;
  CpuBackend backend;
  backend.setScene(scene);
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(float(settings.width) / float(settings.height)));
  backend.render(3);
  for (bool bilateral : {false, true})
    for (ToneMapper mapper : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard})
      for (float exposure : {0.0f, 1.5f, -2.25f}) {
        PostSettings post;
        post.display = {exposure, mapper};
        post.bilateral = bilateral;
        DisplayRequest request;
        request.display = post.display;
        if (bilateral) request.smoothing = post.bilateralParams;
        const DisplayFrame frame = backend.display().read(request);
        const DisplayImage served = displayImage(backend.readImage(), post);
        ASSERT_EQ(frame.width, served.width);
        ASSERT_EQ(frame.height, served.height);
        EXPECT_EQ(std::vector<uint8_t>(frame.rgb, frame.rgb + served.rgb.size()), served.rgb)
            << toneMapperName(mapper) << " at exposure " << exposure << (bilateral ? ", bilateral" : "");
      }
}

}  // namespace
}  // namespace candela
