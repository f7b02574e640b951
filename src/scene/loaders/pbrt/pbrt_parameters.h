#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/loaders/pbrt/pbrt_tokenizer.h"

namespace candela {

// One parameter of a pbrt directive: `"float radius" [ 2 ]`. Numbers and strings are kept as written; `type` is
// the declared type ("float", "rgb", "spectrum", "texture", ...) with pbrt-v3's synonyms folded ("point" →
// "point3", "normal" → "normal3", "color" → "rgb", "vector" → "vector3").
struct PbrtParameter {
  std::string type;
  std::string name;
  std::vector<double> numbers;
  std::vector<std::string> strings;
  mutable bool used = false;  // a lookup asked for it (lookups are const; this only feeds a warning)
};

// A colour a parameter gave: `rgb`, a named or sampled `spectrum`, or a `blackbody` temperature, turned into
// linear sRGB (pbrt_spectra.h). `illuminant` is set for spectra that pbrt normalises to unit luminance when they
// describe light (everything but rgb).
struct PbrtColor {
  Vec3 rgb{0, 0, 0};
  bool normalisedLight = false;
};

// The parameter list of one directive, with typed lookups that fall back to a default when the parameter is
// absent. A parameter of the wrong type or size throws LoadError naming `file:line`.
class PbrtParameters {
 public:
  std::string file;
  size_t line = 0;
  std::vector<PbrtParameter> list;
  // Spectra that colour lookups met but could not turn into RGB (unknown names, files of a scene read from memory).
  mutable std::vector<std::string> unknownSpectra;

  const PbrtParameter* find(const std::string& name) const;
  float getFloat(const std::string& name, float fallback) const;
  int getInt(const std::string& name, int fallback) const;
  bool getBool(const std::string& name, bool fallback) const;
  std::string getString(const std::string& name, const std::string& fallback) const;
  std::vector<double> getNumbers(const std::string& name) const;  // empty when absent
  std::vector<Vec3> getVec3s(const std::string& name) const;      // point3, normal3, vector3
  std::vector<Vec2> getVec2s(const std::string& name) const;      // point2 (or float pairs)
  std::vector<int64_t> getInts(const std::string& name) const;
  // A colour (rgb, spectrum, blackbody, or a float for grey); nothing when absent, a texture, or a spectrum file
  // not read (pbrt_spectrum_files.h) or a name that is not known (recorded in unknownSpectra).
  std::optional<PbrtColor> getColor(const std::string& name) const;
  // The texture a parameter names, when it is of type "texture".
  std::optional<std::string> getTexture(const std::string& name) const;
  // Names of parameters no lookup asked for: what the loader did not apply.
  std::vector<std::string> unused() const;
  // For a directive left out as a whole (one warning says so): none of its parameters is reported on its own.
  void markAllUsed() const;

  [[noreturn]] void fail(const std::string& what) const;
};

// Reads the parameter list that follows a directive (pairs of a quoted "type name" and a value or [values]).
PbrtParameters parsePbrtParameters(PbrtTokenizer& tokens);

}  // namespace candela
