#pragma once
// NanoVDB files (.nvdb, as NanoVDB's io::writeGrid writes them, major version 32: the version pbrt-v4's scenes
// were written with), read without NanoVDB itself: a file is segments, each a 16-byte header (magic "NanoVDB0" or
// "NanoVDB2", version, grid count, codec), then per grid a 176-byte description and its name, then the grids'
// bytes (uncompressed, or each one zlib stream after its 8-byte size for the ZIP codec). Every size a file states
// is checked against its length before anything is read or allocated. Its own reader rather than NanoVDB's:
// Debian packages no NanoVDB, and NanoVDB's io and tree accessors follow the offsets a file states unchecked.
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

// NanoVDB's value types (GridType) and classes (GridClass) that the readers name.
constexpr uint32_t kNanoVdbFloat = 1;
constexpr uint32_t kNanoVdbClassUnknown = 0;
constexpr uint32_t kNanoVdbClassFogVolume = 2;
constexpr uint32_t kNanoVdbMajorVersion = 32;
// "NanoVDB0" (files and grids before NanoVDB 32.6), "NanoVDB1" (a grid since) and "NanoVDB2" (a file since), as
// little-endian 64-bit numbers.
constexpr uint64_t kNanoVdbMagicOld = 0x304244566f6e614eull;
constexpr uint64_t kNanoVdbMagicGrid = 0x314244566f6e614eull;
constexpr uint64_t kNanoVdbMagicFile = 0x324244566f6e614eull;

// One grid of a file, as its segment describes it.
struct NanoVdbGridEntry {
  std::string name;
  uint32_t valueType = 0;    // GridType
  uint32_t gridClass = 0;    // GridClass
  uint64_t gridBytes = 0;    // its size once decompressed
  uint64_t offset = 0;       // where its stored bytes begin in the file
  uint64_t storedBytes = 0;  // their number
  uint16_t codec = 0;        // 0 none, 1 ZIP, 2 Blosc
};

// A .nvdb file read whole: its grids listed, each one's bytes on request.
class NanoVdbFile {
 public:
  // Reads `path` (a regular file no larger than maxInputFileBytes) and lists its grids. Throws LoadError naming
  // the file: not a NanoVDB file, another version, a size beyond the file's end.
  explicit NanoVdbFile(const std::string& path);
  NanoVdbFile(const NanoVdbFile&) = delete;
  NanoVdbFile& operator=(const NanoVdbFile&) = delete;

  const std::vector<NanoVdbGridEntry>& grids() const { return grids_; }
  // The first grid named `name`, or nullptr.
  const NanoVdbGridEntry* find(const std::string& name) const;
  // The bytes of `grid` (a grid buffer: NanoVDB's GridData, tree and nodes), decompressed, their size charged to
  // the load's memory budget first (as the file's are, until this object goes). Throws LoadError for a
  // Blosc-compressed grid (no Blosc here), or a ZIP stream that states more bytes than deflate can expand it to
  // or does not decompress to the size its description states.
  std::vector<uint8_t> gridBytes(const NanoVdbGridEntry& grid) const;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<uint8_t> bytes_;
  std::vector<NanoVdbGridEntry> grids_;
  // What this file charged to the load's budget (the file, the grids handed out), returned when it goes.
  struct Charge {
    uint64_t bytes = 0;
    ~Charge();
  };
  mutable Charge charged_;
};

// A grid type's name for messages ("float", "Vec3f", ..., or its number).
std::string nanoVdbTypeName(uint32_t valueType);

}  // namespace candela
