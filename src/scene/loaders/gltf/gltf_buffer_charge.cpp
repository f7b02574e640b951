#include "scene/loaders/gltf/gltf_buffer_charge.h"

#include "io/load_budget.h"

namespace candela {

GltfBufferCharge::GltfBufferCharge(const GltfBufferList& buffers, const std::string& file) : file_(file) {
  for (size_t i = 0; i < buffers.buffers().size(); ++i) {
    const GltfBufferEntry& buffer = buffers.buffers()[i];
    // A data: URI's text is copied and decoded (three bytes for every four) before tinygltf checks the length.
    const uint64_t bytes = buffer.byteLength + buffer.dataUriBytes + buffer.dataUriBytes / 4 * 3;
    charge(bytes, "buffers[" + std::to_string(i) + "]" + (buffer.dataUriBytes ? " (a data: URI)" : ""));
  }
}

GltfBufferCharge::~GltfBufferCharge() { releaseLoadMemory(charged_); }

void GltfBufferCharge::charge(uint64_t bytes, const std::string& element) {
  chargeLoadMemory(bytes, file_, element);
  charged_ += bytes;
}

}  // namespace candela
