#!/usr/bin/python3
"""Soak receiver: Cura's side of the engine's socket for many slices in one process, on the real libArcus
(Debian's python3-arcus, the binding Cura 4.13 uses) and Cura's installed Cura.proto. Standard library +
Arcus only; run it with /usr/bin/python3:

    /usr/bin/python3 tests/bench/soak_receiver.py jobs.json results.jsonl

Per job it does what Cura does per slice: a NEW Arcus.Socket (and listener) listening on a free port,
`<engine> connect 127.0.0.1:<port> ""` spawned, the Slice sent once connected, the messages taken as they
come. Nothing of one job's state (socket, listener, counts, times) is carried into the next.

jobs.json:
  {"engine": path, "out_dir": folder for the G-code (and vanish stderr) files,
   "cases": {case: {"global": {key: text}, "extruders": {"0": {key: text}}, "limit_to_extruder": [[key, n]]}},
   "stop_after_failures": null or n (skip the remaining jobs after n failed ones, see failed()),
   "jobs": [job, ...]}
  slice job:       {"id": str, "kind": "slice", "case": case, "groups": [...as in cura_frontend.py...],
                    "timeout": 300, "arrivals": false}
  early-close job: {"id", "kind": "early_close", "case", "groups", "how": how, "moment": moment,
                    "delay_s": x, "after_layers": n, "hang_s": 20, "timeout": 300}
    how     close   sock.close() at that moment (Cura's Backend._createSocket, e.g. after a setting change)
            sigterm the engine gets SIGTERM, is waited for, then sock.close() (CuraEngineBackend._terminate)
            vanish  the receiver process itself ends at that moment (os._exit: no close handshake, the
                    socket and the engine's stdout pipe close with it, as when Cura crashes or is killed);
                    run in a child receiver process, this one adopts the orphaned engine
                    (PR_SET_CHILD_SUBREAPER) to learn how it ends; the engine's stderr goes to a file
    moment  before_slice    connected, no Slice sent yet, after delay_s
            after_send      right after the Slice was handed to libArcus
            during          delay_s after the Slice was sent (if the slice finished first: then)
            mid_stream      right after the after_layers-th ";LAYER:" GCodeLayer arrived (while the
                            engine sends its layers; if the slice finished first: then)
            after_finished  right after SlicingFinished arrived
    The engine then gets hang_s to exit; still running then = a hang: every thread's backtrace is taken
    with gdb (when installed) into "hang_stacks", then the engine is killed with SIGKILL.

results.jsonl: one JSON object per job, written as each job ends:
  slice: {"id", "kind", "case", "exit_code" (negative: signal), "signal", "hung", "hang_stacks", "stderr" (tail),
          "errors" (libArcus errors other than its Debug notices, first 50), "error_count",
          "error_counts" {message: n}, "debug_errors", "counts" {type: n}, "layer_chunks" [n of each
          ";LAYER:n" GCodeLayer in arrival order], "preview_layers" [LayerOptimized ids],
          "gcode_file" (Cura's gcode_list joined: prefix first, then the GCodeLayer data in order),
          "gcode_bytes", "finished", "states", "times" {...}, "order" {...}, "arrivals" (if asked)}
  times (s after the engine was spawned, time.monotonic, taken in libArcus's messageReceived callback):
          connected, slice_sent, first {type: t}, last {type: t}, first_layer_chunk, finished
          (SlicingFinished), engine_exit, socket_closed
  order (by arrival): messages, first_layer_chunk_index, last_progress_index,
          layer_chunks_before_last_progress, previews_before_last_progress
  early_close: {"id", "kind", "case", "how", "moment", "delay_s", "acted_at" (s after spawn),
          "finished_before_act", "messages_before_act", "exit_code", "signal", "hung", "hang_stacks",
          "exit_after_act_s", "close_returned", "stderr", "errors", "error_count", "counts"}
  a job that raised in this receiver: {"id", "kind", "case", "receiver_error": traceback}; skipped jobs
  (stop_after_failures): {"id", "kind", "case", "skipped": true}
"""
import ctypes
import functools
import json
import os
import signal
import subprocess
import sys
import threading
import time
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python"))
from arcus_peer import (CLOSED_STATES, DEBUG_ERROR, build_slice, open_socket, spawn_engine,  # noqa: E402
                        wait_connected)
from stl_soup import triangle_soup_bytes  # noqa: E402

HANG_S = 20
STDERR_TAIL = 4000
HANG_STACKS_TAIL = 30000
PR_SET_CHILD_SUBREAPER = 36


@functools.lru_cache(maxsize=16)
def soup(path):
    return triangle_soup_bytes(path)


def short(type_name):
    return type_name.rsplit(".", 1)[-1]


def signal_name(code):
    if isinstance(code, int) and code < 0:
        try:
            return signal.Signals(-code).name
        except ValueError:
            return "signal %d" % -code
    return None


def stacks(pid):
    """Every thread's backtrace of a hung engine (gdb, when installed), for the report; None otherwise."""
    try:
        proc = subprocess.run(["gdb", "-p", str(pid), "-batch", "-nx", "-ex", "set pagination off",
                               "-ex", "thread apply all bt"], capture_output=True, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired):
        return None
    lines = [line for line in proc.stdout.splitlines() if line.startswith(("Thread ", "#"))]
    return "\n".join(lines)[-HANG_STACKS_TAIL:]


def close_bounded(sock, bound):
    """sock.close() (which waits for the peer's close answer or EOF; the binding releases the GIL) in a
    thread; True if it returned within `bound` seconds."""
    done = threading.Event()

    def close():
        try:
            sock.close()
        except Exception:  # noqa: BLE001 - closing a socket that is already closed
            pass
        done.set()

    threading.Thread(target=close, daemon=True).start()
    return done.wait(bound)


class StderrReader:
    def __init__(self, stream):
        self.data = b""
        self.thread = threading.Thread(target=self._read, args=(stream,), daemon=True)
        self.thread.start()

    def _read(self, stream):
        self.data = stream.read()

    def text(self, wait=5):
        self.thread.join(wait)
        return self.data.decode("utf-8", "replace")[-STDERR_TAIL:]


def error_summary(listener, result):
    real = [e for e in listener.error_details if e["code"] != DEBUG_ERROR]
    counts = {}
    for e in real:
        counts[e["message"]] = counts.get(e["message"], 0) + 1
    result["errors"] = [e["message"] for e in real[:50]]
    result["error_count"] = len(real)
    result["error_counts"] = counts
    result["debug_errors"] = [e["message"] for e in listener.error_details if e["code"] == DEBUG_ERROR][:10]
    result["states"] = list(listener.states)


class Receipt:
    """What one slice delivered, message by message (times relative to the engine's spawn)."""

    def __init__(self, t0, keep_arrivals):
        self.t0 = t0
        self.counts, self.first, self.last = {}, {}, {}
        self.gcode_list, self.layer_chunks, self.preview_layers = [], [], []
        self.arrivals = [] if keep_arrivals else None
        self.n = 0
        self.first_layer_chunk = self.first_layer_chunk_index = self.last_progress_index = None
        self.finished = None
        self.progress_marks = []  # (index, layer chunks so far, previews so far) at each Progress

    def add(self, message, arrived):
        t = round(arrived - self.t0, 4)
        kind = short(message.getTypeName())
        self.counts[kind] = self.counts.get(kind, 0) + 1
        self.first.setdefault(kind, t)
        self.last[kind] = t
        if kind == "GCodeLayer":
            text = bytes(message.data).decode("utf-8", "replace")
            self.gcode_list.append(text)
            if text.startswith(";LAYER:"):
                head = text[7:].split("\n", 1)[0]
                self.layer_chunks.append(int(head) if head.lstrip("-").isdigit() else head)
                if self.first_layer_chunk is None:
                    self.first_layer_chunk, self.first_layer_chunk_index = t, self.n
                kind = "GCodeLayer:LAYER"
        elif kind == "GCodePrefix":
            self.gcode_list.insert(0, bytes(message.data).decode("utf-8", "replace"))
        elif kind == "LayerOptimized":
            self.preview_layers.append(message.id)
        elif kind == "Progress":
            self.last_progress_index = self.n
            self.progress_marks.append((self.n, len(self.layer_chunks), len(self.preview_layers)))
        elif kind == "SlicingFinished":
            self.finished = t
        if self.arrivals is not None:
            self.arrivals.append([kind, t])
        self.n += 1

    def order(self):
        last = self.progress_marks[-1] if self.progress_marks else (None, 0, 0)
        return {"messages": self.n, "first_layer_chunk_index": self.first_layer_chunk_index,
                "last_progress_index": self.last_progress_index,
                "layer_chunks_before_last_progress": last[1], "previews_before_last_progress": last[2]}


def slice_job(job, case):
    return {"groups": job["groups"], "global": case["global"], "extruders": case["extruders"],
            "limit_to_extruder": case.get("limit_to_extruder", [])}


def drain(listener, sock, receipt):
    while True:
        got = listener.take_timed(sock)
        if got is None:
            return
        receipt.add(*got)


def run_slice(doc, job):
    case = doc["cases"][job["case"]]
    timeout = job.get("timeout", 300)
    deadline = time.monotonic() + timeout
    sock, listener, port = open_socket(deadline)
    t0 = time.monotonic()
    engine = spawn_engine(doc["engine"], port)
    stderr = StderrReader(engine.stderr)
    receipt = Receipt(t0, job.get("arrivals", False))
    times = {"connected": None, "slice_sent": None}
    if wait_connected(sock, deadline):
        times["connected"] = round(time.monotonic() - t0, 4)
        sock.sendMessage(build_slice(sock, slice_job(job, case), soup))
        times["slice_sent"] = round(time.monotonic() - t0, 4)
    hung = False
    while True:
        listener.event.clear()
        got = listener.take_timed(sock)
        if got is not None:
            receipt.add(*got)
            continue
        if engine.poll() is not None:
            break
        if time.monotonic() > deadline:
            hung = stacks(engine.pid) or True
            engine.kill()
            break
        listener.event.wait(0.05)
    code = engine.wait()
    times["engine_exit"] = round(time.monotonic() - t0, 4)
    # libArcus may still be reading what the engine sent before it exited: wait for the socket to close
    # (the engine's close request, or its end of the connection), bounded
    settle = time.monotonic() + 5
    while int(sock.getState()) not in CLOSED_STATES and time.monotonic() < settle:
        drain(listener, sock, receipt)
        time.sleep(0.01)
    closed = int(sock.getState()) in CLOSED_STATES
    times["socket_closed"] = round(time.monotonic() - t0, 4) if closed else None
    drain(listener, sock, receipt)
    close_bounded(sock, 5)
    drain(listener, sock, receipt)
    engine.stdout.read()
    times.update(first=receipt.first, last=receipt.last, first_layer_chunk=receipt.first_layer_chunk,
                 finished=receipt.finished)
    gcode_file = Path(doc["out_dir"]) / ("%s.gcode" % job["id"])
    data = "".join(receipt.gcode_list).encode("utf-8")
    gcode_file.write_bytes(data)
    result = {"id": job["id"], "kind": "slice", "case": job["case"], "exit_code": code, "signal": signal_name(code),
              "hung": bool(hung), "hang_stacks": hung if isinstance(hung, str) else None,
              "stderr": stderr.text(), "counts": receipt.counts, "layer_chunks": receipt.layer_chunks,
              "preview_layers": receipt.preview_layers, "gcode_file": str(gcode_file), "gcode_bytes": len(data),
              "finished": receipt.finished is not None, "times": times, "order": receipt.order()}
    error_summary(listener, result)
    if receipt.arrivals is not None:
        result["arrivals"] = receipt.arrivals
    return result


def approach(job, case, sock, listener, receipt, deadline, engine):
    """Sends the Slice (unless the moment is before it) and takes messages until the job's moment (or
    until the engine exited); returns whether SlicingFinished arrived before it."""
    moment, delay = job["moment"], float(job.get("delay_s", 0))
    if moment == "before_slice":
        time.sleep(delay)
        return False
    sock.sendMessage(build_slice(sock, slice_job(job, case), soup))
    if moment == "after_send":
        return False
    until = time.monotonic() + delay if moment == "during" else deadline
    layers = int(job.get("after_layers", 0)) if moment == "mid_stream" else None
    while time.monotonic() < min(until, deadline):
        listener.event.clear()
        got = listener.take_timed(sock)
        if got is not None:
            receipt.add(*got)
            if receipt.finished is not None:
                return True
            if layers is not None and len(receipt.layer_chunks) >= layers:
                return False
            continue
        if engine.poll() is not None:
            break
        listener.event.wait(min(0.02, max(0.0, until - time.monotonic())))
    return receipt.finished is not None


def wait_pid(pid, bound):
    """Exit code of child `pid` (negative: signal), or None if it is still running after `bound` s."""
    end = time.monotonic() + bound
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done == pid:
            return os.waitstatus_to_exitcode(status)
        if time.monotonic() >= end:
            return None
        time.sleep(0.01)


def run_early_close(doc, job):
    if job["how"] == "vanish":
        return run_vanish(doc, job)
    case = doc["cases"][job["case"]]
    hang_s = job.get("hang_s", HANG_S)
    deadline = time.monotonic() + job.get("timeout", 300)
    sock, listener, port = open_socket(deadline)
    t0 = time.monotonic()
    engine = spawn_engine(doc["engine"], port)
    stderr = StderrReader(engine.stderr)
    receipt = Receipt(t0, False)
    connected = wait_connected(sock, deadline)
    finished = approach(job, case, sock, listener, receipt, deadline, engine) if connected else False
    acted = time.monotonic()
    close_returned = None
    if job["how"] == "close":
        closer = threading.Thread(target=lambda: close_bounded(sock, hang_s + 10), daemon=True)
        closer.start()
    elif job["how"] == "sigterm":
        engine.send_signal(signal.SIGTERM)  # a no-op when the engine has already exited (after_finished)
    else:
        raise ValueError("unknown early-close kind %r" % job["how"])
    hang_stacks = None
    try:
        code = engine.wait(timeout=hang_s)
        hung = False
    except subprocess.TimeoutExpired:
        hung = True
        hang_stacks = stacks(engine.pid)
        engine.kill()
        code = engine.wait()
    exit_after = time.monotonic() - acted
    if job["how"] == "close":
        closer.join(10)
        close_returned = not closer.is_alive()
    else:
        close_returned = close_bounded(sock, 10)
    engine.stdout.read()
    result = {"id": job["id"], "kind": "early_close", "case": job["case"], "how": job["how"],
              "moment": job["moment"], "delay_s": job.get("delay_s", 0), "acted_at": round(acted - t0, 4),
              "connected": connected, "finished_before_act": finished, "messages_before_act": receipt.n,
              "exit_code": code, "signal": signal_name(code), "hung": hung, "exit_after_act_s": round(exit_after, 4),
              "hang_stacks": hang_stacks, "close_returned": close_returned, "stderr": stderr.text(),
              "counts": receipt.counts}
    error_summary(listener, result)
    return result


def run_vanish(doc, job):
    """Runs the job in a child receiver (--vanish-child) that ends itself at the moment; this process,
    a child subreaper, adopts the engine and waits for it."""
    stderr_file = Path(doc["out_dir"]) / ("%s.stderr" % job["id"])
    spec = {"doc": {k: v for k, v in doc.items() if k != "jobs"}, "job": job, "stderr_file": str(stderr_file)}
    child = subprocess.Popen([sys.executable, __file__, "--vanish-child"], stdin=subprocess.PIPE,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out, err = child.communicate(json.dumps(spec).encode(), timeout=job.get("timeout", 300) + 30)
    try:
        info = json.loads(out.decode().strip().splitlines()[-1])
    except (IndexError, ValueError):
        return {"id": job["id"], "kind": "early_close", "case": job["case"], "how": "vanish",
                "moment": job["moment"], "receiver_error": err.decode("utf-8", "replace")[-STDERR_TAIL:],
                "exit_code": None, "signal": None, "hung": False}
    acted = info.pop("acted_monotonic")
    hang_s = job.get("hang_s", HANG_S)
    if info["engine_exit_before_act"] is not None:
        code = info["engine_exit_before_act"]
    else:
        code = wait_pid(info["engine_pid"], max(0.0, acted + hang_s - time.monotonic()))
    hung = code is None
    hang_stacks = None
    if hung:
        hang_stacks = stacks(info["engine_pid"])
        os.kill(info["engine_pid"], signal.SIGKILL)
        code = wait_pid(info["engine_pid"], 30)
    exit_after = time.monotonic() - acted
    stderr = stderr_file.read_bytes().decode("utf-8", "replace")[-STDERR_TAIL:] if stderr_file.exists() else ""
    result = {"id": job["id"], "kind": "early_close", "case": job["case"], "how": "vanish", "moment": job["moment"],
              "delay_s": job.get("delay_s", 0), **info, "exit_code": code, "signal": signal_name(code),
              "hung": hung, "exit_after_act_s": round(exit_after, 4), "hang_stacks": hang_stacks,
              "close_returned": None, "stderr": stderr}
    if not hung and stderr_file.exists():
        stderr_file.unlink()
    return result


def vanish_child():
    spec = json.loads(sys.stdin.read())
    doc, job = spec["doc"], spec["job"]
    case = doc["cases"][job["case"]]
    deadline = time.monotonic() + job.get("timeout", 300)
    sock, listener, port = open_socket(deadline)
    t0 = time.monotonic()
    with open(spec["stderr_file"], "wb") as err:
        engine = spawn_engine(doc["engine"], port, stderr=err)
    receipt = Receipt(t0, False)
    connected = wait_connected(sock, deadline)
    finished = approach(job, case, sock, listener, receipt, deadline, engine) if connected else False
    acted = time.monotonic()
    info = {"engine_pid": engine.pid, "acted_monotonic": acted, "acted_at": round(acted - t0, 4),
            "engine_exit_before_act": engine.poll(),  # reaped here: the parent cannot wait for it then
            "connected": connected, "finished_before_act": finished, "messages_before_act": receipt.n,
            "counts": receipt.counts, "errors": [e["message"] for e in listener.error_details
                                                 if e["code"] != DEBUG_ERROR][:50]}
    sys.stdout.write(json.dumps(info) + "\n")
    sys.stdout.flush()
    os._exit(0)  # no close, no cleanup: the kernel closes the socket and the engine's stdout pipe


def failed(result):
    """What this receiver can tell on its own (soak.py also compares the G-code)."""
    if result.get("skipped"):
        return False
    if result.get("receiver_error"):
        return True
    if result["kind"] == "slice":
        return result["exit_code"] != 0 or result["hung"] or result["error_count"] > 0 or not result["finished"]
    return result["exit_code"] != 0 or result["hung"]


def main():
    if sys.argv[1:] == ["--vanish-child"]:
        vanish_child()
        return
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)  # adopt the engines of vanished child receivers
    doc = json.loads(Path(sys.argv[1]).read_text())
    Path(doc["out_dir"]).mkdir(parents=True, exist_ok=True)
    stop_after = doc.get("stop_after_failures")
    failures = 0
    with open(sys.argv[2], "w") as out:
        for job in doc["jobs"]:
            if stop_after is not None and failures >= stop_after:
                result = {"id": job["id"], "kind": job["kind"], "case": job["case"], "skipped": True}
            else:
                started = time.monotonic()
                try:
                    result = (run_slice if job["kind"] == "slice" else run_early_close)(doc, job)
                except Exception:  # noqa: BLE001 - reported as this job's failure, the next jobs still run
                    result = {"id": job["id"], "kind": job["kind"], "case": job["case"],
                              "receiver_error": traceback.format_exc()[-STDERR_TAIL:]}
                result["wall_s"] = round(time.monotonic() - started, 3)
                failures += failed(result)
            out.write(json.dumps(result) + "\n")
            out.flush()


if __name__ == "__main__":
    main()
