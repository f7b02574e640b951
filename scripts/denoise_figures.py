#!/usr/bin/env python3
"""Renders the before/after figures and numbers of docs/denoising.md.

  scripts/denoise_figures.py [candela binary] [output folder]

For each scene: a 4-sample render without denoising, with the a-trous and with the bilateral filter (the same
samples: same seed), and a 4096-sample reference, all 160x160 on the CPU backend. Prints a Markdown table of
relMSE against the reference (mean over pixels and channels of (x - ref)^2 / (ref^2 + 1e-2)) and writes one PNG
per scene: the four full images side by side (raw, a-trous, bilateral, reference) above 3x enlargements of one
crop of each, tone mapped like `candela render` writes PNGs (ACES filmic, sRGB). Only the standard library.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SIZE = 160
NOISY_SPP = 4
REFERENCE_SPP = 4096
SCENES = {"cornell-box": (40, 70, 48), "material-gallery": (20, 40, 48)}  # crop x, y, side
VARIANTS = ["none", "atrous", "bilateral"]


def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = f.read()
    endian = "<" if scale < 0 else ">"
    values = struct.unpack(endian + "f" * (3 * width * height), data)
    rows = [values[3 * width * y: 3 * width * (y + 1)] for y in range(height)]
    rows.reverse()  # PFM stores the bottom row first
    return width, height, [v for row in rows for v in row]


def rel_mse(x, ref):
    return sum((a - b) ** 2 / (b * b + 1e-2) for a, b in zip(x, ref)) / len(ref)


def display(v):
    # image/tonemap.h: ACES filmic (Narkowicz), then sRGB encoding.
    v = max(0.0, v)
    v = min(1.0, max(0.0, (v * (2.51 * v + 0.03)) / (v * (2.43 * v + 0.59) + 0.14)))
    v = 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
    return int(v * 255 + 0.5)


def write_png(path, width, height, rgb_rows):
    raw = b"".join(b"\x00" + bytes(row) for row in rgb_rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def render(candela, scene, spp, seed, denoiser, path):
    subprocess.run([candela, "render", scene, "--backend", "cpu", "--width", str(SIZE), "--height", str(SIZE),
                    "--spp", str(spp), "--seed", str(seed), "--denoise", denoiser, "-o", path],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def main():
    candela = sys.argv[1] if len(sys.argv) > 1 else "build/src/candela"
    out = sys.argv[2] if len(sys.argv) > 2 else "docs/images"
    os.makedirs(out, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="candela-denoise-figures-")
    print("| scene | raw relMSE | a-trous relMSE | a-trous gain | bilateral relMSE | bilateral gain |")
    print("| --- | --- | --- | --- | --- | --- |")
    for scene, (cx, cy, side) in SCENES.items():
        images = {}
        for variant in VARIANTS:
            path = os.path.join(tmp, f"{scene}-{variant}.pfm")
            render(candela, scene, NOISY_SPP, 1, variant, path)
            images[variant] = read_pfm(path)[2]
        path = os.path.join(tmp, f"{scene}-reference.pfm")
        render(candela, scene, REFERENCE_SPP, 1000, "none", path)
        images["reference"] = read_pfm(path)[2]
        ref = images["reference"]
        err = {v: rel_mse(images[v], ref) for v in VARIANTS}
        print(f"| {scene} | {err['none']:.4f} | {err['atrous']:.4f} | {err['none'] / err['atrous']:.1f}x | "
              f"{err['bilateral']:.4f} | {err['none'] / err['bilateral']:.2f}x |")

        order = VARIANTS + ["reference"]
        gap, zoom = 4, 3
        crop_side = side * zoom
        width = len(order) * SIZE + (len(order) - 1) * gap
        rows = []
        for y in range(SIZE):
            row = []
            for i, name in enumerate(order):
                img = images[name]
                for x in range(SIZE):
                    row += [display(img[3 * (y * SIZE + x) + c]) for c in range(3)]
                if i + 1 < len(order):
                    row += [255] * (3 * gap)
            rows.append(row)
        rows += [[255] * (3 * width) for _ in range(gap)]
        for y in range(crop_side):
            row = []
            for i, name in enumerate(order):
                img = images[name]
                for x in range(crop_side):
                    p = 3 * ((cy + y // zoom) * SIZE + cx + x // zoom)
                    row += [display(img[p + c]) for c in range(3)]
                row += [255] * (3 * (SIZE - crop_side + (gap if i + 1 < len(order) else 0)))
            rows.append(row)
        write_png(os.path.join(out, f"denoise-{scene}.png"), width, len(rows), rows)
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main()
