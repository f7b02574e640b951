#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.h"
#include "scene/loaders/page_allocator.h"

namespace candela {

// Numbers of OBJ attribute statements ("v", "vt", "vn"), or a reference of each kind.
struct ObjCounts {
  int64_t positions = 0, uvs = 0, normals = 0;
};

// Something wrong in OBJ text and the line it is on.
struct ObjProblem {
  size_t line = 0;
  std::string what;
};

// "mtllib" and "usemtl": what they mean depends on the libraries named before them, so they are handled in file
// order after the chunks are parsed.
struct ObjMaterialStatement {
  enum class Kind : uint8_t { Libraries, UseMaterial };
  Kind kind = Kind::UseMaterial;
  size_t line = 0;
  std::string text;  // the library names as written after "mtllib", or the material name
};

// A face's smoothing group or material statement when the chunk has not set one: whatever held at its start.
constexpr uint32_t kObjInherited = ~0u;

// One piece of OBJ text (whole lines) parsed into compact arrays. Faces keep their corners as written, with
// relative references resolved; they are triangulated once every position in the file is known.
struct ObjChunk {
  // Set before parsing: where the chunk starts, and how many attributes the lines before it define.
  size_t firstLine = 1;
  uint64_t byteOffset = 0;
  size_t byteSize = 0;
  ObjCounts before;

  // In pages of their own, so that the memory goes back to the system as soon as the whole file's arrays are
  // put together.
  PageVector<Vec3> positions, normals;
  PageVector<Vec2> uvs;                          // as written: v runs up the image
  PageVector<uint32_t> cornerPositions;          // 0-based, for positive references possibly past the end
  PageVector<int32_t> cornerUvs, cornerNormals;  // 0-based, -1: none
  PageVector<uint32_t> faceSizes;                // corners per face; left empty while every face is a triangle
  PageVector<uint32_t> faceSmoothing;            // smoothing group per face, or kObjInherited
  PageVector<uint32_t> faceMaterial;  // per face the index of its "usemtl" in materialStatements, or kObjInherited
  std::vector<ObjMaterialStatement> materialStatements;
  std::optional<uint32_t> lastSmoothing;  // the group the chunk leaves set

  ObjCounts largestReference;  // largest positive reference of each kind, to check against the file's totals
  size_t lineAndPointElements = 0;
  size_t degenerateFaces = 0;  // faces with fewer than 3 corners, left out
  std::optional<size_t> firstDegenerateFace, firstSkinWeights;
  size_t droppedReferences = 0;  // texture-coordinate and normal references to nothing, ignored
  std::optional<ObjProblem> firstDroppedReference;
  std::optional<ObjProblem> error;  // parsing stopped at the first error

  size_t faceCount() const { return faceSmoothing.size(); }
};

// The most corners a face may have. Real polygons have far fewer; a face line of millions of corners would cost
// seconds and gigabytes to triangulate, so it is refused with the line's number.
constexpr size_t kMaxObjFaceCorners = size_t(1) << 16;

// The attribute statements, faces and lines in `text`, as parseObjChunk reads them.
struct ObjChunkOutline {
  ObjCounts counts;
  size_t faces = 0;
  size_t lines = 0;
};
ObjChunkOutline outlineObjChunk(std::string_view text);

// Parses the whole lines of `text` into `chunk` (its firstLine and before already set). The statements read
// are v, vt, vn (missing coordinates are 0; every field must be a number), f (polygons; references may be
// relative; at most kMaxObjFaceCorners corners), l and p (counted, not kept), s, usemtl and mtllib (recorded) and vw
// (noted, ignored); o, g and anything else are ignored, as are fields after a '#'. A reference to a missing texture
// coordinate or normal is dropped; any other problem stops parsing with chunk.error. Positive references are checked
// only when `totals` (the counts of the whole file) are given: a forward reference is allowed.
void parseObjChunk(std::string_view text, ObjChunk& chunk, const ObjCounts* totals);

}  // namespace candela
