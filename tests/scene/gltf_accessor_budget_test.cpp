// What a glTF's distinct accessors decode to is bounded by the bytes of its buffers: accessors that alias one
// bufferView at other offsets cannot make a small file ask for any amount of memory, while reading one accessor
// again (for another node, channel or primitive) costs nothing more.
#include <gtest/gtest.h>

#include "io/load_diagnostics.h"
#include "scene/loaders/gltf/gltf_accessors.h"

namespace candela {
namespace {

constexpr size_t kFloats = size_t(1) << 20;  // 4 MiB of buffer: the budget is its floor, 512 MiB

tinygltf::Model aliasingModel(int accessors) {
  tinygltf::Model model;
  model.buffers.resize(1);
  model.buffers[0].data.resize(kFloats * sizeof(float));
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteLength = model.buffers[0].data.size();
  model.bufferViews.push_back(view);
  for (int i = 0; i < accessors; ++i) {
    tinygltf::Accessor a;
    a.bufferView = 0;
    a.byteOffset = size_t(i) * 4;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = kFloats - size_t(i);
    model.accessors.push_back(a);
  }
  return model;
}

TEST(GltfAccessorBudget, RereadingAnAccessorCostsNothingMore) {
  const tinygltf::Model model = aliasingModel(1);
  const GltfAccessorReader reader(model, "alias.glb");
  for (int i = 0; i < 200; ++i) EXPECT_EQ(reader.readScalars(0, "accessors[0]").size(), kFloats);
}

TEST(GltfAccessorBudget, AccessorsAliasingOneBufferViewAreRefusedPastTheBudget) {
  const tinygltf::Model model = aliasingModel(200);
  const GltfAccessorReader reader(model, "alias.glb");
  int refusedAt = -1;
  std::string error;
  for (int i = 0; i < 200 && refusedAt < 0; ++i) {
    try {
      reader.readScalars(i, "meshes[" + std::to_string(i) + "].primitives[0].attributes.POSITION");
    } catch (const LoadError& e) {
      refusedAt = i;
      error = e.what();
    }
  }
  EXPECT_EQ(refusedAt, 128);  // 128 x 4 MiB is 512 MiB
  EXPECT_EQ(error.rfind("alias.glb: meshes[128].primitives[0].attributes.POSITION (accessors[128]): the accessors "
                        "read up to this one decode to ",
                        0),
            0u)
      << error;
}

}  // namespace
}  // namespace candela
