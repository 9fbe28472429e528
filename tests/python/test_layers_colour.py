"""`mixengine layers` on a mixing print (issue 26): each layer's SVG draws the layer's extrusions in the colour the
engine predicts to leave the nozzle, and layers.json lists those colours with the length printed in each.

Checked against the G-code `mixengine slice` writes for the same model and settings (with
machine_center_is_zero=True, which `layers` forces), read here line by line: the ;PREDICTED_COLOR: comments of
each ;LAYER:, and the XY length of the moves that push E or B forward under each. The SVG is read as XML and
its lines measured here; nothing of the engine's code is used. A yellow-to-blue Z gradient is yellow at the
bottom, green in the middle (the pigment model: yellow and blue paint make green) and blue at the top.
"""
import json
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

import helpers
from mixing_gcode import box_stl

GRADIENT = ["-s", "mixing_mode=gradient", "-s", "mixing_channel_colors=#ffff00,#0000ff"]
PRINTERS = {
    "fdmprinter": [],  # an ideal chamber (mixing_chamber_volume 0): one colour per layer
    # a 30 mm3 chamber in 3 stages and a raft: several colours per layer, raft layers below ;LAYER:0
    "makerpi_raft": ["-j", "mixengine_makerpi_m2030x", "-s", "adhesion_type=raft"],
}
SVG = "{http://www.w3.org/2000/svg}"
OLD_KEYS = {"index", "print_z_mm", "slice_z_mm", "area_mm2", "outlines", "open_polylines"}


def run_layers(model, out, *args):
    proc = helpers.mixengine("layers", *args, "-l", model, "-o", out)
    assert proc.returncode == 0, proc.stderr
    return json.loads((Path(out) / "layers.json").read_text())


def run_slice(model, out, *args):
    proc = helpers.mixengine("slice", *args, "-s", "machine_center_is_zero=True", "-l", model, "-o", out)
    assert proc.returncode == 0, proc.stderr
    return out


def gcode_layers(path):
    """{;LAYER: number: {"comments": [;PREDICTED_COLOR: values in order], "mm": {colour: XY length extruded},
    "box": [xmin, xmax, ymin, ymax] of the extruding moves}} (absolute XY, E and B as the engine writes them)."""
    layers, layer, colour = {}, None, None
    pos, axes = {"X": 0.0, "Y": 0.0}, {"E": 0.0, "B": 0.0}
    for line in open(path):
        if line.startswith(";LAYER:"):
            layer = layers.setdefault(int(line[7:]), {"comments": [], "mm": {}, "box": [math.inf, -math.inf] * 2})
        elif line.startswith(";PREDICTED_COLOR:"):
            colour = line[17:].strip().lower()
            if layer is not None:
                layer["comments"].append(colour)
        words = line.split(";")[0].split()
        if words[:1] == ["G92"]:
            axes.update({w[0]: float(w[1:]) for w in words[1:] if w[0] in axes})
        if words[:1] not in (["G0"], ["G1"]):
            continue
        start = dict(pos)
        values = {w[0]: float(w[1:]) for w in words[1:] if w[0] in "XYEB"}
        forward = any(values[a] > axes[a] + 1e-9 for a in axes if a in values)
        pos.update({a: values[a] for a in pos if a in values})
        axes.update({a: values[a] for a in axes if a in values})
        if forward and layer is not None and (pos != start):
            layer["mm"][colour] = layer["mm"].get(colour, 0.0) + math.dist(start.values(), pos.values())
            box = layer["box"]
            for x, y in (start.values(), pos.values()):
                box[:] = [min(box[0], x), max(box[1], x), min(box[2], y), max(box[3], y)]
    return layers


def svg_numbers(d):
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", d)]


def svg_extrusions(path):
    """[(stroke colour, stroke width, [(x, y), ...])] of the paths in <g class="extrusions">, in SVG units (mm),
    and the first point of the outline (to map SVG units back to the model's frame)."""
    root = ET.parse(path).getroot()
    groups = [g for g in root.iter(SVG + "g") if g.get("class") == "extrusions"]
    runs = []
    for g in groups:
        for p in g.iter(SVG + "path"):
            n = svg_numbers(p.get("d"))
            runs.append((p.get("stroke").lower(), float(p.get("stroke-width")), list(zip(n[0::2], n[1::2]))))
    outline = next((p for p in root.iter(SVG + "path") if p.get("class") == "outline"), None)
    first = svg_numbers(outline.get("d"))[:2] if outline is not None and outline.get("d").strip() else None
    return groups, runs, first


def check_layer(svg_path, layer, gcode_layer):
    """The SVG's lines and the JSON entry of one sliced layer against the G-code layer that prints it."""
    groups, runs, first = svg_extrusions(svg_path)
    assert len(groups) == 1, f"{svg_path.name}: one group of extrusions"
    comments = gcode_layer["comments"]
    svg_colours = {colour for colour, _, _ in runs}
    assert svg_colours == set(comments), f"{svg_path.name}: SVG colours vs ;PREDICTED_COLOR: of the layer"
    listed = [entry["color"] for entry in layer["predicted_colors"]]
    assert listed == list(dict.fromkeys(comments)), f"{svg_path.name}: layers.json colours, in first use"
    svg_mm = {}
    for colour, width, points in runs:
        assert 0.1 < width < 2.0
        svg_mm[colour] = svg_mm.get(colour, 0.0) + sum(math.dist(a, b) for a, b in zip(points, points[1:]))
    for entry in layer["predicted_colors"]:
        expected = gcode_layer["mm"].get(entry["color"], 0.0)
        assert entry["length_mm"] == pytest.approx(expected, rel=2e-3, abs=0.05), (svg_path.name, entry)
        assert svg_mm[entry["color"]] == pytest.approx(expected, rel=2e-3, abs=0.05), (svg_path.name, entry)
    # The lines stand where the G-code prints them: the outline's first point fixes the SVG's frame.
    ring = layer["outlines"][0][0]
    left, top = ring[0] - first[0], ring[1] + first[1]
    xs = [left + x for _, _, points in runs for x, _ in points]
    ys = [top - y for _, _, points in runs for _, y in points]
    assert [min(xs), max(xs), min(ys), max(ys)] == pytest.approx(gcode_layer["box"], abs=0.01), svg_path.name


def rgb(hex_colour):
    return tuple(int(hex_colour[i:i + 2], 16) for i in (1, 3, 5))


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("layers_colour") / "cube.stl", 20, 20, 20)


@pytest.mark.parametrize("printer", PRINTERS)
def test_gradient_cube_layers_show_the_predicted_colours(engine, cube, tmp_path, printer, report):
    args = PRINTERS[printer] + GRADIENT
    doc = run_layers(cube, tmp_path / "layers", *args)
    gcode = gcode_layers(run_slice(cube, tmp_path / "cube.gcode", *args))
    layers = doc["layers"]
    assert layers and doc["meshes"] == [str(cube)]
    model = sorted(n for n in gcode if n >= 0)
    assert [layer["gcode_layer"] for layer in layers] == model == list(range(len(layers)))
    for i, layer in enumerate(layers):
        assert OLD_KEYS <= set(layer) and layer["index"] == i
        check_layer(tmp_path / "layers" / f"layer_{i:05d}.svg", layer, gcode[layer["gcode_layer"]])
    raft = [entry["gcode_layer"] for entry in doc["raft_layers"]]
    assert raft == sorted(n for n in gcode if n < 0)
    assert bool(raft) == (printer == "makerpi_raft")
    for entry in doc["raft_layers"]:
        comments = gcode[entry["gcode_layer"]]["comments"]
        assert [c["color"] for c in entry["predicted_colors"]] == list(dict.fromkeys(comments))
        for c in entry["predicted_colors"]:
            assert c["length_mm"] == pytest.approx(gcode[entry["gcode_layer"]]["mm"][c["color"]], rel=2e-3, abs=0.05)

    middle = layers[len(layers) // 2]
    for entry in middle["predicted_colors"]:
        r, g, b = rgb(entry["color"])
        assert g > max(r, b) + 30, f"middle layer {middle['index']}: {entry['color']} is not green"
    bottom, top = rgb(layers[0]["predicted_colors"][-1]["color"]), rgb(layers[-1]["predicted_colors"][-1]["color"])
    assert min(bottom[:2]) > bottom[2] + 100, f"bottom layer {bottom} is not yellow"
    assert top[2] > max(top[:2]) + 100, f"top layer {top} is not blue"
    report(f"layers {printer}: middle layer {middle['index']} "
           + ", ".join(f"{c['color']} {c['length_mm']:.0f} mm" for c in middle["predicted_colors"])
           + f"; {len(raft)} raft layers")


def pyramid_stl(path, half=10.0, height=20.0):
    """An upside-down square pyramid, its tip at z = 0: the first cut is a loop under
    minimum_polygon_circumference and the second too thin for a wall, so the toolpaths drop those layers and
    ;LAYER:0 prints sliced layer 2."""
    base = [(-half, -half), (half, -half), (half, half), (-half, half)]
    tris = [((0, 0, 0), (*base[(i + 1) % 4], height), (*base[i], height)) for i in range(4)]
    tris += [tuple((*base[i], height) for i in (0, 1, 2)), tuple((*base[i], height) for i in (0, 2, 3))]
    out = ["solid pyramid"]
    for tri in tris:
        out += ["facet normal 0 0 0\nouter loop"] + ["vertex %g %g %g" % v for v in tri] + ["endloop\nendfacet"]
    path.write_text("\n".join(out + ["endsolid pyramid"]) + "\n")
    return path


def test_dropped_bottom_layer_is_matched_by_layer_number(engine, tmp_path):
    model = pyramid_stl(tmp_path / "pyramid.stl")
    doc = run_layers(model, tmp_path / "layers", *GRADIENT)
    gcode = gcode_layers(run_slice(model, tmp_path / "pyramid.gcode", *GRADIENT))
    layers = doc["layers"]
    # The tip's first cut is under minimum_polygon_circumference and the next too thin for a wall: both go, as
    # in CuraEngine, and ;LAYER:0 prints sliced layer 2.
    dropped = 2
    assert all(layer["gcode_layer"] is None and layer["predicted_colors"] == [] for layer in layers[:dropped])
    assert ([layer["gcode_layer"] for layer in layers[dropped:]] == sorted(gcode)
            == list(range(len(layers) - dropped)))
    groups, runs, _ = svg_extrusions(tmp_path / "layers" / "layer_00000.svg")
    assert groups == [] and runs == []
    for layer in layers[dropped:]:
        check_layer(tmp_path / "layers" / f"layer_{layer['index']:05d}.svg", layer, gcode[layer["gcode_layer"]])


def test_single_mode_writes_outlines_only(engine, cube, tmp_path):
    doc = run_layers(cube, tmp_path / "layers")
    assert set(doc) == {"meshes", "layers"}
    assert all(set(layer) == OLD_KEYS for layer in doc["layers"])
    groups, runs, _ = svg_extrusions(tmp_path / "layers" / "layer_00010.svg")
    assert groups == [] and runs == []
