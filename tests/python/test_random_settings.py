"""Issue 9 (reliability): a no-crash sweep over fdmprinter's numeric settings, in the manner of CuraEngine's
runtest.py. Model: a 10 mm cube with a 6 mm ledge overhanging one side near its top (two touching boxes:
walls, skin, infill, an overhang for support and bridges), generated here; machine: fdmprinter (no -j).

1. Every int/float setting of fdmprinter.def.json alone at its minimum and at its maximum (Cura's
   minimum_value / maximum_value, else the *_warning bound; setting_bounds.py evaluates the formulas
   against the engine's resolved values; ends that do not evaluate to a finite number are counted
   and skipped).
2. N seeded random combinations: 1-6 numeric settings drawn uniformly inside their bounds (half of the
   draws inside the warning range when there is one), plus 0-3 random bool/enum switches so that the
   numbers reach the features they configure (support, raft, brim, patterns, flavors, ...).
   N = MIXENGINE_RANDOM_SETTINGS_N (default 60), seed = MIXENGINE_RANDOM_SEED (default 9; "random" picks
   one). The seed is printed; a failure names the full -s list, so it can be rerun by hand.

Pass for each run: no crash signal, done within RUN_TIMEOUT_S, and either exit 0 with a valid G-code
(gcode_checks.py: gcodeparser reads it, finite motion values, ;LAYER: lines = ;LAYER_COUNT:) or exit 1 with
exactly one stderr line "mixengine: error: ..." naming one of the settings given, and no output file.
Runs go two at a time (MIXENGINE_RANDOM_WORKERS, default 2: the machine has 2 cores).
"""
import os
import random
import shutil
import struct
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

import gcode_checks
import helpers
import setting_bounds as sb

RUN_TIMEOUT_S = 120
N_RANDOM = int(os.environ.get("MIXENGINE_RANDOM_SETTINGS_N", "60"))
WORKERS = int(os.environ.get("MIXENGINE_RANDOM_WORKERS", "2"))


def _seed():
    text = os.environ.get("MIXENGINE_RANDOM_SEED", "9")
    return random.SystemRandom().randrange(1, 10**6) if text == "random" else int(text)


SEED = _seed()


def _box(x0, y0, z0, x1, y1, z1):
    p = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0), (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
             (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    return [[p[i] for i in f] for f in faces]


def write_model(path):
    triangles = _box(0, 0, 0, 10, 10, 10) + _box(10, 0, 7, 16, 10, 10)
    data = bytearray(80) + struct.pack("<I", len(triangles))
    for t in triangles:
        data += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *v) for v in t) + b"\0\0"
    path.write_bytes(bytes(data))
    return path


@pytest.fixture(scope="module")
def sweep(engine):
    """(model path, definitions, bounds) shared by both tests; the folder is removed afterwards."""
    folder = Path(tempfile.mkdtemp(prefix="mixengine-random-settings-"))
    defs = sb.definitions()
    bounds = sb.numeric_bounds(defs, sb.BoundEvaluator(sb.resolved_context(defs)))
    yield write_model(folder / "ledge.stl"), defs, bounds, folder
    shutil.rmtree(folder, ignore_errors=True)


def run_case(model, folder, index, settings):
    """Slices with settings [(key, text)]; returns None when the run passes, else a description."""
    out_dir = folder / f"run{index}"
    out_dir.mkdir()
    out = out_dir / "out.gcode"
    cmd = [str(helpers.BIN), "slice"]
    for key, text in settings:
        cmd += ["-s", f"{key}={text}"]
    cmd += ["-l", str(model), "-o", str(out)]
    shown = " ".join(f"-s {k}={v}" for k, v in settings)
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=RUN_TIMEOUT_S)
        return judge(proc, out, out_dir, settings, shown)
    except subprocess.TimeoutExpired:
        return f"{shown}: no result within {RUN_TIMEOUT_S} s (hang)"
    finally:
        shutil.rmtree(out_dir, ignore_errors=True)


def judge(proc, out, out_dir, settings, shown):
    lines = helpers.stderr_lines(proc)
    if proc.returncode < 0:
        return f"{shown}: killed by signal {-proc.returncode}; stderr {proc.stderr[-300:]!r}"
    if proc.returncode == 1:
        if len(lines) != 1 or not lines[0].startswith("mixengine: error: "):
            return f"{shown}: exit 1 without exactly one error line: {lines[:4]}"
        if not any(f"'{key}'" in lines[0] or key in lines[0] for key, _ in settings):
            return f"{shown}: the error names none of the settings given: {lines[0]}"
        if any(out_dir.iterdir()):
            return f"{shown}: files left after an error: {[p.name for p in out_dir.iterdir()]}"
        return None
    if proc.returncode != 0:
        return f"{shown}: exit code {proc.returncode}: {lines[-3:]}"
    if not out.is_file():
        return f"{shown}: exit 0 but no G-code written"
    check = gcode_checks.check_gcode(out)
    if check.problems:
        return f"{shown}: invalid G-code: {check.problems}"
    return None


def run_all(model, folder, cases):
    """Runs [(settings)] WORKERS at a time; returns (number run, [failure descriptions])."""
    with ThreadPoolExecutor(max_workers=WORKERS) as pool:
        results = list(pool.map(lambda ic: run_case(model, folder, ic[0], ic[1]), enumerate(cases)))
    return len(cases), [r for r in results if r is not None]


def test_every_numeric_setting_at_its_bounds(sweep, report):
    model, defs, bounds, folder = sweep
    cases = []
    skipped = 0
    for b in bounds:
        for end in (b.low, b.high):
            if end is None:
                skipped += 1
            else:
                cases.append([(b.key, sb.format_value(end, b.type))])
    (folder / "bounds").mkdir()
    count, failures = run_all(model, folder / "bounds", cases)
    report(f"random settings: {len(bounds)} numeric settings, {count} runs at their bounds, {skipped} bounds "
           f"skipped (no finite value), {len(failures)} failed")
    assert not failures, f"{len(failures)} of {count} runs failed:\n" + "\n".join(failures[:40])


def draw(rng, b):
    """A value of the setting inside its bounds (inside the warning range for half of the draws)."""
    low, high = b.low, b.high
    if rng.random() < 0.5:
        low = max(low, b.warn_low) if b.warn_low is not None else low
        high = min(high, b.warn_high) if b.warn_high is not None else high
        if low > high:
            low, high = b.low, b.high
    if rng.random() < 0.15:
        return rng.choice([low, high])
    return rng.randint(int(low), int(high)) if b.type == "int" else rng.uniform(low, high)


def random_cases(bounds, switches, seed, n):
    rng = random.Random(seed)
    usable = [b for b in bounds if b.low is not None and b.high is not None]
    switch_keys = sorted(switches)
    cases = []
    for _ in range(n):
        picked = rng.sample(usable, rng.randint(1, 6))
        settings = [(b.key, sb.format_value(draw(rng, b), b.type)) for b in picked]
        for key in rng.sample(switch_keys, rng.randint(0, 3)):
            settings.append((key, rng.choice(switches[key])))
        cases.append(settings)
    return cases


def test_random_setting_combinations(sweep, report):
    model, defs, bounds, folder = sweep
    (folder / "random").mkdir()
    cases = random_cases(bounds, sb.switch_options(defs), SEED, N_RANDOM)
    print(f"random settings: seed {SEED}, {N_RANDOM} combinations")
    count, failures = run_all(model, folder / "random", cases)
    report(f"random settings: seed {SEED} (MIXENGINE_RANDOM_SEED), {count} random combinations, "
           f"{len(failures)} failed")
    assert not failures, f"seed {SEED}: {len(failures)} of {count} runs failed:\n" + "\n".join(failures[:40])
