#include "scene/loaders/pbrt/pbrt_parameters.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "io/load_diagnostics.h"
#include "scene/loaders/pbrt/pbrt_spectra.h"

namespace candela {

namespace {

std::string canonicalType(const std::string& type) {
  if (type == "point") return "point3";
  if (type == "normal") return "normal3";
  if (type == "vector") return "vector3";
  if (type == "color") return "rgb";
  return type;
}

bool isKnownType(const std::string& type) {
  for (const char* known : {"integer", "float", "point2", "vector2", "point3", "vector3", "normal3", "rgb", "spectrum",
                            "blackbody", "string", "texture", "bool"})
    if (type == known) return true;
  return false;
}

void addValue(const PbrtToken& token, PbrtParameter& p, const std::string& file) {
  if (token.kind == PbrtToken::Kind::String) {
    p.strings.push_back(token.text);
    return;
  }
  if (token.kind != PbrtToken::Kind::Word) failLoad(file, token.line, "expected a value for '" + p.name + "'");
  if (token.text == "true" || token.text == "false") {
    p.strings.push_back(token.text);
    return;
  }
  double value = 0;
  const char* first = token.text.data();
  const char* last = first + token.text.size();
  if (first != last && *first == '+') ++first;  // from_chars takes no leading '+'
  auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last || !std::isfinite(value))
    failLoad(file, token.line, "'" + token.text + "' is not a number (value of '" + p.name + "')");
  // pbrt reads its numbers as floats: one beyond their range would become infinite (a sphere of infinite radius,
  // whose bounds are then not-a-number).
  if (std::fabs(value) > double(std::numeric_limits<float>::max()))
    failLoad(file, token.line, "'" + token.text + "' is beyond the range of a float (value of '" + p.name + "')");
  p.numbers.push_back(value);
}

}  // namespace

PbrtParameters parsePbrtParameters(PbrtTokenizer& tokens) {
  PbrtParameters params;
  params.file = tokens.file();
  params.line = tokens.peek().line;
  while (tokens.peek().kind == PbrtToken::Kind::String) {
    PbrtToken declaration = tokens.next();
    const std::string& d = declaration.text;
    size_t typeBegin = d.find_first_not_of(" \t");
    size_t typeEnd = d.find_first_of(" \t", typeBegin);
    size_t nameBegin = typeEnd == std::string::npos ? typeEnd : d.find_first_not_of(" \t", typeEnd);
    size_t nameEnd = nameBegin == std::string::npos ? nameBegin : d.find_first_of(" \t", nameBegin);
    if (typeBegin == std::string::npos || nameBegin == std::string::npos ||
        (nameEnd != std::string::npos && d.find_first_not_of(" \t", nameEnd) != std::string::npos))
      failLoad(tokens.file(), declaration.line, "expected a parameter \"type name\", found \"" + d + "\"");
    PbrtParameter p;
    p.type = canonicalType(d.substr(typeBegin, typeEnd - typeBegin));
    p.name = d.substr(nameBegin, nameEnd == std::string::npos ? std::string::npos : nameEnd - nameBegin);
    if (!isKnownType(p.type))
      failLoad(tokens.file(), declaration.line, "unknown parameter type '" + p.type + "' of '" + p.name + "'");
    PbrtToken value = tokens.next();
    if (value.kind == PbrtToken::Kind::OpenBracket) {
      for (;;) {
        PbrtToken item = tokens.next();
        if (item.kind == PbrtToken::Kind::CloseBracket) break;
        if (item.kind == PbrtToken::Kind::End) failLoad(tokens.file(), value.line, "unclosed '[' of '" + p.name + "'");
        addValue(item, p, tokens.file());
      }
    } else {
      addValue(value, p, tokens.file());
    }
    params.list.push_back(std::move(p));
  }
  return params;
}

void PbrtParameters::fail(const std::string& what) const { failLoad(file, line, what); }

const PbrtParameter* PbrtParameters::find(const std::string& name) const {
  for (const PbrtParameter& p : list)
    if (p.name == name) {
      p.used = true;
      return &p;
    }
  return nullptr;
}

float PbrtParameters::getFloat(const std::string& name, float fallback) const {
  const PbrtParameter* p = find(name);
  if (!p || p->type == "texture") return fallback;
  if (p->numbers.size() != 1) fail("'" + name + "' needs one number");
  return float(p->numbers[0]);
}

int PbrtParameters::getInt(const std::string& name, int fallback) const {
  const PbrtParameter* p = find(name);
  if (!p) return fallback;
  if (p->numbers.size() != 1) fail("'" + name + "' needs one number");
  double v = p->numbers[0];
  if (!(v >= -2147483648.0 && v <= 2147483647.0)) fail("'" + name + "' is out of range");
  return int(v);
}

bool PbrtParameters::getBool(const std::string& name, bool fallback) const {
  const PbrtParameter* p = find(name);
  if (!p) return fallback;
  if (p->strings.size() != 1 || (p->strings[0] != "true" && p->strings[0] != "false"))
    fail("'" + name + "' needs true or false");
  return p->strings[0] == "true";
}

std::string PbrtParameters::getString(const std::string& name, const std::string& fallback) const {
  const PbrtParameter* p = find(name);
  if (!p) return fallback;
  if (p->strings.size() != 1) fail("'" + name + "' needs one string");
  return p->strings[0];
}

std::vector<double> PbrtParameters::getNumbers(const std::string& name) const {
  const PbrtParameter* p = find(name);
  return p ? p->numbers : std::vector<double>{};
}

std::vector<Vec3> PbrtParameters::getVec3s(const std::string& name) const {
  std::vector<double> n = getNumbers(name);
  if (n.size() % 3 != 0) fail("'" + name + "' needs a multiple of 3 numbers");
  std::vector<Vec3> out(n.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {float(n[3 * i]), float(n[3 * i + 1]), float(n[3 * i + 2])};
  return out;
}

std::vector<Vec2> PbrtParameters::getVec2s(const std::string& name) const {
  std::vector<double> n = getNumbers(name);
  if (n.size() % 2 != 0) fail("'" + name + "' needs a multiple of 2 numbers");
  std::vector<Vec2> out(n.size() / 2);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {float(n[2 * i]), float(n[2 * i + 1])};
  return out;
}

std::vector<int64_t> PbrtParameters::getInts(const std::string& name) const {
  std::vector<double> n = getNumbers(name);
  std::vector<int64_t> out(n.size());
  for (size_t i = 0; i < n.size(); ++i) {
    if (!(n[i] >= -9e15 && n[i] <= 9e15) || n[i] != std::floor(n[i])) fail("'" + name + "' needs integers");
    out[i] = int64_t(n[i]);
  }
  return out;
}

std::optional<PbrtColor> PbrtParameters::getColor(const std::string& name) const {
  const PbrtParameter* p = find(name);
  if (!p || p->type == "texture") return std::nullopt;
  PbrtColor c;
  if (p->type == "rgb") {
    if (p->numbers.size() != 3) fail("'" + name + "' needs 3 numbers");
    c.rgb = {float(p->numbers[0]), float(p->numbers[1]), float(p->numbers[2])};
  } else if (p->type == "float") {
    if (p->numbers.size() != 1) fail("'" + name + "' needs one number");
    float v = float(p->numbers[0]);
    c.rgb = {v, v, v};
  } else if (p->type == "blackbody") {
    if (p->numbers.empty()) fail("'" + name + "' needs a temperature");
    c.rgb = blackbodyRgb(float(p->numbers[0]));
    c.normalisedLight = true;
  } else if (p->type == "spectrum") {
    if (p->strings.size() == 1) {
      std::optional<Vec3> named = namedSpectrumRgb(p->strings[0]);
      if (!named) {
        // A name candela does not know (spectrum files were read before, pbrt_spectrum_files.h): the
        // parameter's default stands in.
        unknownSpectra.push_back(p->strings[0]);
        return std::nullopt;
      }
      c.rgb = *named;
      c.normalisedLight = isNamedIlluminant(p->strings[0]);
    } else if (p->numbers.size() >= 2 && p->numbers.size() % 2 == 0) {
      c.rgb = sampledSpectrumRgb(p->numbers);
      c.normalisedLight = true;
    } else if (p->numbers.size() == 1) {
      float v = float(p->numbers[0]);
      c.rgb = {v, v, v};
    } else {
      fail("'" + name + "' needs wavelength-value pairs, a spectrum's name or a spectrum file");
    }
  } else {
    fail("'" + name + "' needs a colour, not a " + p->type);
  }
  if (!isFinite(c.rgb)) fail("'" + name + "' is not finite");
  return c;
}

std::optional<std::string> PbrtParameters::getTexture(const std::string& name) const {
  const PbrtParameter* p = find(name);
  if (!p || p->type != "texture") return std::nullopt;
  if (p->strings.size() != 1) fail("'" + name + "' needs one texture name");
  return p->strings[0];
}

void PbrtParameters::markAllUsed() const {
  for (const PbrtParameter& p : list) p.used = true;
}

std::vector<std::string> PbrtParameters::unused() const {
  std::vector<std::string> names;
  for (const PbrtParameter& p : list)
    if (!p.used) names.push_back(p.name);
  return names;
}

}  // namespace candela
