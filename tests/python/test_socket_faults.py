"""Socket faults (issue 9): Cura kills and restarts its engine constantly, and a peer may be broken.
For each fault the engine must end cleanly — promptly, never by a crash signal, never hanging —
and say what happened in one line when it is an error.

| fault                                       | defined outcome                                         |
|---------------------------------------------|---------------------------------------------------------|
| SIGTERM while idle / slicing / sending      | stops at once, every thread joined, exit 0 (issue 29)   |
| frontend closes before sending a Slice      | exit 0                                                  |
| frontend closes mid-slice                   | stops, exit 0, no error line: Cura ended the talk       |
| bad header / wrong protocol version         | exit 1, one line naming the mismatch                    |
| unknown message type id                     | exit 1, one line: unknown message type                  |
| a Slice frame whose payload does not parse  | exit 1, one line: failed to parse                       |
| a Slice with no Extruder messages           | sliced with the definitions' extruder values, exit 0    |
| a Slice with a broken vertex buffer         | exit 1, one line naming the object                      |
| frontend never answers the close request    | exit 0 within a bound (the G-code was delivered)        |
"""
import random
import signal
import subprocess
import time

import pytest

from cura_socket import one_object, resolved_settings, slice_over_socket
from mixing_gcode import box_stl
from stl_soup import triangle_soup_bytes
from raw_frontend import CLOSE, RawFrontend, cura_pb2, frame

CRASH_SIGNALS = {-signal.SIGSEGV, -signal.SIGABRT, -signal.SIGBUS, -signal.SIGFPE, -signal.SIGILL}
HANG_BOUND_S = 20  # far above any of these cases; only a hang reaches it


@pytest.fixture(scope="module")
def pb(tmp_path_factory):
    return cura_pb2(tmp_path_factory.mktemp("pb2"))


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("faults") / "cube.stl", 20.0, 20.0, 20.0)


@pytest.fixture(scope="module")
def ender3():
    return resolved_settings("creality_ender3")


def slice_message(pb, cube, global_settings, extruders, vertices=None):
    msg = pb.Slice()
    for key, value in global_settings.items():
        msg.global_settings.settings.add(name=key, value=str(value).encode())
    for nr, values in extruders.items():
        ext = msg.extruders.add(id=int(nr))
        for key, value in values.items():
            ext.settings.settings.add(name=key, value=str(value).encode())
    obj = msg.object_lists.add().objects.add(id=1, name="cube.stl")
    obj.vertices = vertices if vertices is not None else triangle_soup_bytes(cube)
    obj.settings.add(name="extruder_nr", value=b"0")
    return msg


def start_engine(engine, frontend):
    return subprocess.Popen([str(engine), "connect", f"127.0.0.1:{frontend.port}", ""], stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def finish(proc):
    try:
        out, err = proc.communicate(timeout=HANG_BOUND_S)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        pytest.fail(f"the engine hung (> {HANG_BOUND_S} s)")
    assert proc.returncode not in CRASH_SIGNALS, err
    return proc.returncode, err


def error_line(err):
    lines = [line for line in err.splitlines() if line.startswith("mixengine: ")]
    assert len(lines) == 1, err
    return lines[0]


def run_raw(engine, actions):
    """Starts the engine against a raw frontend, runs `actions(frontend)`, returns (code, stderr)."""
    frontend = RawFrontend()
    proc = start_engine(engine, frontend)
    try:
        frontend.accept()
        actions(frontend)
        return finish(proc)
    finally:
        frontend.close()
        if proc.poll() is None:
            proc.kill()


@pytest.mark.parametrize("moment", ["idle", "slicing", "random"])
def test_sigterm_at_any_moment_ends_the_engine_at_once(engine, tmp_path, ender3, moment, corpus, report):
    model = corpus("armadillo52k")
    rng = random.Random(20261123)
    job = {"idle": {"send_slice": False, "terminate_after_s": 0.5},
           "slicing": {"terminate_after_s": 0.3},
           "random": {"terminate_after_s": rng.uniform(0.05, 2.0)}}[moment]
    global_settings, extruders = ender3
    r = slice_over_socket(engine, tmp_path, global_settings, extruders, [one_object(model)], timeout=60, **job)
    report(f"sigterm {moment}: after {r.get('messages_before_sigterm')} messages, exit {r['exit_code']} "
           f"{r['exit_after_sigterm_s']:.2f} s after the signal")
    assert r["exit_code"] == 0, r["stderr"]
    assert "mixengine: " not in r["stderr"] and "terminate called" not in r["stderr"]
    assert r["exit_after_sigterm_s"] < 5
    assert not r.get("finished")


def test_frontend_closing_before_a_slice_is_a_clean_exit(engine):
    code, err = run_raw(engine, lambda f: f.send(b"\xf0\xf0\xf0\xf0"))
    assert code == 0, err


def test_frontend_closing_mid_slice_is_a_clean_exit(engine, pb, ender3, corpus):
    model = corpus("armadillo52k")
    global_settings, extruders = ender3
    msg = slice_message(pb, model, global_settings, extruders, vertices=triangle_soup_bytes(model))

    def actions(f):
        f.send(frame("cura.proto.Slice", msg.SerializeToString()))
        f.read_for(0.3)
        f.close()

    code, err = run_raw(engine, actions)
    assert code == 0, err
    assert "mixengine: " not in err


@pytest.mark.parametrize("case,data,needle", [
    ("bad header", frame("cura.proto.Slice", header=0xDEADBEEF), "Header mismatch"),
    ("protocol version", frame("cura.proto.Slice", header=0x2BAD0200), "version mismatch"),
    ("unknown type", frame("cura.proto.NoSuchMessage", b"\x08\x01"), "Unknown message type"),
    ("unparsable slice", frame("cura.proto.Slice", b"\x0a\xff\xff\xff\xff\x0f\x01"), "parse"),
])
def test_malformed_frames_are_one_error_line(engine, case, data, needle):
    code, err = run_raw(engine, lambda f: (f.send(data), f.read_for(1.0)))
    assert code == 1, err
    assert needle.lower() in error_line(err).lower()


def test_slice_without_extruder_messages_uses_the_definitions(engine, pb, cube, ender3):
    global_settings, _ = ender3
    msg = slice_message(pb, cube, global_settings, {})
    received = {}

    def actions(f):
        f.send(frame("cura.proto.Slice", msg.SerializeToString()))
        data = f.read_for(HANG_BOUND_S / 2)
        received["data"] = data
        f.send(CLOSE.to_bytes(4, "big"))

    code, err = run_raw(engine, actions)
    assert code == 0, err
    assert b";LAYER:0" in received["data"]


def test_broken_vertex_buffer_is_one_error_line_naming_the_object(engine, pb, cube, ender3):
    global_settings, extruders = ender3
    msg = slice_message(pb, cube, global_settings, extruders, vertices=b"\x00" * 35)
    code, err = run_raw(engine, lambda f: (f.send(frame("cura.proto.Slice", msg.SerializeToString())),
                                           f.read_for(2.0)))
    assert code == 1
    assert "object 'cube.stl'" in error_line(err)


def test_frontend_that_never_answers_the_close_request(engine, pb, cube, ender3):
    global_settings, extruders = ender3
    msg = slice_message(pb, cube, global_settings, extruders)
    start = time.monotonic()
    code, err = run_raw(engine, lambda f: (f.send(frame("cura.proto.Slice", msg.SerializeToString())),
                                           f.read_for(HANG_BOUND_S - 5)))
    assert code == 0, err
    assert time.monotonic() - start < HANG_BOUND_S
