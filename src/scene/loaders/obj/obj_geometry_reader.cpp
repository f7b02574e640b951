#include "scene/loaders/obj/obj_geometry_reader.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <climits>
#include <numeric>

#include "io/load_budget.h"
#include "scene/loaders/obj/obj_chunk_parser.h"
#include "scene/loaders/polygon_triangulation.h"

namespace candela {

namespace {

// Cuts `text` into pieces of about `size` bytes, each ending after a '\n' (the last one at the end of `text`).
std::vector<std::string_view> splitIntoChunks(std::string_view text, size_t size) {
  std::vector<std::string_view> pieces;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.size();
    if (text.size() - start > size) {
      size_t newline = text.find('\n', start + size - 1);
      if (newline != std::string_view::npos) end = newline + 1;
    }
    pieces.push_back(text.substr(start, end - start));
    start = end;
  }
  return pieces;
}

// The material and smoothing group in force where a chunk starts, and what its "usemtl" statements chose.
struct ChunkMaterials {
  uint32_t atStart = kObjNoMaterial;
  uint32_t smoothingAtStart = 0;
  std::vector<uint32_t> ofStatement;
};

// Appends the `part` arrays of all chunks into one, freeing each as it goes so that the data is held twice
// only one array at a time.
template <class T>
std::vector<T> concatenate(std::vector<ObjChunk>& chunks, PageVector<T> ObjChunk::*part) {
  std::vector<size_t> offsets(chunks.size() + 1, 0);
  for (size_t i = 0; i < chunks.size(); ++i) offsets[i + 1] = offsets[i] + (chunks[i].*part).size();
  std::vector<T> all(offsets.back());
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t i) {
    PageVector<T>& v = chunks[i].*part;
    std::copy(v.begin(), v.end(), all.begin() + std::ptrdiff_t(offsets[i]));
    PageVector<T>().swap(v);
  });
  return all;
}

// Turns a chunk's faces into triangles: its corner arrays then hold 3 corners per triangle, and its face arrays
// one resolved smoothing group and material per triangle. Returns how many polygons were too large or complex to
// follow their outline (triangulatePolygon).
size_t triangulateChunk(ObjChunk& c, const ChunkMaterials& m, const std::vector<Vec3>& positions) {
  for (uint32_t& s : c.faceSmoothing)
    if (s == kObjInherited) s = m.smoothingAtStart;
  for (uint32_t& k : c.faceMaterial) k = k == kObjInherited ? m.atStart : m.ofStatement[k];
  if (c.faceSizes.empty()) return 0;  // all triangles already

  size_t triangles = 0;
  for (uint32_t n : c.faceSizes) triangles += n - 2;
  PageVector<uint32_t> cornerPositions, smoothing, materials;
  PageVector<int32_t> cornerUvs, cornerNormals;
  cornerPositions.reserve(3 * triangles);
  cornerUvs.reserve(3 * triangles);
  cornerNormals.reserve(3 * triangles);
  smoothing.reserve(triangles);
  materials.reserve(triangles);
  std::vector<Vec3> polygon;
  std::vector<uint32_t> corners;
  size_t first = 0, fanned = 0;
  for (size_t f = 0; f < c.faceSizes.size(); ++f) {
    const size_t n = c.faceSizes[f];
    polygon.resize(n);
    for (size_t k = 0; k < n; ++k) polygon[k] = positions[c.cornerPositions[first + k]];
    corners.clear();
    if (!triangulatePolygon(polygon, corners)) ++fanned;
    for (uint32_t k : corners) {
      cornerPositions.push_back(c.cornerPositions[first + k]);
      cornerUvs.push_back(c.cornerUvs[first + k]);
      cornerNormals.push_back(c.cornerNormals[first + k]);
    }
    smoothing.insert(smoothing.end(), n - 2, c.faceSmoothing[f]);
    materials.insert(materials.end(), n - 2, c.faceMaterial[f]);
    first += n;
  }
  c.cornerPositions = std::move(cornerPositions);
  c.cornerUvs = std::move(cornerUvs);
  c.cornerNormals = std::move(cornerNormals);
  c.faceSmoothing = std::move(smoothing);
  c.faceMaterial = std::move(materials);
  PageVector<uint32_t>().swap(c.faceSizes);
  return fanned;
}

class GeometryReader {
 public:
  GeometryReader(const std::string& name, ObjTextSource& text, ObjMaterialResolver& materials, LoadWarnings& warnings,
                 const ObjReadOptions& options)
      : name_(name), text_(text), materials_(materials), warnings_(warnings), options_(options) {}

  ObjGeometry read() {
    for (ObjTextSource::Window w = text_.next(); !w.text.empty(); w = text_.next()) readWindow(w);
    checkAgainstTotals();
    report();
    return assemble();
  }

 private:
  void readWindow(const ObjTextSource::Window& window) {
    std::vector<std::string_view> pieces = splitIntoChunks(window.text, std::max<size_t>(options_.chunkBytes, 1));
    std::vector<ObjChunkOutline> outlines(pieces.size());
    tbb::parallel_for(size_t(0), pieces.size(), [&](size_t i) { outlines[i] = outlineObjChunk(pieces[i]); });

    const size_t first = chunks_.size(), firstLine = line_;
    chunks_.resize(first + pieces.size());
    chunkMaterials_.resize(chunks_.size());
    for (size_t i = 0; i < pieces.size(); ++i) {
      ObjChunk& c = chunks_[first + i];
      c.firstLine = line_;
      c.byteOffset = window.offset + uint64_t(pieces[i].data() - window.text.data());
      c.byteSize = pieces[i].size();
      c.before = totals_;
      totals_.positions += outlines[i].counts.positions;
      totals_.uvs += outlines[i].counts.uvs;
      totals_.normals += outlines[i].counts.normals;
      line_ += outlines[i].lines;
    }
    if (std::max({totals_.positions, totals_.uvs, totals_.normals}) > INT32_MAX)
      failLoad(name_, "has more than 2147483647 vertices, texture coordinates or normals");
    // The window's attributes and faces as parsed, and the mesh they become (a vertex per corner at worst).
    uint64_t faces = 0, attributeBytes = 0;
    for (const ObjChunkOutline& o : outlines) {
      faces += o.faces;
      attributeBytes +=
          uint64_t(o.counts.positions) * 12 + uint64_t(o.counts.uvs) * 8 + uint64_t(o.counts.normals) * 12;
    }
    chargeLoadMemory(attributeBytes + faces * (3 * 12 + 8 + 3 * 32 + 16), name_,
                     "lines " + std::to_string(firstLine) + " to " + std::to_string(line_ - 1) + " (" +
                         std::to_string(faces) + " faces)");

    tbb::parallel_for(size_t(0), pieces.size(), [&](size_t i) {
      ObjChunk& c = chunks_[first + i];
      const ObjChunkOutline& o = outlines[i];
      c.positions.reserve(size_t(o.counts.positions));
      c.uvs.reserve(size_t(o.counts.uvs));
      c.normals.reserve(size_t(o.counts.normals));
      // Exact for triangles; polygons make the corner arrays grow, but pages never written are not resident.
      c.cornerPositions.reserve(3 * o.faces);
      c.cornerUvs.reserve(3 * o.faces);
      c.cornerNormals.reserve(3 * o.faces);
      c.faceSmoothing.reserve(o.faces);
      c.faceMaterial.reserve(o.faces);
      parseObjChunk(pieces[i], c, nullptr);
    });

    for (size_t i = first; i < chunks_.size(); ++i) {
      if (chunks_[i].error) failLoad(name_, chunks_[i].error->line, chunks_[i].error->what);
      resolveMaterialStatements(chunks_[i], chunkMaterials_[i]);
    }
  }

  void resolveMaterialStatements(ObjChunk& c, ChunkMaterials& m) {
    m.atStart = material_;
    m.smoothingAtStart = smoothing_;
    m.ofStatement.assign(c.materialStatements.size(), kObjNoMaterial);
    for (size_t k = 0; k < c.materialStatements.size(); ++k) {
      const ObjMaterialStatement& s = c.materialStatements[k];
      if (s.kind == ObjMaterialStatement::Kind::Libraries)
        materials_.loadLibraries(s.line, s.text);
      else
        material_ = m.ofStatement[k] = materials_.find(s.line, s.text);
    }
    if (c.lastSmoothing) smoothing_ = *c.lastSmoothing;
    std::vector<ObjMaterialStatement>().swap(c.materialStatements);
  }

  // Positive references may point forward, so they can be checked only now. The few chunks that refer past the
  // end are parsed again with the totals known, which drops or rejects those references at their lines.
  void checkAgainstTotals() {
    std::vector<size_t> again;
    for (size_t i = 0; i < chunks_.size(); ++i) {
      const ObjCounts& r = chunks_[i].largestReference;
      if (r.positions > totals_.positions || r.uvs > totals_.uvs || r.normals > totals_.normals) again.push_back(i);
    }
    tbb::parallel_for(size_t(0), again.size(), [&](size_t k) {
      ObjChunk& c = chunks_[again[k]];
      ObjChunk fresh;
      fresh.firstLine = c.firstLine;
      fresh.byteOffset = c.byteOffset;
      fresh.byteSize = c.byteSize;
      fresh.before = c.before;
      parseObjChunk(text_.reread(c.byteOffset, c.byteSize), fresh, &totals_);
      c = std::move(fresh);
    });
    for (const ObjChunk& c : chunks_)
      if (c.error) failLoad(name_, c.error->line, c.error->what);
  }

  void report() {
    size_t faces = 0, elements = 0, degenerate = 0, dropped = 0;
    std::optional<size_t> skinWeights, firstDegenerate;
    const ObjProblem* firstDropped = nullptr;
    for (const ObjChunk& c : chunks_) {
      faces += c.faceCount();
      elements += c.lineAndPointElements;
      degenerate += c.degenerateFaces;
      dropped += c.droppedReferences;
      if (!skinWeights) skinWeights = c.firstSkinWeights;
      if (!firstDegenerate) firstDegenerate = c.firstDegenerateFace;
      if (!firstDropped && c.firstDroppedReference) firstDropped = &*c.firstDroppedReference;
    }
    auto at = [&](size_t line) { return name_ + ":" + std::to_string(line); };
    if (skinWeights) warnings_.add(at(*skinWeights), "'vw' (skin weight) statements are ignored");
    if (degenerate > 0)
      warnings_.add(at(*firstDegenerate),
                    degenerate == 1 ? "a face with fewer than 3 corners is left out"
                                    : std::to_string(degenerate) + " faces with fewer than 3 corners are left out");
    if (firstDropped)
      warnings_.add(at(firstDropped->line), firstDropped->what + "; " + std::to_string(dropped) +
                                                " references to missing normals or texture coordinates are ignored");
    if (faces == 0)
      failLoad(name_, elements > 0 ? "has only line and point elements, no faces to render" : "has no faces");
    if (elements > 0) warnings_.add(name_, "line and point elements are not rendered");
  }

  ObjGeometry assemble() {
    ObjGeometry g;
    g.positions = concatenate(chunks_, &ObjChunk::positions);
    std::vector<size_t> fanned(chunks_.size());
    tbb::parallel_for(size_t(0), chunks_.size(),
                      [&](size_t i) { fanned[i] = triangulateChunk(chunks_[i], chunkMaterials_[i], g.positions); });
    if (size_t n = std::accumulate(fanned.begin(), fanned.end(), size_t(0)); n > 0)
      warnings_.add(name_, std::to_string(n) + " polygons with more than " + std::to_string(kMaxEarClippedCorners) +
                               " corners, or too intricate to triangulate along their outline in linear time, are cut "
                               "into fans (concave ones are covered wrongly)");
    size_t triangles = 0;
    for (const ObjChunk& c : chunks_) triangles += c.faceCount();
    if (triangles > INT32_MAX / 3) failLoad(name_, "has more than 715827882 triangles");
    g.uvs = concatenate(chunks_, &ObjChunk::uvs);
    g.normals = concatenate(chunks_, &ObjChunk::normals);
    g.cornerPositions = concatenate(chunks_, &ObjChunk::cornerPositions);
    g.cornerUvs = concatenate(chunks_, &ObjChunk::cornerUvs);
    g.cornerNormals = concatenate(chunks_, &ObjChunk::cornerNormals);
    g.smoothingGroups = concatenate(chunks_, &ObjChunk::faceSmoothing);
    g.materials = concatenate(chunks_, &ObjChunk::faceMaterial);
    return g;
  }

  const std::string& name_;
  ObjTextSource& text_;
  ObjMaterialResolver& materials_;
  LoadWarnings& warnings_;
  ObjReadOptions options_;

  std::vector<ObjChunk> chunks_;
  std::vector<ChunkMaterials> chunkMaterials_;
  ObjCounts totals_;
  size_t line_ = 1;
  uint32_t material_ = kObjNoMaterial;
  uint32_t smoothing_ = 0;
};

}  // namespace

ObjGeometry readObjGeometry(const std::string& name, ObjTextSource& text, ObjMaterialResolver& materials,
                            LoadWarnings& warnings, const ObjReadOptions& options) {
  return GeometryReader(name, text, materials, warnings, options).read();
}

}  // namespace candela
