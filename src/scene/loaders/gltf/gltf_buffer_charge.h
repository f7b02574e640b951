#pragma once
#include <cstdint>
#include <string>

#include "scene/loaders/gltf/gltf_buffer_list.h"

namespace candela {

// The load's memory budget (io/load_budget.h) charged for a glTF file's buffers before tinygltf reads them.
// tinygltf holds every buffer at its byteLength, however it comes (a copy of a .glb's BIN chunk, a data: URI
// decoded, an external file read whole), and a data: URI's text is copied and decoded on the way: a file that
// claims more than the load may use is refused in one line naming the buffer, before any of it is allocated.
// Buffers that decoders add to the model later (meshopt's decoded bufferViews) are charged to it too, before they
// are decoded. The charge is returned when the object goes, with the model that held the buffers. A file whose
// JSON cannot be read has no buffers in its list and is charged nothing (tinygltf reports it).
class GltfBufferCharge {
 public:
  GltfBufferCharge(const GltfBufferList& buffers, const std::string& file);
  ~GltfBufferCharge();
  GltfBufferCharge(const GltfBufferCharge&) = delete;
  GltfBufferCharge& operator=(const GltfBufferCharge&) = delete;

  // Charges `bytes` that `element` of the file is about to take in the model (chargeLoadMemory's LoadBudgetError
  // when they do not fit).
  void charge(uint64_t bytes, const std::string& element);

 private:
  std::string file_;
  uint64_t charged_ = 0;
};

}  // namespace candela
