#include "app/viewer/image_display.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "app/viewer/display_shaders.h"

namespace candela {

ImageDisplay::ImageDisplay()
    : bilateral_(kFullViewportVertexShader, kBilateralFragmentShader),
      toneMap_(kFullViewportVertexShader, kToneMapFragmentShader) {
  glGenVertexArrays(1, &emptyVertexArray_);
}

ImageDisplay::~ImageDisplay() { glDeleteVertexArrays(1, &emptyVertexArray_); }

void ImageDisplay::upload(const Image& image, const Image* emission) {
  static_assert(sizeof(Vec3) == 3 * sizeof(float));
  if (emission && (emission->width != image.width || emission->height != image.height))
    throw std::invalid_argument("the emission image differs in size from the image");
  source_.upload(GLsizei(image.width), GLsizei(image.height), &image.pixels.data()->x);
  hasEmission_ = emission != nullptr;
  if (hasEmission_) emission_.upload(GLsizei(emission->width), GLsizei(emission->height), &emission->pixels.data()->x);
}

void ImageDisplay::uploadFromPixelBuffer(GLuint buffer, GLsizei width, GLsizei height) {
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer);
  source_.upload(width, height, nullptr);  // with an unpack buffer bound, the pointer is an offset into it
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  hasEmission_ = false;
}

const GlTexture& ImageDisplay::runBilateral(const BilateralParams& params) {
  if (params.radius < 0 || params.radius > kMaxBilateralRadius || !(params.spatialSigma > 0.0f) ||
      !(params.rangeSigma > 0.0f))
    throw std::invalid_argument("bilateral parameters out of range");
  filtered_.allocate(source_.width(), source_.height());
  filteredTarget_.attach(filtered_);
  glBindFramebuffer(GL_FRAMEBUFFER, filteredTarget_.id());
  glViewport(0, 0, source_.width(), source_.height());
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glUseProgram(bilateral_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, source_.id());
  glUniform1i(bilateral_.uniform("image"), 0);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, hasEmission_ ? emission_.id() : source_.id());  // unread without emission
  glUniform1i(bilateral_.uniform("emission"), 1);
  glUniform1i(bilateral_.uniform("separateEmission"), hasEmission_ ? 1 : 0);
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(bilateral_.uniform("radius"), params.radius);
  glUniform1f(bilateral_.uniform("spatialScale"), 1.0f / (2.0f * params.spatialSigma * params.spatialSigma));
  glUniform1f(bilateral_.uniform("rangeScale"), 1.0f / (2.0f * params.rangeSigma * params.rangeSigma));
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return filtered_;
}

void ImageDisplay::draw(const PostSettings& post, int x, int y, int width, int height) {
  if (source_.width() == 0 || width <= 0 || height <= 0) return;
  GLint framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  const GlTexture& shown = post.bilateral ? runBilateral(post.bilateralParams) : source_;
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer));

  glViewport(x, y, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glUseProgram(toneMap_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, shown.id());
  // At one texel per pixel, nearest sampling returns each texel exactly; a preview image is stretched smoothly.
  const bool oneToOne = shown.width() == width && shown.height() == height;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, oneToOne ? GL_NEAREST : GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, oneToOne ? GL_NEAREST : GL_LINEAR);
  glUniform1i(toneMap_.uniform("image"), 0);
  glUniform1f(toneMap_.uniform("exposureScale"), std::exp2(post.display.exposure));
  glUniform1i(toneMap_.uniform("toneMapper"), GLint(post.display.toneMapper));
  glBindVertexArray(emptyVertexArray_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

Image ImageDisplay::bilateralOnGpu(const BilateralParams& params) {
  const GlTexture& result = runBilateral(params);
  Image image(uint32_t(result.width()), uint32_t(result.height()));
  std::vector<float> rgba(image.pixels.size() * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, filteredTarget_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, result.width(), result.height(), GL_RGBA, GL_FLOAT, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
  return image;
}

}  // namespace candela
