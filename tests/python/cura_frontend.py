#!/usr/bin/python3
"""A minimal Cura frontend for tests: the real libArcus (Debian's python3-arcus, the binding Cura
itself uses) and Cura's own installed Cura.proto, driving an engine the way Cura 4.13 does.

It listens on 127.0.0.1 (port chosen free), spawns `<engine> connect 127.0.0.1:<port> ""`, sends
one Slice built from a JSON job, collects everything the engine sends and writes a JSON result.
Run it with /usr/bin/python3 (the Arcus binding is built for Debian's Python):

    /usr/bin/python3 tests/python/cura_frontend.py job.json result.json

Job: {"engine": path, "global": {key: text}, "extruders": {"0": {key: text}},
      "limit_to_extruder": [[key, n]], "groups": [{"settings": {}, "objects":
      [{"name": str, "stl": path (binary STL), "settings": {key: text}}]}],
      "timeout": s, "send_slice": true, "terminate_after_s": null, "raw_layers": false}
Result: {"gcode_list": [prefix, chunk, ...] (as Cura holds it), "counts": {type: n},
         "progress": [...], "layers": [{id, height, thickness, segments: [{extruder, types}]}],
         "estimates": {time_* fields, "materials"}, "exit_code": n, "stderr": text, "states": [...], "errors": [...]}
Standard library + Arcus only.
"""
import json
import os
import signal
import socket
import struct
import subprocess
import sys
import threading
import time

import Arcus

from stl_soup import triangle_soup_bytes  # noqa: E402 (beside this script)

CURA_PROTO = "/usr/lib/cura/plugins/CuraEngineBackend/Cura.proto"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Listener(Arcus.SocketListener):
    """The frontend's listener. Its state lives in the class (one job per process): libArcus calls back
    from its own thread, and python3-arcus may hand that call a fresh Python wrapper of the same C++
    listener, which has none of the instance's attributes (seen once in CI as an AttributeError)."""
    states, errors = [], []
    event = threading.Event()
    pending = 0  # messages announced and not yet taken (takeNextMessage raises when none)
    lock = threading.Lock()

    def stateChanged(self, state):
        Listener.states.append(int(state))
        Listener.event.set()

    def messageReceived(self):
        with Listener.lock:
            Listener.pending += 1
        Listener.event.set()

    def take(self, sock):
        with Listener.lock:
            if Listener.pending == 0:
                return None
            Listener.pending -= 1
        return sock.takeNextMessage()

    def error(self, error):
        Listener.errors.append(str(error.getErrorMessage()))
        Listener.event.set()


def add_settings(container, items):
    for key, value in items.items():
        s = container.addRepeatedMessage("settings")
        s.name = key
        s.value = str(value).encode("utf-8")


def build_slice(sock, job):
    msg = sock.createMessage("cura.proto.Slice")
    for group in job.get("groups", []):
        obj_list = msg.addRepeatedMessage("object_lists")
        add_settings(obj_list, group.get("settings", {}))
        for o in group.get("objects", []):
            obj = obj_list.addRepeatedMessage("objects")
            obj.id = 1
            obj.name = o.get("name", os.path.basename(o.get("stl", "object")))
            obj.vertices = triangle_soup_bytes(o["stl"]) if "stl" in o else bytes.fromhex(o.get("vertices_hex", ""))
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


def record(message, result, raw=False):
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
        est = {f: getattr(message, f) for f in TIME_FIELDS}
        est["materials"] = [message.getRepeatedMessage("materialEstimates", i).material_amount
                            for i in range(message.repeatedMessageCount("materialEstimates"))]
        result["estimates"] = est


def run(job):
    result = {"gcode_list": [], "counts": {}, "progress": [], "layers": [], "estimates": None,
              "exit_code": None, "stderr": "", "errors": [], "states": []}
    sock, listener = Arcus.Socket(), Listener()
    sock.addListener(listener)
    sock.registerAllMessageTypes(CURA_PROTO)
    port = free_port()
    sock.listen("127.0.0.1", port)
    deadline = time.monotonic() + job.get("timeout", 120)
    while sock.getState() != Arcus.SocketState.Listening and time.monotonic() < deadline:
        time.sleep(0.01)
    engine = subprocess.Popen([job["engine"], "connect", "127.0.0.1:%d" % port, ""] + job.get("engine_args", []),
                              stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = {}
    reader = threading.Thread(target=lambda: out.update(stderr=engine.stderr.read()), daemon=True)
    reader.start()
    while sock.getState() != Arcus.SocketState.Connected and time.monotonic() < deadline:
        time.sleep(0.01)
    if job.get("send_slice", True):
        sock.sendMessage(build_slice(sock, job))
    terminate_at = None
    if job.get("terminate_after_s") is not None:
        terminate_at = time.monotonic() + float(job["terminate_after_s"])
    finished = False
    while time.monotonic() < deadline:
        message = listener.take(sock)
        if message is not None:
            record(message, result, job.get("raw_layers", False))
            finished = finished or message.getTypeName() == "cura.proto.SlicingFinished"
            continue
        if terminate_at is not None and time.monotonic() >= terminate_at:
            engine.send_signal(signal.SIGTERM)
            result["sigterm_at"] = time.monotonic()
            result["messages_before_sigterm"] = sum(result["counts"].values())
            terminate_at = None
        if engine.poll() is not None:
            break
        listener.event.wait(0.05)
        listener.event.clear()
    while True:  # drain what arrived before the engine exited
        message = listener.take(sock)
        if message is None:
            break
        record(message, result, job.get("raw_layers", False))
    try:
        result["exit_code"] = engine.wait(timeout=max(1.0, deadline - time.monotonic()))
    except subprocess.TimeoutExpired:
        engine.kill()
        result["exit_code"] = "timeout"
    if "sigterm_at" in result:
        result["exit_after_sigterm_s"] = time.monotonic() - result.pop("sigterm_at")
    engine.stdout.read()
    reader.join(5)
    result["stderr"] = out.get("stderr", b"").decode("utf-8", "replace")
    result["errors"], result["states"] = listener.errors, listener.states
    result["finished"] = finished
    try:
        sock.close()
    except Exception:  # noqa: BLE001 - closing a socket the engine already closed
        pass
    return result


def main():
    with open(sys.argv[1]) as f:
        job = json.load(f)
    result = run(job)
    with open(sys.argv[2], "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main()
