#include "scene/loaders/pbrt/pbrt_tokenizer.h"

#include "io/load_diagnostics.h"

namespace candela {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool endsWord(char c) { return isSpace(c) || c == '"' || c == '[' || c == ']' || c == '#'; }

// Where the text starts: after a UTF-8 byte-order mark, which some editors put at the start of a file.
size_t afterByteOrderMark(std::string_view text) { return text.starts_with("\xEF\xBB\xBF") ? 3 : 0; }

}  // namespace

PbrtTokenizer::PbrtTokenizer(std::string file, std::string text)
    : file_(std::move(file)), ownedText_(std::move(text)), text_(ownedText_), pos_(afterByteOrderMark(text_)) {}

PbrtTokenizer::PbrtTokenizer(std::string file, std::vector<uint8_t>&& bytes)
    : file_(std::move(file)),
      storage_(std::move(bytes)),
      text_(reinterpret_cast<const char*>(storage_.data()), storage_.size()),
      pos_(afterByteOrderMark(text_)) {}

const PbrtToken& PbrtTokenizer::peek() {
  if (!haveLookahead_) {
    scan();
    haveLookahead_ = true;
  }
  return lookahead_;
}

PbrtToken PbrtTokenizer::next() {
  peek();
  haveLookahead_ = false;
  return std::move(lookahead_);
}

void PbrtTokenizer::scan() {
  lookahead_ = PbrtToken{};
  for (;;) {
    while (pos_ < text_.size() && isSpace(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ < text_.size() && text_[pos_] == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      continue;
    }
    break;
  }
  lookahead_.line = line_;
  if (pos_ >= text_.size()) return;  // End
  char c = text_[pos_];
  if (c == '[' || c == ']') {
    lookahead_.kind = c == '[' ? PbrtToken::Kind::OpenBracket : PbrtToken::Kind::CloseBracket;
    lookahead_.text = std::string(1, c);
    ++pos_;
    return;
  }
  if (c == '"') {
    lookahead_.kind = PbrtToken::Kind::String;
    ++pos_;
    for (;;) {
      if (pos_ >= text_.size()) failLoad(file_, lookahead_.line, "unterminated string");
      char s = text_[pos_++];
      if (s == '"') return;
      if (s == '\n') failLoad(file_, lookahead_.line, "line break inside a string");
      if (s == '\\') {
        if (pos_ >= text_.size()) failLoad(file_, lookahead_.line, "unterminated string");
        char e = text_[pos_++];
        if (e == '\n') ++line_;
        // \n \t \r \b \f as in C; \\, \", \' and anything else stand for themselves.
        constexpr std::string_view kEscapes = "ntrbf", kMeanings = "\n\t\r\b\f";
        size_t k = kEscapes.find(e);
        s = k == std::string_view::npos ? e : kMeanings[k];
      }
      lookahead_.text.push_back(s);
    }
  }
  lookahead_.kind = PbrtToken::Kind::Word;
  size_t start = pos_;
  while (pos_ < text_.size() && !endsWord(text_[pos_])) ++pos_;
  lookahead_.text.assign(text_.substr(start, pos_ - start));
}

}  // namespace candela
