#!/usr/bin/env bash
# Renders the small images docs/materials.md shows. Needs a build in ./build (scripts/build.sh); the glTF and
# Cornell box renders need ../shared/scenes and are skipped without it.
set -euo pipefail
cd "$(dirname "$0")/.."
candela=./build/src/candela
out=docs/images
shared=${CANDELA_SHARED_SCENES:-../shared/scenes}
mkdir -p "$out"
render() { "$candela" render "$@" --backend cpu > /dev/null; }

for model in phong pbr disney; do
  render material-gallery --shading "$model" --spp 256 --width 280 --height 240 -o "$out/gallery-$model.png"
done
render material-gallery --spp 256 --width 280 --height 240 --override roughness=0.2 --override clearcoat=1 \
  -o "$out/gallery-overrides.png"
render mirror-corridor --max-depth 100 --spp 512 --width 320 --height 200 -o "$out/mirror-corridor.png"

if [ -d "$shared" ]; then
  env="$shared/envmaps/royal_esplanade_1k.hdr"
  render "$shared/cornell_box/CornellBox-Sphere.obj" --spp 1024 --width 240 --height 240 --exposure 1 \
    -o "$out/cornell-sphere.png"
  for scene in MetalRoughSpheresNoTextures NormalTangentMirrorTest AlphaBlendModeTest TransmissionRoughnessTest; do
    file=$(find "$shared/gltf_material_tests/$scene" -name '*.gltf' -o -name '*.glb' | sort | head -n 1)
    render "$file" --env "$env" --spp 64 --width 240 --height 240 -o "$out/gltf-$scene.png"
  done
  helmet=$(find "$shared/damaged_helmet" -name '*.glb' | head -n 1)
  render "$helmet" --env "$env" --spp 64 --width 240 --height 240 -o "$out/damaged-helmet.png"
fi
echo "images in $out"
