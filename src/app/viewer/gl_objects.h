#pragma once
#include <string>

#include "app/viewer/gl.h"

namespace candela {

// Owners of OpenGL objects; they need a current context when created and destroyed.

class GlProgram {
 public:
  // Compiles and links; throws std::runtime_error with the driver's log on failure.
  GlProgram(const char* vertexSource, const char* fragmentSource);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

// A 2D RGB float texture sampled with nearest or linear filtering and clamped at the edges.
class GlTexture {
 public:
  GlTexture();
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  // Reallocates when the size changes; `rgb` holds width * height * 3 floats, row 0 first.
  void upload(GLsizei width, GLsizei height, const float* rgb);
  void allocate(GLsizei width, GLsizei height);  // contents undefined
  GLuint id() const { return id_; }
  GLsizei width() const { return width_; }
  GLsizei height() const { return height_; }

 private:
  GLuint id_ = 0;
  GLsizei width_ = 0;
  GLsizei height_ = 0;
};

// A framebuffer whose one colour attachment is a GlTexture.
class GlFramebuffer {
 public:
  GlFramebuffer();
  ~GlFramebuffer();
  GlFramebuffer(const GlFramebuffer&) = delete;
  GlFramebuffer& operator=(const GlFramebuffer&) = delete;

  // Throws std::runtime_error when the driver rejects the attachment.
  void attach(const GlTexture& texture);
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

}  // namespace candela
