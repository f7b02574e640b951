#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "app/interactive/post_settings.h"
#include "app/interactive/render_session.h"
#include "app/interactive/viewer_denoiser.h"
#include "backends/film_display.h"

namespace candela {

// A rendered frame as the front end presents it: the session's accumulated image through the post settings. Each
// image is made on the host when first asked for, then kept for the rest of the frame.
class FrameImages {
 public:
  FrameImages(const RenderSession& session, ViewerDenoiser& denoiser, const PostSettings& post)
      : session_(session), denoiser_(denoiser), post_(post) {}

  const RenderSession& session() const { return session_; }
  const PostSettings& post() const { return post_; }
  // Whether the image has to come to the host: a denoiser or the bilateral filter is on. Otherwise a front end may
  // take the backend's image where it lies (the viewer's CUDA-OpenGL interop).
  bool needsHost() const { return post_.denoiser != DenoiserChoice::None || post_.bilateral; }

  // The accumulated image through the chosen denoiser.
  const Image& image();
  // The part of image() the camera sees emitted, which the bilateral filter keeps out of its sums; null while the
  // filter is off.
  const Image* emission();
  // image() through the bilateral filter on the host, emission() kept apart (postFiltered); image() while it is off.
  const Image& filtered();
  // filtered() tone mapped to 8-bit sRGB pixels (backends/film_display.h), made where the film is: on a GPU the
  // filters and the tone mapping run there and only the bytes come back. The OptiX AI denoiser's image is made on
  // the host (filtered()) and tone mapped there. The pixels last as long as this object and the backend's next
  // display read.
  DisplayFrame display();

 private:
  const RenderSession& session_;
  ViewerDenoiser& denoiser_;
  const PostSettings& post_;
  std::optional<Image> image_, emission_, filtered_;
  std::vector<uint8_t> hostPixels_;  // display()'s pixels where they are made on the host
};

}  // namespace candela
