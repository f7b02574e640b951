#include "scene/loaders/pbrt/pbrt_spectrum_files.h"

#include <cmath>
#include <cstddef>
#include <cstdlib>

#include "io/file_bytes.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/pbrt/pbrt_spectra.h"

namespace candela {

std::vector<double> parsePbrtSpectrumFile(const std::string& path, const std::string& text) {
  std::vector<double> numbers;
  size_t line = 1, i = 0;
  while (i < text.size()) {
    char c = text[i];
    if (c == '\n') ++line;
    if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',') {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < text.size() && std::string(" \t\r\n,#").find(text[end]) == std::string::npos) ++end;
    std::string word = text.substr(i, end - i);
    char* last = nullptr;
    double value = std::strtod(word.c_str(), &last);
    if (*last != '\0' || !std::isfinite(value)) failLoad(path, line, "'" + word + "' is not a number");
    numbers.push_back(value);
    i = end;
  }
  if (numbers.empty() || numbers.size() % 2 != 0)
    failLoad(path,
             "a spectrum file needs wavelength-value pairs, found " + std::to_string(numbers.size()) + " numbers");
  return numbers;
}

void readPbrtSpectrumFiles(PbrtParameters& params, PbrtContext& context) {
  if (!context.filesAllowed) return;
  for (size_t i = 0; i < params.list.size();) {
    PbrtParameter& p = params.list[i];
    if (p.type != "spectrum" || p.strings.size() != 1 || namedSpectrumRgb(p.strings[0])) {
      ++i;
      continue;
    }
    try {
      std::string path = context.resolve(p.strings[0], params.file, params.line);
      InputFile file(path);
      if (file.size() > kMaxSpectrumFileBytes)
        failLoad(path, "a spectrum file of more than " + std::to_string(kMaxSpectrumFileBytes) + " bytes");
      std::vector<uint8_t> bytes = readFileBytes(file);
      p.numbers = parsePbrtSpectrumFile(path, std::string(bytes.begin(), bytes.end()));
      p.strings.clear();
      ++i;
    } catch (const LoadError& e) {
      // The warning names the file; without the parameter, the lookups take its default.
      context.warn("spectrum file " + p.strings[0],
                   std::string("spectrum file left out: ") + e.what() + ": the parameter's default is used");
      params.list.erase(params.list.begin() + std::ptrdiff_t(i));
    }
  }
}

}  // namespace candela
