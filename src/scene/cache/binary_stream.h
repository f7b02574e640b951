#pragma once
#include <xxhash.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace candela {

// Writes values and arrays to a file and keeps a checksum (XXH3) of everything written, which finish()
// appends. Failures are sticky: ok() says whether every write so far succeeded.
class BinaryWriter {
 public:
  explicit BinaryWriter(std::FILE* file);
  ~BinaryWriter();
  BinaryWriter(const BinaryWriter&) = delete;
  BinaryWriter& operator=(const BinaryWriter&) = delete;

  void bytes(const void* data, size_t size);
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void string(const std::string& s) {
    value(uint64_t(s.size()));
    bytes(s.data(), s.size());
  }
  template <class T>
  void array(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value(uint64_t(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  // Appends the checksum of everything written before it.
  void finish();
  bool ok() const { return ok_; }

 private:
  std::FILE* file_;
  XXH3_state_t* hash_;
  bool ok_ = true;
};

// Reads what a BinaryWriter wrote, never past `size` bytes (the file's size): a length that does not fit in
// what is left fails the read before anything is allocated. Failures are sticky; after one, reads do nothing.
class BinaryReader {
 public:
  BinaryReader(std::FILE* file, uint64_t size);
  ~BinaryReader();
  BinaryReader(const BinaryReader&) = delete;
  BinaryReader& operator=(const BinaryReader&) = delete;

  void bytes(void* data, size_t size);
  template <class T>
  void value(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void string(std::string& s);
  template <class T>
  void array(std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    uint64_t n = 0;
    value(n);
    if (!ok_ || n > remaining_ / sizeof(T)) return fail();
    v.resize(size_t(n));
    bytes(v.data(), size_t(n) * sizeof(T));
  }
  // A count of things that each take at least `minimumBytes`; fails when that many cannot fit.
  uint64_t count(uint64_t minimumBytes);
  // Reads the checksum finish() wrote and compares it; the file must end right after it.
  bool checksumMatches();
  bool ok() const { return ok_; }
  void fail() { ok_ = false; }

 private:
  std::FILE* file_;
  XXH3_state_t* hash_;
  uint64_t remaining_;
  bool ok_ = true;
};

}  // namespace candela
