#!/usr/bin/env python3
"""Measures what candela serve delivers to one client: frames per second and input-to-frame latency.

    measure_client.py URL [--seconds 10] [--width 1280] [--height 720] [--inputs 20] [--stream jpeg|h264] [--moving]

URL is the address candela serve printed (with its ?token=... where it has one). The client takes control,
asks for a view of the given size, acknowledges every frame as a browser would (so the server renders no faster
than this client reads), and, after a warm-up, sends a wheel step every so often and times how long until a frame
with the moved camera arrives (with --moving, the camera moves every frame: a wheel step in or out with each
acknowledgement, and the timed inputs ride on them). --stream h264 asks for the video stream (the client does not
decode it; a browser would). Prints one JSON object, with the medians of the frames' render_ms, post_ms and
encode_ms. Python's standard library only, through serve_client.py.
"""
import argparse
import json
import math
import statistics
import sys
import time

from serve_client import connect, frames


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("url")
    parser.add_argument("--seconds", type=float, default=10.0, help="how long to measure")
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=720)
    parser.add_argument("--inputs", type=int, default=20, help="wheel steps to time, spread over the measurement")
    parser.add_argument("--stream", choices=["jpeg", "h264"], default="jpeg", help="the frames' stream")
    parser.add_argument("--moving", action="store_true", help="move the camera with every frame")
    args = parser.parse_args()

    ws = connect(args.url, args.width, args.height, args.stream)
    timings = {"render_ms": [], "post_ms": [], "encode_ms": [], "frame_ms": []}
    moves = 0
    messages, received, frame_bytes, latencies = {}, 0, 0, []
    start = time.monotonic()
    warmup_end = start + 1.0
    interval = args.seconds / max(args.inputs, 1)
    next_input, pending_input, position, header = warmup_end, None, None, {}
    steps = 0

    def keep(message):
        messages[message.get("type")] = message

    for header, size, now in frames(ws, keep):
        if now - start >= args.seconds + 1.0:
            break
        if now < warmup_end:
            position = header["camera"]["position"]
            continue
        received += 1
        frame_bytes += size
        for key, values in timings.items():
            if key in header:
                values.append(header[key])
        if pending_input is not None and header["camera"]["position"] != position:
            latencies.append(now - pending_input)
            pending_input = None
        position = header["camera"]["position"]
        if pending_input is None and now >= next_input and steps < args.inputs:
            # Alternate in and out, so the camera stays where it was.
            ws.send({"type": "wheel", "steps": 1 if steps % 2 == 0 else -1})
            steps += 1
            pending_input, next_input = time.monotonic(), now + interval
        elif args.moving:
            ws.send({"type": "wheel", "steps": 0.2 if moves % 2 == 0 else -0.2})
            moves += 1
    elapsed = time.monotonic() - warmup_end
    hello = messages.get("hello")
    result = {
        "url": args.url.split("?")[0],
        "backend": hello["backend"] if hello else None,
        "device": hello["device"] if hello else None,
        "scene": hello["scene"] if hello else None,
        "view": [args.width, args.height],
        "seconds": round(elapsed, 3),
        "frames": received,
        "fps_delivered": round(received / elapsed, 2) if elapsed > 0 else 0.0,
        "megabytes_per_second": round(frame_bytes / elapsed / 1e6, 3) if elapsed > 0 else 0.0,
        "stream": args.stream,
        "moving": args.moving,
        "last_frame": {k: header.get(k) for k in ("format", "width", "height", "preview", "quality", "samples")},
        "median_ms": {k: round(statistics.median(v), 3) if v else None for k, v in timings.items()},
        "inputs_timed": len(latencies),
        "input_to_frame_ms": {
            "median": round(1000 * statistics.median(latencies), 2) if latencies else None,
            "p95": round(1000 * sorted(latencies)[math.ceil(0.95 * len(latencies)) - 1], 2) if latencies else None,
            "max": round(1000 * max(latencies), 2) if latencies else None,
            "all": [round(1000 * x, 2) for x in latencies],
        },
    }
    print(json.dumps(result))


if __name__ == "__main__":
    try:
        main()
    except (RuntimeError, OSError) as e:
        print(f"measure_client: {e}", file=sys.stderr)
        sys.exit(1)
