"""Cura's side of the Arcus socket, shared by tests/python/cura_frontend.py (one slice per process) and
tests/bench/soak_receiver.py (many slices per process): the real libArcus through Debian's python3-arcus
(the binding Cura itself uses) and Cura's installed Cura.proto. Standard library + Arcus only; run with
/usr/bin/python3 (the Arcus binding is built for Debian's Python).

Pieces: free_port; new_listener (a SocketListener whose state lives in a class of its own, one per
socket); open_socket (a new socket listening on a free port, as Uranium's Backend._createSocket does);
spawn_engine (`<engine> connect 127.0.0.1:<port> ""`, as CuraEngineBackend.getEngineCommand); build_slice
(the Slice message from a JSON job); record (what Cura keeps of each message it receives)."""
import os
import socket
import struct
import subprocess
import threading
import time

import Arcus

from stl_soup import triangle_soup_bytes  # noqa: E402 (beside this script)

CURA_PROTO = "/usr/lib/cura/plugins/CuraEngineBackend/Cura.proto"
DEBUG_ERROR = int(Arcus.ErrorCode.Debug)  # libArcus's notices ("Closing socket because ..."), not failures
CLOSED_STATES = (int(Arcus.SocketState.Closed), int(Arcus.SocketState.Error))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def new_listener():
    """A listener for one socket. Its state lives in a class made for it (Listener.states, .errors, ...),
    not in the instance: libArcus calls back from its own thread, and python3-arcus may hand that call a
    fresh Python wrapper of the same C++ listener, which has none of the instance's attributes (seen once
    in CI as an AttributeError). A class per socket keeps one socket's late callbacks (say, a state change
    while it closes) out of the next socket's state.

    Listener.arrivals holds the time.monotonic() of every messageReceived callback not yet taken: libArcus
    calls it right after queueing the message, in order, so take_timed pairs each message with the moment
    libArcus had read it off the wire."""

    class Listener(Arcus.SocketListener):
        states, errors, error_details, arrivals = [], [], [], []
        event = threading.Event()
        pending = 0  # messages announced and not yet taken (takeNextMessage blocks when none)
        lock = threading.Lock()

        def stateChanged(self, state):
            Listener.states.append(int(state))
            Listener.event.set()

        def messageReceived(self):
            now = time.monotonic()
            with Listener.lock:
                Listener.pending += 1
                Listener.arrivals.append(now)
            Listener.event.set()

        def take(self, sock):
            got = self.take_timed(sock)
            return None if got is None else got[0]

        def take_timed(self, sock):
            """(message, arrival time) of the next received message, or None when none is waiting."""
            with Listener.lock:
                if Listener.pending == 0:
                    return None
                Listener.pending -= 1
                arrived = Listener.arrivals.pop(0)
            return sock.takeNextMessage(), arrived

        def error(self, error):
            Listener.errors.append(str(error.getErrorMessage()))
            Listener.error_details.append({"code": int(error.getErrorCode()), "message": str(error.getErrorMessage()),
                                           "fatal": bool(error.isFatalError()), "t": time.monotonic()})
            Listener.event.set()

    return Listener()


_FAILED_SOCKETS = []  # sockets that could not bind, kept alive: their destructor would delete their listener


def open_socket(deadline, address="127.0.0.1"):
    """A new Arcus socket with a new listener (new_listener) and Cura.proto registered, listening on a free
    port of `address` (a port taken meanwhile by someone else is retried with another, as Cura does);
    returns (sock, listener, port) once it is Listening or the deadline passed."""
    while True:
        sock, listener = Arcus.Socket(), new_listener()
        sock.addListener(listener)
        sock.registerAllMessageTypes(CURA_PROTO)
        port = free_port()
        sock.listen(address, port)
        while sock.getState() not in (Arcus.SocketState.Listening, Arcus.SocketState.Error) \
                and time.monotonic() < deadline:
            time.sleep(0.01)
        if sock.getState() != Arcus.SocketState.Error or time.monotonic() >= deadline:
            return sock, listener, port
        _FAILED_SOCKETS.append(sock)


def spawn_engine(engine, port, extra_args=(), stderr=subprocess.PIPE):
    """`<engine> connect 127.0.0.1:<port> ""` with stdin closed and stdout/stderr piped, as Cura runs it."""
    return subprocess.Popen([str(engine), "connect", "127.0.0.1:%d" % port, ""] + list(extra_args),
                            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=stderr)


def wait_connected(sock, deadline):
    while sock.getState() != Arcus.SocketState.Connected and time.monotonic() < deadline:
        if int(sock.getState()) in CLOSED_STATES:
            return False
        time.sleep(0.005)
    return sock.getState() == Arcus.SocketState.Connected


def add_settings(container, items):
    for key, value in items.items():
        s = container.addRepeatedMessage("settings")
        s.name = key
        s.value = str(value).encode("utf-8")


def build_slice(sock, job, soup=triangle_soup_bytes):
    """The Slice message of a JSON job (see cura_frontend.py); soup(path) gives an STL's vertex bytes."""
    msg = sock.createMessage("cura.proto.Slice")
    for group in job.get("groups", []):
        obj_list = msg.addRepeatedMessage("object_lists")
        add_settings(obj_list, group.get("settings", {}))
        for o in group.get("objects", []):
            obj = obj_list.addRepeatedMessage("objects")
            obj.id = 1
            obj.name = o.get("name", os.path.basename(o.get("stl", "object")))
            obj.vertices = soup(o["stl"]) if "stl" in o else bytes.fromhex(o.get("vertices_hex", ""))
            add_settings(obj, o.get("settings", {"extruder_nr": "0"}))
    add_settings(msg.getMessage("global_settings"), job.get("global", {}))
    for nr, values in sorted(job.get("extruders", {}).items(), key=lambda kv: int(kv[0])):
        ext = msg.addRepeatedMessage("extruders")
        ext.id = int(nr)
        add_settings(ext.getMessage("settings"), values)
    for key, nr in job.get("limit_to_extruder", []):
        lim = msg.addRepeatedMessage("limit_to_extruder")
        lim.name = key
        lim.extruder = int(nr)
    return msg


def segment_summary(layer, raw=False):
    """Per path segment: extruder, the line types present, counts; raw: also every line type and point
    (x, y) in mm, as Cura's ProcessSlicedLayersJob reads them."""
    segments = []
    for i in range(layer.repeatedMessageCount("path_segment")):
        seg = layer.getRepeatedMessage("path_segment", i)
        types = bytes(seg.line_type)
        points = struct.unpack("<%df" % (len(seg.points) // 4), seg.points)
        segments.append({"extruder": seg.extruder, "types": sorted(set(types)), "lines": len(types),
                         "points": len(points) // 2,
                         "widths": len(seg.line_width) // 4, "feedrates": len(seg.line_feedrate) // 4})
        if raw:
            segments[-1].update(line_types=list(types), xy=[list(points[k:k + 2]) for k in range(0, len(points), 2)])
    return segments


TIME_FIELDS = ("time_none", "time_inset_0", "time_inset_x", "time_skin", "time_support", "time_skirt",
               "time_infill", "time_support_infill", "time_travel", "time_retract", "time_support_interface",
               "time_prime_tower")


def estimates(message):
    est = {f: getattr(message, f) for f in TIME_FIELDS}
    est["materials"] = [message.getRepeatedMessage("materialEstimates", i).material_amount
                        for i in range(message.repeatedMessageCount("materialEstimates"))]
    return est


def record(message, result, raw=False):
    """Keeps what Cura keeps of a message: the G-code list (prefix first, as CuraEngineBackend's
    _onGCodePrefixMessage inserts it at 0), progress, the preview layers, the estimates."""
    name = message.getTypeName()
    result["counts"][name] = result["counts"].get(name, 0) + 1
    if name == "cura.proto.GCodeLayer":
        result["gcode_list"].append(bytes(message.data).decode("utf-8"))
    elif name == "cura.proto.GCodePrefix":
        result["gcode_list"].insert(0, bytes(message.data).decode("utf-8"))
    elif name == "cura.proto.Progress":
        result["progress"].append(message.amount)
    elif name == "cura.proto.LayerOptimized":
        result["layers"].append({"id": message.id, "height": message.height, "thickness": message.thickness,
                                 "segments": segment_summary(message, raw)})
    elif name == "cura.proto.PrintTimeMaterialEstimates":
        result["estimates"] = estimates(message)
