#include "app/viewer/cuda_gl_interop.h"

// cuda_gl_interop.h includes the system's GL/gl.h, which agrees with the core profile header included above.
#include <cuda_gl_interop.h>
#include <cuda_runtime.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela {

namespace {

using Uuid = std::array<unsigned char, 16>;

// GL_EXT_memory_object's names for the devices that run the current context.
constexpr GLenum kNumDeviceUuids = 0x9596;  // GL_NUM_DEVICE_UUIDS_EXT
constexpr GLenum kDeviceUuid = 0x9597;      // GL_DEVICE_UUID_EXT
using GetUnsignedBytei = void (*)(GLenum target, GLuint index, GLubyte* data);

void check(cudaError_t result, const std::string& what) {
  if (result != cudaSuccess) {
    cudaGetLastError();
    throw std::runtime_error(what + ": " + cudaGetErrorString(result));
  }
}

// The UUIDs of the devices behind the current OpenGL context: from GL_EXT_memory_object where the driver has
// it, else from CUDA's list of the devices that run the context.
std::vector<Uuid> openGlDeviceUuids() {
  std::vector<Uuid> uuids;
  auto getUuid = reinterpret_cast<GetUnsignedBytei>(glfwGetProcAddress("glGetUnsignedBytei_vEXT"));
  if (glfwExtensionSupported("GL_EXT_memory_object") && getUuid) {
    GLint count = 0;
    glGetIntegerv(kNumDeviceUuids, &count);
    for (GLint i = 0; i < count; ++i) {
      Uuid uuid{};
      getUuid(kDeviceUuid, GLuint(i), uuid.data());
      uuids.push_back(uuid);
    }
    return uuids;
  }
  unsigned int count = 0;
  std::array<int, 8> devices{};
  if (cudaGLGetDevices(&count, devices.data(), unsigned(devices.size()), cudaGLDeviceListAll) != cudaSuccess) {
    cudaGetLastError();
    return uuids;
  }
  for (unsigned int i = 0; i < std::min<unsigned int>(count, unsigned(devices.size())); ++i) {
    cudaDeviceProp properties{};
    if (cudaGetDeviceProperties(&properties, devices[i]) != cudaSuccess) continue;
    Uuid uuid{};
    std::copy(std::begin(properties.uuid.bytes), std::end(properties.uuid.bytes), uuid.begin());
    uuids.push_back(uuid);
  }
  return uuids;
}

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "unknown";
}

}  // namespace

CudaGlInterop::CudaGlInterop(const DeviceImage& image, const std::string& deviceName) : image_(image) {
  const Uuid wanted = image.deviceUuid();
  const std::vector<Uuid> uuids = openGlDeviceUuids();
  if (std::find(uuids.begin(), uuids.end(), wanted) == uuids.end())
    throw std::runtime_error("OpenGL runs on " + glString(GL_RENDERER) + ", not on the backend's " + deviceName);
  glGenBuffers(1, &buffer_);
  resize(sizeof(Vec3));  // registers once now, so that a refusal shows before the first frame
}

CudaGlInterop::~CudaGlInterop() { release(); }

void CudaGlInterop::release() noexcept {
  if (resource_) cudaGraphicsUnregisterResource(resource_);
  resource_ = nullptr;
  if (buffer_) glDeleteBuffers(1, &buffer_);
  buffer_ = 0;
}

void CudaGlInterop::resize(size_t bytes) {
  if (bytes == bytes_) return;
  if (resource_) check(cudaGraphicsUnregisterResource(resource_), "unregistering the pixel buffer");
  resource_ = nullptr;
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer_);
  glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(bytes), nullptr, GL_STREAM_DRAW);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  bytes_ = bytes;
  check(cudaGraphicsGLRegisterBuffer(&resource_, buffer_, cudaGraphicsRegisterFlagsWriteDiscard),
        "registering an OpenGL pixel buffer with CUDA");
}

void CudaGlInterop::transfer(ImageDisplay& display, uint32_t width, uint32_t height) {
  resize(size_t(width) * height * sizeof(Vec3));
  check(cudaGraphicsMapResources(1, &resource_, nullptr), "mapping the pixel buffer for CUDA");
  try {
    void* pixels = nullptr;
    size_t mappedBytes = 0;
    check(cudaGraphicsResourceGetMappedPointer(&pixels, &mappedBytes, resource_), "finding the pixel buffer");
    if (mappedBytes < bytes_) throw std::runtime_error("CUDA mapped less of the pixel buffer than was allocated");
    image_.writeImageToDevice(static_cast<Vec3*>(pixels));
  } catch (...) {
    cudaGraphicsUnmapResources(1, &resource_, nullptr);
    throw;
  }
  check(cudaGraphicsUnmapResources(1, &resource_, nullptr), "unmapping the pixel buffer");
  display.uploadFromPixelBuffer(buffer_, GLsizei(width), GLsizei(height));
}

}  // namespace candela
