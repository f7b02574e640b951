#include "scene/loaders/obj_text_buffer.h"

namespace candela {

std::unique_ptr<ObjTextBuffer> ObjTextBuffer::openFile(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return nullptr;
  std::unique_ptr<ObjTextBuffer> buffer(new ObjTextBuffer());
  buffer->file_ = f;
  buffer->chunk_.resize(size_t(1) << 20);
  return buffer;
}

ObjTextBuffer::ObjTextBuffer(std::string_view text) {
  char* p = const_cast<char*>(text.data());
  setg(p, p, p + text.size());
  scan(text.data(), text.data() + text.size());
}

ObjTextBuffer::~ObjTextBuffer() {
  if (file_) std::fclose(file_);
}

ObjTextBuffer::int_type ObjTextBuffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  if (!file_ || unsupportedLine_) return traits_type::eof();
  size_t n = std::fread(chunk_.data(), 1, chunk_.size(), file_);
  if (n == 0) {
    readFailed_ = std::ferror(file_) != 0;
    return traits_type::eof();
  }
  setg(chunk_.data(), chunk_.data(), chunk_.data() + n);
  scan(chunk_.data(), chunk_.data() + n);
  if (gptr() == egptr()) return traits_type::eof();
  return traits_type::to_int_type(*gptr());
}

void ObjTextBuffer::scan(const char* begin, const char* end) {
  keywordStart_ = nullptr;
  for (const char* p = begin; p < end; ++p) {
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
        keywordStart_ = p;
        state_ = State::Keyword;
        [[fallthrough]];
      case State::Keyword:
        if (c == ' ' || c == '\t') {
          if (keywordLength_ == 2 && keyword_[0] == 'v' && keyword_[1] == 'w') {
            unsupportedLine_ = line_;
            char* cut = const_cast<char*>(keywordStart_ ? keywordStart_ : begin);
            setg(eback(), gptr(), cut);
            return;
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
