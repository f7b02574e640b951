#include "scene/loaders/obj_line_locator.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace candela {

namespace {

bool startsWith(const char* s, const char* keyword) {
  size_t n = std::strlen(keyword);
  return std::strncmp(s, keyword, n) == 0 && (s[n] == ' ' || s[n] == '\t');
}

const char* skipSpace(const char* s) { return s + std::strspn(s, " \t"); }

// Checks one OBJ reference ("7", "-2", "") against `count` elements; returns an explanation when it is bad.
struct ElementKind {
  const char* one;
  const char* many;
};

std::optional<std::string> checkReference(const char* begin, const char* end, size_t count, ElementKind kind) {
  std::string text(begin, end);
  if (text.empty()) return std::nullopt;
  errno = 0;
  char* stop = nullptr;
  long long value = std::strtoll(text.c_str(), &stop, 10);
  if (stop == text.c_str() || *stop != '\0' || errno == ERANGE)
    return std::string(kind.one) + " reference '" + text + "' is not a number";
  if (value == 0) return std::string(kind.one) + " reference 0 (OBJ counts from 1)";
  long long resolved = value > 0 ? value : (long long)count + value + 1;
  if (resolved < 1 || resolved > (long long)count)
    return std::string(kind.one) + " reference " + text + " but " + std::to_string(count) + " " +
           (count == 1 ? kind.one : kind.many) + (count == 1 ? " is" : " are") + " defined before it";
  return std::nullopt;
}

}  // namespace

std::optional<ObjProblem> findBadReference(std::istream& obj) {
  size_t positions = 0, uvs = 0, normals = 0, lineNumber = 0;
  std::string line;
  while (std::getline(obj, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const char* s = skipSpace(line.c_str());
    if (startsWith(s, "v")) ++positions;
    else if (startsWith(s, "vt")) ++uvs;
    else if (startsWith(s, "vn")) ++normals;
    else if (startsWith(s, "f") || startsWith(s, "l") || startsWith(s, "p")) {
      s = skipSpace(s + 1);
      while (*s) {
        size_t len = std::strcspn(s, " \t");
        const char* end = s + len;
        const char* field = s;
        const size_t counts[3] = {positions, uvs, normals};
        const ElementKind kinds[3] = {{"vertex", "vertices"}, {"texture coordinate", "texture coordinates"},
                                      {"normal", "normals"}};
        for (int k = 0; k < 3 && field <= end; ++k) {
          const char* slash = static_cast<const char*>(std::memchr(field, '/', size_t(end - field)));
          const char* fieldEnd = slash ? slash : end;
          if (k == 0 && fieldEnd == field) return ObjProblem{lineNumber, "element with an empty vertex reference"};
          if (auto why = checkReference(field, fieldEnd, counts[k], kinds[k])) return ObjProblem{lineNumber, *why};
          if (!slash) break;
          field = slash + 1;
        }
        s = skipSpace(end);
      }
    }
  }
  return std::nullopt;
}

std::optional<size_t> lineOfStatement(std::istream& obj, const char* keyword, size_t ordinal) {
  size_t seen = 0, lineNumber = 0;
  std::string line;
  while (std::getline(obj, line)) {
    ++lineNumber;
    if (startsWith(skipSpace(line.c_str()), keyword) && seen++ == ordinal) return lineNumber;
  }
  return std::nullopt;
}

}  // namespace candela
