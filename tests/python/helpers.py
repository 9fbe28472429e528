"""Shared helpers for the MixEngine end-to-end tests and benchmarks (no pytest import here).

Paths come from the environment:
  MIXENGINE_BIN     the binary under test (default: build/mixengine in the repository)
  MIXENGINE_CORPUS  the corpus made by tests/corpus/fetch.sh (default: ~/.cache/mixengine-corpus)
"""
import json
import math
import os
import re
import struct
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
BIN = Path(os.environ.get("MIXENGINE_BIN", REPO / "build" / "mixengine"))
CORPUS = Path(os.environ.get("MIXENGINE_CORPUS", Path.home() / ".cache" / "mixengine-corpus"))

CURA_BIN = "/usr/bin/CuraEngine"
CURA_DEFS = Path("/usr/share/cura/resources/definitions")
CURA_ENV = {"CURA_ENGINE_SEARCH_PATH": f"{CURA_DEFS}:/usr/share/cura/resources/extruders"}
FDMPRINTER = CURA_DEFS / "fdmprinter.def.json"
ENDER3 = CURA_DEFS / "creality_ender3.def.json"

H0_UM, H_UM = 300, 100  # fdmprinter defaults: layer_height_0 0.3 mm, layer_height 0.1 mm


def expected_layer_count(z_max_mm, h0_um=H0_UM, h_um=H_UM):
    """Number of slice planes at or below z_max (planes at h0/2, h0 + h/2, h0 + 3h/2, ...), in integer
    microns. This is CuraEngine 4.13's count, (z_max - (h0 - h/2)) / h + 1, which the oracle confirms
    (e.g. bunny_lowpoly: 1071 layers where floor((z_max - h0) / h) + 1 would give 1070)."""
    z_um = round(z_max_mm * 1000)
    if 2 * z_um < h0_um:
        return 0
    return max(1, (2 * z_um - 2 * h0_um + h_um) // (2 * h_um) + 1)


def expected_slice_z(index, h0_um=H0_UM, h_um=H_UM):
    """slicing_tolerance=middle: layer 0 at h0/2, layer n at h0 + (n - 1/2) h (mm)."""
    if index == 0:
        return h0_um / 2000
    return (h0_um + (index - 0.5) * h_um) / 1000


def run(cmd, timeout=600, env=None, cwd=None):
    """Runs a command, capturing text output."""
    full_env = dict(os.environ, **(env or {}))
    return subprocess.run([str(c) for c in cmd], capture_output=True, text=True, timeout=timeout,
                          env=full_env, cwd=cwd)


def mixengine(*args, timeout=600):
    return run([BIN, *args], timeout=timeout)


def slice_with(model, out, *settings):
    """`mixengine slice -s KEY=VALUE ... -l MODEL -o OUT` (fdmprinter); returns OUT, asserting success."""
    args = ["slice"]
    for s in settings:
        args += ["-s", s]
    proc = mixengine(*args, "-l", model, "-o", out)
    assert proc.returncode == 0, proc.stderr
    return out


def cura(*args, timeout=600):
    return run([CURA_BIN, *args], timeout=timeout, env=CURA_ENV)


def stderr_lines(proc):
    return [line for line in proc.stderr.splitlines() if line.strip()]


def gcode_layer_count(path):
    """The value of the first ;LAYER_COUNT: line, or None."""
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith(";LAYER_COUNT:"):
                return int(line.split(":", 1)[1])
    return None


def extrusion_by_layer(path):
    """Parses G-code with gcodeparser and returns {layer: [xmin, xmax, ymin, ymax, set of z]} over the
    moves that extrude (E grows) while a ;LAYER:n is open. Honours M82/M83, G90/G91 and G92 E."""
    from gcodeparser import parse_gcode_lines
    layers, layer, e, rel_e, rel_all = {}, None, 0.0, False, False
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    with open(path) as f:
        for line in parse_gcode_lines(f.read(), include_comments=True):
            cmd, p = line.command, line.params
            if line.comment.startswith("LAYER:"):
                layer = int(line.comment[6:])
            elif cmd in (("M", 82), ("M", 83)):
                rel_e = cmd[1] == 83
            elif cmd in (("G", 90), ("G", 91)):
                rel_all = cmd[1] == 91
            elif cmd == ("G", 92) and "E" in p:
                e = float(p["E"])
            elif cmd in (("G", 0), ("G", 1)):
                for k in "XYZ":
                    if k in p:
                        pos[k] = pos[k] + p[k] if rel_all else float(p[k])
                if "E" not in p:
                    continue
                new_e = e + p["E"] if (rel_e or rel_all) else float(p["E"])
                if new_e > e and layer is not None and ("X" in p or "Y" in p):
                    b = layers.setdefault(layer, [math.inf, -math.inf, math.inf, -math.inf, set()])
                    b[0], b[1] = min(b[0], pos["X"]), max(b[1], pos["X"])
                    b[2], b[3] = min(b[2], pos["Y"]), max(b[3], pos["Y"])
                    b[4].add(round(pos["Z"], 4))
                e = new_e
    return layers


def read_layers(out_dir):
    data = json.loads((Path(out_dir) / "layers.json").read_text())
    return data["layers"]


def signed_area(ring):
    """Shoelace area of one closed ring [[x, y], ...] (positive when counter-clockwise)."""
    s = 0.0
    for (x1, y1), (x2, y2) in zip(ring, ring[1:] + ring[:1]):
        s += x1 * y2 - x2 * y1
    return s / 2


def stl_vertices(path):
    """All vertex coordinates of an STL file as a list of (x, y, z), read leniently and independently
    of any mesh library: ASCII when the file holds 'facet'/'vertex' text, otherwise binary with the
    face count limited to what the file really holds (extra or trailing bytes are ignored)."""
    data = Path(path).read_bytes()
    head = data[:512].lstrip().lower()
    if head.startswith(b"solid") and (b"facet" in head or b"endsolid" in head):
        nums = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
        return [tuple(float(v) for v in t) for t in nums]
    if len(data) < 84:
        return []
    count = min(struct.unpack_from("<I", data, 80)[0], (len(data) - 84) // 50)
    verts = []
    for i in range(count):
        vals = struct.unpack_from("<12f", data, 84 + 50 * i)
        verts += [vals[3:6], vals[6:9], vals[9:12]]
    return verts


def stl_z_max(path):
    zs = [v[2] for v in stl_vertices(path) if math.isfinite(v[2])]
    return max(zs) if zs else None


class ReferenceSections:
    """Cross-sections of a mesh computed by trimesh (an implementation independent of MixEngine)."""

    def __init__(self, path):
        import trimesh  # imported lazily: the CLI tests do not need it
        self.mesh = trimesh.load(path, force="mesh")

    def at(self, zs):
        """For each z: (area in mm², perimeter of the closed loops in mm, length of dangling section
        segments in mm). Dangling segments are pieces trimesh could not close into a loop (open meshes);
        area and perimeter count closed loops only."""
        import numpy as np
        sections = self.mesh.section_multiplane([0, 0, 0], [0, 0, 1], list(zs))
        result = []
        for s in sections:
            if s is None:
                result.append((0.0, 0.0, 0.0))
                continue
            dangling = sum(float(np.linalg.norm(np.diff(s.entities[i].discrete(s.vertices), axis=0), axis=1).sum())
                           for i in s.dangling)
            perimeter = sum(p.exterior.length + sum(h.length for h in p.interiors) for p in s.polygons_full)
            result.append((float(s.area), float(perimeter), dangling))
        return result
