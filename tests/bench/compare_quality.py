#!/usr/bin/env python3
"""MixEngine and CuraEngine 4.13 side by side, one run: layers, filament, estimated time, print quality
(coverage / outside, tests/python/print_quality.py) and slice wall time per model, plus pictures.

    compare_quality.py --bin build/mixengine [--cases cube20,knot2] [--out-dir out/quality] [--cached]

Settings and models are those of tests/python/test_compare_cura.py (side_by_side.py: the Ender-3 with
0.2 mm layers, every resolved value given to both engines). CuraEngine runs afresh so that both slice times
come from the same run; --cached reuses the test suite's CuraEngine cache instead.

Pictures: OUT_DIR/<case>_layer<N>.png for the first layer, the middle layer and the layer where
MixEngine's coverage falls furthest below CuraEngine's, and on a raft its lowest and highest layers (N < 0,
drawn over the model's first section); with ironing the top layer too. MixEngine left, CuraEngine right, on
the same grid (0.05 mm squares, one pixel each). Colours: light grey = model section not covered, blue =
model extrusion inside the section, orange = within the 0.1 mm tolerance outside it, red = beyond it
(counted as outside), green = skirt/brim/support/raft (not measured), purple = ironing (model extrusions
thinner than a quarter nozzle, drawn one pixel wide over the rest), dark grey = the section's outline band.
OUT_DIR/summary.json holds every number, per layer too.
"""
import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python"))
import gcode_model  # noqa: E402
import helpers  # noqa: E402
import print_quality as pq  # noqa: E402
import side_by_side as sbs  # noqa: E402
from test_compare_cura import CASES as TEST_CASES  # noqa: E402

# The test suite's cases plus two the bench alone measures (issue 19): an organic scan and a real part.
CASES = dict(TEST_CASES, bunny69k=("bunny69k", {}), rear_case=("rear_case", {}))

COLOURS = {"free": (225, 225, 225), "inside": (40, 90, 200), "band": (245, 160, 0), "outside": (220, 30, 30),
           "other": (40, 170, 60), "ironing": (150, 40, 170), "background": (255, 255, 255)}


def hms(seconds):
    if seconds is None:
        return "-"
    s = int(round(seconds))
    return f"{s // 3600}h{s // 60 % 60:02d}m{s % 60:02d}s"


def colour(r):
    e, s, grown = r["E"], r["S"], r["S+"]
    img = np.empty(e.shape + (3,), np.uint8)
    img[:] = COLOURS["background"]
    img[s] = COLOURS["free"]
    if "O" in r:
        img[r["O"]] = COLOURS["other"]
    img[e & s] = COLOURS["inside"]
    img[e & grown & ~s] = COLOURS["band"]
    img[e & ~grown] = COLOURS["outside"]
    if "I" in r:
        img[r["I"]] = COLOURS["ironing"]
    return img[::-1]  # row 0 at the top of the picture: +Y up


def ironing_raster(m, layer, grid, diameter, nozzle):
    """The layer's ironing: model extrusions thinner than a quarter nozzle (ironing_flow of a line), one pixel
    wide."""
    widths = gcode_model.segment_widths_mm(m, layer, diameter)
    mask = ~m.feature_mask(layer, pq.NON_MODEL_FEATURES) & (widths > 0) & (widths < 0.25 * nozzle)
    radius = np.full(int(mask.sum()), grid.g / 2)
    return pq.rasterise_capsules(grid, layer.x0[mask], layer.y0[mask], layer.x1[mask], layer.y1[mask], radius)


def picture(path, index, engines, sections, overrides):
    """engines: [(label, gcode_model.Model, LayerQuality or None)]. Draws layer `index` of each side by side."""
    from PIL import Image, ImageDraw
    offset, diameter, nozzle = sbs.machine(overrides)
    present = [(label, m, lq) for label, m, lq in engines if index in m.layers and m.layers[index].z_mm is not None]
    if not present:
        return None
    # a raft layer (index < 0) is drawn over the model's first section: what the raft carries
    mids = {label: pq.layer_mid_heights(m, sbs.raft_lift_mm(overrides)).get(index, 0.1) for label, m, _ in present}
    secs = dict(zip(mids, sections.at(mids.values())))
    extents = [pq.layer_extent(m, m.layers[index], secs[label], offset, diameter, nozzle) for label, m, _ in present]
    if any(e is None for e in extents):
        return None
    boxes = np.array(extents)
    grid = pq.Grid.around(boxes[:, 0].min(), boxes[:, 1].min(), boxes[:, 2].max(), boxes[:, 3].max(), pq.GRID_MM)
    panels = []
    for label, m, lq in present:
        r = pq.layer_rasters(m, m.layers[index], secs[label], offset, diameter, nozzle, grid=grid, others=True)
        r["I"] = ironing_raster(m, m.layers[index], grid, diameter, nozzle)
        img = Image.fromarray(colour(r))
        text = f"{label}  layer {index}  z {m.layers[index].z_mm:.2f} mm"
        if lq is not None and lq.section_mm2 > 0:
            text += f"  coverage {lq.covered_mm2 / lq.section_mm2:.3f}  outside {lq.outside_mm2 / lq.section_mm2:.4f}"
        canvas = Image.new("RGB", (img.width, img.height + 18), COLOURS["background"])
        canvas.paste(img, (0, 18))
        ImageDraw.Draw(canvas).text((4, 3), text, fill=(0, 0, 0))
        panels.append(canvas)
    width = sum(p.width for p in panels) + 10 * (len(panels) - 1)
    out = Image.new("RGB", (width, max(p.height for p in panels)), COLOURS["background"])
    x = 0
    for p in panels:
        out.paste(p, (x, 0))
        x += p.width + 10
    out.save(path)
    return path


def worst_layer(mix_q, cura_q):
    """Layer index where MixEngine's covered area falls furthest below CuraEngine's (or its outside is
    largest when it never falls below)."""
    cura = {lq.index: lq for lq in cura_q.layers}
    best, key = None, None
    for lq in mix_q.layers:
        other = cura.get(lq.index)
        if other is None:
            continue
        k = (other.covered_mm2 - lq.covered_mm2, lq.outside_mm2)
        if key is None or k > key:
            best, key = lq.index, k
    return best


def row(label, run, model, q):
    return {"engine": label, "rc": run.rc, "layers": model.layer_count if model else None,
            "filament_mm": run.filament_mm(), "time_s": run.time_s(), "coverage": q.coverage if q else None,
            "outside": q.outside_ratio if q else None, "slice_s": run.seconds,
            "e_in_layers_mm": model.layer_extruded_e if model else None}


def fmt(r):
    def num(v, f):
        return "-" if v is None else format(v, f)
    return (f"  {r['engine']:<11}{num(r['layers'], 'd'):>7}{num(r['filament_mm'], '.0f'):>10}"
            f"{hms(r['time_s']):>12}{num(r['coverage'], '.4f'):>10}{num(r['outside'], '.4f'):>9}"
            f"{num(r['slice_s'], '.2f'):>9}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", type=Path, default=helpers.BIN)
    ap.add_argument("--cases", default=",".join(CASES), help=f"comma-separated, from {', '.join(CASES)}")
    ap.add_argument("--out-dir", type=Path, default=helpers.REPO / "out" / "quality")
    ap.add_argument("--cached", action="store_true", help="reuse the cached CuraEngine G-code (slice time cached too)")
    opt = ap.parse_args()
    helpers.BIN = opt.bin.resolve()
    opt.out_dir.mkdir(parents=True, exist_ok=True)

    print(f"machine {sbs.MACHINE.name}, {sbs.BASE_SETTINGS}; quality grid {pq.GRID_MM} mm, "
          f"tolerance {pq.TOLERANCE_MM} mm; pictures in {opt.out_dir}")
    print(f"  {'engine':<11}{'layers':>7}{'filament':>10}{'time':>12}{'coverage':>10}{'outside':>9}{'slice s':>9}")
    results = {}
    for name in opt.cases.split(","):
        model_name, overrides = CASES[name]
        if sbs.model_path(model_name) is None:
            print(f"{name}: missing from the corpus, skipped")
            continue
        print(f"{name} ({model_name}{', ' + str(overrides) if overrides else ''})")
        results[name] = {"model": model_name, "overrides": overrides, "rows": [], "pictures": []}
        mix = sbs.run_mixengine(model_name, overrides, memo=False)
        cura = sbs.run_cura(model_name, overrides, use_cache=opt.cached)
        sections = pq.ModelSections(sbs.model_path(model_name))
        measured = {}
        for label, run in (("mixengine", mix), ("CuraEngine", cura)):
            measured[label] = sbs.measured(run, model_name, overrides, sections) if run.rc == 0 else (None, None)
            r = row(label, run, *measured[label])
            results[name]["rows"].append(r)
            print(fmt(r) + ("" if run.rc == 0 else f"   rc {run.rc}: {run.stderr.strip()[-200:]}"))
        (mm, mq), (cm, cq) = measured["mixengine"], measured["CuraEngine"]
        if mm is None or cm is None:
            continue
        results[name]["layers"] = {label: [vars(x) for x in q.layers]
                                   for label, q in (("mixengine", mq), ("CuraEngine", cq))}
        indices = [lq.index for lq in mq.layers]
        chosen = {indices[0], indices[len(indices) // 2], worst_layer(mq, cq)} - {None} if indices else set()
        below = [i for i in mm.layers if i < 0]
        if below:  # the raft: its base and its top surface
            chosen |= {min(below), max(below)}
        if indices and overrides.get("ironing_enabled") == "True":
            chosen.add(indices[-1])
        chosen = sorted(chosen)
        by_index = {label: {lq.index: lq for lq in q.layers} for label, q in (("mixengine", mq), ("CuraEngine", cq))}
        for index in chosen:
            path = picture(opt.out_dir / f"{name}_layer{index}.png", index,
                           [("mixengine", mm, by_index["mixengine"].get(index)),
                            ("CuraEngine", cm, by_index["CuraEngine"].get(index))], sections, overrides)
            if path:
                results[name]["pictures"].append(str(path))
        print(f"  pictures: {', '.join(Path(p).name for p in results[name]['pictures'])}")
    (opt.out_dir / "summary.json").write_text(json.dumps(results, indent=1) + "\n")
    print("coverage = model extrusion inside the section / section area; outside = model extrusion more than "
          f"{pq.TOLERANCE_MM} mm outside the section / section area (sums over layers). "
          f"Numbers in {opt.out_dir / 'summary.json'}")


if __name__ == "__main__":
    main()
