#!/usr/bin/env bash
# Makes the Debian package of the build tree BUILD with cpack into a fresh folder and checks it: the command, the
# library, its CMake package and the Python module at their places, and dependencies found by dpkg-shlibdeps
# (the Debian packages of the libraries it links), not written by hand.
# Usage: debian_package.sh BUILD WITH_PYTHON(0|1)
set -euo pipefail
build=$1 with_python=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out" >/dev/null
package=$(ls "$out"/candela_*.deb)
contents=$(dpkg-deb -c "$package")
expected=(./usr/bin/candela ./usr/lib/libcandela.so.0.1.0 ./usr/include/candela/candela.h
          ./usr/lib/cmake/candela/candelaConfig.cmake ./usr/share/doc/candela/README.md)
[ "$with_python" = 1 ] && expected+=(./usr/lib/python3/dist-packages/candela.cpython-)
for path in "${expected[@]}"; do
  grep -qF " $path" <<<"$contents" || { echo "the package lacks $path" >&2; exit 1; }
done
depends=$(dpkg-deb -f "$package" Depends)
for library in libembree3 libtbb12 libopenexr libc6; do
  grep -q "$library" <<<"$depends" || { echo "Depends lacks $library: $depends" >&2; exit 1; }
done
if [ "$with_python" = 1 ]; then
  grep -q "python3-numpy" <<<"$depends" || { echo "Depends lacks python3-numpy: $depends" >&2; exit 1; }
fi
echo "$(basename "$package"): Depends: $depends"
