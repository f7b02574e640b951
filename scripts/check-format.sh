#!/usr/bin/env bash
# Checks that every C++ file is formatted as .clang-format says: prints the files that differ and exits 1 when
# there are any (scripts/format.sh fixes them), 0 otherwise. Nothing is changed.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/format-files.sh
echo ">>> $clang_format --style=file, compared with each tracked C++ file (nothing is changed)"
differ=$(formatted_files | xargs -d '\n' -P "$(nproc)" -I{} sh -c \
  '"$1" --style=file "$2" | cmp -s - "$2" || echo "$2"' sh "$clang_format" {} | sort)
if [ -n "$differ" ]; then
  echo "not formatted as .clang-format says (run scripts/format.sh):"
  echo "$differ" | sed 's/^/  /'
  exit 1
fi
echo "format: all $(formatted_files | wc -l) files as .clang-format says"
