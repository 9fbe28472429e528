"""MixEngine and Debian's CuraEngine 4.13 on the same model with equal settings, for
test_compare_cura.py, test_gcode_validity.py and tests/bench/compare_quality.py (no pytest import here).

Equal settings: MixEngine resolves the machine's settings (`mixengine settings -j MACHINE -s ... --json`,
Cura's `value` formulas evaluated, as Cura's frontend does before it starts CuraEngine), and BOTH engines get
that same complete list: every resolved global value as `-s key=value`, then `-e0` and the extruder-only
keys. CuraEngine's command line does not evaluate formulas (it would otherwise use `default_value`s, e.g.
infill_line_distance 2 mm where the formula gives 6 mm), so handing it the resolved values is what makes the
two runs comparable.

CuraEngine's results are cached in CACHE_DIR (default ~/.cache/mixengine-compare, env MIXENGINE_COMPARE_CACHE):
<key>.gcode.gz and <key>.json, the key hashing CuraEngine's size and mtime, every argument and the models'
contents. Its print-quality numbers are cached too, keyed also by the source of gcode_model.py and
print_quality.py. CuraEngine's file header holds placeholders in command-line mode (;TIME:6666), so its
real header is taken from its -v log ("Gcode header after slicing:" ... "End of gcode header.").
"""
import atexit
import gzip
import hashlib
import json
import math
import os
import shutil
import tempfile
import threading
import time
from pathlib import Path

import gcode_model
import helpers
import print_quality

MACHINE = helpers.CURA_DEFS / "creality_ender3.def.json"
# 0.2 mm layers keep CuraEngine and the quality measure fast; everything else is the Ender-3's resolved value.
BASE_SETTINGS = {"layer_height": "0.2", "layer_height_0": "0.2"}
CACHE_DIR = Path(os.environ.get("MIXENGINE_COMPARE_CACHE", Path.home() / ".cache" / "mixengine-compare"))
_TMP = Path(tempfile.mkdtemp(prefix="mixengine-side-by-side-"))  # this process's G-code, removed at exit
atexit.register(shutil.rmtree, _TMP, True)
_MEMO = {}


GENERATED = ("tube", "tee", "parity", "shelf", "slivers", "dual_a", "dual_b", "hook", "pin")
# Parts of one two-extruder scene, made in the scene's frame (kept where they are, not centred one by one).
PLACED = ("dual_a", "dual_b")


def _make(name):
    import shapely
    import trimesh
    if name in PLACED:
        return _dual_part(name, trimesh)
    if name == "tube":
        return trimesh.creation.annulus(r_min=6.0, r_max=12.0, height=15.0, sections=128)
    if name == "parity":
        return _parity_scene(shapely, trimesh)
    if name == "shelf":
        return _shelf(shapely, trimesh)
    if name == "slivers":
        return _slivers(shapely, trimesh)
    if name == "hook":
        return _hook(trimesh)
    if name == "pin":
        return _pin(trimesh)
    # tee: a T profile (30 x 6 mm bar on an 8 x 16 mm stem) extruded 10 mm, stood up so that the bar's
    # underside is a 90-degree overhang on both sides of the stem.
    profile = shapely.Polygon([(-4, 0), (4, 0), (4, 16), (15, 16), (15, 22), (-15, 22), (-15, 16), (-4, 16)])
    mesh = trimesh.creation.extrude_polygon(profile, 10.0)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0]))
    return mesh


def _parity_scene(shapely, trimesh):
    """parity.py's model, three disjoint bodies on a 40 x 30 mm plot, 8 mm tall: two pillars under a 16 mm
    bridge whose deck overhangs 4 mm on both sides (bridge, overhangs, support), a 0.6 mm fin 5 mm tall
    (thin walls) and a tube with a 4 mm hole (holes, combing)."""
    side = shapely.Polygon([(-10, 0), (-6, 0), (-6, 5), (6, 5), (6, 0), (10, 0), (10, 5), (14, 5), (14, 7),
                            (-14, 7), (-14, 5), (-10, 5)])
    bridge = trimesh.creation.extrude_polygon(side, 6.0)
    bridge.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0]))
    bridge.apply_translation([0, 10, 0])
    fin = trimesh.creation.box(extents=[8.0, 0.6, 5.0])
    fin.apply_translation([-6, -6, 2.5])
    tube = trimesh.creation.annulus(r_min=2.0, r_max=5.0, height=8.0, sections=64)
    tube.apply_translation([8, -8, 4.0])
    return trimesh.util.concatenate([bridge, fin, tube])


def _side_profile(shapely, trimesh, points, depth):
    """POINTS (x, z) extruded DEPTH mm along y, centred on y = 0."""
    body = trimesh.creation.extrude_polygon(shapely.Polygon(points), depth)
    body.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0]))
    body.apply_translation([0, depth / 2, 0])
    return body


def _shelf(shapely, trimesh):
    """parity.py's second model, a shelf 47 x 24 x 14 mm that needs support under wide overhangs: a 28 mm slab
    (2 mm) carrying two pillars under a 2 mm deck; the deck bridges 20 mm between the pillars over the slab
    (support that stands on the model: support bottoms), runs on 12 mm beyond the right pillar over the bed
    (support from the bed) and carries on its left a 60-degree slope hanging 7 mm out (an overhang to support,
    not a bridge)."""
    slab = trimesh.creation.box(extents=[28.0, 24.0, 2.0])
    slab.apply_translation([-6, 0, 1.0])
    left = _side_profile(shapely, trimesh, [(-20, 2), (-16, 2), (-16, 12), (-27, 12), (-20, 8)], 24.0)
    right = trimesh.creation.box(extents=[4.0, 24.0, 10.0])
    right.apply_translation([6, 0, 7.0])
    deck = trimesh.creation.box(extents=[47.0, 24.0, 2.0])
    deck.apply_translation([-3.5, 0, 13.0])
    return trimesh.boolean.union([slab, left, right, deck], engine="manifold")


def _slivers(shapely, trimesh):
    """parity.py's third model, seven small parts on a 40 x 30 mm plot: thin walls of 0.8, 0.35 and 0.2 mm, a
    wedge narrowing from 2 mm to 0.1 mm, pins of 1.5, 2.5 and 4 mm diameter and a 6 mm block with a 1.6 mm
    hole: thin features, gaps, small parts and small holes (one body each, several islands a layer)."""
    parts = []
    for width, x, height in ((0.8, -14, 6.0), (0.35, -10, 5.0), (0.2, -6, 4.0)):
        wall = trimesh.creation.box(extents=[width, 14.0, height])
        wall.apply_translation([x, 4, height / 2])
        parts.append(wall)
    wedge = trimesh.creation.extrude_polygon(shapely.Polygon([(0, -1.0), (12, -0.05), (12, 0.05), (0, 1.0)]), 5.0)
    wedge.apply_translation([-2, 8, 0])
    parts.append(wedge)
    for diameter, x in ((1.5, -12), (2.5, -6), (4.0, 2)):
        pin = trimesh.creation.cylinder(radius=diameter / 2, height=8.0, sections=48)
        pin.apply_translation([x, -9, 4.0])
        parts.append(pin)
    block = trimesh.creation.extrude_polygon(
        shapely.Polygon([(0, 0), (6, 0), (6, 6), (0, 6)], [shapely.Point(3, 3).buffer(0.8, 16).exterior.coords]), 3.0)
    block.apply_translation([10, -12, 0])
    parts.append(block)
    return trimesh.util.concatenate(parts)


def _hook(trimesh):
    """A 20 x 4 x 12 mm wall with a 2 x 2 mm arm sticking out 8 mm at 9 to 11 mm, whose end hangs down 3 mm: the
    hanging end's lowest layer is a small part with nothing under it (CuraEngine's support towers)."""
    wall = trimesh.creation.box(extents=[20.0, 4.0, 12.0])
    wall.apply_translation([0, 0, 6.0])
    arm = trimesh.creation.box(extents=[2.0, 8.0, 2.0])
    arm.apply_translation([0, 6.0, 10.0])
    drop = trimesh.creation.box(extents=[2.0, 2.0, 3.0])
    drop.apply_translation([0, 9.0, 7.5])
    return trimesh.util.concatenate([wall, arm, drop])


def _pin(trimesh):
    """A 20 x 4 x 12 mm wall with a 1.2 x 1.2 mm pin sticking out 2 mm at 8.4 to 9.6 mm: support too small to
    print without CuraEngine's support towers."""
    wall = trimesh.creation.box(extents=[20.0, 4.0, 12.0])
    wall.apply_translation([0, 0, 6.0])
    pin = trimesh.creation.box(extents=[1.2, 2.0, 1.2])
    pin.apply_translation([0, 3.0, 9.0])
    return trimesh.util.concatenate([wall, pin])


def _dual_part(name, trimesh):
    """The two parts of parity.py's two-extruder scene, 34 x 14 mm together around the origin: dual_a (for
    extruder 0) a 14 x 14 x 8 mm box at x = -10, dual_b (extruder 1) a tube of 7 mm outer and 3 mm inner
    radius, 5 mm tall, at x = +10: both extruders print up to 5 mm, extruder 0 alone above."""
    if name == "dual_a":
        part = trimesh.creation.box(extents=[14.0, 14.0, 8.0])
        part.apply_translation([-10, 0, 4.0])
    else:
        part = trimesh.creation.annulus(r_min=3.0, r_max=7.0, height=5.0, sections=64)
        part.apply_translation([10, 0, 2.5])
    return part


def generated_model(name):
    """Models made here (not in the corpus), written once into CACHE_DIR/models, centred in XY with their
    lowest point at Z 0: tube (a 24 mm tube with a 12 mm hole, 15 mm tall: a hole in every layer; 128-gon)
    and tee (a 30 x 22 x 10 mm T standing on its stem: overhangs that need support)."""
    path = CACHE_DIR / "models" / f"{name}.stl"
    if not path.is_file():
        if name not in GENERATED:
            raise ValueError(f"unknown generated model {name}")
        mesh = _make(name)
        if name not in PLACED:
            (x0, y0, z0), (x1, y1, _) = mesh.bounds
            mesh.apply_translation([-(x0 + x1) / 2, -(y0 + y1) / 2, -z0])
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.{threading.get_ident()}.tmp")  # parity.py makes them on threads
        mesh.export(tmp, file_type="stl")
        tmp.replace(path)
    return path


def model_path(name):
    """Corpus model (CORPUS/name.stl) or generated model; None when the corpus lacks it."""
    if name in GENERATED:
        return generated_model(name)
    path = helpers.CORPUS / f"{name}.stl"
    return path if path.is_file() else None


def resolve(overrides=None):
    """(global, extruder 0) settings as MixEngine resolves them for MACHINE with BASE_SETTINGS + overrides."""
    values = dict(BASE_SETTINGS, **(overrides or {}))
    key = ("resolve", tuple(sorted(values.items())))
    if key not in _MEMO:
        args = ["settings", "-j", MACHINE]
        for k, v in values.items():
            args += ["-s", f"{k}={v}"]
        proc = helpers.mixengine(*args, "--json")
        if proc.returncode != 0:
            raise RuntimeError(f"mixengine settings failed (rc {proc.returncode}): {proc.stderr.strip()[-500:]}")
        data = json.loads(proc.stdout)
        _MEMO[key] = (data["global"], data["extruders"][0])
    return _MEMO[key]


def resolve_machine(machine, overrides=None, extruder_overrides=None):
    """(global, [every extruder train]) as MixEngine resolves them for MACHINE (a definition file) with
    BASE_SETTINGS + overrides (user values of the global stack, seen by every train) and
    extruder_overrides ({extruder_nr: {key: value}}, user values of that train alone)."""
    values = dict(BASE_SETTINGS, **(overrides or {}))
    per_train = {nr: dict(v) for nr, v in sorted((extruder_overrides or {}).items()) if v}
    key = ("resolve_machine", str(machine), tuple(sorted(values.items())),
           tuple((nr, tuple(sorted(v.items()))) for nr, v in per_train.items()))
    if key not in _MEMO:
        args = ["settings", "-j", machine]
        for k, v in values.items():
            args += ["-s", f"{k}={v}"]
        for nr, train_values in per_train.items():
            args.append(f"-e{nr}")
            for k, v in train_values.items():
                args += ["-s", f"{k}={v}"]
        proc = helpers.mixengine(*args, "--json")
        if proc.returncode != 0:
            raise RuntimeError(f"mixengine settings failed (rc {proc.returncode}): {proc.stderr.strip()[-500:]}")
        data = json.loads(proc.stdout)
        _MEMO[key] = (data["global"], data["extruders"])
    return _MEMO[key]


def multi_slice_args(machine, global_values, extruders, models):
    """Arguments for both engines: every global value, then for each train -eN with the values it
    resolves differently from the global ones, followed by the models it prints (MODELS: [(path,
    extruder_nr)]), each -l with -s extruder_nr=N, so that a model's settings inherit from its own train
    as in a slice from Cura (CuraEngine's command line parents a model to the last -e given)."""
    args = ["-j", machine]
    for k in sorted(global_values):
        args += ["-s", f"{k}={global_values[k]}"]
    for nr, values in enumerate(extruders):
        args.append(f"-e{nr}")
        for k in sorted(values):
            if global_values.get(k) != values[k]:
                args += ["-s", f"{k}={values[k]}"]
        for path, model_extruder in models:
            if model_extruder == nr:
                args += ["-l", path, "-s", f"extruder_nr={nr}"]
    return args


def slice_args(global_values, extruder_values):
    args = ["-j", MACHINE]
    for k in sorted(global_values):
        args += ["-s", f"{k}={global_values[k]}"]
    args.append("-e0")
    for k in sorted(extruder_values):
        if k not in global_values:
            args += ["-s", f"{k}={extruder_values[k]}"]
    return args


def _file_digest(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _cura_key(args):
    stat = os.stat(helpers.CURA_BIN)
    parts = [stat.st_size, int(stat.st_mtime)]
    for a in map(str, args):
        parts.append(_file_digest(a) if a.endswith(".stl") and os.path.isfile(a) else a)
    return hashlib.sha256(json.dumps(parts).encode()).hexdigest()[:24]


def log_header(log_text):
    """The ;KEY:value lines CuraEngine -v logs after slicing (its file header has placeholders)."""
    header, inside = {}, False
    for line in log_text.splitlines():
        if line.startswith("Gcode header after slicing:"):
            inside = True
        elif line.startswith("End of gcode header."):
            break
        elif inside and line.startswith(";") and ":" in line:
            key, _, value = line[1:].partition(":")
            header.setdefault(key.strip(), value.strip())
    return header


class Run:
    """One engine's slice: rc, wall seconds, G-code path, the header with real values, stderr tail."""

    def __init__(self, engine, rc, seconds, gcode, header, stderr):
        self.engine, self.rc, self.seconds, self.gcode, self.header, self.stderr = \
            engine, rc, seconds, gcode, header, stderr

    def time_s(self):
        return float(self.header["TIME"]) if "TIME" in self.header else None

    def filament_mm(self):
        """';Filament used: 1.2m' (several extruders: '1.2m, 0.3m') in mm; None when absent."""
        text = self.header.get("Filament used")
        if text is None:
            return None
        return sum(float(part.strip().rstrip("m")) for part in text.split(",") if part.strip()) * 1000.0


def _timed(cmd, env=None):
    start = time.perf_counter()
    proc = helpers.run(cmd, env=env)
    return proc, time.perf_counter() - start


def run_mixengine(name, overrides=None, memo=True):
    """MixEngine on a model with the resolved settings; memoised per process (the G-code lives in a temp dir)."""
    g, e = resolve(overrides)
    key = ("mix", name, tuple(sorted((overrides or {}).items())))
    if memo and key in _MEMO:
        return _MEMO[key]
    out = _TMP / f"mix-{hashlib.sha256(repr(key).encode()).hexdigest()[:16]}.gcode"
    proc, seconds = _timed([helpers.BIN, "slice", *slice_args(g, e), "-l", model_path(name), "-o", out],
                           env=helpers.CURA_ENV)
    header = gcode_model.read_header(out) if proc.returncode == 0 and out.exists() else {}
    run = Run("mixengine", proc.returncode, seconds, out, header, proc.stderr[-2000:])
    _MEMO[key] = run
    return run


def run_cura(name, overrides=None, use_cache=True):
    """CuraEngine on a model with the same resolved settings; cached on disk (see the module doc)."""
    g, e = resolve(overrides)
    args = [*slice_args(g, e), "-l", model_path(name)]
    key = _cura_key(args)
    meta_path, gz_path = CACHE_DIR / f"{key}.json", CACHE_DIR / f"{key}.gcode.gz"
    out = _TMP / f"cura-{key}.gcode"
    if use_cache and meta_path.is_file() and gz_path.is_file():
        meta = json.loads(meta_path.read_text())
        if not out.exists():
            with gzip.open(gz_path, "rb") as src, open(out, "wb") as dst:
                shutil.copyfileobj(src, dst)
        return Run("CuraEngine", meta["rc"], meta["seconds"], out, meta["header"], meta["stderr"])
    proc, seconds = _timed([helpers.CURA_BIN, "slice", "-v", *args, "-o", out], env=helpers.CURA_ENV)
    run = Run("CuraEngine", proc.returncode, seconds, out, log_header(proc.stderr), proc.stderr[-2000:])
    if proc.returncode == 0 and out.exists():
        CACHE_DIR.mkdir(parents=True, exist_ok=True)
        tmp = gz_path.with_suffix(f".{os.getpid()}.tmp")
        with open(out, "rb") as src, gzip.open(tmp, "wb", compresslevel=6) as dst:
            shutil.copyfileobj(src, dst)
        tmp.replace(gz_path)
        _write_json(meta_path, {"rc": run.rc, "seconds": seconds, "header": run.header, "stderr": run.stderr,
                                "model": name, "overrides": overrides or {}})
    return run


def _write_json(path, data):
    tmp = path.with_suffix(f".{os.getpid()}.tmp")
    tmp.write_text(json.dumps(data, indent=1))
    tmp.replace(path)


def bed_offset(global_values):
    """Where the engines put the model's origin: the bed centre unless machine_center_is_zero."""
    if global_values.get("machine_center_is_zero", "False").lower() == "true":
        return 0.0, 0.0
    return float(global_values["machine_width"]) / 2, float(global_values["machine_depth"]) / 2


def _quality_source_digest():
    here = Path(__file__).resolve().parent
    h = hashlib.sha256()
    for f in ("gcode_model.py", "print_quality.py"):
        h.update((here / f).read_bytes())
    return h.hexdigest()[:16]


def machine(overrides=None):
    """(bed offset, filament diameter, nozzle size) from the resolved settings."""
    g, e = resolve(overrides)
    return bed_offset(g), float(e["material_diameter"]), float(e["machine_nozzle_size"])


def raft_lift_mm(overrides=None):
    """How far both engines raise the model over a raft (adhesion_type raft; MixEngine's
    toolpaths/adhesion/RaftLayout.h, CuraEngine's raft.cpp): the raft's thickness + raft_airgap - layer_0_z_overlap
    (layer 0 sits that overlap higher); 0 without a raft."""
    g, e = resolve(overrides)
    if g.get("adhesion_type") != "raft":
        return 0.0
    thickness = (float(e["raft_base_thickness"]) + float(e["raft_interface_thickness"])
                 + int(e["raft_surface_layers"]) * float(e["raft_surface_thickness"]))
    return thickness + float(e["raft_airgap"]) - float(e["layer_0_z_overlap"])


def measured(run, name, overrides=None, sections=None):
    """(gcode_model.Model, print_quality.Quality) of run.gcode against the model, with the resolved
    settings (filament diameter, nozzle, bed offset, the raft's lift)."""
    offset, diameter, nozzle = machine(overrides)
    model = gcode_model.read(run.gcode)
    q = print_quality.measure(model, model_path(name), offset, diameter, nozzle_mm=nozzle, sections=sections,
                              lift_mm=raft_lift_mm(overrides))
    return model, q


def summary(run, name, overrides=None, cache=None):
    """Quality numbers as a dict: coverage, outside_ratio, grid_mm, tolerance_mm, layers (per layer),
    layer_count, extruded_mm (E in segments inside layers), net_e. cache: optional JSON file to reuse."""
    digest = _quality_source_digest()
    if cache and Path(cache).is_file():
        data = json.loads(Path(cache).read_text())
        if data.get("source") == digest:
            return data["quality"]
    model, q = measured(run, name, overrides)
    result = dict(q.as_dict(), layer_count=model.layer_count, extruded_mm=model.layer_extruded_e,
                  net_e=model.net_e)
    if cache:
        Path(cache).parent.mkdir(parents=True, exist_ok=True)
        _write_json(Path(cache), {"source": digest, "quality": result})
    return result


def cura_quality_cache(run):
    """The cache file for the quality numbers of a (cached) CuraEngine run."""
    return CACHE_DIR / (Path(run.gcode).stem.replace("cura-", "") + ".quality.json")
