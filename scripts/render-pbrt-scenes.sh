#!/usr/bin/env bash
# Fetches public pbrt scenes, renders each with candela and prints the rows of the table in docs/pbrt-v4.md
# (scene, load time, warnings, thumbnail). Needs network access, git, curl and unzip, and a build in ./build.
#   scripts/render-pbrt-scenes.sh [work folder]      (default: build/pbrt-scenes)
# The scenes are kept in the work folder, never in the repository. SPP, WIDTH and HEIGHT set the thumbnails.
set -euo pipefail
cd "$(dirname "$0")/.."
candela=$PWD/build/src/candela
work=${1:-build/pbrt-scenes}
spp=${SPP:-64}
width=${WIDTH:-320}
height=${HEIGHT:-240}
mkdir -p "$work/thumbnails"
work=$(cd "$work" && pwd)

# pbrt-v4-scenes (https://github.com/mmp/pbrt-v4-scenes): a sparse checkout of the smaller scenes.
v4_folders=(killeroos lte-orb ganesha crown pbrt-book sssdragon transparent-machines watercolor)
v4_scenes=(killeroos/killeroo-simple.pbrt killeroos/killeroo-gold.pbrt killeroos/killeroo-coated-gold.pbrt
           lte-orb/lte-orb-silver.pbrt lte-orb/lte-orb-rough-glass.pbrt ganesha/ganesha.pbrt crown/crown.pbrt
           pbrt-book/book.pbrt)
if [ ! -d "$work/pbrt-v4-scenes/.git" ]; then
  git clone --depth 1 --filter=blob:none --sparse https://github.com/mmp/pbrt-v4-scenes.git "$work/pbrt-v4-scenes"
fi
git -C "$work/pbrt-v4-scenes" sparse-checkout set "${v4_folders[@]}"

# Benedikt Bitterli's rendering resources (https://benedikt-bitterli.me/resources/), in pbrt-v3's format.
bitterli=(cornell-box veach-mis veach-bidir staircase2 living-room-2 kitchen glass-of-water material-testball)
mkdir -p "$work/bitterli"
for name in "${bitterli[@]}"; do
  if [ ! -d "$work/bitterli/$name" ]; then
    curl -fsSL -o "$work/bitterli/$name.zip" "https://benedikt-bitterli.me/resources/pbrt-v3/$name.zip" &&
      unzip -q -o "$work/bitterli/$name.zip" -d "$work/bitterli" || echo "could not fetch $name" >&2
  fi
done

files=()
for s in "${v4_scenes[@]}"; do files+=("$work/pbrt-v4-scenes/$s"); done
for name in "${bitterli[@]}"; do
  [ -f "$work/bitterli/$name/scene.pbrt" ] && files+=("$work/bitterli/$name/scene.pbrt")
done

echo "| scene | load time | warnings | thumbnail |"
echo "| --- | --- | --- | --- |"
for file in "${files[@]}"; do
  [ -f "$file" ] || { echo "missing $file" >&2; continue; }
  label=${file#"$work/"}
  thumb="$work/thumbnails/$(echo "$label" | tr '/' '-' | sed 's/\.pbrt$//').png"
  load=$("$candela" load "$file" --no-cache 2>/dev/null | sed -n 's/.*"seconds":\([0-9.e-]*\).*/\1/p' || true)
  if "$candela" render "$file" --no-cache --backend cpu --spp "$spp" --width "$width" --height "$height" \
       -o "$thumb" > /dev/null 2> "$work/stderr.txt"; then
    warnings=$(grep 'warning:' "$work/stderr.txt" | sed 's/^candela: warning: [^:]*: //' | paste -sd ';' - || true)
  else
    warnings="failed: $(tail -n 1 "$work/stderr.txt")"
  fi
  printf '| %s | %s s | %s | ![](%s) |\n' "$label" "${load:-?}" "${warnings:-none}" "$thumb"
done
