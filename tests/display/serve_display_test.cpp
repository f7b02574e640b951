// The CPU backend's display frames are the serve page's frames (app/serve/frame_encoding.h's displayImage), byte for
// byte, with and without the bilateral filter that keeps the emission apart.
#include <gtest/gtest.h>

#include <vector>

#include "app/serve/frame_encoding.h"
#include "backends/cpu/cpu_backend.h"
#include "backends/film_display.h"
#include "backends/film_filters.h"
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
  backend.setAovsEnabled(true);
  backend.render(3);
  const BilateralParams bilateral;
  for (bool filtered : {false, true})
    for (ToneMapper mapper : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard})
      for (float exposure : {0.0f, 1.5f, -2.25f}) {
        const DisplaySettings display{exposure, mapper};
        DisplayRequest request;
        request.display = display;
        if (filtered) request.source = BilateralFiltered{bilateral};
        const DisplayFrame frame = backend.display().read(request);
        // The page's bilateral pass is the film filter that keeps the emission apart (app/interactive/post_filter).
        const Image linear = filtered ? backend.filters().bilateral(bilateral) : backend.readImage();
        const DisplayImage served = displayImage(linear, display);
        ASSERT_EQ(frame.width, served.width);
        ASSERT_EQ(frame.height, served.height);
        EXPECT_EQ(std::vector<uint8_t>(frame.rgb, frame.rgb + served.rgb.size()), served.rgb)
            << toneMapperName(mapper) << " at exposure " << exposure << (filtered ? ", bilateral" : "");
      }
}

}  // namespace
}  // namespace candela
