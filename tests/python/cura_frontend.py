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
import signal
import subprocess
import sys
import threading
import time

# the Arcus pieces (listener, socket, Slice, what Cura keeps of each message) are shared with
# tests/bench/soak_receiver.py; stl_soup.py and arcus_peer.py sit beside this script
from arcus_peer import build_slice, open_socket, record, spawn_engine, wait_connected


def run(job):
    result = {"gcode_list": [], "counts": {}, "progress": [], "layers": [], "estimates": None,
              "exit_code": None, "stderr": "", "errors": [], "states": []}
    deadline = time.monotonic() + job.get("timeout", 120)
    sock, listener, port = open_socket(deadline)
    engine = spawn_engine(job["engine"], port, job.get("engine_args", []))
    out = {}
    reader = threading.Thread(target=lambda: out.update(stderr=engine.stderr.read()), daemon=True)
    reader.start()
    wait_connected(sock, deadline)
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
