#!/usr/bin/env bash
# Formats every C++ file in place as .clang-format says.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/format-files.sh
echo ">>> $clang_format -i (every tracked C++ file)"
formatted_files | xargs -d '\n' -P "$(nproc)" -n 16 "$clang_format" -i --style=file
