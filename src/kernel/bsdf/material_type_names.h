#pragma once
// The names of the models of CANDELA_MATERIAL_MODELS (kernel/material.h) in scene files and for --shading. Host
// code only.
#include <optional>
#include <string>
#include <string_view>

#include "kernel/material.h"

namespace candela {

struct MaterialModelNames {
  MaterialType type;
  const char* name;         // in scene files
  const char* shadingName;  // for --shading, or nullptr where it does not offer the model
};

inline constexpr MaterialModelNames kMaterialModelNames[] = {
#define CANDELA_MODEL_NAMES(type, Model, name, shadingName) {MaterialType::type, name, shadingName},
    CANDELA_MATERIAL_MODELS(CANDELA_MODEL_NAMES)
#undef CANDELA_MODEL_NAMES
};

// The type whose model scene files call `name`, if any (a mix has no name: scene files cannot make one).
constexpr std::optional<MaterialType> materialTypeNamed(std::string_view name) {
  for (const MaterialModelNames& model : kMaterialModelNames)
    if (name == model.name) return model.type;
  return std::nullopt;
}

// The scene files' name of the model of `type`; nullptr for Mix.
constexpr const char* materialTypeName(MaterialType type) {
  for (const MaterialModelNames& model : kMaterialModelNames)
    if (model.type == type) return model.name;
  return nullptr;
}

// Every model's name, for messages: "diffuse, blinn-phong, ...".
inline std::string materialTypeNameList() {
  std::string list;
  for (const MaterialModelNames& model : kMaterialModelNames)
    list += (list.empty() ? "" : ", ") + std::string(model.name);
  return list;
}

}  // namespace candela
