#!/usr/bin/env python3
"""Times candela serve's first frames from the moment it is started: the first frame a browser gets, and the
first one the GPU renders (while the GPU programs compile, serve renders on the CPU meanwhile).

    serve_first_frame.py CANDELA [--seconds 90] [--width 1920] [--height 1080] -- SERVE ARGUMENTS...

Starts `CANDELA serve --port 0 SERVE ARGUMENTS...`, reads the address it prints, connects as a browser does
(tests/serve/serve_client.py: take control, resize, acknowledge every frame) and prints one JSON object: the seconds
from the start to the address, to the first frame and to the first frame of another backend than the first one's (the
handover), with each one's backend and device, the frames rendered before the handover and the compile's progress
as the last CPU frame reported it. Ends serve when the handover was seen or after --seconds.
"""
import argparse
import json
import os
import subprocess
import sys
import time

# serve_client.py is in tests/serve, or beside this script in a bundle (bundle.sh).
here = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [here, os.path.join(here, "..", "serve")]
from serve_client import connect, frames  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("candela")
    parser.add_argument("--seconds", type=float, default=90.0, help="the longest wait for the handover")
    parser.add_argument("--width", type=int, default=1920)
    parser.add_argument("--height", type=int, default=1080)
    # serve's arguments are those after "--", split off by hand: argparse would take the positional `candela` and an
    # empty list of them together at the first positional, and then refuse the rest after the options.
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    args.serve_args = argv[split + 1:]

    start = time.monotonic()
    serve = subprocess.Popen([args.candela, "serve", "--port", "0", *args.serve_args], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True)
    result = {"command": " ".join(["serve", *args.serve_args])}
    try:
        line = serve.stdout.readline()
        if "open " not in line:
            raise RuntimeError(f"serve printed no address: {line!r}")
        result["address_seconds"] = round(time.monotonic() - start, 3)
        ws = connect(line.split("open ", 1)[1].strip(), args.width, args.height)
        first, before_handover, starting = None, 0, None
        for header, _, arrival in frames(ws):
            if arrival - start >= args.seconds:
                break
            seen = {"seconds": round(arrival - start, 3), "backend": header.get("backend"),
                    "device": header.get("device")}
            if first is None:
                first = seen
                result["first_frame"] = first
            if header.get("backend") != first["backend"]:
                result["handover"] = seen
                break
            before_handover += 1
            starting = header.get("starting")
        result["frames_before_handover"] = before_handover
        result["last_starting"] = starting
    finally:
        serve.terminate()
        serve.wait(timeout=30)
    print(json.dumps(result))


if __name__ == "__main__":
    try:
        main()
    except (RuntimeError, OSError) as e:
        print(f"serve_first_frame: {e}", file=sys.stderr)
        sys.exit(1)
