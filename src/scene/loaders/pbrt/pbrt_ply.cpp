#include "scene/loaders/pbrt/pbrt_ply.h"

#include <zlib.h>

#include <cstring>
#include <istream>
#include <memory>
#include <optional>
#include <streambuf>

#include "io/file_bytes.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"
#include "tinyply.h"

namespace candela {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// An input stream over bytes in memory that can seek, as tinyply's reading of variable-length lists needs,
// without the copy a std::istringstream would make.
class MemoryBuffer : public std::streambuf {
 public:
  explicit MemoryBuffer(std::vector<uint8_t>& bytes) {
    char* begin = reinterpret_cast<char*>(bytes.data());
    setg(begin, begin, begin + bytes.size());
  }

 protected:
  pos_type seekoff(off_type offset, std::ios_base::seekdir dir, std::ios_base::openmode) override {
    off_type base = dir == std::ios_base::beg ? 0 : dir == std::ios_base::cur ? gptr() - eback() : egptr() - eback();
    return seekpos(pos_type(base + offset), std::ios_base::in);
  }
  pos_type seekpos(pos_type position, std::ios_base::openmode) override {
    off_type p = off_type(position);
    if (p < 0 || p > egptr() - eback()) return pos_type(off_type(-1));
    setg(eback(), eback() + p, egptr());
    return position;
  }
};

const tinyply::PlyProperty* findProperty(const tinyply::PlyElement& element, const std::string& name) {
  for (const tinyply::PlyProperty& p : element.properties)
    if (p.name == name) return &p;
  return nullptr;
}

template <class T>
T readAs(const uint8_t* at, tinyply::Type type) {
  auto load = [at](auto value) {
    std::memcpy(&value, at, sizeof(value));
    return T(value);
  };
  switch (type) {
    case tinyply::Type::INT8: return load(int8_t());
    case tinyply::Type::UINT8: return load(uint8_t());
    case tinyply::Type::INT16: return load(int16_t());
    case tinyply::Type::UINT16: return load(uint16_t());
    case tinyply::Type::INT32: return load(int32_t());
    case tinyply::Type::UINT32: return load(uint32_t());
    case tinyply::Type::FLOAT32: return load(float());
    case tinyply::Type::FLOAT64: return load(double());
    case tinyply::Type::INVALID: break;
  }
  return T();
}

template <class T>
std::vector<T> values(const tinyply::PlyData& data) {
  size_t stride = size_t(tinyply::PropertyTable[data.t].stride);
  size_t n = stride > 0 ? data.buffer.size_bytes() / stride : 0;
  std::vector<T> out(n);
  const uint8_t* bytes = const_cast<tinyply::PlyData&>(data).buffer.get();
  for (size_t i = 0; i < n; ++i) out[i] = readAs<T>(bytes + i * stride, data.t);
  return out;
}

// Smallest number of bytes one element can take in the file, to refuse counts that the file cannot hold.
uint64_t smallestElementBytes(const tinyply::PlyElement& element, bool binary) {
  uint64_t bytes = 0;
  for (const tinyply::PlyProperty& p : element.properties)
    bytes += binary ? uint64_t(tinyply::PropertyTable[p.isList ? p.listType : p.propertyType].stride) : 2;
  return bytes;
}

// The longest an ASCII PLY value may be, with the white space after it: real numbers need fewer than 32
// characters.
constexpr uint64_t kMaxAsciiValueBytes = 64;

// The most bytes the elements a PLY header declares can take after it (an ASCII value at most
// kMaxAsciiValueBytes), or nothing when the header is not complete in `bytes` or declares no such bound (lists
// whose counts may be large).
std::optional<uint64_t> plyBytesBound(std::vector<uint8_t> bytes) {
  MemoryBuffer buffer(bytes);
  std::istream stream(&buffer);
  tinyply::PlyFile ply;
  try {
    if (!ply.parse_header(stream)) return std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const bool binary = ply.is_binary_file();
  uint64_t total = uint64_t(std::max<std::streamoff>(stream.tellg(), 0));
  for (const tinyply::PlyElement& e : ply.get_elements()) {
    uint64_t each = 0;
    for (const tinyply::PlyProperty& p : e.properties) {
      const uint64_t stride = binary ? uint64_t(tinyply::PropertyTable[p.propertyType].stride) : kMaxAsciiValueBytes;
      if (!p.isList) {
        each += stride;
        continue;
      }
      const int countBytes = tinyply::PropertyTable[p.listType].stride;
      if (countBytes > 2) return std::nullopt;
      each += (binary ? uint64_t(countBytes) : kMaxAsciiValueBytes) + ((uint64_t(1) << (8 * countBytes)) - 1) * stride;
    }
    if (each > 0 && e.size > (uint64_t(1) << 62) / each) return std::nullopt;
    total += e.size * each;
    if (total > (uint64_t(1) << 62)) return std::nullopt;
  }
  return total;
}

// The content of a gzip file, decompressed no further than its header says its elements can reach (what follows
// is never read), charged to the load's memory budget as it grows, and refused beyond the size any input
// may have (maxInputFileBytes): a small "zip bomb" cannot fill the memory.
std::vector<uint8_t> gunzip(const std::string& path, const std::vector<uint8_t>& compressed, uint64_t& charged) {
  z_stream stream{};
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) failLoad(path, "cannot start decompressing it");
  std::unique_ptr<z_stream, int (*)(z_stream*)> cleanup(&stream, inflateEnd);
  stream.next_in = const_cast<Bytef*>(compressed.data());
  stream.avail_in = uInt(std::min<size_t>(compressed.size(), UINT32_MAX));
  std::vector<uint8_t> out;
  uint64_t limit = maxInputFileBytes();
  bool bounded = false;
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    size_t used = out.size();
    if (!bounded && used > 0) {
      // The header is in the first chunk unless it is longer than any real one.
      if (std::optional<uint64_t> bound = plyBytesBound(out)) limit = std::min(limit, *bound);
      bounded = true;
    }
    if (used >= limit) {
      if (bounded && limit < maxInputFileBytes()) break;
      failLoad(path, "decompresses to more than the largest input accepted (--max-file-gib)");
    }
    const size_t grow = std::min<uint64_t>(std::max<size_t>(size_t(1) << 20, used), limit - used);  // doubling
    chargeLoadMemory(grow, path, "its decompressed data");
    charged += grow;
    out.resize(used + grow);
    stream.next_out = out.data() + used;
    stream.avail_out = uInt(out.size() - used);
    status = inflate(&stream, Z_NO_FLUSH);
    out.resize(out.size() - stream.avail_out);
    if (status == Z_BUF_ERROR && stream.avail_in == 0) failLoad(path, "compressed data ends early");
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR)
      failLoad(path, std::string("cannot decompress it: ") + (stream.msg ? stream.msg : "corrupt data"));
  }
  return out;
}

// Returns what a PLY read charged to the load's budget for its temporary buffers once they are gone.
struct TemporaryCharge {
  uint64_t bytes = 0;
  ~TemporaryCharge() { releaseLoadMemory(bytes); }
};

}  // namespace

Mesh readPlyMesh(const std::string& path) {
  TemporaryCharge temporary;
  std::vector<uint8_t> bytes = readFileBytes(path);
  if (endsWith(path, ".gz")) bytes = gunzip(path, bytes, temporary.bytes);
  const uint64_t totalBytes = bytes.size();
  MemoryBuffer buffer(bytes);
  std::istream stream(&buffer);
  tinyply::PlyFile ply;
  Mesh mesh;
  try {
    if (!ply.parse_header(stream)) failLoad(path, "not a PLY file");
    uint64_t remaining = totalBytes - uint64_t(std::max<std::streamoff>(stream.tellg(), 0));
    uint64_t needed = 0;
    for (const tinyply::PlyElement& e : ply.get_elements()) {
      uint64_t each = smallestElementBytes(e, ply.is_binary_file());
      if (each > 0 && e.size > remaining / each)
        failLoad(path, "element '" + e.name + "' claims more data than the file has");
      needed += e.size * each;
    }
    if (needed > remaining) failLoad(path, "its elements claim more data than the file has");
    uint64_t vertexCount = 0, faceCount = 0;
    for (const tinyply::PlyElement& e : ply.get_elements()) {
      if (e.name == "vertex") vertexCount = e.size;
      if (e.name == "face") faceCount = e.size;
    }
    // tinyply's buffers and the values read from them, then the mesh (positions, normals, texture coordinates,
    // two triangles of a quad with their materials): a PLY that claims a billion faces is refused here.
    const uint64_t estimate = vertexCount * (2 * 32 + 32) + faceCount * (2 * 4 * 8 + 2 * 16);
    chargeLoadMemory(estimate, path,
                     std::to_string(vertexCount) + " vertices and " + std::to_string(faceCount) + " faces");
    temporary.bytes += estimate;

    const tinyply::PlyElement* vertex = nullptr;
    const tinyply::PlyElement* face = nullptr;
    std::vector<tinyply::PlyElement> elements = ply.get_elements();
    for (const tinyply::PlyElement& e : elements) {
      if (e.name == "vertex") vertex = &e;
      if (e.name == "face") face = &e;
    }
    if (!vertex || !findProperty(*vertex, "x") || !findProperty(*vertex, "y") || !findProperty(*vertex, "z"))
      failLoad(path, "no vertex positions (element 'vertex' with x, y and z)");
    auto request = [&](const tinyply::PlyElement& e, const char* name) -> std::shared_ptr<tinyply::PlyData> {
      return findProperty(e, name) ? ply.request_properties_from_element(e.name, {name}) : nullptr;
    };
    auto requestPair = [&](const char* a, const char* b) {
      std::pair<std::shared_ptr<tinyply::PlyData>, std::shared_ptr<tinyply::PlyData>> pair;
      if (findProperty(*vertex, a) && findProperty(*vertex, b)) pair = {request(*vertex, a), request(*vertex, b)};
      return pair;
    };
    auto x = request(*vertex, "x"), y = request(*vertex, "y"), z = request(*vertex, "z");
    auto nx = request(*vertex, "nx"), ny = request(*vertex, "ny"), nz = request(*vertex, "nz");
    auto uv = requestPair("u", "v");
    if (!uv.first) uv = requestPair("s", "t");
    if (!uv.first) uv = requestPair("texture_u", "texture_v");
    if (!uv.first) uv = requestPair("texture_s", "texture_t");
    std::shared_ptr<tinyply::PlyData> faces;
    if (face)
      faces = findProperty(*face, "vertex_indices") ? request(*face, "vertex_indices") : request(*face, "vertex_index");
    if (!faces) failLoad(path, "no faces (element 'face' with vertex_indices)");
    ply.read(stream);

    std::vector<float> px = values<float>(*x), py = values<float>(*y), pz = values<float>(*z);
    if (px.size() != vertex->size || py.size() != px.size() || pz.size() != px.size())
      failLoad(path, "vertex positions are incomplete");
    mesh.positions.resize(px.size());
    for (size_t i = 0; i < px.size(); ++i) mesh.positions[i] = {px[i], py[i], pz[i]};
    if (nx && ny && nz) {
      std::vector<float> a = values<float>(*nx), b = values<float>(*ny), c = values<float>(*nz);
      if (a.size() == px.size() && b.size() == px.size() && c.size() == px.size()) {
        mesh.normals.resize(px.size());
        for (size_t i = 0; i < px.size(); ++i) mesh.normals[i] = {a[i], b[i], c[i]};
      }
    }
    if (uv.first) {
      std::vector<float> u = values<float>(*uv.first), v = values<float>(*uv.second);
      if (u.size() == px.size() && v.size() == px.size()) {
        mesh.uvs.resize(px.size());
        for (size_t i = 0; i < px.size(); ++i) mesh.uvs[i] = {u[i], v[i]};
      }
    }
    std::vector<int64_t> indices = values<int64_t>(*faces);
    std::vector<size_t> sizes = faces->list_sizes;
    if (sizes.empty()) sizes.assign(faces->count, faces->count > 0 ? indices.size() / faces->count : 0);
    size_t at = 0;
    for (size_t f = 0; f < sizes.size(); ++f) {
      size_t n = sizes[f];
      if (n != 3 && n != 4)
        failLoad(path, "face " + std::to_string(f) + " has " + std::to_string(n) + " vertices (3 or 4 are read)");
      if (at + n > indices.size()) failLoad(path, "face indices are incomplete");
      for (size_t k = 0; k < n; ++k)
        if (indices[at + k] < 0 || uint64_t(indices[at + k]) >= mesh.positions.size())
          failLoad(path, "face " + std::to_string(f) + " refers to vertex " + std::to_string(indices[at + k]) + " of " +
                             std::to_string(mesh.positions.size()));
      auto corner = [&](size_t k) { return uint32_t(indices[at + k]); };
      mesh.indices.insert(mesh.indices.end(), {corner(0), corner(1), corner(2)});
      if (n == 4) mesh.indices.insert(mesh.indices.end(), {corner(0), corner(2), corner(3)});
      at += n;
    }
  } catch (const LoadError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    failLoad(path, std::string("malformed PLY: ") + e.what());
  }
  mesh.triangleMaterials.assign(mesh.triangleCount(), 0);
  return mesh;
}

}  // namespace candela
