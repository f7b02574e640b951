#include "app/viewer/gl_objects.h"

#include <stdexcept>
#include <vector>

namespace candela {

namespace {

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(size_t(length > 1 ? length : 1), '\0');
  if (isProgram)
    glGetProgramInfoLog(object, GLsizei(log.size()), nullptr, log.data());
  else
    glGetShaderInfoLog(object, GLsizei(log.size()), nullptr, log.data());
  return log.data();
}

GLuint compileShader(GLenum stage, const char* source) {
  GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string log = infoLog(shader, false);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("the display shader did not compile: ") + log);
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const char* vertexSource, const char* fragmentSource) {
  GLuint vertex = compileShader(GL_VERTEX_SHADER, vertexSource);
  GLuint fragment = 0;
  try {
    fragment = compileShader(GL_FRAGMENT_SHADER, fragmentSource);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string log = infoLog(id_, true);
    glDeleteProgram(id_);
    throw std::runtime_error("the display shader did not link: " + log);
  }
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

GlTexture::GlTexture() {
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GlTexture::~GlTexture() { glDeleteTextures(1, &id_); }

void GlTexture::upload(GLsizei width, GLsizei height, const float* rgb) {
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (width != width_ || height != height_) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGB, GL_FLOAT, rgb);
    width_ = width;
    height_ = height;
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGB, GL_FLOAT, rgb);
  }
}

void GlTexture::allocate(GLsizei width, GLsizei height) {
  if (width == width_ && height == height_) return;
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  width_ = width;
  height_ = height;
}

GlFramebuffer::GlFramebuffer() { glGenFramebuffers(1, &id_); }
GlFramebuffer::~GlFramebuffer() { glDeleteFramebuffers(1, &id_); }

void GlFramebuffer::attach(const GlTexture& texture) {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.id(), 0);
  GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("the driver cannot render into a float texture (framebuffer status " +
                             std::to_string(status) + ")");
}

}  // namespace candela
