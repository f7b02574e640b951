#!/usr/bin/env bash
# Renders public pbrt scenes with candela and prints the rows of the table in docs/pbrt-v4.md (scene, result, load
# time, warnings, thumbnail).
#   scripts/render-pbrt-scenes.sh [work folder]      (default: build/pbrt-scenes)
# Scenes are looked for in the work folder, never in the repository:
#   pbrt-v4-scenes/  a checkout of https://github.com/mmp/pbrt-v4-scenes (the smaller scenes below)
#   bitterli/        Bitterli's rendering resources: <name>/scene.pbrt (pbrt-v3, from his site) or
#                    <name>/pbrt/scene-v4.pbrt (pbrt-v4, as in https://github.com/gonsolo/bitterli)
# Those that are missing are fetched when FETCH=1 (the default; needs network access, git, curl and unzip); a fetch
# that fails is reported and the script goes on with what it has. `.xz` files (compressed meshes and maps in some
# copies) are decompressed next to themselves when unxz is there.
# CANDELA names the binary (default: build/src/candela); SPP, WIDTH and HEIGHT set the thumbnails; TIMEOUT bounds
# each load and render in seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
candela=$(realpath "${CANDELA:-build/src/candela}")
work=${1:-build/pbrt-scenes}
spp=${SPP:-64}
width=${WIDTH:-320}
height=${HEIGHT:-240}
timeout=${TIMEOUT:-900}
fetch=${FETCH:-1}
mkdir -p "$work/thumbnails" "$work/bitterli"
work=$(cd "$work" && pwd)

v4_folders=(killeroos lte-orb ganesha crown pbrt-book sssdragon transparent-machines watercolor)
v4_scenes=(killeroos/killeroo-simple.pbrt killeroos/killeroo-gold.pbrt killeroos/killeroo-coated-gold.pbrt
           killeroos/killeroo-moving.pbrt lte-orb/lte-orb-silver.pbrt lte-orb/lte-orb-rough-glass.pbrt
           lte-orb/lte-orb-blue-agat-spec.pbrt lte-orb/lte-orb-simple-ball.pbrt ganesha/ganesha.pbrt crown/crown.pbrt
           pbrt-book/book.pbrt sssdragon/dragon_10.pbrt)
bitterli=(cornell-box veach-mis veach-bidir veach-ajar staircase staircase2 living-room living-room-2
          living-room-3 kitchen glass-of-water material-testball coffee classroom bathroom bathroom2 bedroom
          dining-room house lamp spaceship dragon car car2 teapot teapot-full water-caustic volumetric-caustic
          hair-curl curly-hair straight-hair furball)

if [ "$fetch" = 1 ]; then
  if [ ! -d "$work/pbrt-v4-scenes" ]; then
    { git clone --depth 1 --filter=blob:none --sparse https://github.com/mmp/pbrt-v4-scenes.git \
        "$work/pbrt-v4-scenes" && git -C "$work/pbrt-v4-scenes" sparse-checkout set "${v4_folders[@]}"; } ||
      echo "could not fetch pbrt-v4-scenes" >&2
  fi
  for name in "${bitterli[@]}"; do
    [ -d "$work/bitterli/$name" ] && continue
    { curl -fsSL -o "$work/bitterli/$name.zip" "https://benedikt-bitterli.me/resources/pbrt-v3/$name.zip" &&
        unzip -q -o "$work/bitterli/$name.zip" -d "$work/bitterli"; } || echo "could not fetch $name" >&2
  done
fi
if command -v unxz > /dev/null; then
  find "$work" -name '*.xz' -print0 | while IFS= read -r -d '' packed; do
    [ -e "${packed%.xz}" ] || unxz -k "$packed" || echo "could not decompress $packed" >&2
  done
fi

files=()
for s in "${v4_scenes[@]}"; do
  [ -f "$work/pbrt-v4-scenes/$s" ] && files+=("$work/pbrt-v4-scenes/$s")
done
for name in "${bitterli[@]}"; do
  for s in "$work/bitterli/$name/pbrt/scene-v4.pbrt" "$work/bitterli/$name/scene.pbrt"; do
    [ -f "$s" ] && files+=("$s")
  done
done
[ ${#files[@]} -gt 0 ] || { echo "no scenes in $work" >&2; exit 1; }

# One line of text for the table: no pipes, the scene folder left out of paths.
cell() { sed "s#$work/##g; s/|/\\\\|/g" | paste -sd ';' - | sed 's/;/; /g'; }

echo "| scene | result | load time | warnings | thumbnail |"
echo "| --- | --- | --- | --- | --- |"
for file in "${files[@]}"; do
  label=${file#"$work/"}
  thumb="$work/thumbnails/$(echo "$label" | tr '/' '-' | sed 's/\.pbrt$//').png"
  load=$(timeout "$timeout" "$candela" load "$file" --no-cache 2> /dev/null |
         sed -n 's/.*"seconds":\([0-9.e-]*\).*/\1/p' || true)
  if timeout "$timeout" "$candela" render "$file" --no-cache --backend cpu --spp "$spp" --width "$width" \
       --height "$height" -o "$thumb" > /dev/null 2> "$work/stderr.txt"; then
    warnings=$(grep 'warning:' "$work/stderr.txt" | sed 's/^candela: warning: [^:]*: //' | cell || true)
    result=$([ -n "$warnings" ] && echo "renders with warnings" || echo "renders")
    picture="![]($thumb)"
  else
    status=$?
    if [ "$status" = 124 ]; then
      result="no image within $timeout s"
    else
      result="refused: $(grep -v 'warning:' "$work/stderr.txt" | tail -n 1 | sed 's/^candela: //' | cell || true)"
    fi
    warnings=$(grep 'warning:' "$work/stderr.txt" | sed 's/^candela: warning: [^:]*: //' | cell || true)
    picture=""
  fi
  printf '| %s | %s | %s s | %s | %s |\n' "$label" "$result" "${load:-?}" "${warnings:-none}" "$picture"
done
