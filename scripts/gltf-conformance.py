#!/usr/bin/env python3
"""Renders every model of a copy of the Khronos glTF sample models and writes a conformance table.

    scripts/gltf-conformance.py SAMPLES_DIR [-o docs/gltf-conformance.md] [--candela build/src/candela]

SAMPLES_DIR is a checkout of KhronosGroup/glTF-Sample-Assets (its Models/ folder) or of the older
glTF-Sample-Models (its 2.0/ folder), fetched separately: nothing of it belongs in this repository. Each model
folder holds variants (glTF, glTF-Binary, glTF-Embedded, glTF-Draco, glTF-Quantized,
glTF-pbrSpecularGlossiness, ...); the first of glTF, glTF-Binary and glTF-Embedded is rendered, or every variant
with --all-variants. Each render is small (--spp, --width, --height) and lit by --env when given, so that what
is seen depends on the model. The table lists per model whether it rendered or was refused, candela's warnings
and the seconds the command took; renders go to --images, with a contact sheet of them all (contact-sheet.png, in
the table's order, eight to a row). Animated models render in their rest pose, or at --time seconds of their
first animation. Stdlib only.
"""
import argparse
import html
import json
import os
import re
import struct
import subprocess
import sys
import time
import zlib
from pathlib import Path

PREFERRED_VARIANTS = ["glTF", "glTF-Binary", "glTF-Embedded"]


def model_folders(samples: Path):
    """Folders that hold a model's variants: they have a glTF* subfolder with a .gltf or .glb file."""
    for root in (samples / "Models", samples / "2.0", samples):
        if root.is_dir() and any(root.glob("*/glTF*/*.gl*")):
            return sorted(p for p in root.iterdir() if p.is_dir() and any(p.glob("glTF*/*.gl*")))
    return []


def variants(model: Path, all_variants: bool):
    found = {}
    for folder in sorted(model.glob("glTF*")):
        files = sorted(list(folder.glob("*.gltf")) + list(folder.glob("*.glb")))
        if files:
            found[folder.name] = files[0]
    if all_variants:
        return list(found.items())
    for name in PREFERRED_VARIANTS:
        if name in found:
            return [(name, found[name])]
    return list(found.items())[:1]


def gltf_json(path: Path):
    """The JSON of a .gltf or .glb, or None when it cannot be read."""
    try:
        data = path.read_bytes()
        if data[:4] == b"glTF" and len(data) >= 20:
            (length,) = struct.unpack_from("<I", data, 12)
            data = data[20 : 20 + length]
        return json.loads(data)
    except (OSError, ValueError):
        return None


def features(doc):
    """What the file asks of a renderer beyond core glTF: extensions and animation."""
    if doc is None:
        return ""
    notes = list(doc.get("extensionsUsed", []))
    if doc.get("animations"):
        notes.append(f"{len(doc['animations'])} animations")
    if doc.get("skins"):
        notes.append("skins")
    if any(p.get("targets") for m in doc.get("meshes", []) for p in m.get("primitives", [])):
        notes.append("morph targets")
    return ", ".join(notes)


def strip_path(line: str, model_file: Path):
    """The message without the model's path, and the files beside it named relative to its folder."""
    return line.replace(str(model_file) + ": ", "").replace(str(model_file.parent) + "/", "")


def render(candela, model_file: Path, image: Path, animated: bool, args):
    command = [candela, "render", str(model_file), "--no-cache", "--backend", args.backend, "--spp", str(args.spp),
               "--width", str(args.width), "--height", str(args.height), "-o", str(image)]
    if args.env:
        command += ["--env", args.env]
    if animated and args.time is not None:
        command += ["--time", str(args.time)]
    start = time.monotonic()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
        seconds = time.monotonic() - start
        output, status = done.stderr, done.returncode
    except subprocess.TimeoutExpired:
        return {"status": f"timed out after {args.timeout} s", "warnings": [], "seconds": args.timeout, "error": ""}
    lines = [l for l in output.splitlines() if l.startswith("candela: ")]
    warnings = [strip_path(l[len("candela: warning: "):], model_file) for l in lines
                if l.startswith("candela: warning: ")]
    errors = [strip_path(l[len("candela: "):], model_file) for l in lines if not l.startswith("candela: warning: ")]
    if status == 0:
        return {"status": "rendered", "warnings": warnings, "seconds": seconds, "error": ""}
    return {"status": "refused", "warnings": warnings, "seconds": seconds,
            "error": errors[-1] if errors else f"exit status {status}"}


def cell(text: str, limit: int = 200):
    text = text if len(text) <= limit else text[:limit - 3] + "..."
    return html.escape(text, quote=False).replace("|", "\\|").replace("\n", " ")


def read_png(path: Path):
    """(width, height, rows of RGB bytes) of an 8-bit, non-interlaced RGB or RGBA PNG, as candela writes them."""
    data = path.read_bytes()
    width = height = colour = 0
    idat = b""
    at = 8
    while at < len(data):
        (length,) = struct.unpack_from(">I", data, at)
        kind, body = data[at + 4:at + 8], data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise ValueError(f"{path}: not an 8-bit RGB or RGBA PNG")
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    channels = 3 if colour == 2 else 4
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up, up_left = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 255
        previous = line
        rows.append(bytes(line) if channels == 3 else bytes(b for i, b in enumerate(line) if i % 4 != 3))
    return width, height, rows


def write_png(path: Path, width: int, height: int, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + row for row in rows)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                     chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def contact_sheet(images, sheet: Path, columns: int):
    """The renders side by side, `columns` to a row, in one PNG (all renders have one size)."""
    if not images:
        return False
    tiles = [read_png(image) for image in images]
    width, height = tiles[0][0], tiles[0][1]
    blank = bytes(width * 3)
    rows = []
    for first in range(0, len(tiles), columns):
        group = tiles[first:first + columns]
        for y in range(height):
            rows.append(b"".join(t[2][y] if (t[0], t[1]) == (width, height) else blank for t in group) +
                        blank * (columns - len(group)))
    write_png(sheet, width * columns, len(rows), rows)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("samples", type=Path, help="a copy of glTF-Sample-Assets or glTF-Sample-Models")
    parser.add_argument("-o", "--output", type=Path, default=Path("gltf-conformance.md"), help="the markdown table")
    parser.add_argument("--images", type=Path, default=Path("gltf-conformance-images"), help="where renders go")
    parser.add_argument("--candela", default="build/src/candela")
    parser.add_argument("--backend", default="auto")
    parser.add_argument("--env", help="an .hdr or .exr that lights every model")
    parser.add_argument("--spp", type=int, default=8)
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=120)
    parser.add_argument("--timeout", type=int, default=300, help="seconds per model")
    parser.add_argument("--time", type=float, help="render animated models at this time (seconds), not at rest")
    parser.add_argument("--all-variants", action="store_true", help="render every variant of each model")
    parser.add_argument("--only", help="a regular expression: render only models whose name matches")
    args = parser.parse_args()

    models = model_folders(args.samples)
    if not models:
        sys.exit(f"{args.samples}: no model folders (Models/<name>/glTF*/ or 2.0/<name>/glTF*/) found")
    args.images.mkdir(parents=True, exist_ok=True)
    rows, images = [], []
    for model in models:
        if args.only and not re.search(args.only, model.name):
            continue
        for variant, model_file in variants(model, args.all_variants):
            image = args.images / f"{model.name}.{variant}.png"
            doc = gltf_json(model_file)
            result = render(args.candela, model_file, image, bool(doc and doc.get("animations")), args)
            if result["status"] == "rendered":
                images.append(image)
            rows.append((model.name, variant, features(doc), result))
            print(f"{model.name:32} {variant:28} {result['status']:10} {result['seconds']:7.2f} s "
                  f"{len(result['warnings'])} warnings {result['error']}", flush=True)

    rendered = sum(1 for r in rows if r[3]["status"] == "rendered")
    lines = [f"{rendered} of {len(rows)} renders succeeded ({args.spp} spp, {args.width}x{args.height}, "
             f"backend {args.backend}{', lit by ' + os.path.basename(args.env) if args.env else ''}).", "",
             "| model | variant | uses | status | warnings | seconds |", "| --- | --- | --- | --- | --- | --- |"]
    for name, variant, uses, result in rows:
        status = result["status"] + (": " + result["error"] if result["error"] else "")
        warnings = "<br>".join(cell(w) for w in result["warnings"]) or "-"
        lines.append(f"| {name} | {variant} | {cell(uses) or '-'} | {cell(status)} | {warnings} | "
                     f"{result['seconds']:.2f} |")
    args.output.write_text("\n".join(lines) + "\n")
    sheet = args.images / "contact-sheet.png"
    if contact_sheet(images, sheet, 8):
        print(f"contact sheet: {sheet}")
    print(f"{args.output}: {rendered} of {len(rows)} rendered")


if __name__ == "__main__":
    main()
