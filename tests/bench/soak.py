#!/usr/bin/env python3
"""Soak of Cura's socket (issue 29, "a soak that would have caught this"): many slices through the real
libArcus (tests/bench/soak_receiver.py, Debian's python3-arcus, used as Cura uses it), each slice's G-code
compared byte for byte with the command line's, libArcus's errors counted; plus early closes at random
moments (Cura closing its socket, SIGTERM, or Cura vanishing) after which the engine must exit 0, never by
a signal, never hang.

    tests/bench/soak.py --bin build/mixengine [--slices 520] [--early 120] [--quick] [--seed N]
                        [--receivers 2] [--repro 30] [--out out/soak] [--keep]
    make soak            (the build's engine, the defaults)

Cases: the dialect cases of tests/python/test_connect.py (SAME_GCODE_CASES: plain Ender-3 and the four
mixing dialects), sent as Cura sends them (every setting resolved, `mixengine settings --json`), and a
two-model case on a dual-extrusion printer. Models: boxes of several sizes (tests/python/mixing_gcode.py
box_stl) and corpus models (tests/corpus: cube20 ... armadillo52k, bunny69k; --quick: boxes and cube20).
Object names 1..80 characters long (some non-ASCII), since the loss depended on the byte count; --repro
slices are issue 29's reproduction exactly: fdmprinter + gradient/marlin_m163 50..50, the 20x20x10 box,
a name of 46 characters.

The reference for each (case, model) is `mixengine slice -j DEF -s ... -l MODEL -o ref.gcode`, computed once.
The socket's G-code is Cura's gcode_list (GCodePrefix first, then the GCodeLayer data in arrival order) and
must equal it line for line but for ;Date/;Time/;TIME_ELAPSED_AT lines (test_connect.without_volatile_lines)
and the ;MESH:<name> lines, which carry the object's name (the command line names the model by its path).

Early closes: each of close / sigterm / vanish (soak_receiver.py) at each moment: before the Slice, right
after sending it, during the slice (a random time within this machine's slicing time of the model, or
right after a random number of layers arrived: mid_stream) and after SlicingFinished.

About 5 to 6 minutes on 2 shared cores (--quick: under a minute). The engine binary is copied into --out
first (build/ may be rebuilt meanwhile), and the command line and the socket both run that copy. Prints a
summary (slices ok, libArcus errors, mismatches with the missing layers, arrival times per case and per
model, early-close outcomes with a hung engine's backtraces), writes --out/summary.json, keeps the failing
slices' G-code, exits 1 if any slice or early close failed."""
import argparse
import json
import random
import shutil
import statistics
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "python"))
import helpers  # noqa: E402
from cura_socket import DEBIAN_PYTHON, debian_python_env, resolved_settings  # noqa: E402
from mixing_gcode import box_stl  # noqa: E402
from test_connect import SAME_GCODE_CASES, without_volatile_lines  # noqa: E402

RECEIVER = HERE / "soak_receiver.py"
HOWS = ("close", "sigterm", "vanish")
MOMENTS = ("before_slice", "after_send", "during", "mid_stream", "after_finished")

# name -> (definition, settings, layout): "one" model, or "two" models side by side on extruders 0 and 1
CASES = {**{name: (definition, settings, "one") for name, (definition, settings) in SAME_GCODE_CASES.items()},
         "dual_two_models": ("ultimaker_original_dual", ("extruders_enabled_count=2", "adhesion_type=skirt"), "two")}
REPRO_CASE, REPRO_MODEL, REPRO_NAME_LEN = "gradient_m163", "box20x20x10", 46  # issue 29's reproduction

BOXES = {"box20x20x10": (20, 20, 10), "box10x10x3": (10, 10, 3), "box30x20x15": (30, 20, 15),
         "box15x15x40": (15, 15, 40), "box40x40x2": (40, 40, 2)}
TWO_MODEL_BOXES = ("box20x20x10", "box10x10x3", "box15x15x40")  # fit side by side at x = -15 and +15
# corpus model -> weight (a box weighs 1); the heavy ones a few times per 500 slices (and each case once)
CORPUS = {"cube20": 1.0, "cylinder1000": 0.5, "bunny_lowpoly": 0.3, "armadillo52k": 0.06, "bunny69k": 0.05}
QUICK_CORPUS = {"cube20": 1.0}
# early closes: models whose slice lasts from a fraction of a second to a few seconds
EARLY_MODELS = {"box20x20x10": 1.0, "box15x15x40": 1.0, "bunny_lowpoly": 0.6, "armadillo52k": 0.15}
NAME_CHARS = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 -_.()"
NON_ASCII = "éüßøñ日本Ω"


# ------------------------------------------------------------------------------------------------ models


def model_paths(folder, corpus_weights):
    """name -> path of every box (written into folder) and of the corpus models present."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = {name: box_stl(folder / f"{name}.stl", *size) for name, size in BOXES.items()}
    for name in corpus_weights:
        path = helpers.CORPUS / f"{name}.stl"
        if path.is_file():
            paths[name] = path
        else:
            print(f"soak: corpus model {name} missing ({path}; tests/corpus/fetch.sh), left out", flush=True)
    return paths


def object_name(rng, length, ascii_only=False):
    """A name of `length` characters as a user may give a model in Cura (some with non-ASCII letters,
    some ending in .stl), so the byte counts vary."""
    chars = [rng.choice(NAME_CHARS) for _ in range(length)]
    if length >= 3 and not ascii_only and rng.random() < 0.25:
        chars[rng.randrange(length)] = rng.choice(NON_ASCII)
    name = "".join(chars)
    if length >= 8 and rng.random() < 0.3:
        name = name[:length - 4] + ".stl"
    return name


# ------------------------------------------------------------------------------------- cases and jobs


def case_settings(name):
    """What Cura sends for a case: {"global": ..., "extruders": ...} (helpers.BIN's `settings --json`)."""
    definition, settings, _ = CASES[name]
    global_settings, extruders = resolved_settings(definition, *settings)
    return {"global": global_settings, "extruders": extruders}


def groups(case, model_path, name):
    if CASES[case][2] == "two":
        return [{"settings": {}, "objects": [
            {"name": name, "stl": str(model_path), "settings": {"extruder_nr": "0", "mesh_position_x": "-15"}},
            {"name": name, "stl": str(model_path), "settings": {"extruder_nr": "1", "mesh_position_x": "15"}}]}]
    return [{"settings": {}, "objects": [{"name": name, "stl": str(model_path), "settings": {"extruder_nr": "0"}}]}]


def slice_job(job_id, case, model, model_path, name, arrivals=False):
    return {"id": job_id, "kind": "slice", "case": case, "model": model, "name": name,
            "groups": groups(case, model_path, name), "timeout": 600, "arrivals": arrivals}


def early_job(job_id, case, model, model_path, how, moment, delay_s=0.0, after_layers=0, hang_s=20):
    return {"id": job_id, "kind": "early_close", "case": case, "model": model, "how": how, "moment": moment,
            "delay_s": round(delay_s, 3), "after_layers": after_layers, "hang_s": hang_s, "timeout": 600,
            "groups": groups(case, model_path, object_name(random.Random(job_id), 12))}


def cli_reference(binary, case, model_path, out):
    """`mixengine slice` of the case's settings and model: the G-code the socket must deliver."""
    definition, settings, layout = CASES[case]
    args = [binary, "slice", "-j", definition]
    for s in settings:
        args += ["-s", s]
    if layout == "two":
        args += ["-l", model_path, "-s", "mesh_position_x=-15", "-e1", "-l", model_path, "-s", "mesh_position_x=15"]
    else:
        args += ["-l", model_path]
    proc = helpers.run(args + ["-o", out])
    if proc.returncode != 0:
        raise RuntimeError(f"command line slice of {case} / {model_path} failed: {proc.stderr[-2000:]}")
    return out


def references(binary, pairs, paths, folder, workers=2):
    """(case, model) -> reference G-code path, computed `workers` at a time."""
    folder.mkdir(parents=True, exist_ok=True)
    with ThreadPoolExecutor(workers) as pool:
        futures = {(case, model): pool.submit(cli_reference, binary, case, paths[model],
                                              folder / f"{case}__{model}.gcode")
                   for case, model in sorted(pairs)}
        return {key: f.result() for key, f in futures.items()}


# ------------------------------------------------------------------------------------------ receivers


def run_receivers(binary, cases, jobs, folder, receivers=2, stop_after_failures=None, progress_every=15.0):
    """Runs the jobs on `receivers` soak_receiver.py processes in parallel (jobs dealt round-robin);
    returns their results in job order. Prints a progress line every progress_every seconds (None: never)."""
    folder.mkdir(parents=True, exist_ok=True)
    procs, outs = [], []
    for i in range(receivers):
        mine = jobs[i::receivers]
        if not mine:
            continue
        doc = {"engine": str(binary), "out_dir": str(folder / "gcode"), "cases": cases, "jobs": mine,
               "stop_after_failures": stop_after_failures}
        job_file, out_file = folder / f"jobs{i}.json", folder / f"results{i}.jsonl"
        job_file.write_text(json.dumps(doc))
        log = open(folder / f"receiver{i}.log", "w")
        procs.append((subprocess.Popen(["nice", DEBIAN_PYTHON, str(RECEIVER), str(job_file), str(out_file)],
                                       stdout=log, stderr=subprocess.STDOUT, env=debian_python_env()), log))
        outs.append(out_file)
    start = last = time.monotonic()
    while any(p.poll() is None for p, _ in procs):
        time.sleep(0.5)
        if progress_every is not None and time.monotonic() - last >= progress_every:
            last = time.monotonic()
            done = sum(len(o.read_text().splitlines()) for o in outs if o.exists())
            print(f"soak: {done}/{len(jobs)} jobs done, {last - start:.0f} s", flush=True)
    for p, log in procs:
        log.close()
        if p.returncode != 0:
            raise RuntimeError(f"a soak receiver failed (exit {p.returncode}): see {folder}/receiver*.log:\n"
                               + (folder / "receiver0.log").read_text()[-3000:])
    by_id = {}
    for o in outs:
        for line in o.read_text().splitlines():
            r = json.loads(line)
            by_id[r["id"]] = r
    return [by_id[j["id"]] for j in jobs]


# ------------------------------------------------------------------------------------------- checking


def expected_lines(ref_text, name):
    """The reference's lines as the socket must deliver them: volatile lines dropped, the ;MESH: lines
    naming the model by its path on the command line name it as Cura named the object."""
    lines = without_volatile_lines(ref_text)
    mesh_names = {line[6:] for line in lines if line.startswith(";MESH:") and line != ";MESH:NONMESH"}
    return [f";MESH:{name}" if line.startswith(";MESH:") and line[6:] in mesh_names else line for line in lines]


def layer_ids(text):
    return [int(line[7:]) for line in text.splitlines()
            if line.startswith(";LAYER:") and line[7:].lstrip("-").isdigit()]


def check_slice(result, job, ref_text):
    """Adds 'ok' and, when not, 'problems' (and 'missing_layers', 'first_difference') to a slice result."""
    problems = []
    if result.get("skipped") or result.get("receiver_error"):
        result.update(ok=False, problems=["skipped (too many failures before it)" if result.get("skipped")
                                          else "receiver failed: " + result["receiver_error"][-300:]])
        return result
    if result["hung"]:
        problems.append("the engine did not exit (killed)")
    if result["exit_code"] != 0:
        problems.append(f"exit {result['exit_code']}" + (f" ({result['signal']})" if result["signal"] else ""))
    if not result["finished"]:
        problems.append("no SlicingFinished")
    if result["error_count"]:
        problems.append(f"{result['error_count']} libArcus errors")
    want_ids = layer_ids(ref_text)
    missing_previews = sorted(set(want_ids) - set(result["preview_layers"]))
    if missing_previews:
        result["missing_previews"] = missing_previews
        problems.append(f"no LayerOptimized (preview) for layer{'s' if len(missing_previews) > 1 else ''} "
                        f"{compress(missing_previews)}")
    gcode_file = Path(result["gcode_file"])
    got = gcode_file.read_bytes().decode("utf-8", "replace") if gcode_file.exists() else ""
    want = expected_lines(ref_text, job["name"])
    have = without_volatile_lines(got)
    if have != want:
        have_layers = result["layer_chunks"]
        missing = sorted(set(want_ids) - set(have_layers))
        extra = len(have_layers) - len(set(have_layers))
        result["missing_layers"] = missing
        first = next((i for i, (a, b) in enumerate(zip(have, want)) if a != b), min(len(have), len(want)))
        result["first_difference"] = {"line": first + 1, "socket": have[first] if first < len(have) else None,
                                      "command_line": want[first] if first < len(want) else None}
        what = f"G-code differs from the command line's from line {first + 1}"
        if missing:
            what += f"; missing layer{'s' if len(missing) > 1 else ''} {compress(missing)}"
        if extra:
            what += f"; {extra} duplicated layer chunks"
        problems.append(what)
    result["ok"] = not problems
    result["problems"] = problems
    return result


def check_early(result, job):
    """Adds 'ok' and 'problems' to an early-close result: the engine must have exited 0 (no signal, no hang)."""
    for key in ("how", "moment", "model", "delay_s", "after_layers"):
        result.setdefault(key, job[key])
    problems = []
    if result.get("skipped"):
        problems.append("skipped (too many failures before it)")
    elif result.get("receiver_error"):
        problems.append("receiver failed: " + result["receiver_error"][-300:])
    else:
        if result["hung"]:
            problems.append(f"hang: still running {job.get('hang_s', 20)} s after the close (killed)")
        elif result["signal"]:
            problems.append(f"died of {result['signal']}")
        elif result["exit_code"] != 0:
            problems.append(f"exit {result['exit_code']}")
    result["ok"] = not problems
    result["problems"] = problems
    return result


def stack_digest(stacks, frames=3):
    """Per thread of a hung engine's backtraces (soak_receiver's hang_stacks): its innermost `frames`
    frames in MixEngine's own code, as 'function (file:line)' joined by ' < '."""
    threads, current = [], None
    for line in (stacks or "").splitlines():
        if line.startswith("Thread "):
            current = []
            threads.append(current)
        elif current is not None and "mixengine::" in line and len(current) < frames:
            head = line.split(" in ", 1)[-1] if " in " in line else line.split(" ", 2)[-1]
            fn = head.split(" (", 1)[0]
            where = line.rsplit(" at ", 1)[-1].rsplit("/", 1)[-1] if " at " in line else ""
            current.append(f"{fn} ({where})" if where else fn)
    return ["thread: " + " < ".join(t) for t in threads if t]


def compress(ids):
    """[3, 4, 5, 9] -> '3-5, 9'."""
    parts, start = [], None
    for i, n in enumerate(ids):
        if start is None:
            start = n
        if i + 1 == len(ids) or ids[i + 1] != n + 1:
            parts.append(str(start) if start == n else f"{start}-{n}")
            start = None
    return ", ".join(parts)


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def fmt_s(value):
    return "-" if value is None else f"{value:.2f}"


def arrival_table(slices, by=("case", "model")):
    """Per group of slices (by case, by model, or both): the median arrival (s after the engine's spawn) of
    the first ;LAYER: chunk, the first LayerOptimized and SlicingFinished, and of the engine's exit; and the
    median share of the layer chunks that arrived before the last Progress message."""
    rows = {}
    for r, job in slices:
        if r.get("skipped") or r.get("receiver_error"):
            continue
        rows.setdefault(tuple(job[k] for k in by), []).append(r)
    width = {"case": 22, "model": 15}
    lines = ["".join(f"{k:<{width[k]}}" for k in by) + f"{'n':>4}{'1st layer':>10}{'1st preview':>12}"
             f"{'finished':>10}{'exit':>8}  layer chunks in before the last Progress"]
    for key, rs in sorted(rows.items()):
        shares = [r["order"]["layer_chunks_before_last_progress"] / len(r["layer_chunks"])
                  for r in rs if r["layer_chunks"]]
        first_layer = median(r["times"]["first_layer_chunk"] for r in rs)
        first_preview = median(r["times"]["first"].get("LayerOptimized") for r in rs)
        finished = median(r["times"]["finished"] for r in rs)
        exit_t = median(r["times"]["engine_exit"] for r in rs)
        share = median(shares)
        lines.append("".join(f"{v:<{width[k]}}" for k, v in zip(by, key))
                     + f"{len(rs):>4}{fmt_s(first_layer):>10}{fmt_s(first_preview):>12}"
                     f"{fmt_s(finished):>10}{fmt_s(exit_t):>8}  {'-' if share is None else f'{share:.0%}'}")
    return lines


def early_table(earlies):
    cells = {}
    for r in earlies:
        cells.setdefault((r["how"], r["moment"]), []).append(r)
    lines = [f"{'how':<9}{'moment':<16}{'n':>4}{'exit 0':>8}  other outcomes (median exit s after the close)"]
    for (how, moment), rs in sorted(cells.items()):
        others = {}
        for r in rs:
            if not r["ok"]:
                key = r["problems"][0] if r["problems"] else "?"
                key = key if not key.startswith("hang") else "hang"
                others[key] = others.get(key, 0) + 1
        ok = sum(1 for r in rs if r["ok"])
        exits = median(r.get("exit_after_act_s") for r in rs if not r.get("skipped") and not r.get("hung"))
        other = ", ".join(f"{k} x{v}" for k, v in sorted(others.items())) or "none"
        lines.append(f"{how:<9}{moment:<16}{len(rs):>4}{ok:>8}  {other} ({fmt_s(exits)} s)")
    return lines


# ------------------------------------------------------------------------------------------------ plan


def slice_timing(binary, model_path, folder):
    """(wall seconds, layer count) of one command-line slice of the model (Ender-3), to aim the early
    closes 'during' and 'mid_stream'."""
    start = time.monotonic()
    out = cli_reference(binary, "ender3", model_path, folder / "timing.gcode")
    return time.monotonic() - start, helpers.gcode_layer_count(out) or 1


def moment_of(rng, moment, timing):
    """The early close's delay_s and after_layers: before_slice 0..0.5 s idle; during: a moment while the
    slice runs, within the engine's start, connection and set-up (about 0.25 s) plus the model's slicing
    time, with some margin (a slice that finished first is closed then); mid_stream: after 1..all of the
    model's layers arrived (the Ender-3 count; other cases differ a little); the other moments: none."""
    seconds, layers = timing
    if moment == "before_slice":
        return {"delay_s": rng.uniform(0.0, 0.5)}
    if moment == "during":
        return {"delay_s": rng.uniform(0.0, 1.2 * (seconds + 0.25))}
    if moment == "mid_stream":
        return {"after_layers": rng.randint(1, layers)}
    return {}


def plan(rng, slices, early, repro, paths, corpus_weights, timings):
    """The slice jobs (every (case, model) at least once, issue 29's reproduction `repro` times, the rest
    drawn by the models' weights) and the early-close jobs (timings: model -> slice_timing), shuffled."""
    weights = {m: 1.0 for m in BOXES}
    weights.update({m: w for m, w in corpus_weights.items() if m in paths})
    pairs = [(c, m) for c in CASES for m in weights if CASES[c][2] == "one" or m in TWO_MODEL_BOXES]
    picks = [(REPRO_CASE, REPRO_MODEL, REPRO_NAME_LEN)] * min(repro, slices)
    picks += [(c, m, None) for c, m in pairs][:max(0, slices - len(picks))]
    while len(picks) < slices:
        c, m = rng.choices(pairs, [weights[m] for _, m in pairs])[0]
        picks.append((c, m, None))
    jobs = []
    for i, (c, m, length) in enumerate(picks):
        repro_name = length is not None
        length = length or (REPRO_NAME_LEN if rng.random() < 0.05 else rng.randint(1, 80))
        jobs.append(slice_job(f"s{i:04d}", c, m, paths[m], object_name(rng, length, ascii_only=repro_name)))
    early_models = [m for m in EARLY_MODELS if m in paths]
    for i in range(early):
        how, moment = HOWS[i % len(HOWS)], MOMENTS[(i // len(HOWS)) % len(MOMENTS)]
        m = rng.choices(early_models, [EARLY_MODELS[m] for m in early_models])[0]
        c = rng.choice([c for c in CASES if CASES[c][2] == "one"])
        jobs.append(early_job(f"e{i:04d}", c, m, paths[m], how, moment, **moment_of(rng, moment, timings[m])))
    rng.shuffle(jobs)
    return jobs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", type=Path, default=helpers.BIN)
    ap.add_argument("--slices", type=int, default=None, help="slice jobs (default 520; --quick 60)")
    ap.add_argument("--early", type=int, default=None, help="early closes (default 120; --quick 30)")
    ap.add_argument("--repro", type=int, default=None,
                    help="of the slices, issue 29's reproduction (default 30; --quick 6)")
    ap.add_argument("--quick", action="store_true", help="boxes and cube20 only, fewer jobs")
    ap.add_argument("--seed", type=int, default=None)
    ap.add_argument("--receivers", type=int, default=2, help="receiver processes in parallel")
    ap.add_argument("--out", type=Path, default=helpers.REPO / "out" / "soak")
    ap.add_argument("--keep", action="store_true", help="keep every slice's G-code (default: failing ones only)")
    opt = ap.parse_args()
    slices = opt.slices if opt.slices is not None else (60 if opt.quick else 520)
    early = opt.early if opt.early is not None else (30 if opt.quick else 120)
    repro = opt.repro if opt.repro is not None else (6 if opt.quick else 30)
    seed = opt.seed if opt.seed is not None else random.SystemRandom().randrange(1 << 31)
    rng = random.Random(seed)

    opt.out = opt.out.resolve()  # the receivers get absolute paths
    if opt.out.exists():
        shutil.rmtree(opt.out)
    opt.out.mkdir(parents=True)
    binary = opt.out / "mixengine"
    shutil.copy2(opt.bin, binary)  # build/ may be rebuilt while this runs
    helpers.BIN = binary
    started = time.monotonic()
    print(f"soak: engine {opt.bin} (run as its copy {binary}), seed {seed}, {opt.receivers} receivers, "
          f"{slices} slices ({repro} of them issue 29's reproduction) + {early} early closes", flush=True)

    corpus_weights = QUICK_CORPUS if opt.quick else CORPUS
    paths = model_paths(opt.out / "models", corpus_weights)
    timings = {m: slice_timing(binary, paths[m], opt.out) for m in EARLY_MODELS if m in paths} if early else {}
    jobs = plan(rng, slices, early, repro, paths, corpus_weights, timings)
    slice_jobs = [j for j in jobs if j["kind"] == "slice"]
    cases = {c: case_settings(c) for c in sorted({j["case"] for j in jobs})}
    refs = references(binary, {(j["case"], j["model"]) for j in slice_jobs}, paths, opt.out / "reference")
    print(f"soak: {len(refs)} command-line references in {time.monotonic() - started:.0f} s", flush=True)

    results = run_receivers(binary, cases, jobs, opt.out)
    ref_texts = {}
    slices_done, earlies = [], []
    for job, r in zip(jobs, results):
        r.update(model=job["model"])
        if job["kind"] == "slice":
            key = (job["case"], job["model"])
            if key not in ref_texts:
                ref_texts[key] = refs[key].read_text()
            r.update(name=job["name"], name_chars=len(job["name"]), name_bytes=len(job["name"].encode()))
            check_slice(r, job, ref_texts[key])
            if r["ok"] and not opt.keep and Path(r["gcode_file"]).exists():
                Path(r["gcode_file"]).unlink()
            slices_done.append((r, job))
        else:
            earlies.append(check_early(r, job))
    wall = time.monotonic() - started
    ok_slices = [r for r, _ in slices_done if r["ok"]]
    bad_slices = [(r, j) for r, j in slices_done if not r["ok"]]
    error_counts = {}
    for r, _ in slices_done:
        for message, n in r.get("error_counts", {}).items():
            error_counts[message] = error_counts.get(message, 0) + n
    with_errors = sum(1 for r, _ in slices_done if r.get("error_count"))
    lost = [(r, j) for r, j in bad_slices if r.get("missing_layers")]

    print(f"\nsoak: {wall:.0f} s, seed {seed}")
    print(f"slices: {len(ok_slices)}/{len(slices_done)} ok (byte-identical with the command line, exit 0, "
          f"no libArcus error)")
    print(f"libArcus errors: {sum(error_counts.values())} in {with_errors} slices"
          + (": " + ", ".join(f"{m!r} x{n}" for m, n in sorted(error_counts.items(), key=lambda kv: -kv[1]))
             if error_counts else ""))
    print(f"slices that lost G-code layers: {len(lost)}; that lost preview layers (LayerOptimized): "
          f"{sum(1 for r, _ in bad_slices if r.get('missing_previews'))}")
    repro_rs = [r for r, j in slices_done if j["case"] == REPRO_CASE and j["model"] == REPRO_MODEL
                and len(j["name"]) == REPRO_NAME_LEN and j["name"].isascii()]
    if repro_rs:
        print(f"issue 29's reproduction (gradient_m163, box20x20x10, ASCII name of 46 characters): "
              f"{sum(1 for r in repro_rs if not r['ok'])}/{len(repro_rs)} failed")
    if bad_slices:
        print(f"failed slices ({len(bad_slices)}):")
        for r, j in bad_slices[:60]:
            errs = ", ".join(f"{m} x{n}" for m, n in r.get("error_counts", {}).items())
            print(f"  {r['id']} {j['case']} {j['model']} name {len(j['name'])} ch / {len(j['name'].encode())} B: "
                  + "; ".join(r["problems"]) + (f" [libArcus: {errs}]" if errs else ""))
        if len(bad_slices) > 60:
            print(f"  ... and {len(bad_slices) - 60} more (summary.json)")
    print("\narrival over the socket, s after the engine's spawn (median over the slices), per case:")
    for line in arrival_table(slices_done, ("case",)):
        print("  " + line)
    print("per model:")
    for line in arrival_table(slices_done, ("model",)):
        print("  " + line)
    if earlies:
        bad_early = [r for r in earlies if not r["ok"]]
        print(f"\nearly closes: {len(earlies) - len(bad_early)}/{len(earlies)} ended with exit 0 "
              f"(a hang = still running 20 s after the close)")
        for line in early_table(earlies):
            print("  " + line)
        for r in bad_early[:20]:
            last = [line for line in r.get("stderr", "").splitlines() if line.strip()][-1:] or [""]
            print(f"  {r['id']} {r['how']} {r['moment']} (at {r.get('acted_at', 0):.2f} s, {r['model']}): "
                  f"{'; '.join(r['problems'])}; stderr: {last[0][:160]}")
            for line in stack_digest(r.get("hang_stacks")):
                print(f"      {line}")
    summary = {"seed": seed, "wall_s": wall, "engine": str(opt.bin), "slices": len(slices_done),
               "slices_ok": len(ok_slices), "libarcus_errors": error_counts, "slices_with_errors": with_errors,
               "failed_slices": [{k: r.get(k) for k in ("id", "case", "model", "name", "problems", "missing_layers",
                                                        "missing_previews", "error_counts", "exit_code", "gcode_file",
                                                        "first_difference")}
                                 for r, _ in bad_slices],
               "arrival": arrival_table(slices_done, ("case", "model")),
               "early_closes": len(earlies), "early_ok": sum(1 for r in earlies if r["ok"]),
               "failed_early": [{k: r.get(k) for k in ("id", "how", "moment", "acted_at", "model", "problems",
                                                       "exit_code", "signal", "stderr", "hang_stacks")}
                                for r in earlies if not r["ok"]]}
    (opt.out / "summary.json").write_text(json.dumps(summary, indent=1))
    print(f"\nsoak: results in {opt.out} (summary.json, results*.jsonl, failing slices' G-code in gcode/)")
    return 0 if not bad_slices and all(r["ok"] for r in earlies) else 1


if __name__ == "__main__":
    sys.exit(main())
