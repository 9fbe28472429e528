"""Issue 17 part 1 and issue 26, without Cura: the plugin's reading of the G-code (plugin/MixGCode.py: the
extruding moves and the colour the engine predicts for each, ";PREDICTED_COLOR:#rrggbb"), the recolouring of
the layer view's vertices with exactly those colours (LayerRecolour.py), the channel colours of the legend
(MixColours.py) and the list of settings MixEngine does not act on (NotHonoured.py). The real Cura runs in
test_e2e_cura.py; here the engine's G-code is read back against mixing_gcode.py, an independent model of each
firmware, and the layer view is built from the LayerOptimized messages the engine sends over the socket, by
Cura's vertex rule (cura/LayerPolygon.py). The plugin mixes no colours: every colour checked here is one the
engine wrote (or `mixengine mix` predicts for the same ratio).
"""
import json
import re
import subprocess
import sys

import numpy
import pytest

import helpers
from cura_socket import one_object, resolved_settings, slice_over_socket
from mixing_gcode import box_stl, read_mixing_gcode

sys.path.insert(0, str(helpers.REPO / "plugin"))
import LayerRecolour  # noqa: E402
import MixColours  # noqa: E402
import MixGCode  # noqa: E402
import NotHonoured  # noqa: E402

DIALECTS = ["eb_axes", "klipper_b", "rrf_colon", "marlin_m163", "marlin_m165", "rrf_m567"]
FIVE_STOPS = "0=1:0:0:0:0; 25=0:1:0:0:0; 50=0:0:1:0:0; 75=0:0:0:0.5:0.5; 100=0:0:0:0:1"
YELLOW_BLUE = "#ffff00,#0000ff"
CMYKW = "#00ffff,#ff00ff,#ffff00,#000000,#ffffff"
NONE = None  # a move without a predicted colour


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("mix_preview") / "cube.stl", 20, 20, 20)


def slice_cube(cube, out, *settings):
    return helpers.slice_with(cube, out, *settings)


def written_colours(text):
    """{layer id: the ;PREDICTED_COLOR: values written in that layer's chunk, in order, lower case}."""
    out, layer = {}, None
    for line in text.splitlines():
        if line.startswith(";LAYER:"):
            layer = int(line[7:])
            out.setdefault(layer, [])
        elif line.startswith(";PREDICTED_COLOR:") and layer is not None:
            out[layer].append(line[17:].strip().lower())
    return out


def predicted_colour(colours, ratio):
    """What `mixengine mix` predicts for `ratio` of `colours` (the engine's pigment model, no chamber)."""
    proc = helpers.mixengine("mix", "--colors", colours, "--ratio", ratio)
    assert proc.returncode == 0, proc.stderr
    return re.search(r"^predicted\s+(#[0-9a-f]{6})$", proc.stdout, re.M).group(1)


def move_hex(moves, layer_id):
    return [moves.colours[c] if c >= 0 else NONE for c in moves.layers[layer_id].colour]


def green(rgb):
    """G clearly above R and B: yellow and blue mixed as pigments (their linear-light blend is grey)."""
    r, g, b = rgb
    return g > r + 0.2 and g > b + 0.1


def hex_rgb(text):
    return numpy.array([int(text[i:i + 2], 16) / 255 for i in (1, 3, 5)])


# ---- the G-code: extruding moves and the predicted colour in force -------------------------------------------
EB_CHUNKS = [
    ";FLAVOR:Marlin\n;Generated with MixEngine\n",
    "G90\nM82\nG92 E0 B0\nG1 X5 Y5 E8 B8 ;prime line: outside the layers, not listed\nG92 E0 B0\n",
    ";LAYER:0\n"
    "G0 X0 Y0 Z0.3\n"
    "G1 X10 Y0 E1 B0\n"  # before any PREDICTED_COLOR: no colour
    ";PREDICTED_COLOR:#FFFF00\n"
    "G1 X10 Y10 E2 B0\n"
    "G1 E1.5 B0\n"  # retraction (no XY): not a line
    "G0 X20 Y10\n"
    "G1 E2 B0\n"  # unretraction
    ";TYPE:WALL-OUTER\n"
    ";PREDICTED_COLOR: #038b55\n"
    "G1 X20 Y20 E2 B1\n"  # only B moves forward: extrudes
    "G1 X30 Y20 E3 B2 ;a comment\n",
    ";LAYER:1\n"
    "G1 X30 Y30 E4 B3\n"  # the colour in force carries over
    ";PREDICTED_COLOR:#0000ff\n"
    "G1 X0 Y30 E4 B4\n"
    ";PREDICTED_COLOR:lilac\n"  # malformed: no colour until the next good one
    "G1 X0 Y0 E4 B5\n",
    ";End of Gcode\nG1 X0 Y0 E10 B10\n",
]
EB_EXPECTED = {0: [NONE, "#ffff00", "#038b55", "#038b55"], 1: ["#038b55", "#0000ff", NONE]}


def test_each_extruding_move_takes_the_predicted_colour_in_force():
    moves = MixGCode.read(EB_CHUNKS, "eb_axes")
    assert moves.order == [0, 1]
    assert {i: move_hex(moves, i) for i in moves.order} == EB_EXPECTED
    assert moves.layers[0].xy == [(10, 0), (10, 10), (20, 20), (30, 20)]
    assert moves.layers[1].xy == [(30, 30), (0, 30), (0, 0)]
    assert moves.layers[0].amount == [1, 1, 1, 2] and moves.layers[1].amount == [2, 1, 1]
    assert moves.colours == ["#ffff00", "#038b55", "#0000ff"] and moves.malformed == 1
    assert (moves.extrusions(), moves.predicted()) == (7, 5)
    # the colours exactly as written, 8 bits per channel; NaN where a move has none
    rgb = moves.moveColours()
    assert numpy.array_equal(rgb[0][1], [1, 1, 0]) and numpy.array_equal(rgb[1][1], [0, 0, 1])
    assert numpy.array_equal(rgb[0][2], [3 / 255, 0x8b / 255, 0x55 / 255])
    assert numpy.isnan(rgb[0][0]).all() and numpy.isnan(rgb[1][2]).all()


@pytest.mark.parametrize("dialect, layer", [
    ("rrf_colon", "M83\n;PREDICTED_COLOR:#102030\nG1 X1 Y0 E0:0.5\nG1 X2 Y0 E-1:0\nG1 X3 Y0 E0.2:0.3\n"),
    ("marlin_m165", "M83\n;PREDICTED_COLOR:#102030\nM165 A0 B1\nG1 X1 Y0 E0.5\nG1 X2 Y0 E-1\nG1 X3 Y0 E0.5\n"),
    ("marlin_m163", "G92 E0\n;PREDICTED_COLOR:#102030\nM163 S0 P0.2\nM163 S1 P0.8\nM164 S0\n"
                    "G1 X1 Y0 E0.5\nG1 X2 Y0 E-0.5\nG1 X3 Y0 E0.5\n"),
    ("rrf_m567", "G91\n;PREDICTED_COLOR:#102030\nM567 P0 E0.5:0.5\nG1 X1 Y0 E0.5\nG1 X1 E-1\nG1 X1 E1\n"),
    ("klipper_b", "G91\nM83\n;PREDICTED_COLOR:#102030\nG1 X1 Y0 E0 B0.5\nG1 X1 E-1 B0\nG1 X1 E0.5 B0\n"),
])
def test_mix_command_and_axis_dialects_list_the_extruding_moves(dialect, layer):
    """A retraction is no line; a move of only the second channel is. The mix itself is not read: the colour is
    the engine's."""
    moves = MixGCode.read([";LAYER:0\n" + layer], dialect)
    assert moves.layers[0].xy == [(1, 0), (3, 0)]
    assert move_hex(moves, 0) == ["#102030", "#102030"]


def colour_in_force(text):
    """{layer id: [(x, y, colour)]} for every G0/G1 line of the layer that names X or Y, in order: where it ends
    and the last ;PREDICTED_COLOR: before it (None before any). Absolute X/Y, as the engine writes them."""
    out, layer, colour, xy = {}, None, None, [0.0, 0.0]
    for line in text.splitlines():
        if line.startswith(";LAYER:"):
            layer = int(line[7:])
            out.setdefault(layer, [])
        elif line.startswith(";PREDICTED_COLOR:"):
            colour = line[17:].strip().lower()
        elif line.startswith(("G0 ", "G1 ")):
            words = {w[0]: w[1:] for w in line.split(";")[0].split()[1:]}
            if "X" in words or "Y" in words:
                xy = [float(words.get("X", xy[0])), float(words.get("Y", xy[1]))]
                if layer is not None:
                    out[layer].append((xy[0], xy[1], colour))
    return out


@pytest.mark.parametrize("chamber", [0, 40])
@pytest.mark.parametrize("relative", [False, True])
@pytest.mark.parametrize("dialect", DIALECTS)
def test_extrusions_and_predicted_colours_read_from_the_engine_gcode(cube, tmp_path, dialect, relative, chamber):
    """The moves the plugin colours are the firmware's extrusions, one for one, and each has the colour of the
    last ;PREDICTED_COLOR: the engine wrote before it. With a 40 mm3 chamber the colour leaving the nozzle
    changes inside layers too."""
    path = slice_cube(cube, tmp_path / "g.gcode", f"relative_extrusion={relative}", "mixing_mode=gradient",
                      f"mixing_dialect={dialect}", "mixing_gradient_start=20", "mixing_gradient_end=80",
                      f"mixing_channel_colors={YELLOW_BLUE}", f"mixing_chamber_volume={chamber}")
    text = path.read_text()
    moves = MixGCode.read([text], dialect)
    firmware = {}
    for m in read_mixing_gcode(path, dialect, 2).extrusions():
        firmware.setdefault(m.layer, []).append((m.end, m.total))
    assert sorted(i for i in moves.order if moves.layers[i].xy) == sorted(firmware)
    assert len(firmware) == helpers.expected_layer_count(20.0)
    assert moves.predicted() == moves.extrusions() > 5000  # every extrusion has the engine's colour
    in_force = colour_in_force(text)
    changing = 0
    for layer, theirs in firmware.items():
        xy, amount, _ = moves.layers[layer].arrays()
        assert numpy.allclose(xy, [end for end, _ in theirs], atol=1e-9), layer
        assert numpy.allclose(amount, [total for _, total in theirs], atol=1e-9), layer
        expected, pointer = [], 0
        for (x, y), _ in theirs:  # the firmware's extrusions are a subsequence of the layer's X/Y moves
            while in_force[layer][pointer][:2] != (x, y):
                pointer += 1
            expected.append(in_force[layer][pointer][2])
            pointer += 1
        assert move_hex(moves, layer) == expected, layer
        changing += len(set(expected)) > 1
    if chamber:
        assert changing > 10, changing  # the chamber's colour drifts inside layers


def test_a_yellow_to_blue_gradient_is_green_in_the_middle(cube, tmp_path, report):
    """The layer whose commanded mix is 50:50 is coloured as `mixengine mix` predicts for 0.5:0.5: green (the
    pigments), not the grey of a linear-light blend of yellow and blue."""
    path = slice_cube(cube, tmp_path / "g.gcode", "mixing_mode=gradient", "mixing_gradient_start=20",
                      "mixing_gradient_end=80", f"mixing_channel_colors={YELLOW_BLUE}")
    moves = MixGCode.read([path.read_text()], "eb_axes")
    totals = read_mixing_gcode(path, "eb_axes").layer_totals()
    half = [layer for layer, (_, (a, b)) in totals.items() if abs(b / (a + b) - 0.5) < 1e-3]
    assert half, "no layer at 50:50"
    expected = predicted_colour(YELLOW_BLUE, "0.5:0.5")
    assert green(hex_rgb(expected)), expected
    for layer in half:
        assert set(move_hex(moves, layer)) == {expected}, layer
    bottom, top = move_hex(moves, min(totals)), move_hex(moves, max(totals))
    assert set(bottom) == {predicted_colour(YELLOW_BLUE, "1:0")}
    assert set(top) == {predicted_colour(YELLOW_BLUE, "0:1")}
    report(f"yellow-to-blue gradient: layers {half} at 50:50 are {expected}; bottom {bottom[0]}, top {top[0]}")


@pytest.mark.parametrize("dialect", ["marlin_m165", "rrf_colon"])
def test_five_channels_along_stops(cube, tmp_path, dialect):
    path = slice_cube(cube, tmp_path / "g.gcode", "mixing_mode=gradient", f"mixing_dialect={dialect}",
                      "mixing_channels=5", f"mixing_gradient_stops={FIVE_STOPS}", f"mixing_channel_colors={CMYKW}")
    moves = MixGCode.read([path.read_text()], dialect)
    totals = read_mixing_gcode(path, dialect, channels=5).layer_totals()
    counts = {}
    for m in read_mixing_gcode(path, dialect, channels=5).extrusions():
        counts[m.layer] = counts.get(m.layer, 0) + 1
    assert {i: len(moves.layers[i].xy) for i in moves.order if moves.layers[i].xy} == counts
    assert moves.predicted() == moves.extrusions()
    # around 50 % only channel C (yellow) is printed: coloured as `mixengine mix` predicts for C alone
    only_c = [layer for layer, (_, amounts) in totals.items() if amounts[2] > 0.999 * sum(amounts)]
    assert only_c
    expected = predicted_colour(CMYKW, "0:0:1:0:0")
    for layer in only_c:
        assert set(move_hex(moves, layer)) == {expected}, layer


def test_dual_mode_gives_each_object_its_predicted_colour(tmp_path):
    left, right = box_stl(tmp_path / "left.stl", 10, 10, 10), box_stl(tmp_path / "right.stl", 10, 10, 10)
    out = tmp_path / "dual.gcode"
    proc = helpers.mixengine("slice", "-s", "mixing_mode=dual", "-s", "mixing_dialect=marlin_m163",
                             "-s", f"mixing_channel_colors={YELLOW_BLUE}",
                             "-l", left, "-s", "mesh_position_x=-15", "-s", "mixing_ratio=0.25:0.75",
                             "-l", right, "-s", "mesh_position_x=15", "-s", "mixing_ratio=0.9:0.1", "-o", out)
    assert proc.returncode == 0, proc.stderr
    moves = MixGCode.read([out.read_text()], "marlin_m163")
    left_colour, right_colour = predicted_colour(YELLOW_BLUE, "0.25:0.75"), predicted_colour(YELLOW_BLUE, "0.9:0.1")
    assert left_colour != right_colour
    centre_x = numpy.mean([x for i in moves.order for x, _ in moves.layers[i].xy])
    for layer_id in moves.order[1:]:  # above the first layer's skirt
        xy = moves.layers[layer_id].arrays()[0]
        colours = numpy.array(move_hex(moves, layer_id))
        left_side = xy[:, 0] < centre_x
        assert set(colours[left_side]) == {left_colour}, layer_id
        assert set(colours[~left_side]) == {right_colour}, layer_id


def test_channel_colours_of_the_legend():
    rgb = MixColours.channelColours("#000000,#ffffff,#zz0000", 3, "#f2c500,#e0408a,#00a3e0")
    assert numpy.array_equal(rgb[:2], [[0, 0, 0], [1, 1, 1]])
    assert numpy.allclose(rgb[2], [0, 0xa3 / 255, 0xe0 / 255])  # a malformed colour falls back to the default
    assert numpy.allclose(MixColours.channelColours("", 2, ""), 0.5)  # neither: grey


# ---- the layer view ----------------------------------------------------------------------------------------
class Polygon:
    """What LayerRecolour reads of Cura's LayerPolygon: types (n, 1) and points (n + 1, 3) in the scene
    frame (x, layer height, -y), as ProcessSlicedLayersJob builds them."""

    def __init__(self, segment, height_mm):
        self.types = numpy.array(segment["line_types"], dtype=numpy.uint8).reshape(-1, 1)
        xy = numpy.array(segment["xy"], dtype=numpy.float32)
        self.data = numpy.column_stack((xy[:, 0], numpy.full(len(xy), height_mm), -xy[:, 1])).astype(numpy.float32)


class Layer:
    def __init__(self, polygons):
        self.polygons = polygons


def cura_vertex_count(polygon):
    """LayerPolygon.buildCache: every line's end point, plus its start point where the type changes."""
    types = polygon.types.reshape(-1)
    return len(types) + 1 + int((types[1:] != types[:-1]).sum()) if len(types) else 0


def vertex_lines(polygon):
    """For each vertex LayerDataBuilder makes of `polygon`: the index of its line (Cura's vertex rule)."""
    types = polygon.types.reshape(-1)
    needed = numpy.ones((len(types), 2), dtype=bool)
    needed[1:, 0] = types[1:] != types[:-1]
    return numpy.repeat(numpy.arange(len(types)), 2)[needed.ravel()]


def hand_polygon(types, xy, height_mm):
    return Polygon({"line_types": types, "xy": xy}, height_mm)


CURA_RGBA = numpy.array([0.2, 0.4, 0.6, 1.0], dtype=numpy.float32)  # the extruder's material colour


def test_layer_view_lines_take_the_written_colours_exactly():
    """EB_CHUNKS drawn as Cura would: every extrusion line in the colour written for its move, to the last bit
    of the float32 attribute; travel, and lines whose move has no predicted colour, keep Cura's."""
    layer_0 = [(0, 0), (10, 0), (10, 10), (20, 10), (20, 20), (30, 20)]
    layers = {0: Layer([hand_polygon([1, 1, 8, 1, 1], layer_0, 0.3)]),
              1: Layer([hand_polygon([1, 1, 1], [(30, 20), (30, 30), (0, 30), (0, 0)], 0.4)])}
    moves = MixGCode.read(EB_CHUNKS, "eb_axes")
    vertices = sum(cura_vertex_count(p) for layer in layers.values() for p in layer.polygons)
    cura = numpy.tile(CURA_RGBA, (vertices, 1))
    out = LayerRecolour.recolour(layers, cura, moves, moves.moveColours(), MixGCode.viewLayerIds(moves))
    assert (out.lines, out.matched, out.coloured) == (7, 7, 5)
    yellow, green_, blue = (numpy.float32(v) for v in ([1, 1, 0], [3 / 255, 0x8b / 255, 0x55 / 255], [0, 0, 1]))
    keep = CURA_RGBA[:3]
    expected_lines = [[keep, yellow, keep, green_, green_], [green_, blue, keep]]
    start = 0
    for number, want in zip(sorted(layers), expected_lines):
        polygon = layers[number].polygons[0]
        lines_of = vertex_lines(polygon)
        block = out.colours[start:start + len(lines_of)]
        assert numpy.array_equal(block[:, :3], numpy.array(want, dtype=numpy.float32)[lines_of]), number
        assert numpy.array_equal(block[:, 3], numpy.ones(len(lines_of), dtype=numpy.float32))  # alpha kept
        start += len(lines_of)
    assert start == vertices


@pytest.fixture(scope="module")
def socket_slice(engine, cube, tmp_path_factory):
    # an ideal chamber (the profile's estimate is 30 mm³): each layer of the gradient in one colour
    global_settings, extruders = resolved_settings("mixengine_makerpi_m2030x", "mixing_mode=gradient",
                                                   "mixing_gradient_start=20", "mixing_gradient_end=80",
                                                   f"mixing_channel_colors={YELLOW_BLUE}", "mixing_chamber_volume=0")
    result = slice_over_socket(engine, tmp_path_factory.mktemp("socket"), global_settings, extruders,
                               [one_object(cube)], raw_layers=True)
    assert result["exit_code"] == 0 and result["finished"]
    return result, global_settings


def layer_view(result):
    """{abs layer number: Layer} numbered as Cura 4.13's ProcessSlicedLayersJob numbers the layers it receives:
    from the lowest id, and the layers at and above 0 right after the negative (raft) ones."""
    messages = [m for m in result["layers"] if m["segments"]]
    first = min(m["id"] for m in messages)
    negative = sum(1 for m in messages if m["id"] < 0)
    number = {m["id"]: (m["id"] + negative if m["id"] >= 0 and negative else m["id"] - first) for m in messages}
    return {number[m["id"]]: Layer([Polygon(s, m["height"] / 1000) for s in m["segments"]]) for m in messages}


def view_colours(layers, colours):
    """{abs layer number: (extrusion vertex colours (k, 4), travel vertex colours (t, 4))}."""
    out, start = {}, 0
    for number in sorted(layers):
        extrusion, travel = [], []
        for polygon in layers[number].polygons:
            lines_of = vertex_lines(polygon)
            block = colours[start:start + len(lines_of)]
            jump = numpy.isin(polygon.types.reshape(-1)[lines_of], LayerRecolour.JUMP_TYPES)
            extrusion.append(block[~jump])
            travel.append(block[jump])
            start += len(lines_of)
        out[number] = (numpy.concatenate(extrusion), numpy.concatenate(travel))
    assert start == len(colours)
    return out


def test_every_line_of_the_layer_view_gets_the_predicted_colour_of_its_gcode_move(socket_slice, report):
    """The layer view of a yellow-to-blue gradient built from the engine's LayerOptimized messages: every
    extrusion line in a colour the engine wrote for that layer (exactly, as float32 of #rrggbb), travel in
    Cura's; the bottom yellow's prediction, the top blue's, the 50:50 layers green."""
    result, settings = socket_slice
    layers = layer_view(result)
    vertices = sum(cura_vertex_count(p) for layer in layers.values() for p in layer.polygons)
    cura = numpy.tile(CURA_RGBA, (vertices, 1))
    moves = MixGCode.read(result["gcode_list"], "eb_axes")
    ids = MixGCode.viewLayerIds(moves)
    out = LayerRecolour.recolour(layers, cura, moves, moves.moveColours(), ids)
    assert out is not None and out.coloured == out.matched == out.lines > 5000
    assert numpy.array_equal(cura, numpy.tile(CURA_RGBA, (vertices, 1)))  # the input is not changed
    written = written_colours("".join(result["gcode_list"]))
    as_float32 = {h: numpy.float32(hex_rgb(h)) for h in set(c for w in written.values() for c in w)}
    shown = view_colours(layers, out.colours)
    for number, (extrusion, travel) in shown.items():
        assert (travel == CURA_RGBA).all(), number
        allowed = numpy.array([as_float32[h] for h in written[ids[number]]])
        exact = (extrusion[:, None, :3] == allowed[None]).all(axis=2).any(axis=1)
        assert exact.all(), (number, written[ids[number]])
    bottom, top = shown[min(shown)][0][:, :3], shown[max(shown)][0][:, :3]
    assert (bottom == as_float32[predicted_colour(YELLOW_BLUE, "1:0")]).all()
    assert (top == as_float32[predicted_colour(YELLOW_BLUE, "0:1")]).all()
    half = predicted_colour(YELLOW_BLUE, "0.5:0.5")
    middle = [n for n in shown if written[ids[n]] == [half]]
    assert middle and green(hex_rgb(half)), (middle, half)
    for number in middle:
        assert (shown[number][0][:, :3] == as_float32[half]).all(), number
    report(f"layer view of the yellow-to-blue cube: layers {middle} drawn {half}, every one of {out.lines} lines "
           "in its move's predicted colour")
    # a vertex list that does not follow Cura's rule is left alone
    assert LayerRecolour.recolour(layers, cura[:-1], moves, moves.moveColours(), ids) is None


def test_gcode_without_predicted_colours_leaves_cura_colours(socket_slice):
    """An engine before issue 26 writes no ;PREDICTED_COLOR: the plugin has no colour to show and invents none."""
    result, _ = socket_slice
    old = [re.sub(r"^;PREDICTED_COLOR:.*\n", "", chunk, flags=re.M) for chunk in result["gcode_list"]]
    assert old != result["gcode_list"]
    moves = MixGCode.read(old, "eb_axes")
    assert moves.extrusions() > 5000 and moves.predicted() == 0 and moves.colours == []
    assert all(numpy.isnan(rgb).all() for rgb in moves.moveColours().values())
    layers = layer_view(result)
    vertices = sum(cura_vertex_count(p) for layer in layers.values() for p in layer.polygons)
    cura = numpy.tile(CURA_RGBA, (vertices, 1))
    out = LayerRecolour.recolour(layers, cura, moves, moves.moveColours(), MixGCode.viewLayerIds(moves))
    assert out.coloured == 0 and out.matched == out.lines > 5000
    assert numpy.array_equal(out.colours, cura)


CURA_PREVIEW_SCRIPT = r"""
import importlib, json, sys, types
import numpy
plugin_dir, chunks, mode = json.loads(sys.stdin.read())
package = types.ModuleType("mixengine_plugin")  # the plugin's modules without its __init__ (no Cura app here)
package.__path__ = [plugin_dir]
sys.modules["mixengine_plugin"] = package
MixPreview = importlib.import_module("mixengine_plugin.MixPreview")
from cura import LayerDataBuilder, LayerPolygon
LayerPolygon.LayerPolygon._LayerPolygon__color_map = numpy.tile([0.5, 0.5, 0.5, 1.0], (12, 1))  # no theme


class Signal:
    def connect(self, *args):
        pass


class Stack:
    def getProperty(self, key, prop):
        return {"mixing_mode": mode, "mixing_dialect": "eb_axes", "mixing_channels": 2,
                "mixing_channel_colors": "#ffff00,#0000ff"}.get(key)


class App:
    def __init__(self):
        self.prefs = types.SimpleNamespace(preferenceChanged=Signal(), getValue=lambda key: 0)
        self.scene = types.SimpleNamespace(gcode_dict={0: chunks})
        self.controller = types.SimpleNamespace(activeStageChanged=Signal(), activeViewChanged=Signal(),
                                                getScene=lambda: self.scene, getActiveStage=lambda: None,
                                                getActiveView=lambda: None)
    def getPreferences(self): return self.prefs
    def getController(self): return self.controller
    def getBackend(self): return types.SimpleNamespace(backendStateChange=Signal())
    def getGlobalContainerStack(self): return Stack()
    def callLater(self, f, *args): f(*args)


class ProcessSlicedLayersJob:  # the caller MixPreview recognises, as Cura's job builds the layer view
    def __init__(self, builder):
        self.builder = builder
    def getBuildPlate(self):
        return 0
    def run(self):
        return self.builder.build(numpy.array([[0.2, 0.4, 0.6, 1.0]], dtype=numpy.float32))


preview = MixPreview.MixPreview(App(), "")
preview.install()
builder = LayerDataBuilder.LayerDataBuilder()
HAND_LAYERS = [([1, 1, 8, 1, 1], [(0, 0), (10, 0), (10, 10), (20, 10), (20, 20), (30, 20)], 0.3),
               ([1, 1, 1], [(30, 20), (30, 30), (0, 30), (0, 0)], 0.4)]
for number, (types_, xy, height) in enumerate(HAND_LAYERS):
    builder.addLayer(number)
    builder.setLayerHeight(number, height)
    points = numpy.array([(x, height, -y) for x, y in xy], dtype=numpy.float32)
    ones = numpy.ones((len(types_), 1), dtype=numpy.float32)
    polygon = LayerPolygon.LayerPolygon(0, numpy.array(types_, dtype=numpy.uint8).reshape(-1, 1), points, 0.4 * ones,
                                        0.1 * ones, 30 * ones)
    polygon.buildCache()
    builder.getLayer(number).polygons.append(polygon)
layer_data = ProcessSlicedLayersJob(builder).run()
colours = layer_data.getAttribute("colors")["value"]
print(json.dumps({"last": preview.last, "colours": colours.tolist(), "legend": preview.legend.shown,
                  "channels": preview.legend.channels}))
"""


def cura_preview(chunks, mode="gradient"):
    """MixPreview in Cura's own Python: Cura's LayerDataBuilder (wrapped by MixPreview.install) builds the layer
    view of the EB_CHUNKS geometry as ProcessSlicedLayersJob would, from `chunks` as scene.gcode_dict holds them."""
    proc = subprocess.run(["/usr/bin/python3", "-c", CURA_PREVIEW_SCRIPT], capture_output=True, text=True,
                          input=json.dumps([str(helpers.REPO / "plugin"), chunks, mode]), timeout=120)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout.strip().splitlines()[-1])


def test_cura_layer_view_shows_the_predicted_colours():
    out = cura_preview(EB_CHUNKS)
    last = out["last"]
    assert last["state"] == "coloured" and (last["lines"], last["matched"], last["coloured"]) == (7, 7, 5), last
    assert (last["moves"], last["predicted_moves"], last["distinct_colours"]) == (7, 5, 3), last
    assert out["legend"] is False  # not in the Preview stage here
    assert last["channels"] == ["#ffff00", "#0000ff"]
    colours = numpy.array(out["colours"], dtype=numpy.float32)
    cura = CURA_RGBA[:3]
    yellow, green_, blue = (numpy.float32(v) for v in ([1, 1, 0], [3 / 255, 0x8b / 255, 0x55 / 255], [0, 0, 1]))
    # vertices by Cura's rule: layer 0 lines of types 1, 1, 8, 1, 1 -> 2 + 1 + 2 + 2 + 1 vertices; layer 1 lines
    # 1, 1, 1 -> 2 + 1 + 1
    per_vertex = [cura, cura, yellow, None, None, green_, green_, green_, green_, green_, blue, cura]
    assert len(colours) == len(per_vertex)
    for i, want in enumerate(per_vertex):
        if want is not None:
            assert numpy.array_equal(colours[i, :3], want), (i, colours[i])
    assert (colours[:, 3] == 1).all()
    # the travel line's two vertices keep Cura's own colour for travel (the line-type colour, 0.5 grey here)
    assert numpy.array_equal(colours[3:5, :3], numpy.full((2, 3), 0.5, dtype=numpy.float32))


def test_cura_layer_view_without_predicted_colours_is_left_alone():
    """G-code of an engine before issue 26: Cura's colours stay, and the state says why."""
    old = [re.sub(r"^;PREDICTED_COLOR:.*\n", "", chunk, flags=re.M) for chunk in EB_CHUNKS]
    out = cura_preview(old)
    assert out["last"]["state"] == "no predicted colour in the G-code; colours left alone", out["last"]
    colours = numpy.array(out["colours"], dtype=numpy.float32)
    assert numpy.array_equal(colours[[0, 1, 2, 5, 6, 7, 8, 9, 10, 11], :3], numpy.tile(CURA_RGBA[:3], (10, 1)))
    assert cura_preview(EB_CHUNKS, mode="single")["last"]["state"] == "not a mixing slice"


def test_view_layer_ids_follow_cura_under_a_raft():
    """Under a raft CuraEngine writes ;LAYER:-8..-5 and then 0..: Cura's layer view numbers them 0..3 and 4..,
    so the ids the raft's air gap leaves out (-4..-1) take no place, and a print without a raft starts at 0."""
    chunks = [f";LAYER:{i}\nG1 X{10 + i} Y10 E{i + 20}\nG1 X{10 + i} Y20 E{i + 21} B0.1\n" for i in (-8, -7, -6, -5, 0, 1, 2)]
    ids = MixGCode.viewLayerIds(MixGCode.read(chunks, "eb_axes"))
    assert ids == {0: -8, 1: -7, 2: -6, 3: -5, 4: 0, 5: 1, 6: 2}
    plain = MixGCode.viewLayerIds(MixGCode.read(chunks[4:], "eb_axes"))
    assert plain == {0: 0, 1: 1, 2: 2}


def test_matching_skips_moves_the_layer_view_does_not_show():
    lines = numpy.array([[0, 0], [1, 0], [2, 0], [9, 9]])
    moves = numpy.array([[0, 0], [0.5, 0], [1, 0], [2, 0.004]])
    assert LayerRecolour.matchLayer(lines, moves).tolist() == [0, 2, 3, -1]
    assert LayerRecolour.matchLayer(moves, moves).tolist() == [0, 1, 2, 3]


# ---- settings MixEngine does not act on -----------------------------------------------------------------------
def test_not_honoured_entries_from_the_shared_list():
    entries = NotHonoured.load(str(helpers.REPO / "settings"))
    # the engine's list, read as it is (a key listed whole, and one listed for some values)
    assert "wireframe_enabled" in entries and entries["wireframe_strategy"]["values"] == ["retract", "knot"]
    found = [("wireframe_strategy", "retract", "compensate", "global"),
             ("wireframe_enabled", True, False, "global"),
             ("wireframe_enabled", "True", "False", "cube.stl"), ("magic_spiralize", False, False, "global"),
             ("wireframe_strategy", "compensate", "compensate", "global"), ("not_listed", 1, 2, "global")]
    rows = NotHonoured.offending(entries, found)
    assert [(r[0], r[1]) for r in rows] == [("wireframe_enabled", True), ("wireframe_strategy", "retract")]
    assert rows[0][3] == ["global", "cube.stl"]  # one row per key and value, every place named
    text = NotHonoured.messageText(rows, label={"wireframe_strategy": "Strategy",
                                                "wireframe_enabled": "Wire Printing"}.get)
    assert "Strategy = retract: wire printing is not built" in text
    assert "Wire Printing = True (global, cube.stl): wire printing is not built" in text
    assert NotHonoured.offending(entries, [("wireframe_enabled", False, False, "global")]) == []
    # a listed value that is the machine's own default is not the user's request (the engine's rule too)
    assert NotHonoured.offending(entries, [("wireframe_strategy", "retract", "retract", "global")]) == []
