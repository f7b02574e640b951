# Sourced by format.sh and check-format.sh: the clang-format they use, and the C++ files it applies to (every
# tracked .h, .cpp, .cu and .cuh file except the vendored libraries of third_party/, kept as their authors wrote
# them).
clang_format="${CLANG_FORMAT:-clang-format-14}"  # one version: others break lines differently
if ! command -v "$clang_format" >/dev/null; then
  echo "$clang_format not found: install it (scripts/install-dependencies.sh) or set CLANG_FORMAT" >&2
  exit 2
fi
formatted_files() { git ls-files -- '*.h' '*.cpp' '*.cu' '*.cuh' ':!:third_party/*'; }
