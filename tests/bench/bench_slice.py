#!/usr/bin/env python3
"""Benchmark: MixEngine against CuraEngine 4.13 with equal arguments (test-corpus.md §6.1).

    bench_slice.py --bin build/mixengine [--repeat 3] [--phase full|load+slice] [--models a,b] [--out out/bench.json]

Each engine runs --repeat times per model, in turn (CuraEngine, MixEngine, CuraEngine, ...) after one
unrecorded run of each; the table shows each engine's median wall time, the peak RSS of its median-time run
(os.wait4), and the ratio mixengine / CuraEngine: the median of the runs' pair by pair ratios, so that a
drift of the machine's speed during the call (a shared machine's neighbours) moves both sides of a pair alike. --phase load+slice times `mixengine layers` (load and
slice only, no G-code) and still divides by CuraEngine's full slice. The machine definition is
creality_ender3.def.json when MixEngine accepts it, otherwise fdmprinter.def.json for both engines.
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python"))
import helpers  # noqa: E402

MODELS = ["cube20", "armadillo52k", "armadillo208k", "armadillo832k", "knot2"]
SETTINGS = ["center_object=true", "layer_height=0.2", "layer_height_0=0.2", "wall_line_count=2",
            "infill_sparse_density=20", "top_layers=4", "bottom_layers=4", "material_print_temperature=210",
            "material_bed_temperature=60", "adhesion_type=skirt"]


def timed(cmd, env):
    """Runs cmd once; returns (wall seconds, peak RSS in MiB, exit code)."""
    start = time.perf_counter()
    proc = subprocess.Popen([str(c) for c in cmd], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            env=dict(os.environ, **env))
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    return wall, usage.ru_maxrss / 1024, proc.returncode


def summary(runs):
    failed = [r[2] for r in runs if r[2] != 0]
    walls = sorted(r[0] for r in runs)
    median = statistics.median(walls)
    rss = min(runs, key=lambda r: abs(r[0] - median))[1]
    return {"median_s": median, "rss_mib": rss, "runs_s": [r[0] for r in runs], "rc": failed[0] if failed else 0}


def measure_pairs(cura_cmd, mix_cmd, env, repeat):
    """Runs both commands in turn `repeat` times (after one unrecorded run each); returns their summaries and
    the median of the pair by pair wall-time ratios mix / cura."""
    timed(cura_cmd, env)
    timed(mix_cmd, env)
    cura_runs, mix_runs = [], []
    for _ in range(repeat):
        cura_runs.append(timed(cura_cmd, env))
        mix_runs.append(timed(mix_cmd, env))
    cura, mix = summary(cura_runs), summary(mix_runs)
    ratio = statistics.median(m[0] / c[0] for c, m in zip(cura_runs, mix_runs)) \
        if cura["rc"] == 0 and mix["rc"] == 0 else None
    return cura, mix, ratio


def machine_args(binary, tmp):
    """-j creality_ender3 if MixEngine slices cube20 with it, else fdmprinter."""
    probe = [binary, "slice", "-j", helpers.ENDER3, "-l", helpers.CORPUS / "cube20.stl", "-o", tmp / "probe.gcode"]
    ok = helpers.run(probe, env=helpers.CURA_ENV).returncode == 0 and (tmp / "probe.gcode").exists() \
        and helpers.gcode_layer_count(tmp / "probe.gcode") is not None
    return ["-j", helpers.ENDER3 if ok else helpers.FDMPRINTER]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", type=Path, default=helpers.BIN)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--phase", choices=["full", "load+slice"], default="full")
    ap.add_argument("--models", default=",".join(MODELS))
    ap.add_argument("--out", type=Path, default=helpers.REPO / "out" / "bench.json")
    opt = ap.parse_args()

    tmp = Path(tempfile.mkdtemp(prefix="mixengine-bench-"))
    common = machine_args(opt.bin.resolve(), tmp) + [a for s in SETTINGS for a in ("-s", s)]
    print(f"machine {Path(common[1]).name}, phase {opt.phase}, {opt.repeat} runs each, {os.cpu_count()} cores")
    header = f"{'model':<14}{'tris':>8}  {'CuraEngine s':>12}{'MiB':>6}  {'mixengine s':>12}{'MiB':>6}  {'ratio':>6}  layers"
    print(header + "\n" + "-" * len(header))
    results = []
    for name in opt.models.split(","):
        model = helpers.CORPUS / f"{name}.stl"
        if not model.is_file():
            print(f"{name:<14} missing from the corpus, skipped")
            continue
        args = common + ["-l", model]
        cura_out, mix_out = tmp / "cura.gcode", tmp / "mix.gcode"
        cura_cmd = [helpers.CURA_BIN, "slice", *args, "-o", cura_out]
        if opt.phase == "full":
            cura, mix, ratio = measure_pairs(cura_cmd, [opt.bin, "slice", *args, "-o", mix_out], helpers.CURA_ENV,
                                             opt.repeat)
            mix_layers = helpers.gcode_layer_count(mix_out) if mix_out.exists() else None
        else:
            cura, mix, ratio = measure_pairs(cura_cmd, [opt.bin, "layers", *args, "-o", tmp / "layers"],
                                             helpers.CURA_ENV, opt.repeat)
            mix_layers = len(helpers.read_layers(tmp / "layers")) if (tmp / "layers/layers.json").exists() else None
        tris = (model.stat().st_size - 84) // 50
        row = dict(model=name, triangles=tris, cura=cura, mixengine=mix, ratio=ratio,
                   layers={"cura": helpers.gcode_layer_count(cura_out) if cura_out.exists() else None,
                           "mixengine": mix_layers})
        results.append(row)
        status = f"{ratio:6.2f}" if ratio is not None else f"rc {cura['rc']}/{mix['rc']}"
        print(f"{name:<14}{tris:>8}  {cura['median_s']:>12.3f}{cura['rss_mib']:>6.0f}  {mix['median_s']:>12.3f}"
              f"{mix['rss_mib']:>6.0f}  {status:>6}  {row['layers']['cura']}/{row['layers']['mixengine']}")
    opt.out.parent.mkdir(parents=True, exist_ok=True)
    opt.out.write_text(json.dumps({"phase": opt.phase, "repeat": opt.repeat, "args": [str(a) for a in common],
                                   "cpu": platform.processor() or platform.machine(), "cores": os.cpu_count(),
                                   "results": results}, indent=1) + "\n")
    what = "full slice" if opt.phase == "full" else "mixengine layers vs CuraEngine full slice"
    print(f"ratio = median of the paired runs' mixengine / CuraEngine wall times ({what}); results in {opt.out}")


if __name__ == "__main__":
    main()
