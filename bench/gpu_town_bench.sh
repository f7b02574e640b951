#!/usr/bin/env bash
# gpu_town_bench.sh <candela> <candela-generate-scene> <environment .hdr> <work dir>: the 10M-triangle town seen
# from inside, for docs/performance.md. Writes the generated town as glTF with a camera added in a street (eye at
# (384, 1.7, 740) looking down x = 384 towards (384, 3, 0), 60 degrees vertically), then prints the JSON line of
# `candela bench` on the OptiX backend, lit by the environment map, at 1920x1080, depth 8, one sample per pixel
# per launch, median of 100 CUDA-event launches after 20, with the raw-trace mode on the same rays. Extra
# arguments after the four go to `candela bench`.
set -euo pipefail
if [ $# -lt 4 ]; then
  echo "usage: gpu_town_bench.sh <candela> <candela-generate-scene> <environment .hdr> <work dir> [bench options]" >&2
  exit 2
fi
candela=$1 generate=$2 environment=$3 work=$4
shift 4
scene=$work/town-10M
if [ ! -e "$scene/street.gltf" ]; then
  "$generate" --triangles 10000000 --out "$scene" --format gltf >/dev/null
  python3 - "$scene/scene.gltf" "$scene/street.gltf" <<'PY'
import json, math, sys
gltf = json.load(open(sys.argv[1]))
eye, target = (384.0, 1.7, 740.0), (384.0, 3.0, 0.0)
# A glTF camera looks down its -z axis: turn it about x until -z points from the eye to the target.
pitch = math.atan2(target[1] - eye[1], eye[2] - target[2])
gltf["cameras"] = [{"type": "perspective",
                    "perspective": {"yfov": math.radians(60.0), "aspectRatio": 16 / 9, "znear": 0.01}}]
gltf["nodes"].append({"camera": 0, "translation": list(eye),
                      "rotation": [math.sin(pitch / 2), 0.0, 0.0, math.cos(pitch / 2)]})
gltf["scenes"][0]["nodes"].append(len(gltf["nodes"]) - 1)
json.dump(gltf, open(sys.argv[2], "w"))
PY
fi
"$candela" bench "$scene/street.gltf" --env "$environment" --backend optix --width 1920 --height 1080 --max-depth 8 \
  --spp 100 --warmup 20 --raw-trace "$@"
