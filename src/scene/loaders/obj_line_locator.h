#pragma once
#include <cstddef>
#include <istream>
#include <optional>
#include <string>

namespace candela {

// Rescans OBJ text to say on which line a problem found after parsing sits; used only when loading fails,
// since the parser keeps no line numbers.
struct ObjProblem {
  size_t line = 0;
  std::string what;
};

// The first face, line or point element whose vertex, texture-coordinate or normal reference is zero, not a
// number, or beyond the elements defined before it (relative references included).
std::optional<ObjProblem> findBadReference(std::istream& obj);

// The line of the `ordinal`-th (0-based) statement that starts with `keyword` ("v", "vt", "vn").
std::optional<size_t> lineOfStatement(std::istream& obj, const char* keyword, size_t ordinal);

}  // namespace candela
