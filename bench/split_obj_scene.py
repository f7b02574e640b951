#!/usr/bin/env python3
"""split_obj_scene.py <scene.obj> <parts> <out dir>: splits an OBJ file by its objects ('o') into <parts> OBJ
files that all name the input's one material library, and writes scene.json placing them all. The geometry is
the same as the input's: each part keeps its objects' faces and the vertices they use, renumbered. For the
many-files load benchmark (bench/many_files_bench.sh)."""
import json
import os
import sys


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    source, parts, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    os.makedirs(out, exist_ok=True)
    positions, uvs, normals = [], [], []
    objects = []  # per object: its header lines ('o', 'usemtl') and its faces as lists of (v, vt, vn) strings
    library = None
    with open(source) as f:
        for line in f:
            tag = line[:2]
            if tag == "v ":
                positions.append(line)
            elif tag == "vt":
                uvs.append(line)
            elif tag == "vn":
                normals.append(line)
            elif tag == "f ":
                objects[-1][1].append(line.split()[1:])
            elif line.startswith("mtllib"):
                library = line.split(None, 1)[1].strip()
            elif line.startswith("o "):
                objects.append(([line], []))
            elif line.startswith("usemtl"):
                objects[-1][0].append(line)
    if len(objects) < parts:
        sys.exit("%s has %d objects, fewer than %d parts" % (source, len(objects), parts))
    models = []
    for p in range(parts):
        chosen = objects[p * len(objects) // parts:(p + 1) * len(objects) // parts]
        name = "part%03d.obj" % p
        remap = [{}, {}, {}]
        lists = [positions, uvs, normals]
        body = []
        for header, faces in chosen:
            body.extend(header)
            for face in faces:
                corners = []
                for corner in face:
                    refs = corner.split("/")
                    for k, r in enumerate(refs):
                        if r:
                            refs[k] = str(remap[k].setdefault(int(r), len(remap[k]) + 1))
                    corners.append("/".join(refs))
                body.append("f " + " ".join(corners) + "\n")
        with open(os.path.join(out, name), "w") as f:
            f.write("mtllib %s\n" % os.path.relpath(os.path.join(os.path.dirname(source), library), out))
            for k in range(3):
                for old in sorted(remap[k], key=remap[k].get):
                    f.write(lists[k][old - 1])
            f.writelines(body)
        models.append({"file": name})
    with open(os.path.join(out, "scene.json"), "w") as f:
        json.dump({"models": models}, f, indent=1)


main()
