#include "scene/loaders/nanovdb/nanovdb_file.h"

#include <cstring>

#include <zlib.h>

#include "io/file_bytes.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

constexpr uint64_t kHeaderBytes = 16;
constexpr uint64_t kGridDescriptionBytes = 176;
// The longest grid name NanoVDB writes (GridData's 256 characters) and a little room.
constexpr uint32_t kMaxNameBytes = 1024;
constexpr uint64_t kMaxDeflateRatio = 1032;

template <typename T>
T readAt(const std::vector<uint8_t>& bytes, uint64_t at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof(T));
  return v;
}

uint64_t reversed(uint64_t v) {
  uint64_t r = 0;
  for (int i = 0; i < 8; ++i) r = (r << 8) | ((v >> (8 * i)) & 0xff);
  return r;
}

std::string versionText(uint32_t v) {
  return std::to_string(v >> 21) + "." + std::to_string((v >> 10) & 0x7ff) + "." + std::to_string(v & 0x3ff);
}

}  // namespace

std::string nanoVdbTypeName(uint32_t valueType) {
  static const char* const names[] = {"unknown", "float", "double", "int16",  "int32", "int64", "Vec3f",
                                      "Vec3d",   "mask",  "half",   "uint32", "bool",  "RGBA8", "fp4",
                                      "fp8",     "fp16",  "fpN",    "Vec4f",  "Vec4d", "index", "onIndex"};
  if (valueType < sizeof(names) / sizeof(names[0])) return names[valueType];
  return "type " + std::to_string(valueType);
}

NanoVdbFile::NanoVdbFile(const std::string& path) : path_(path) {
  InputFile file(path);
  chargeLoadMemory(file.size(), path, "the file");
  charged_.bytes = file.size();
  bytes_ = readFileBytes(file);
  const uint64_t size = bytes_.size();
  uint64_t at = 0;
  while (at < size) {
    if (size - at < kHeaderBytes) failLoad(path, "ends inside a segment header: the file is truncated");
    const uint64_t magic = readAt<uint64_t>(bytes_, at);
    if (magic != kNanoVdbMagicOld && magic != kNanoVdbMagicFile) {
      if (at > 0) failLoad(path, "has bytes after its last segment that are no NanoVDB segment");
      if (magic == kNanoVdbMagicGrid)
        failLoad(path, "is a raw NanoVDB grid buffer, not a .nvdb file with grid descriptions");
      if (reversed(magic) == kNanoVdbMagicOld || reversed(magic) == kNanoVdbMagicFile)
        failLoad(path, "is a NanoVDB file of the other byte order");
      failLoad(path, "is not a NanoVDB file");
    }
    const uint32_t version = readAt<uint32_t>(bytes_, at + 8);
    if (version >> 21 != kNanoVdbMajorVersion)
      failLoad(path, "is a NanoVDB " + versionText(version) + " file; version 32 files are read");
    const uint16_t gridCount = readAt<uint16_t>(bytes_, at + 12);
    const uint16_t codec = readAt<uint16_t>(bytes_, at + 14);
    if (codec > 2) failLoad(path, "names an unknown compression (codec " + std::to_string(codec) + ")");
    at += kHeaderBytes;
    const size_t first = grids_.size();
    for (uint16_t i = 0; i < gridCount; ++i) {
      if (size - at < kGridDescriptionBytes) failLoad(path, "ends inside a grid description: the file is truncated");
      NanoVdbGridEntry grid;
      grid.gridBytes = readAt<uint64_t>(bytes_, at);
      grid.storedBytes = readAt<uint64_t>(bytes_, at + 8);
      grid.valueType = readAt<uint32_t>(bytes_, at + 32);
      grid.gridClass = readAt<uint32_t>(bytes_, at + 36);
      const uint32_t nameBytes = readAt<uint32_t>(bytes_, at + 136);
      grid.codec = codec;
      at += kGridDescriptionBytes;
      if (nameBytes > kMaxNameBytes || size - at < nameBytes)
        failLoad(path, "states a grid name of " + std::to_string(nameBytes) + " bytes, beyond the file's end");
      const char* name = reinterpret_cast<const char*>(bytes_.data() + at);
      grid.name.assign(name, strnlen(name, nameBytes));
      at += nameBytes;
      grids_.push_back(grid);
    }
    for (size_t i = first; i < grids_.size(); ++i) {
      NanoVdbGridEntry& grid = grids_[i];
      if (grid.storedBytes > size - at)
        failLoad(path, "grid '" + grid.name + "' states " + std::to_string(grid.storedBytes) +
                           " bytes, beyond the file's end: the file is truncated");
      grid.offset = at;
      at += grid.storedBytes;
    }
  }
  if (grids_.empty()) failLoad(path, "holds no grids");
}

NanoVdbFile::Charge::~Charge() { releaseLoadMemory(bytes); }

const NanoVdbGridEntry* NanoVdbFile::find(const std::string& name) const {
  for (const NanoVdbGridEntry& grid : grids_)
    if (grid.name == name) return &grid;
  return nullptr;
}

std::vector<uint8_t> NanoVdbFile::gridBytes(const NanoVdbGridEntry& grid) const {
  const std::string what = "grid '" + grid.name + "'";
  if (grid.codec == 2)
    failLoad(path_, what +
                        " is Blosc-compressed, which is not read: save it uncompressed or with ZIP "
                        "(nanovdb_convert --codec ZIP)");
  if (grid.gridBytes > maxInputFileBytes())
    failLoad(path_, what + " states " + std::to_string(grid.gridBytes) +
                        " bytes, more than the largest input accepted (--max-file-gib)");
  const uint8_t* stored = bytes_.data() + grid.offset;
  if (grid.codec == 0) {
    if (grid.storedBytes != grid.gridBytes)
      failLoad(path_, what + " states " + std::to_string(grid.gridBytes) + " bytes but stores " +
                          std::to_string(grid.storedBytes));
    chargeLoadMemory(grid.gridBytes, path_, what);
    charged_.bytes += grid.gridBytes;
    return std::vector<uint8_t>(stored, stored + grid.gridBytes);
  }
  // ZIP: the compressed stream's size, then the stream.
  if (grid.storedBytes < 8) failLoad(path_, what + ": its compressed data is missing");
  uint64_t compressed;
  std::memcpy(&compressed, stored, 8);
  if (compressed > grid.storedBytes - 8)
    failLoad(path_, what + ": its compressed data runs beyond the grid's bytes: the file is corrupt");
  // Deflate expands at most 1032 times (zlib's FAQ): a stated size beyond that is a lie, not to be allocated.
  if (grid.gridBytes > compressed * kMaxDeflateRatio + 1024)
    failLoad(path_, what + " states " + std::to_string(grid.gridBytes) + " bytes, more than its " +
                        std::to_string(compressed) + " compressed bytes can hold");
  chargeLoadMemory(grid.gridBytes, path_, what);
  charged_.bytes += grid.gridBytes;
  std::vector<uint8_t> out(grid.gridBytes);
  uLongf outBytes = uLongf(out.size());
  const int status = uncompress(out.data(), &outBytes, stored + 8, uLong(compressed));
  if (status != Z_OK || outBytes != out.size())
    failLoad(path_,
             what + ": its ZIP data does not decompress to the " + std::to_string(grid.gridBytes) + " bytes it states");
  return out;
}

}  // namespace candela
