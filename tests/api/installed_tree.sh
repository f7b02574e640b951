#!/usr/bin/env bash
# Installs the build tree BUILD into a fresh prefix and uses it as a user would: runs bin/candela, builds and
# runs a program that finds the library with find_package(candela), and imports the Python module from the
# installed tree (where the build has one: PYTHON names its interpreter).
# Usage: installed_tree.sh BUILD CONSUMER_SOURCE [PYTHON]
set -euo pipefail
build=$1 consumer=$2 python=${3:-}
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix/usr" >/dev/null

"$prefix/usr/bin/candela" --help >/dev/null
for f in include/candela/candela.h share/doc/candela/README.md share/doc/candela/design.md; do
  [ -f "$prefix/usr/$f" ] || { echo "not installed: $f" >&2; exit 1; }
done

cmake -S "$consumer" -B "$prefix/consumer" -DCMAKE_PREFIX_PATH="$prefix/usr" >/dev/null
cmake --build "$prefix/consumer" >/dev/null
"$prefix/consumer/consumer"

if [ -n "$python" ]; then
  # Only the installed tree on the path: the module must find its libcandela relative to itself.
  PYTHONPATH="$prefix/usr/lib/python3/dist-packages" "$python" -c "
import candela, sys
assert candela.__file__.startswith('$prefix'), candela.__file__
image = candela.render('cornell-box', width=32, height=24, spp=4, backend='cpu')
print('python module', candela.__version__, image.shape)
"
fi
