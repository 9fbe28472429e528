"""Scenes with Cura's per-model settings (issue 16), sliced by MixEngine and by Debian's CuraEngine 4.13 with
the same arguments (no pytest import here; test_per_model.py and tests/e2e use it).

A scene is a list of parts, each an STL made here in one shared frame (kept where it is: neither engine
centres a model without center_object) and its per-model settings. Both engines get side_by_side.py's
resolved Ender-3 settings, then `-l part.stl -s key=value ...` per part (CuraEngine's focus rules: a -s after
-l belongs to that model). The per-model values are what Cura's frontend sends for a per-object stack: the
keys the user set (infill_mesh, ...) and every value that resolves differently because of them (e.g.
infill_line_distance for a per-object infill_sparse_density), since CuraEngine's command line does not
evaluate formulas.

Per-feature extrusion is read with gcode_model.py (our own reader): E laid down per ;TYPE:.
"""
import gzip
import hashlib
import json
import math
import os
import shutil
from pathlib import Path

import gcode_model
import helpers
import side_by_side as sbs

MODEL_DIR = sbs.CACHE_DIR / "models" / "permodel"
ROLE_KEYS = ("infill_mesh", "cutting_mesh", "support_mesh", "anti_overhang_mesh", "infill_mesh_order",
             "support_mesh_drop_down")


def _box(trimesh, lo, hi):
    box = trimesh.creation.box(extents=[h - l for l, h in zip(lo, hi)])
    box.apply_translation([(l + h) / 2 for l, h in zip(lo, hi)])
    return box


def _cylinder(trimesh, radius, z0, z1, x=0.0, y=0.0):
    cyl = trimesh.creation.cylinder(radius=radius, height=z1 - z0, sections=96)
    cyl.apply_translation([x, y, (z0 + z1) / 2])
    return cyl


def _open_box(trimesh):
    """A 20 x 20 x 10 mm box without its -y side: every layer's cut is an open U, 20 mm across the gap."""
    box = _box(trimesh, (-10, -10, 0), (10, 10, 10))
    keep = [i for i, n in enumerate(box.face_normals) if not n[1] < -0.9]
    return trimesh.Trimesh(box.vertices, box.faces[keep], process=False)


def _tee(trimesh, shapely):
    """A 30 x 10 mm bar 6 mm thick at z 16..22 on an 8 x 10 mm stem: 11 mm of 90-degree overhang each side."""
    import math
    profile = shapely.Polygon([(-4, 0), (4, 0), (4, 16), (15, 16), (15, 22), (-15, 22), (-15, 16), (-4, 16)])
    mesh = trimesh.creation.extrude_polygon(profile, 10.0)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, [1, 0, 0]))
    mesh.apply_translation([0, 5, 0])
    return mesh


SHAPES = {
    # name -> builder(trimesh, shapely)
    "box30": lambda t, s: _box(t, (-15, -15, 0), (15, 15, 30)),
    "cyl8_in_box": lambda t, s: _cylinder(t, 8.0, 5.0, 25.0),
    "cyl8_through": lambda t, s: _cylinder(t, 8.0, 0.0, 30.0),
    "cyl6_shifted": lambda t, s: _cylinder(t, 6.0, 8.0, 22.0, x=6.0),
    "tee": _tee,
    "blocker_right": lambda t, s: _box(t, (3, -7, 0), (17, 7, 24)),
    "box20x10": lambda t, s: _box(t, (-10, -10, 0), (10, 10, 10)),
    "pillar_beside": lambda t, s: _box(t, (14, -4, 0), (22, 4, 12)),
    "float_beside": lambda t, s: _box(t, (14, -4, 8), (22, 4, 12)),
    "box_left": lambda t, s: _box(t, (-14, -8, 0), (4, 8, 12)),
    "box_right": lambda t, s: _box(t, (-4, -8, 0), (14, 8, 12)),
    # one mesh of two overlapping shells (meshfix_union_all), and a box open on its -y side (the open pieces
    # of meshfix_keep_open_polygons / meshfix_extensive_stitching)
    "two_shells": lambda t, s: t.util.concatenate([_box(t, (-14, -8, 0), (4, 8, 12)), _box(t, (-4, -8, 0), (14, 8, 12))]),
    "open_box": lambda t, s: _open_box(t),
}


def part_path(name):
    path = MODEL_DIR / f"{name}.stl"
    if not path.is_file():
        import shapely
        import trimesh
        mesh = SHAPES[name](trimesh, shapely)
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        mesh.export(tmp, file_type="stl")
        tmp.replace(path)
    return path


def mesh_values(values):
    """The per-model values for a part: the role keys as given, and for other keys every resolved value
    (global or extruder) that differs from the plain machine's, as Cura's frontend sends them."""
    roles = {k: v for k, v in values.items() if k in ROLE_KEYS}
    others = {k: v for k, v in values.items() if k not in ROLE_KEYS}
    if not others:
        return roles
    g0, e0 = sbs.resolve()
    g1, e1 = sbs.resolve(others)
    changed = {k: v for k, v in {**g1, **e1}.items() if {**g0, **e0}.get(k) != v}
    return {**changed, **others, **roles}


def scene_args(parts, overrides=None):
    """Both engines' arguments: the resolved machine (side_by_side.py) and -l/-s per part."""
    g, e = sbs.resolve(overrides)
    args = sbs.slice_args(g, e)
    for name, values in parts:
        args += ["-l", str(part_path(name))]
        for k, v in sorted(mesh_values(values).items()):
            args += ["-s", f"{k}={v}"]
    return args


class Result:
    def __init__(self, rc, gcode, header, stderr):
        self.rc, self.gcode, self.header, self.stderr = rc, gcode, header, stderr
        self._model = None

    @property
    def model(self):
        if self._model is None:
            self._model = gcode_model.read(self.gcode)
        return self._model

    def filament_mm(self):
        """The header's filament; when CuraEngine stops early for want of layers (a modifier alone) its
        header says "-nanm": then what the file extrudes in layers (none)."""
        text = self.header.get("Filament used", "0m")
        total = sum(float(p.strip().rstrip("m")) for p in text.split(",") if p.strip()) * 1000.0
        return self.model.layer_extruded_e if math.isnan(total) else total

    def layer_count(self):
        """;LAYER_COUNT:, 0 when there is none (CuraEngine writes none when no layer prints)."""
        return self.model.layer_count or 0

    def by_feature(self):
        """;TYPE: name -> E (mm of filament) laid down in segments inside layers."""
        totals = {}
        for layer in self.model.layers.values():
            for index, name in enumerate(self.model.features):
                e = float(layer.e[layer.feature == index].sum())
                if e > 0:
                    totals[name] = totals.get(name, 0.0) + e
        return totals


def run_mixengine(parts, out_dir, overrides=None, extra=()):
    out = Path(out_dir) / ("mix-" + hashlib.sha256(repr((parts, overrides, extra)).encode()).hexdigest()[:16]
                           + ".gcode")
    proc = helpers.run([helpers.BIN, "slice", *scene_args(parts, overrides), *extra, "-o", out],
                       env=helpers.CURA_ENV)
    header = gcode_model.read_header(out) if proc.returncode == 0 and out.exists() else {}
    return Result(proc.returncode, out, header, proc.stderr[-3000:])


def run_cura(parts, out_dir, overrides=None):
    """CuraEngine on the scene, cached in side_by_side's cache (keyed by its binary, arguments and models)."""
    args = scene_args(parts, overrides)
    key = "permodel-" + sbs._cura_key(args)
    meta_path, gz_path = sbs.CACHE_DIR / f"{key}.json", sbs.CACHE_DIR / f"{key}.gcode.gz"
    out = Path(out_dir) / f"{key}.gcode"
    if meta_path.is_file() and gz_path.is_file():
        meta = json.loads(meta_path.read_text())
        with gzip.open(gz_path, "rb") as src, open(out, "wb") as dst:
            shutil.copyfileobj(src, dst)
        return Result(meta["rc"], out, meta["header"], meta["stderr"])
    proc = helpers.run([helpers.CURA_BIN, "slice", "-v", *args, "-o", out], env=helpers.CURA_ENV)
    result = Result(proc.returncode, out, sbs.log_header(proc.stderr), proc.stderr[-3000:])
    if proc.returncode == 0 and out.exists():
        sbs.CACHE_DIR.mkdir(parents=True, exist_ok=True)
        with open(out, "rb") as src, gzip.open(gz_path, "wb") as dst:
            shutil.copyfileobj(src, dst)
        meta_path.write_text(json.dumps({"rc": result.rc, "header": result.header, "stderr": result.stderr}))
    return result
