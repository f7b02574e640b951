#include "scene/loaders/load_diagnostics.h"

namespace candela {

namespace {

// Keeps messages to one line whatever a library put into them.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace

void failLoad(const std::string& file, const std::string& what) { throw LoadError(oneLine(file + ": " + what)); }

void failLoad(const std::string& file, size_t line, const std::string& what) {
  throw LoadError(oneLine(file + ":" + std::to_string(line) + ": " + what));
}

}  // namespace candela
