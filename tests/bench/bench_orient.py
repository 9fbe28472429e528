#!/usr/bin/env python3
"""Benchmark of the dual-nozzle orientation pass (`mixengine orient`, issue 7). No thresholds: it prints.

    bench_orient.py --bin build/mixengine [--repeat 3] [--offsets 35,22] [--grid-step 30] [--out out/bench_orient.json]

Pairs: the corpus's knot2 (two interlinked knots) and armadillo52k split at half height (manifold3d).
For each pair and offset: the whole-sphere search plus exact verification (`--method sphere`, the
default) on 2 threads, median of --repeat runs, with the engine's own time breakdown. Then the seed's
exact latitude/longitude grid: run at --grid-step (30° = 144 rotations by default) and extrapolated
linearly to the seed's 10° grid (1296 rotations); the printout says it is an extrapolation.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python"))
import helpers  # noqa: E402
from test_orient import split_pair  # noqa: E402

TARGET_S = {"knot2": 2.0, "armadillo52k split": 5.0}


def run(binary, args, report):
    """Runs `mixengine orient` on 2 threads; returns (wall s, CPU s = user + sys, report)."""
    start = time.perf_counter()
    proc = subprocess.Popen([str(binary), "orient", *map(str, args), "-m", "2", "--report", str(report)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"orient failed: {proc.stderr.read().decode()}")
    return wall, usage.ru_utime + usage.ru_stime, json.loads(Path(report).read_text())


def bench_sphere(binary, name, pair, offset, repeat, tmp):
    runs = [run(binary, [*pair, "--offset", f"{offset},0"], tmp / "s.json") for _ in range(repeat)]
    walls = sorted(r[0] for r in runs)
    median = min(runs, key=lambda r: abs(r[0] - statistics.median(walls)))
    doc = median[2]
    t = doc["time_s"]
    print(f"{name:20s} d={offset:4.0f}  sphere+exact  wall {statistics.median(walls):6.2f} s, CPU {median[1]:5.2f} s "
          f"(target {TARGET_S[name]:.0f} s wall)  engine {t['total']:.2f} = checks {t['checks']:.2f} + voxels/FFT "
          f"{t['voxels_fft']:.2f} + search {t['search']:.2f} + exact {t['exact']:.2f} + spin {t['spin']:.2f}"
          f"   V {doc['v_before_mm3']:.1f} -> {doc['v_after_mm3']:.1f} mm³ (FFT {doc['v_after_estimate_mm3']:.1f})")
    return {"pair": name, "offset_mm": offset, "wall_s": walls, "cpu_s": median[1], "time_s": t, "v_before_mm3": doc["v_before_mm3"],
            "v_after_mm3": doc["v_after_mm3"], "v_after_estimate_mm3": doc["v_after_estimate_mm3"]}


def bench_grid(binary, name, pair, offset, step, tmp):
    _, _, doc = run(binary, [*pair, "--offset", f"{offset},0", "--method", "grid", "--grid-step", str(step)],
                    tmp / "g.json")
    rotations = doc["map"]["rows"] * doc["map"]["columns"]
    per_rotation = doc["time_s"]["search"] / rotations
    print(f"{name:20s} d={offset:4.0f}  exact grid    {rotations} rotations in {doc['time_s']['search']:.1f} s "
          f"({per_rotation * 1000:.1f} ms each, 2 threads) -> seed's 1296-rotation grid ≈ "
          f"{per_rotation * 1296:.0f} s (extrapolated from {rotations} of 1296)")
    return {"pair": name, "offset_mm": offset, "rotations": rotations, "search_s": doc["time_s"]["search"],
            "extrapolated_1296_s": per_rotation * 1296}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=str(helpers.BIN))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--offsets", default="35,22")
    ap.add_argument("--grid-step", type=int, default=30)
    ap.add_argument("--out", default=str(helpers.REPO / "out" / "bench_orient.json"))
    args = ap.parse_args()
    results = {"sphere": [], "grid": []}
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        knot = [helpers.CORPUS / "knot2_a.stl", helpers.CORPUS / "knot2_b.stl"]
        arm = helpers.CORPUS / "armadillo52k.stl"
        pairs = {}
        if all(p.is_file() for p in knot):
            pairs["knot2"] = knot
        if arm.is_file():
            pairs["armadillo52k split"] = split_pair(arm, tmp)
        print(f"load average before the runs: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores "
              "(wall times grow with other work on the machine; CPU times do not)")
        if not pairs:
            raise SystemExit("bench_orient: corpus models missing (run tests/corpus/fetch.sh)")
        offsets = [float(o) for o in args.offsets.split(",")]
        for name, pair in pairs.items():
            for offset in offsets:
                results["sphere"].append(bench_sphere(args.bin, name, pair, offset, args.repeat, tmp))
        for name, pair in pairs.items():
            results["grid"].append(bench_grid(args.bin, name, pair, offsets[0], args.grid_step, tmp))
    Path(args.out).parent.mkdir(parents=True, exist_ok=True)
    Path(args.out).write_text(json.dumps(results, indent=1))
    print(f"written {args.out}")


if __name__ == "__main__":
    main()
