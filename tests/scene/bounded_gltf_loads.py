#!/usr/bin/env python3
"""bounded_gltf_loads.py <repeated_gltf_inputs> <candela> <folder>

glTF files that reference one piece of data many times are made in <folder>, then each is rendered at a tiny
size by candela. A file must be refused (exit status 1, one line naming the cause) or rendered within a few
seconds and a bounded peak memory; a file rendered from repeated data must take little more memory than the
same data referenced once, as the data are decoded once and the mesh instanced.
"""
import os
import re
import resource
import subprocess
import sys
import time

SECONDS = 5.0
PEAK_MIB = 1024
SHARED_RATIO = 1.2  # peak memory of N references over that of one


def render(candela, folder, name):
    """Exit status, output, seconds and peak resident MiB of one render of folder/name."""
    args = [candela, "render", os.path.join(folder, name), "--no-cache", "--backend", "cpu", "--spp", "1",
            "--width", "16", "--height", "12", "-o", os.path.join(folder, name + ".png")]
    start = time.monotonic()
    # Address space and time are limited well beyond the bounds, so that a regression fails the test rather than
    # the machine.
    def limit_memory():
        resource.setrlimit(resource.RLIMIT_AS, (4 * PEAK_MIB << 20, 4 * PEAK_MIB << 20))

    child = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, preexec_fn=limit_memory)
    deadline = start + 6 * SECONDS
    while True:
        pid, status, usage = os.wait4(child.pid, os.WNOHANG)
        if pid != 0:
            break
        if time.monotonic() > deadline:
            child.kill()
        time.sleep(0.02)
    seconds = time.monotonic() - start
    output = child.stdout.read().decode(errors="replace")
    return os.waitstatus_to_exitcode(status), output, seconds, usage.ru_maxrss / 1024.0  # ru_maxrss is in KiB on Linux


def main():
    generator, candela, folder = sys.argv[1:4]
    os.makedirs(folder, exist_ok=True)
    subprocess.run([generator, folder], check=True)
    # (file, expected outcome, file of the data referenced once or None)
    cases = [
        ("draco-500-primitives.glb", "rendered", "draco-1-primitive.glb"),
        ("meshopt-x1000-same.glb", "rendered", "meshopt-1-view.glb"),
        ("meshopt-x4000-distinct.glb", "refused: bufferViews\\[[0-9]+\\].*decode to", None),
        ("accessor-5000-meshes.glb", "rendered", "accessor-1-mesh.glb"),
        ("accessor-5000-primitives.glb", "rendered", "accessor-1-mesh.glb"),
    ]
    failures = []
    peaks = {}
    for name, expected, single in cases:
        for file in [single, name] if single else [name]:
            if file in peaks:
                continue
            status, output, seconds, peak = render(candela, folder, file)
            peaks[file] = peak
            print(f"{file}: exit {status}, {seconds:.2f} s, {peak:.0f} MiB peak")
            print("  " + output.strip().replace("\n", "\n  "))
            if seconds > SECONDS or peak > PEAK_MIB:
                failures.append(f"{file}: {seconds:.2f} s and {peak:.0f} MiB, over {SECONDS} s or {PEAK_MIB} MiB")
            if expected.startswith("refused") and file == name:
                pattern = expected.split(": ", 1)[1]
                lines = [line for line in output.splitlines() if line.strip()]
                if status != 1 or not re.search(pattern, output) or len(lines) != 1:
                    failures.append(f"{file}: expected one line matching /{pattern}/ and exit status 1")
            elif status != 0:
                failures.append(f"{file}: expected a picture, got exit status {status}")
        if single and peaks[name] > SHARED_RATIO * peaks[single]:
            failures.append(f"{name}: {peaks[name]:.0f} MiB, more than {SHARED_RATIO} x the {peaks[single]:.0f} MiB "
                            f"of {single}")
    for failure in failures:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
