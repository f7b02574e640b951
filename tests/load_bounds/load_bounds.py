#!/usr/bin/env python3
"""Small files that once made a load take minutes and gigabytes, generated here and rendered (or refused) under a
bound on wall time and peak memory: python3 load_bounds.py CASE CANDELA WORKDIR.

Each case writes its inputs into WORKDIR, runs candela on them and measures the child's peak resident memory
(wait4's ru_maxrss) and its time. The time bound (5 s, or the case's own) is on the child's CPU time (user and
system, all its threads): on a machine shared with other work the wall time says more about the neighbours than
about candela; swapping, which costs wall time, shows in the memory bound. A case passes when candela renders or
refuses (as the case says) within the bounds; a case of shared data also renders the scene with one reference and requires the many references to
cost no more than 1.2 times its memory."""

import gzip
import json
import os
import re
import struct
import subprocess
import sys
import time
import zlib

SECONDS = 5.0
MEMORY_BYTES = 1 << 30
SHARED_RATIO = 1.2

TINY = ["--spp", "1", "--width", "16", "--height", "12", "--backend", "cpu", "--no-cache"]


def run(candela, args, workdir):
    """Runs candela; returns (exit status, output, seconds, peak resident bytes, CPU seconds)."""
    start = time.monotonic()
    child = subprocess.Popen([candela] + args, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    out = b""
    # Read before waiting so that a talkative child cannot block on a full pipe.
    out = child.stdout.read()
    _, status, usage = os.wait4(child.pid, 0)
    child.returncode = os.waitstatus_to_exitcode(status)
    seconds = time.monotonic() - start
    cpu = usage.ru_utime + usage.ru_stime
    return child.returncode, out.decode(errors="replace"), seconds, usage.ru_maxrss * 1024, cpu


def render(candela, workdir, scene, extra=()):
    return run(candela, ["render", scene, *TINY, *extra, "-o", os.path.join(workdir, "out.png")], workdir)


def write(path, data):
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def png_bytes(width, height, channels=3):
    """A PNG of zero pixels: a few kilobytes however large it claims to be."""
    color_type = {1: 0, 3: 2, 4: 6}[channels]
    row = b"\0" * (1 + width * channels)
    compressor = zlib.compressobj(9)
    data = b"".join(compressor.compress(row) for _ in range(height)) + compressor.flush()

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    header = struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", data) + chunk(b"IEND", b"")


def pfm_bytes(width, height):
    return b"PF\n%d %d\n-1\n" % (width, height) + struct.pack("<f", 0.5) * (3 * width * height)


def ply_grid(cells):
    """A binary PLY of a cells x cells grid of quads."""
    n = cells + 1
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
              "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (n * n, cells * cells)).encode()
    vertices = b"".join(struct.pack("<fff", i / cells, j / cells, 0.0) for j in range(n) for i in range(n))
    faces = b"".join(struct.pack("<Biiii", 4, j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i)
                     for j in range(cells) for i in range(cells))
    return header + vertices + faces


CAMERA = 'LookAt 0 0 -5  0 0 0  0 1 0\nCamera "perspective" "float fov" 45\nWorldBegin\n'
SCENE_HEAD = CAMERA + 'LightSource "infinite" "rgb L" [1 1 1]\n'


def shapes_scene(count, shape):
    """A pbrt scene of `count` shapes on a grid of 60 columns; `shape` is the shape's line, or a function that
    gives the line of the i-th."""
    lines = [SCENE_HEAD]
    for i in range(count):
        line = shape if isinstance(shape, str) else shape(i)
        lines.append("AttributeBegin\nTranslate %g %g 0\n%s\nAttributeEnd\n" % (i % 60 * 0.1, i // 60 * 0.1, line))
    return "".join(lines)


def case_ply_referenced_many(candela, workdir):
    write(os.path.join(workdir, "grid.ply"), ply_grid(300))
    for count in (1, 2000):
        write(os.path.join(workdir, "ply-%d.pbrt" % count),
              shapes_scene(count, 'Shape "plymesh" "string filename" "grid.ply"'))
    return "shared", "ply-1.pbrt", "ply-2000.pbrt"


def case_include_many(candela, workdir):
    cells = 150
    points = " ".join("%g %g 0" % (i / cells, j / cells) for j in range(cells + 1) for i in range(cells + 1))
    n = cells + 1
    indices = " ".join("%d %d %d %d %d %d" % (j * n + i, j * n + i + 1, (j + 1) * n + i + 1,
                                              j * n + i, (j + 1) * n + i + 1, (j + 1) * n + i)
                       for j in range(cells) for i in range(cells))
    write(os.path.join(workdir, "part.pbrt"),
          'Shape "trianglemesh" "point3 P" [%s] "integer indices" [%s]\n' % (points, indices))
    for count in (1, 2000):
        write(os.path.join(workdir, "include-%d.pbrt" % count), shapes_scene(count, 'Include "part.pbrt"'))
    return "shared", "include-1.pbrt", "include-2000.pbrt"


def case_spheres(candela, workdir):
    write(os.path.join(workdir, "spheres-1.pbrt"), shapes_scene(1, 'Shape "sphere" "float radius" 0.04'))
    write(os.path.join(workdir, "spheres-3600.pbrt"),
          shapes_scene(3600, lambda i: 'Shape "sphere" "float radius" %g' % (0.01 + 0.00001 * i)))
    return "shared", "spheres-1.pbrt", "spheres-3600.pbrt"


def mix_textures_scene(workdir, name, count, image_size, shared_images, materials, shape_per_material,
                       value_type="spectrum", material='Material "diffuse" "texture reflectance" "%s"'):
    """A pbrt scene of `count` mix textures of two PNG images of image_size^2 zero pixels, written to workdir/name.
    shared_images: every mix blends the same two image textures, else each its own pair (one of them scaled, so
    that no two are alike); materials: a material names each mix (`material`, the mix's name in place of %s);
    shape_per_material: a sphere follows each material, else one sphere ends the scene. value_type: the
    textures' pbrt type, "spectrum" or "float"."""
    write(os.path.join(workdir, "a.png"), png_bytes(image_size, image_size))
    write(os.path.join(workdir, "b.png"), png_bytes(image_size, image_size))
    lines = [SCENE_HEAD]
    if shared_images:
        lines.append('Texture "a" "%s" "imagemap" "string filename" "a.png"\n'
                     'Texture "b" "%s" "imagemap" "string filename" "b.png"\n' % (value_type, value_type))
    for i in range(count):
        a, b = ("a", "b") if shared_images else ("a%d" % i, "b%d" % i)
        if not shared_images:
            lines.append('Texture "%s" "%s" "imagemap" "string filename" "a.png" "float uscale" %d\n'
                         % (a, value_type, i + 1))
            lines.append('Texture "%s" "%s" "imagemap" "string filename" "b.png"\n' % (b, value_type))
        lines.append('Texture "m%d" "%s" "mix" "texture tex1" "%s" "texture tex2" "%s"\n' % (i, value_type, a, b))
        if materials:
            lines.append(material % ("m%d" % i) + "\n")
        if shape_per_material:
            lines.append('Shape "sphere"\n')
    if not shape_per_material:
        lines.append('Shape "sphere"\n')
    write(os.path.join(workdir, name), "".join(lines))


def case_unused_mix_textures(candela, workdir):
    mix_textures_scene(workdir, "mix.pbrt", 200, 4096, shared_images=False, materials=False,
                       shape_per_material=False)
    return "bounded", "mix.pbrt"


def case_used_mix_textures(candela, workdir):
    """200 distinct mixes that materials use: refused when their bakes are charged, before any is baked."""
    mix_textures_scene(workdir, "used-mix.pbrt", 200, 4096, shared_images=False, materials=True,
                       shape_per_material=True)
    # A budget of about 2 GiB: ten bakes of 192 MiB would fit it, and break the bound on memory, if the mixes
    # were baked before the refusal.
    return ("refused", "used-mix.pbrt", ["--max-memory", "4G"],
            r"used-mix\.pbrt:\d+: mix texture 'm\d+' baked at 4096x4096 texels needs about 192 MiB")


def case_roughness_mix_textures(candela, workdir):
    """200 distinct float mixes that materials use as roughness: the mix and the roughness made of it are both
    charged, and refused, before any is baked."""
    mix_textures_scene(workdir, "roughness-mix.pbrt", 200, 4096, shared_images=False, materials=True,
                       shape_per_material=True, value_type="float",
                       material='Material "conductor" "texture roughness" "%s"')
    # A budget of about 2 GiB, which seven bakes of 192 MiB with their roughness of 64 MiB would fit, and break the
    # bound on memory, if each mix were baked when its roughness is made.
    return ("refused", "roughness-mix.pbrt", ["--max-memory", "4G"],
            r"roughness-mix\.pbrt:\d+: (mix texture 'm\d+' baked|the roughness of texture 'm\d+') at 4096x4096 "
            r"texels needs about")


def case_mean_mix_textures(candela, workdir):
    """200 distinct mixes whose mean colour materials take (diffusetransmission's transmittance): read from the
    mixes' inputs, and the mixes refused when charged, before any is baked."""
    mix_textures_scene(workdir, "mean-mix.pbrt", 200, 4096, shared_images=False, materials=True,
                       shape_per_material=True, material='Material "diffusetransmission" "texture transmittance" "%s"')
    # A budget of about 2 GiB: ten bakes of 192 MiB would fit it, and break the bound on memory, if each mix were
    # baked for its mean.
    return ("refused", "mean-mix.pbrt", ["--max-memory", "4G"],
            r"mean-mix\.pbrt:\d+: mix texture 'm\d+' baked at 4096x4096 texels needs about 192 MiB")


def case_shared_mix_textures(candela, workdir):
    """The same mix defined under 200 names, each used by a material: one bake."""
    for count in (1, 200):
        # One shape: spheres of 200 materials would be 200 meshes.
        mix_textures_scene(workdir, "mix-%d.pbrt" % count, count, 2048, shared_images=True, materials=True,
                           shape_per_material=False)
    return "shared", "mix-1.pbrt", "mix-200.pbrt"


def sphere_scene(workdir, name, texture=None, environment=None, shape='Shape "sphere"'):
    """A pbrt scene of one shape (a sphere unless `shape` says otherwise) under an infinite light, written to
    workdir/name: the sphere's reflectance is the image file `texture`, the light's radiance the image file
    `environment` (else white)."""
    lines = [SCENE_HEAD if environment is None
             else CAMERA + 'LightSource "infinite" "string filename" "%s"\n' % environment]
    if texture is not None:
        lines.append('Texture "t" "spectrum" "imagemap" "string filename" "%s"\n'
                     'Material "diffuse" "texture reflectance" "t"\n' % texture)
    lines.append(shape + "\n")
    write(os.path.join(workdir, name), "".join(lines))


def case_tall_pfm(candela, workdir):
    write(os.path.join(workdir, "tall.pfm"), pfm_bytes(1, 1000000))
    sphere_scene(workdir, "tall-pfm.pbrt", texture="tall.pfm", environment="tall.pfm")
    return "bounded", "tall-pfm.pbrt"


def case_ply_gzip_bomb(candela, workdir):
    return gzip_bomb(workdir, "binary_little_endian")


def case_ply_gzip_ascii_bomb(candela, workdir):
    return gzip_bomb(workdir, "ascii")


def gzip_bomb(workdir, encoding):
    """A gzip PLY of three vertices and a face, followed by 1 GiB of zeros."""
    header = (b"ply\nformat %s 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              b"property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
              % encoding.encode())
    compressor = zlib.compressobj(9, zlib.DEFLATED, 31)
    block = b"\0" * (1 << 20)
    data = compressor.compress(header) + b"".join(compressor.compress(block) for _ in range(1024))
    write(os.path.join(workdir, "bomb.ply.gz"), data + compressor.flush())
    sphere_scene(workdir, "bomb.pbrt", shape='Shape "plymesh" "string filename" "bomb.ply.gz"')
    return "bounded", "bomb.pbrt"


def case_large_png(candela, workdir):
    """256 million pixels: inflated (768 MB of RGB), area-averaged a row at a time to 8192x8192 and given their
    mip levels, which costs 4 to 5 s of CPU on two shared cores, linear in the pixels; its bound is twice that.
    The memory bound is the one that catches the image held whole (1 GiB as RGBA)."""
    write(os.path.join(workdir, "large.png"), png_bytes(16000, 16000))
    sphere_scene(workdir, "large-png.pbrt", texture="large.png")
    return "bounded", "large-png.pbrt", 10.0


def case_obj_face_corners(candela, workdir):
    corners = 12000000
    with open(os.path.join(workdir, "corners.obj"), "wb") as f:
        f.write(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf")
        f.write(b" 1 2 3" * (corners // 3))
        f.write(b"\n")
    return "bounded", "corners.obj"


def case_thin_environment(candela, workdir):
    write(os.path.join(workdir, "thin.pfm"), pfm_bytes(1, 8192))
    sphere_scene(workdir, "thin-env.pbrt", environment="thin.pfm")
    return "bounded", "thin-env.pbrt"


def case_max_memory(candela, workdir):
    write(os.path.join(workdir, "budget.png"), png_bytes(8192, 8192, 4))
    sphere_scene(workdir, "budget.pbrt", texture="budget.png")
    return "refused", "budget.pbrt", ["--max-memory", "200M"], "budget.png: an image decoded at 8192x8192 pixels needs about 256 MiB.*--max-memory"


def case_many_curves(candela, workdir):
    """A hair model's worth of curves, one directive each (pbrt-v4's hair scenes hold hundreds of thousands)."""
    lines = [SCENE_HEAD, 'Material "hair"\n']
    for i in range(200000):
        x, z = (i % 500) / 250 - 1, (i // 500) / 200 - 1
        lines.append('Shape "curve" "string type" "cylinder" "point3 P" [%.4f -1 %.4f %.4f -0.3 %.4f %.4f 0.3 %.4f '
                     '%.4f 1 %.4f] "float width0" 0.004 "float width1" 0.001\n' % (x, z, x + 0.05, z, x - 0.05, z, x, z))
    write(os.path.join(workdir, "many-curves.pbrt"), "".join(lines))
    return "bounded", "many-curves.pbrt"


def case_curve_max_memory(candela, workdir):
    """One b-spline of a million control points: its segments are charged before they are made."""
    points = " ".join("%d 1 2" % (i % 10) for i in range(1000000))
    write(os.path.join(workdir, "long-curve.pbrt"),
          SCENE_HEAD + 'Shape "curve" "string basis" "bspline" "point3 P" [%s]\n' % points)
    return "refused", "long-curve.pbrt", ["--max-memory", "200M"], "long-curve.pbrt:5: shape 'curve' needs about .*--max-memory"


def glb_bytes(document, binary):
    """A .glb of a JSON document and a BIN chunk, each padded to four bytes."""
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text +
            struct.pack("<I4s", len(binary), b"BIN\0") + binary)


def case_meshopt_decoded_size(candela, workdir):
    """A triangle whose positions are an EXT_meshopt_compression stream of 8 MiB (zeros, no valid stream) that
    claims 2 GiB decoded, within the 256 times its bytes that the codec allows: refused by the load budget before
    the decoded buffer is allocated."""
    compressed, stride = 8 << 20, 256
    count = compressed * 256 // stride
    stream = {"buffer": 0, "byteLength": compressed, "byteStride": stride, "count": count, "mode": "ATTRIBUTES"}
    document = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": compressed},
                    {"byteLength": stride * count, "extensions": {"EXT_meshopt_compression": {"fallback": True}}}],
        "bufferViews": [{"buffer": 1, "byteLength": stride * count,
                         "extensions": {"EXT_meshopt_compression": stream}}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "extensionsUsed": ["EXT_meshopt_compression"],
        "extensionsRequired": ["EXT_meshopt_compression"],
    }
    write(os.path.join(workdir, "meshopt.glb"), glb_bytes(document, b"\0" * compressed))
    return ("refused", "meshopt.glb", ["--max-memory", "1G"],
            r"meshopt\.glb: bufferViews\[0\] decoded from EXT_meshopt_compression needs about 2\.0 GiB.*--max-memory")


CASES = {name[len("case_"):]: f for name, f in globals().items() if name.startswith("case_")}


def describe(label, result):
    status, out, seconds, peak, cpu = result
    last = out.strip().splitlines()[-1] if out.strip() else ""
    print("%s: exit %d in %.2f s (%.2f s of CPU), peak %.0f MiB: %s" % (label, status, seconds, cpu, peak / 2**20, last))


def within_bounds(label, result, bound=SECONDS):
    status, out, _, peak, seconds = result
    describe(label, result)
    ok = True
    if status not in (0, 1) or (status == 1 and len(out.strip().splitlines()) == 0):
        print("FAIL: %s neither rendered nor refused in a line" % label)
        ok = False
    if seconds > bound:
        print("FAIL: %s took %.2f s of CPU, more than %.0f s" % (label, seconds, bound))
        ok = False
    if peak > MEMORY_BYTES:
        print("FAIL: %s peaked at %.0f MiB, more than %.0f MiB" % (label, peak / 2**20, MEMORY_BYTES / 2**20))
        ok = False
    return ok


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in CASES:
        print("usage: load_bounds.py {%s} CANDELA WORKDIR" % "|".join(sorted(CASES)))
        return 2
    name, candela, workdir = sys.argv[1], os.path.abspath(sys.argv[2]), os.path.join(sys.argv[3], sys.argv[1])
    os.makedirs(workdir, exist_ok=True)
    kind, *scenes = CASES[name](candela, workdir)
    if kind == "refused":
        scene, options, pattern = scenes
        result = render(candela, workdir, scene, options)
        ok = within_bounds(scene, result)
        if result[0] != 1 or not re.search(pattern, result[1]):
            print("FAIL: %s was not refused with a line like '%s'" % (scene, pattern))
            ok = False
        return 0 if ok else 1
    if kind == "bounded":
        bound = scenes[1] if len(scenes) > 1 else SECONDS
        return 0 if within_bounds(scenes[0], render(candela, workdir, scenes[0]), bound) else 1
    one = render(candela, workdir, scenes[0])
    describe(scenes[0], one)
    many = render(candela, workdir, scenes[1])
    ok = within_bounds(scenes[1], many)
    if one[0] != 0 or many[0] != 0:
        print("FAIL: a scene of shared data must render")
        ok = False
    if many[3] > SHARED_RATIO * one[3]:
        print("FAIL: %s peaked at %.2f times the memory of one reference, more than %.1f"
              % (scenes[1], many[3] / one[3], SHARED_RATIO))
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
