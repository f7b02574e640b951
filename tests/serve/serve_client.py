"""A client of candela serve as a browser is, for the measuring scripts (measure_client.py, and
tests/gpu/serve_first_frame.py, which a GPU bundle carries with this file): it speaks the WebSocket protocol itself
(RFC 6455, client side), with Python's standard library only, takes control of the view and acknowledges every
frame, so that the server renders no faster than the client reads.
"""
import base64
import json
import os
import socket
import struct
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


def connect(url, width, height, stream=None):
    """The WebSocket of the viewer at `url` (the address candela serve printed, with its ?token=... where it has
    one), in control of a view of width x height, with the frames' stream `stream` (jpeg or h264) when given."""
    ws = WebSocket(url)
    ws.send({"type": "action", "name": "take_control"})
    ws.send({"type": "resize", "width": width, "height": height})
    if stream is not None:
        ws.send({"type": "stream", "codec": stream})
    return ws


def frames(ws, on_text=None):
    """Yields (header, bytes, arrival time) of every frame the server sends, each acknowledged as a browser
    acknowledges it; text messages go to on_text, as JSON, when it is given."""
    while True:
        opcode, payload = ws.receive()
        now = time.monotonic()
        if opcode == 0x1:
            if on_text is not None:
                on_text(json.loads(payload))
            continue
        header, size = frame_header(payload)
        if header.get("kind") != "frame":
            continue
        ws.send({"type": "frame_ack", "frame": header["frame"]})
        yield header, size, now
