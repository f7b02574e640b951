#pragma once
#include <memory>

#include "app/interactive/post_settings.h"
#include "app/viewer/gl_objects.h"
#include "image/image.h"

namespace candela {

// Puts the backend's linear image on screen: a float texture upload, the bilateral pass into a float
// framebuffer when it is on, and tone mapping while drawing into a viewport. Needs a current GL 3.3 context.
class ImageDisplay {
 public:
  ImageDisplay();
  ~ImageDisplay();
  ImageDisplay(const ImageDisplay&) = delete;
  ImageDisplay& operator=(const ImageDisplay&) = delete;

  // The image to show and, unless null, the part of it the camera sees emitted (Backend::readEmission, of the same
  // size), which the bilateral pass then keeps apart: it smooths the rest and adds the emission back.
  void upload(const Image& image, const Image* emission = nullptr);
  // The image from a pixel buffer object holding width * height RGB floats (row 0 first), GPU to GPU; no emission.
  void uploadFromPixelBuffer(GLuint buffer, GLsizei width, GLsizei height);
  // Draws the uploaded image, stretched over the viewport (x, y, width, height) of the current framebuffer.
  void draw(const PostSettings& post, int x, int y, int width, int height);
  // The bilateral pass on the uploaded image, read back.
  Image bilateralOnGpu(const BilateralParams& params);

 private:
  const GlTexture& runBilateral(const BilateralParams& params);

  GlProgram bilateral_;
  GlProgram toneMap_;
  GlTexture source_;
  GlTexture emission_;
  bool hasEmission_ = false;  // emission_ belongs to source_
  GlTexture filtered_;
  GlFramebuffer filteredTarget_;
  GLuint emptyVertexArray_ = 0;
};

}  // namespace candela
