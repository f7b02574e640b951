#include "scene/cache/binary_stream.h"

#include <new>

namespace candela {

namespace {

XXH3_state_t* newHash() {
  XXH3_state_t* state = XXH3_createState();
  if (!state) throw std::bad_alloc();
  XXH3_64bits_reset(state);
  return state;
}

}  // namespace

BinaryWriter::BinaryWriter(std::FILE* file) : file_(file), hash_(newHash()) {}

BinaryWriter::~BinaryWriter() { XXH3_freeState(hash_); }

void BinaryWriter::bytes(const void* data, size_t size) {
  if (!ok_ || size == 0) return;
  XXH3_64bits_update(hash_, data, size);
  ok_ = std::fwrite(data, 1, size, file_) == size;
}

void BinaryWriter::finish() {
  uint64_t digest = XXH3_64bits_digest(hash_);
  if (ok_) ok_ = std::fwrite(&digest, sizeof digest, 1, file_) == 1;
}

BinaryReader::BinaryReader(std::FILE* file, uint64_t size) : file_(file), hash_(newHash()), remaining_(size) {}

BinaryReader::~BinaryReader() { XXH3_freeState(hash_); }

void BinaryReader::bytes(void* data, size_t size) {
  if (!ok_ || size == 0) return;
  if (size > remaining_ || std::fread(data, 1, size, file_) != size) return fail();
  remaining_ -= size;
  XXH3_64bits_update(hash_, data, size);
}

void BinaryReader::string(std::string& s) {
  uint64_t n = count(1);
  if (!ok_) return;
  s.resize(size_t(n));
  bytes(s.data(), size_t(n));
}

uint64_t BinaryReader::count(uint64_t minimumBytes) {
  uint64_t n = 0;
  value(n);
  if (ok_ && minimumBytes > 0 && n > remaining_ / minimumBytes) fail();
  return ok_ ? n : 0;
}

bool BinaryReader::checksumMatches() {
  const uint64_t expected = XXH3_64bits_digest(hash_);
  uint64_t stored = 0;
  if (!ok_ || remaining_ != sizeof stored || std::fread(&stored, sizeof stored, 1, file_) != 1) return false;
  remaining_ = 0;
  return stored == expected;
}

}  // namespace candela
