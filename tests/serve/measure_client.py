#!/usr/bin/env python3
"""Measures what candela serve delivers to one client: frames per second and input-to-frame latency.

    measure_client.py URL [--seconds 10] [--width 1280] [--height 720] [--inputs 20] [--stream jpeg|h264] [--moving]

URL is the address candela serve printed (with its ?token=... where it has one). The client takes control,
asks for a view of the given size, acknowledges every frame as a browser would (so the server renders no faster
than this client reads), and, after a warm-up, sends a wheel step every so often and times how long until a frame
with the moved camera arrives (with --moving, the camera moves every frame: a wheel step in or out with each
acknowledgement, and the timed inputs ride on them). --stream h264 asks for the video stream (the client does not
decode it; a browser would). Prints one JSON object, with the medians of the frames' render_ms, post_ms and
encode_ms. Python's standard library only: it speaks the WebSocket
protocol itself (RFC 6455, client side).
"""
import argparse
import base64
import json
import math
import os
import socket
import statistics
import struct
import sys
import time
import urllib.parse


class WebSocket:
    def __init__(self, url):
        parts = urllib.parse.urlsplit(url)
        self.sock = socket.create_connection((parts.hostname, parts.port or 80), timeout=30)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        key = base64.b64encode(os.urandom(16)).decode()
        path = "/ws" + ("?" + parts.query if parts.query else "")
        request = (f"GET {path} HTTP/1.1\r\nHost: {parts.netloc}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                   f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n")
        self.sock.sendall(request.encode())
        self.buffer = b""
        while b"\r\n\r\n" not in self.buffer:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise RuntimeError("the server closed the connection during the handshake")
            self.buffer += chunk
        head, self.buffer = self.buffer.split(b"\r\n\r\n", 1)
        status = head.split(b"\r\n", 1)[0].decode()
        if " 101 " not in status:
            raise RuntimeError(f"the server refused the WebSocket: {status}")

    def _read(self, n):
        while len(self.buffer) < n:
            chunk = self.sock.recv(1 << 20)
            if not chunk:
                raise RuntimeError("the server closed the connection")
            self.buffer += chunk
        data, self.buffer = self.buffer[:n], self.buffer[n:]
        return data

    def send_text(self, text):
        payload = text.encode()
        mask = os.urandom(4)
        header = bytes([0x81])
        n = len(payload)
        if n < 126:
            header += bytes([0x80 | n])
        elif n < 65536:
            header += bytes([0x80 | 126]) + struct.pack(">H", n)
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", n)
        masked = bytes(b ^ mask[i % 4] for i, b in enumerate(payload))
        self.sock.sendall(header + mask + masked)

    def send(self, message):
        self.send_text(json.dumps(message))

    def receive(self):
        """Returns (opcode, payload) of the next data message, its fragments joined; answers pings."""
        message_opcode, parts = None, []
        while True:
            b0, b1 = self._read(2)
            final, opcode, n = b0 & 0x80, b0 & 0x0F, b1 & 0x7F
            if n == 126:
                n = struct.unpack(">H", self._read(2))[0]
            elif n == 127:
                n = struct.unpack(">Q", self._read(8))[0]
            payload = self._read(n)
            if opcode == 0x9:  # ping: answer with a masked pong
                mask = os.urandom(4)
                self.sock.sendall(bytes([0x8A, 0x80 | len(payload)]) + mask +
                                  bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))
            elif opcode == 0x8:
                raise RuntimeError("the server closed the WebSocket")
            elif opcode in (0x0, 0x1, 0x2):
                if opcode != 0x0:
                    message_opcode, parts = opcode, []
                parts.append(payload)
                if final:
                    return message_opcode, b"".join(parts)


def frame_header(payload):
    length = struct.unpack("<I", payload[:4])[0]
    return json.loads(payload[4:4 + length]), len(payload)


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

    ws = WebSocket(args.url)
    ws.send({"type": "action", "name": "take_control"})
    ws.send({"type": "resize", "width": args.width, "height": args.height})
    ws.send({"type": "stream", "codec": args.stream})
    timings = {"render_ms": [], "post_ms": [], "encode_ms": [], "frame_ms": []}
    moves = 0
    hello, frames, frame_bytes, latencies = None, 0, 0, []
    start = time.monotonic()
    warmup_end = start + 1.0
    interval = args.seconds / max(args.inputs, 1)
    next_input, pending_input, position, header = warmup_end, None, None, {}
    steps = 0
    while time.monotonic() - start < args.seconds + 1.0:
        opcode, payload = ws.receive()
        now = time.monotonic()
        if opcode == 0x1:
            message = json.loads(payload)
            if message.get("type") == "hello":
                hello = message
            continue
        header, size = frame_header(payload)
        if header.get("kind") != "frame":
            continue
        ws.send({"type": "frame_ack", "frame": header["frame"]})
        if now < warmup_end:
            position = header["camera"]["position"]
            continue
        frames += 1
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
    result = {
        "url": args.url.split("?")[0],
        "backend": hello["backend"] if hello else None,
        "device": hello["device"] if hello else None,
        "scene": hello["scene"] if hello else None,
        "view": [args.width, args.height],
        "seconds": round(elapsed, 3),
        "frames": frames,
        "fps_delivered": round(frames / elapsed, 2) if elapsed > 0 else 0.0,
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
