"""A small G-code reader of our own (independent of both engines and of gcodeparser): it turns a Cura-style
G-code file into per-layer extrusion segments, for the print-quality measure (print_quality.py) and the
side-by-side comparison with CuraEngine (test_compare_cura.py, tests/bench/compare_quality.py).

    model = gcode_model.read("print.gcode")
    layer = model.layers[12]        # Layer: index, z_mm, thickness_mm, segments (numpy arrays)
    model.layer_count               # ;LAYER_COUNT: or None
    model.header["TIME"]            # header comments ;KEY:value written before the first command

What it understands:
- G0/G1 moves with X Y Z E F; G90/G91 (absolute/relative positioning; like Marlin, they also switch E),
  M82/M83 (absolute/relative E only), G92 (set any axis; without words: all axes to 0), G28 (the homed axes,
  or all, go to 0), T<n> (tool changes), G10/G11 (firmware retraction: counted, E unchanged), M200 D<d>
  (volumetric E: a later E is mm³ when d > 0 is announced by the flavor, see `volumetric`).
- Comments: ;LAYER:n opens layer n (negative for raft), ;TYPE:name sets the feature of the following
  extrusions (kept across layers until the next ;TYPE:), ;LAYER_COUNT:n, ;MESH:name.
- Arcs (G2/G3) and inches (G20) are not produced by either engine; they raise GcodeError rather than being
  measured wrongly.

Extrusion segments: a move whose XY position changes and whose E grows by more than it restores from an
earlier retraction. E bookkeeping per move: a negative E delta is a retraction (the amount is remembered); a
positive delta first restores the remembered retraction (a prime) and only the rest is extrusion. So Cura's
`G1 E-6.5` ... `G1 E0` pairs, and retract/prime done while moving, never become segments. Extrusion before the
first ;LAYER: (start-code prime lines) is counted in the totals but belongs to no layer.
"""
import math
from dataclasses import dataclass, field

import numpy as np

VOLUMETRIC_FLAVORS = ("UltiGCode", "Marlin(Volumetric)")


class GcodeError(ValueError):
    """A construct this reader refuses to measure (arcs, inches, unparsable numbers): line number and text."""


@dataclass
class Layer:
    """The extrusion segments of one ;LAYER:n block, as numpy arrays of equal length n_segments.

    x0, y0, x1, y1, z: start/end position of each segment (mm, machine coordinates);
    e: filament (mm, or mm³ when the file is volumetric) extruded along it, retraction/prime excluded;
    feature: index into Model.features (the ;TYPE: name in force), tool: the active T number.
    z_mm: the layer's print height (median Z of its segments; for a layer without segments the lowest Z a
    move inside it reached, None when none did), thickness_mm: z_mm minus the previous layer's z_mm (the
    first layer's: its z_mm)."""
    index: int
    x0: np.ndarray
    y0: np.ndarray
    x1: np.ndarray
    y1: np.ndarray
    z: np.ndarray
    e: np.ndarray
    feature: np.ndarray
    tool: np.ndarray
    z_mm: float = None
    thickness_mm: float = None

    def lengths(self):
        return np.hypot(self.x1 - self.x0, self.y1 - self.y0)


@dataclass
class Model:
    """Everything read from one file. Totals are in E units (mm of filament, mm³ when volumetric)."""
    header: dict = field(default_factory=dict)     # ";KEY:value" comments before the first command
    layer_count: int = None                        # first ;LAYER_COUNT:
    layers: dict = field(default_factory=dict)     # index -> Layer, in file order of first appearance
    features: list = field(default_factory=list)   # feature names; Layer.feature indexes this list
    volumetric: bool = False
    net_e: float = 0.0              # sum of every E delta (what the E axis really fed, end retractions included)
    extruded_e: float = 0.0         # E laid down in segments (any layer or none)
    layer_extruded_e: float = 0.0   # E laid down in segments inside ;LAYER: blocks
    tool_extruded_e: dict = field(default_factory=dict)  # tool -> E in segments
    max_abs_e_value: float = 0.0    # largest |E word| written while E was absolute (the E-growth bound)
    firmware_retractions: int = 0
    lines: int = 0

    def feature_mask(self, layer, names):
        """Boolean mask of the layer's segments whose feature is in names."""
        wanted = [i for i, f in enumerate(self.features) if f in names]
        return np.isin(layer.feature, wanted)


class _LayerBuilder:
    __slots__ = ("cols", "min_move_z")

    def __init__(self):
        self.cols = [[] for _ in range(8)]
        self.min_move_z = None  # lowest Z any move reached inside the layer (its height when it has no segment)

    def add(self, *values):
        for col, v in zip(self.cols, values):
            col.append(v)

    def build(self, index):
        x0, y0, x1, y1, z, e = (np.asarray(c, dtype=float) for c in self.cols[:6])
        feature, tool = (np.asarray(c, dtype=np.int32) for c in self.cols[6:8])
        layer = Layer(index, x0, y0, x1, y1, z, e, feature, tool)
        layer.z_mm = float(np.median(z)) if len(z) else self.min_move_z
        return layer


def _words(code, lineno, line):
    """{'X': 1.0, ...} for the words after the command letter."""
    out = {}
    for w in code.split()[1:]:
        try:
            out[w[0].upper()] = float(w[1:]) if len(w) > 1 else 0.0
        except ValueError:
            raise GcodeError(f"line {lineno}: cannot read number in {line.strip()!r}") from None
    return out


def read(path, volumetric=None):
    """Reads a G-code file. volumetric=None decides from ;FLAVOR: (UltiGCode and Marlin(Volumetric) write
    E in mm³); True/False forces it."""
    m = Model()
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    e_reg, retracted = 0.0, 0.0
    rel_xyz = rel_e = False
    layer, feature, tool = None, -1, 0
    builders, feature_ids = {}, {}
    seen_command, lineno = False, 0
    with open(path, errors="replace") as f:
        for lineno, line in enumerate(f, 1):
            code, _, comment = line.partition(";")
            code = code.strip()
            if comment:
                comment = comment.strip()
                if comment.startswith("LAYER:"):
                    layer = int(comment[6:])
                    builders.setdefault(layer, _LayerBuilder())
                elif comment.startswith("TYPE:"):
                    name = comment[5:]
                    if name not in feature_ids:
                        feature_ids[name] = len(m.features)
                        m.features.append(name)
                    feature = feature_ids[name]
                elif comment.startswith("LAYER_COUNT:") and m.layer_count is None:
                    m.layer_count = int(comment[12:])
                elif not seen_command and ":" in comment:
                    key, _, value = comment.partition(":")
                    m.header.setdefault(key.strip(), value.strip())
            if not code:
                continue
            seen_command = True
            letter, num = code[0].upper(), code.split()[0][1:]
            if letter == "T":
                tool = int(num)
                continue
            if letter not in "GM":
                continue
            try:
                n = int(float(num))
            except ValueError:
                raise GcodeError(f"line {lineno}: unreadable command {line.strip()!r}") from None
            if letter == "M":
                if n in (82, 83):
                    rel_e = n == 83
                continue
            if n in (0, 1):
                w = _words(code, lineno, line)
                start = (pos["X"], pos["Y"])
                for k in "XYZ":
                    if k in w:
                        pos[k] = pos[k] + w[k] if rel_xyz else w[k]
                if layer is not None and "Z" in w:
                    b = builders[layer]
                    b.min_move_z = pos["Z"] if b.min_move_z is None else min(b.min_move_z, pos["Z"])
                if "E" not in w:
                    continue
                if rel_e:
                    delta = w["E"]
                else:
                    delta = w["E"] - e_reg
                    m.max_abs_e_value = max(m.max_abs_e_value, abs(w["E"]))
                e_reg += delta
                m.net_e += delta
                if delta < 0:
                    retracted -= delta
                    continue
                restore = min(delta, retracted)
                retracted -= restore
                extruded = delta - restore
                if extruded <= 0 or (pos["X"], pos["Y"]) == start:
                    continue
                m.extruded_e += extruded
                m.tool_extruded_e[tool] = m.tool_extruded_e.get(tool, 0.0) + extruded
                if layer is not None:
                    m.layer_extruded_e += extruded
                    builders[layer].add(start[0], start[1], pos["X"], pos["Y"], pos["Z"], extruded, feature, tool)
            elif n == 92:
                w = _words(code, lineno, line)
                if not w:
                    w = {"X": 0.0, "Y": 0.0, "Z": 0.0, "E": 0.0}
                for k in "XYZ":
                    if k in w:
                        pos[k] = w[k]
                if "E" in w:
                    e_reg = w["E"]
            elif n == 28:
                w = _words(code, lineno, line)
                for k in "XYZ":
                    if k in w or not w:
                        pos[k] = 0.0
            elif n in (90, 91):
                rel_xyz = rel_e = n == 91
            elif n in (10, 11):
                m.firmware_retractions += n == 10
            elif n in (2, 3, 20):
                raise GcodeError(f"line {lineno}: G{n} is not measured by this reader: {line.strip()!r}")
    m.lines = lineno
    if volumetric is None:
        volumetric = m.header.get("FLAVOR") in VOLUMETRIC_FLAVORS
    m.volumetric = volumetric
    m.layers = {i: b.build(i) for i, b in builders.items()}
    _set_heights(m)
    return m


def _set_heights(m):
    previous = 0.0
    for index in sorted(m.layers):
        layer = m.layers[index]
        if layer.z_mm is None:
            continue
        layer.thickness_mm = layer.z_mm - previous
        previous = layer.z_mm


def read_header(path):
    """The ;KEY:value comments before the first command of a file (as Model.header)."""
    header = {}
    with open(path, errors="replace") as f:
        for line in f:
            code, _, comment = line.partition(";")
            if code.strip():
                break
            key, sep, value = comment.partition(":")
            if sep:
                header.setdefault(key.strip(), value.strip())
    return header


def filament_area_mm2(diameter_mm):
    return math.pi * (diameter_mm / 2) ** 2


def segment_widths_mm(model, layer, filament_diameter_mm):
    """Real width of each segment: extruded volume / (length x layer thickness). Volume is E x filament
    cross-section, or E itself when the file is volumetric."""
    volume = layer.e if model.volumetric else layer.e * filament_area_mm2(filament_diameter_mm)
    length = layer.lengths()
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(length > 0, volume / (length * layer.thickness_mm), 0.0)
