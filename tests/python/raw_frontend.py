"""A raw-socket Cura frontend for fault injection: the Arcus framing written by hand (big-endian
0x2BAD0100 | size | FNV-1a-32("cura.proto.<Name>") | protobuf), so tests can send what libArcus
never would — bad headers, unknown type ids, unparsable payloads — and behave as a broken peer
(close mid-slice, never answer the close request). Protobuf messages come from Cura's installed
Cura.proto compiled by protoc at test time."""
import importlib
import socket
import struct
import subprocess
import sys
import time

CURA_PROTO_DIR = "/usr/lib/cura/plugins/CuraEngineBackend"
HEADER = 0x2BAD0100
CLOSE = 0xF0F0F0F0


def type_id(name):
    """Arcus's message type id: 32-bit FNV-1a of the full name."""
    h = 2166136261
    for byte in name.encode():
        h = ((h ^ byte) * 16777619) & 0xFFFFFFFF
    return h


def cura_pb2(tmp_dir):
    """Cura.proto compiled to Python in tmp_dir and imported."""
    subprocess.run(["protoc", f"-I{CURA_PROTO_DIR}", f"--python_out={tmp_dir}", "Cura.proto"], check=True)
    sys.path.insert(0, str(tmp_dir))
    try:
        return importlib.import_module("Cura_pb2")
    finally:
        sys.path.pop(0)


def frame(name, payload=b"", header=HEADER, type_override=None):
    tid = type_id(name) if type_override is None else type_override
    return struct.pack(">III", header, len(payload), tid) + payload


class RawFrontend:
    """Listens on a free port; accept() waits for the engine."""

    def __init__(self):
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(1)
        self.port = self.server.getsockname()[1]
        self.conn = None

    def accept(self, timeout=10):
        self.server.settimeout(timeout)
        self.conn, _ = self.server.accept()
        self.conn.settimeout(0.2)

    def send(self, data):
        self.conn.sendall(data)

    def read_for(self, seconds):
        """Everything the engine sends within `seconds` (or until it closes); answers nothing."""
        data, end = b"", time.monotonic() + seconds
        while time.monotonic() < end:
            try:
                chunk = self.conn.recv(1 << 16)
            except socket.timeout:
                continue
            except OSError:
                break
            if not chunk:
                break
            data += chunk
        return data

    def close(self):
        for s in (self.conn, self.server):
            if s is not None:
                try:
                    s.close()
                except OSError:
                    pass
