#include "scene/loaders/obj/obj_chunk_parser.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/loaders/obj/obj_numbers.h"

namespace candela {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }
bool isLineEnd(char c) { return c == '\n' || c == '\r'; }

// The first '\n' or '\r' at or after `p`, or `end`. Lines end in "\n", "\r\n" or a lone "\r".
const char* lineEnd(const char* p, const char* end) {
  const void* newline = std::memchr(p, '\n', size_t(end - p));
  const char* stop = newline ? static_cast<const char*>(newline) : end;
  const void* carriageReturn = std::memchr(p, '\r', size_t(stop - p));
  return carriageReturn ? static_cast<const char*>(carriageReturn) : stop;
}

// Moves past the line end at `p` (if any); returns the start of the next line.
const char* pastLineEnd(const char* p, const char* end) {
  if (p < end && *p == '\r') ++p;
  if (p < end && *p == '\n') ++p;
  return p;
}

// The statement keyword at the start of a line: a word followed by a blank ("v 1 2 3"). A bare word, a blank
// line or a comment gives an empty keyword. `p` ends up after the keyword.
std::string_view keywordAt(const char*& p, const char* end) {
  while (p < end && isBlank(*p)) ++p;
  const char* start = p;
  while (p < end && !isBlank(*p) && !isLineEnd(*p)) ++p;
  if (p == end || !isBlank(*p) || *start == '#') return {};
  return {start, size_t(p - start)};
}

enum class Attribute { Position = 0, Uv = 1, Normal = 2 };

int64_t& count(ObjCounts& c, Attribute a) {
  return a == Attribute::Position ? c.positions : a == Attribute::Uv ? c.uvs : c.normals;
}
int64_t count(const ObjCounts& c, Attribute a) { return count(const_cast<ObjCounts&>(c), a); }

struct AttributeNames {
  const char* one;
  const char* many;
};
constexpr AttributeNames kNames[3] = {{"vertex", "vertices"},
                                      {"texture coordinate", "texture coordinates"},
                                      {"normal", "normals"}};

class ChunkParser {
 public:
  ChunkParser(std::string_view text, ObjChunk& chunk, const ObjCounts* totals)
      : p_(text.data()), end_(text.data() + text.size()), line_(chunk.firstLine), c_(chunk), totals_(totals) {}

  void run() {
    while (p_ < end_ && !c_.error) {
      statement();
      p_ = pastLineEnd(lineEnd(p_, end_), end_);
      ++line_;
    }
  }

 private:
  void statement() {
    std::string_view k = keywordAt(p_, end_);
    float x[3] = {0, 0, 0};
    if (k == "v") {
      if (attribute(x, 3, "vertex position")) c_.positions.push_back({x[0], x[1], x[2]});
    } else if (k == "vt") {
      if (attribute(x, 2, "texture coordinate")) c_.uvs.push_back({x[0], x[1]});
    } else if (k == "vn") {
      if (attribute(x, 3, "normal")) c_.normals.push_back({x[0], x[1], x[2]});
    } else if (k == "f") {
      face();
    } else if (k == "l" || k == "p") {
      element();
    } else if (k == "s") {
      smoothingGroup();
    } else if (k == "usemtl") {
      material_ = uint32_t(c_.materialStatements.size());
      c_.materialStatements.push_back({ObjMaterialStatement::Kind::UseMaterial, line_, std::string(word())});
    } else if (k == "mtllib") {
      const char* names = p_ + 1;  // after the one blank that ends the keyword
      c_.materialStatements.push_back(
          {ObjMaterialStatement::Kind::Libraries, line_, std::string(names, lineEnd(names, end_))});
    } else if (k == "vw" && !c_.firstSkinWeights) {
      c_.firstSkinWeights = line_;
    }
  }

  // The next blank-separated word of the line; empty at the line end.
  std::string_view word() {
    while (p_ < end_ && isBlank(*p_)) ++p_;
    const char* start = p_;
    while (p_ < end_ && !isBlank(*p_) && !isLineEnd(*p_)) ++p_;
    return {start, size_t(p_ - start)};
  }

  // The next field of a statement of numbers or references; empty at the line end or at a '#' comment.
  std::string_view field() {
    std::string_view w = word();
    if (!w.empty() && w[0] == '#') {
      p_ = lineEnd(p_, end_);
      return {};
    }
    return w;
  }

  bool fail(std::string what) {
    c_.error = ObjProblem{line_, std::move(what)};
    return false;
  }

  // Reads up to `n` coordinates into `out` (the rest stay 0); later fields, such as vertex colours or a w, must
  // still be numbers.
  bool attribute(float* out, int n, const char* what) {
    for (int i = 0;; ++i) {
      std::string_view f = field();
      if (f.empty()) return true;
      float x;
      if (!parseObjFloat(f, x)) return fail("a coordinate is not a number");
      if (i < n) {
        if (!std::isfinite(x)) return fail(std::string("non-finite ") + what);
        out[i] = x;
      }
    }
  }

  int64_t definedBefore(Attribute a) const {
    size_t here = a == Attribute::Position ? c_.positions.size()
                  : a == Attribute::Uv     ? c_.uvs.size()
                                           : c_.normals.size();
    return count(c_.before, a) + int64_t(here);
  }

  // Resolves one reference to a 0-based index; -1 when it refers to a missing texture coordinate or normal
  // (dropped, with a note). False after an error.
  bool resolve(std::string_view text, Attribute a, int64_t& index) {
    const AttributeNames& name = kNames[int(a)];
    int64_t value;
    if (!parseObjInteger(text, value))
      return fail(std::string(name.one) + " reference '" + std::string(text) + "' is not a number");
    if (value == 0) return fail(std::string(name.one) + " reference 0 (OBJ counts from 1)");
    int64_t before = definedBefore(a);
    bool inRange;
    if (value < 0) {
      index = before + value;
      inRange = index >= 0;
    } else {
      index = value - 1;
      int64_t& largest = count(c_.largestReference, a);
      largest = std::max(largest, value);
      inRange = !totals_ || value <= count(*totals_, a);
    }
    if (inRange) return true;
    std::string why = std::string(name.one) + " reference " + std::string(text) + " but " + std::to_string(before) +
                      " " + (before == 1 ? std::string(name.one) + " is" : std::string(name.many) + " are") +
                      " defined before it";
    if (a == Attribute::Position) return fail(why);
    if (c_.droppedReferences++ == 0) c_.firstDroppedReference = ObjProblem{line_, why};
    index = -1;
    return true;
  }

  // One corner "v", "v/t", "v//n" or "v/t/n"; fields after a third '/' are ignored.
  bool corner(std::string_view text, int64_t (&index)[3]) {
    index[1] = index[2] = -1;
    for (int a = 0; a < 3; ++a) {
      size_t slash = text.find('/');
      std::string_view part = text.substr(0, slash);
      if (a == 0 && part.empty()) return fail("element with an empty vertex reference");
      if (!part.empty() && !resolve(part, Attribute(a), index[a])) return false;
      if (slash == std::string_view::npos) break;
      text.remove_prefix(slash + 1);
    }
    return true;
  }

  void face() {
    const size_t first = c_.cornerPositions.size();
    for (std::string_view f = field(); !f.empty(); f = field()) {
      int64_t index[3];
      if (!corner(f, index)) return;
      if (c_.cornerPositions.size() - first == kMaxObjFaceCorners) {
        fail("a face of more than " + std::to_string(kMaxObjFaceCorners) + " corners");
        return;
      }
      c_.cornerPositions.push_back(uint32_t(std::min<int64_t>(index[0], UINT32_MAX)));
      c_.cornerUvs.push_back(int32_t(std::min<int64_t>(index[1], INT32_MAX)));
      c_.cornerNormals.push_back(int32_t(std::min<int64_t>(index[2], INT32_MAX)));
    }
    const size_t corners = c_.cornerPositions.size() - first;
    if (corners < 3) {
      c_.cornerPositions.resize(first);
      c_.cornerUvs.resize(first);
      c_.cornerNormals.resize(first);
      if (c_.degenerateFaces++ == 0) c_.firstDegenerateFace = line_;
      return;
    }
    if (corners != 3 || !c_.faceSizes.empty()) {
      c_.faceSizes.resize(c_.faceCount(), 3);
      c_.faceSizes.push_back(uint32_t(corners));
    }
    c_.faceSmoothing.push_back(smoothing_);
    c_.faceMaterial.push_back(material_);
  }

  // Line and point elements are not rendered; their references must still be well formed.
  void element() {
    size_t corners = 0;
    for (std::string_view f = field(); !f.empty(); f = field(), ++corners) {
      int64_t index[3];
      size_t dropped = c_.droppedReferences;
      std::optional<ObjProblem> firstDropped = c_.firstDroppedReference;
      if (!corner(f, index)) return;
      c_.droppedReferences = dropped;  // nothing of an element is kept, so nothing is lost
      c_.firstDroppedReference = std::move(firstDropped);
    }
    if (corners > 0) ++c_.lineAndPointElements;
  }

  // "s off", "s 0" or "s <group>"; a word that is not a number reads as 0.
  void smoothingGroup() {
    std::string_view w = word();
    if (w.empty()) return;
    uint32_t group = 0;
    if (w.rfind("off", 0) != 0) {
      if (w[0] == '+') w.remove_prefix(1);
      size_t digits = 0;
      while (digits < w.size() && w[digits] >= '0' && w[digits] <= '9') ++digits;
      int64_t value = 0;
      if (digits > 0 && parseObjInteger(w.substr(0, digits), value))
        group = uint32_t(std::min<int64_t>(value, INT32_MAX));
    }
    smoothing_ = group;
    c_.lastSmoothing = group;
  }

  const char* p_;
  const char* end_;
  size_t line_;
  ObjChunk& c_;
  const ObjCounts* totals_;
  uint32_t smoothing_ = kObjInherited;
  uint32_t material_ = kObjInherited;
};

}  // namespace

ObjChunkOutline outlineObjChunk(std::string_view text) {
  ObjChunkOutline outline;
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end) {
    std::string_view k = keywordAt(p, end);
    if (k == "v")
      ++outline.counts.positions;
    else if (k == "vt")
      ++outline.counts.uvs;
    else if (k == "vn")
      ++outline.counts.normals;
    else if (k == "f")
      ++outline.faces;
    p = pastLineEnd(lineEnd(p, end), end);
    ++outline.lines;
  }
  return outline;
}

void parseObjChunk(std::string_view text, ObjChunk& chunk, const ObjCounts* totals) {
  ChunkParser(text, chunk, totals).run();
}

}  // namespace candela
