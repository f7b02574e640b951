#pragma once
#include <OpenEXR/ImfIO.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace candela {

// OpenEXR's input stream over bytes in memory; reading past the end throws "file is truncated".
class ExrMemoryStream : public Imf::IStream {
 public:
  ExrMemoryStream(const std::string& name, const uint8_t* data, size_t size)
      : Imf::IStream(name.c_str()), data_(data), size_(size) {}

  bool read(char c[], int n) override {
    if (n < 0 || size_ - position_ < size_t(n)) throw std::runtime_error("file is truncated");
    std::memcpy(c, data_ + position_, size_t(n));
    position_ += size_t(n);
    return position_ < size_;
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override { position_ = size_t(std::min<uint64_t>(position, size_)); }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t position_ = 0;
};

}  // namespace candela
