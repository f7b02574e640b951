#include "scene/loaders/obj_text_buffer.h"

#include <cstring>

namespace candela {

std::unique_ptr<ObjTextBuffer> ObjTextBuffer::openFile(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return nullptr;
  std::unique_ptr<ObjTextBuffer> buffer(new ObjTextBuffer());
  buffer->file_ = f;
  buffer->chunk_.resize(size_t(1) << 20);
  return buffer;
}

ObjTextBuffer::ObjTextBuffer(std::string_view text) : chunk_(text.begin(), text.end()) {
  setg(chunk_.data(), chunk_.data(), chunk_.data() + chunk_.size());
  scan(chunk_.data(), chunk_.data() + chunk_.size());
}

ObjTextBuffer::~ObjTextBuffer() {
  if (file_) std::fclose(file_);
}

// Hands over whole lines where it can, so that a statement can still be rewritten before the parser reads it.
ObjTextBuffer::int_type ObjTextBuffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  if (!file_) return traits_type::eof();
  std::memmove(chunk_.data(), chunk_.data() + carryStart_, carrySize_);
  size_t n = carrySize_ + std::fread(chunk_.data() + carrySize_, 1, chunk_.size() - carrySize_, file_);
  if (std::ferror(file_)) readFailed_ = true;
  if (n == 0) return traits_type::eof();
  size_t end = n;
  if (n == chunk_.size()) {
    const void* lastNewline = nullptr;
    for (size_t i = n; i > 0 && !lastNewline; --i)
      if (chunk_[i - 1] == '\n') lastNewline = &chunk_[i - 1];
    if (lastNewline) end = size_t(static_cast<const char*>(lastNewline) - chunk_.data()) + 1;
  }
  carryStart_ = end;
  carrySize_ = n - end;
  setg(chunk_.data(), chunk_.data(), chunk_.data() + end);
  scan(chunk_.data(), chunk_.data() + end);
  return traits_type::to_int_type(*gptr());
}

void ObjTextBuffer::scan(char* begin, char* end) {
  char* keywordStart = nullptr;
  for (char* p = begin; p < end; ++p) {
    char c = *p;
    if (c == '\n') {
      ++line_;
      state_ = State::LineStart;
      continue;
    }
    switch (state_) {
      case State::LineStart:
        if (c == ' ' || c == '\t') break;
        keywordLength_ = 0;
        keywordStart = p;
        state_ = State::Keyword;
        [[fallthrough]];
      case State::Keyword:
        if (c == ' ' || c == '\t') {
          if (keywordLength_ == 2 && keyword_[0] == 'v' && keyword_[1] == 'w') {
            if (keywordStart) *keywordStart = '#';  // the parser now skips the line as a comment
            if (!skippedLine_) skippedLine_ = line_;
            state_ = State::Rest;
            break;
          }
          bool vertexData = keyword_[0] == 'v' && (keywordLength_ == 1 || (keywordLength_ == 2 &&
                                                   (keyword_[1] == 'n' || keyword_[1] == 't')));
          state_ = vertexData ? State::Numbers : State::Rest;
        } else if (keywordLength_ < 3) {
          keyword_[keywordLength_++] = c;
        } else {
          state_ = State::Rest;
        }
        break;
      case State::Numbers:
        if (c == '#' && (p == begin ? previousWasSpace_ : (p[-1] == ' ' || p[-1] == '\t'))) {
          state_ = State::Rest;
        } else if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E' ||
                     c == ' ' || c == '\t' || c == '\r')) {
          if (!badLine_) badLine_ = line_;
          state_ = State::Rest;
        }
        break;
      case State::Rest:
        break;
    }
  }
  if (end > begin) previousWasSpace_ = end[-1] == ' ' || end[-1] == '\t';
}

}  // namespace candela
