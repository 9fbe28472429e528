"""Issue 17, part 1 without Cura: the plugin's reading of the mix from the G-code (plugin/MixGCode.py), the
chamber model and colours (MixColours.py), the recolouring of the layer view's vertices (LayerRecolour.py)
and the list of settings MixEngine does not act on (NotHonoured.py). The real Cura runs in
test_e2e_cura.py; here the engine's G-code is read back against mixing_gcode.py, an independent model of
each firmware, and the layer view is built from the LayerOptimized messages the engine sends over the
socket, by Cura's vertex rule (cura/LayerPolygon.py).
"""
import math
import sys

import numpy
import pytest

import helpers
from cura_socket import one_object, resolved_settings, slice_over_socket
from mixing_gcode import box_stl, read_mixing_gcode, seed_share_b

sys.path.insert(0, str(helpers.REPO / "plugin"))
import LayerRecolour  # noqa: E402
import MixColours  # noqa: E402
import MixGCode  # noqa: E402
import NotHonoured  # noqa: E402

DIALECTS = ["eb_axes", "klipper_b", "rrf_colon", "marlin_m163", "marlin_m165", "rrf_m567"]
FIVE_STOPS = "0=1:0:0:0:0; 25=0:1:0:0:0; 50=0:0:1:0:0; 75=0:0:0:0.5:0.5; 100=0:0:0:0:1"
SHARE_ROUNDING = 1e-4  # MixGCode keeps shares to 4 decimals


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("mix_preview") / "cube.stl", 20, 20, 20)


def slice_cube(cube, out, *settings):
    return helpers.slice_with(cube, out, *settings)


def layer_shares(moves):
    """{layer id: amount-weighted mix} of a MixGCode result."""
    out = {}
    for layer_id in moves.order:
        xy, mix, amount = moves.layers[layer_id].arrays()
        if len(xy):
            out[layer_id] = (moves.mixes[mix] * amount[:, None]).sum(axis=0) / amount.sum()
    return out


def model_shares(path, dialect, channels):
    """The same from the firmware model: {layer: (z, shares)} and the extrusions per layer."""
    reading = read_mixing_gcode(path, dialect, channels=channels)
    counts = {}
    for m in reading.extrusions():
        counts[m.layer] = counts.get(m.layer, 0) + 1
    return {layer: [a / sum(amounts) for a in amounts] for layer, (z, amounts) in reading.layer_totals().items()}, counts


@pytest.mark.parametrize("relative", [False, True])
@pytest.mark.parametrize("dialect", DIALECTS)
def test_mix_read_from_the_gcode_agrees_with_the_firmware_model(cube, tmp_path, dialect, relative):
    path = slice_cube(cube, tmp_path / "g.gcode", f"relative_extrusion={relative}", "mixing_mode=gradient",
                      f"mixing_dialect={dialect}", "mixing_gradient_start=20", "mixing_gradient_end=80")
    moves = MixGCode.read([path.read_text()], dialect, 2)
    ours = layer_shares(moves)
    theirs, counts = model_shares(path, dialect, 2)
    assert sorted(ours) == sorted(theirs) and len(ours) == helpers.expected_layer_count(20.0)
    for layer, shares in theirs.items():
        assert len(moves.layers[layer].xy) == counts[layer], layer
        assert ours[layer] == pytest.approx(shares, abs=SHARE_ROUNDING), layer
    assert ours[min(ours)][1] == 0 and ours[max(ours)][1] == pytest.approx(1, abs=SHARE_ROUNDING)


@pytest.mark.parametrize("dialect", ["marlin_m165", "rrf_colon"])
def test_five_channels_along_stops(cube, tmp_path, dialect):
    path = slice_cube(cube, tmp_path / "g.gcode", "mixing_mode=gradient", f"mixing_dialect={dialect}",
                      "mixing_channels=5", f"mixing_gradient_stops={FIVE_STOPS}")
    ours = layer_shares(MixGCode.read([path.read_text()], dialect, 5))
    theirs, _ = model_shares(path, dialect, 5)
    for layer, shares in theirs.items():
        assert ours[layer] == pytest.approx(shares, abs=SHARE_ROUNDING), layer
    # the middle of the cube is mostly channel C (C alone exactly at 50 %)
    middle = ours[min(ours, key=lambda layer: abs(layer - len(ours) / 2))]
    assert middle[2] > 0.9 and middle[2] == max(middle)


def test_dual_mode_gives_each_object_its_mix(tmp_path):
    left, right = box_stl(tmp_path / "left.stl", 10, 10, 10), box_stl(tmp_path / "right.stl", 10, 10, 10)
    out = tmp_path / "dual.gcode"
    proc = helpers.mixengine("slice", "-s", "mixing_mode=dual", "-s", "mixing_dialect=marlin_m163",
                             "-l", left, "-s", "mesh_position_x=-15", "-s", "mixing_ratio=0.25:0.75",
                             "-l", right, "-s", "mesh_position_x=15", "-s", "mixing_ratio=0.9:0.1", "-o", out)
    assert proc.returncode == 0, proc.stderr
    moves = MixGCode.read([out.read_text()], "marlin_m163", 2)
    centre_x = numpy.mean([x for i in moves.order for x, _ in moves.layers[i].xy])
    for layer_id in moves.order[1:]:  # above the first layer's skirt
        xy, mix, _ = moves.layers[layer_id].arrays()
        shares = moves.mixes[mix]
        left_side = xy[:, 0] < centre_x
        assert numpy.allclose(shares[left_side], [0.25, 0.75], atol=0.01), layer_id  # M163 in 1/100
        assert numpy.allclose(shares[~left_side], [0.9, 0.1], atol=0.01), layer_id


def test_chamber_model_turns_the_compensated_schedule_into_the_target(cube, tmp_path, report):
    """With mixing_chamber_volume the engine commands each mix early; what leaves the nozzle (the plugin's
    plug-flow model of the chamber) follows the height as the gradient asks. Read without the chamber,
    the same G-code would show the colour too low."""
    chamber_mm3, area = 40.0, math.pi * (2.85 / 2) ** 2  # fdmprinter's material_diameter
    path = slice_cube(cube, tmp_path / "g.gcode", "mixing_mode=gradient", "mixing_gradient_start=20",
                      "mixing_gradient_end=80", f"mixing_chamber_volume={chamber_mm3}")
    moves = MixGCode.read([path.read_text()], "eb_axes", 2)
    index = numpy.concatenate([moves.layers[i].arrays()[1] for i in moves.order])
    amount = numpy.concatenate([moves.layers[i].arrays()[2] for i in moves.order])
    z = numpy.array([m.z for m in read_mixing_gcode(path, "eb_axes").extrusions()])
    assert len(z) == len(index)
    target = numpy.array([seed_share_b(20, 80, 100 * h / 20) for h in z])
    commanded = moves.mixes[index][:, 1]
    delivered = MixColours.delayedMixes(moves.mixes[index], amount * area, chamber_mm3)[:, 1]
    step = 0.1 / 12  # one 0.1 mm layer of the 12 mm gradient
    assert numpy.abs(delivered - target).mean() < 0.1 * step
    assert numpy.quantile(numpy.abs(delivered - target), 0.99) <= step + 2 * SHARE_ROUNDING
    assert numpy.abs(commanded - target).mean() > step  # the shift is real: the commands run ahead
    report(f"chamber model: |delivered - target| mean {numpy.abs(delivered - target).mean():.5f}, "
           f"commanded {numpy.abs(commanded - target).mean():.5f}")


def test_delayed_mixes_by_hand():
    mixes = numpy.array([[1.0, 0.0], [0.0, 1.0], [0.0, 1.0], [1.0, 0.0]])
    volumes = numpy.array([10.0, 10.0, 10.0, 10.0])
    assert numpy.allclose(MixColours.delayedMixes(mixes, volumes, 0), mixes)
    # a 5 mm3 chamber: each extrusion is half its own mix, half the one before (the first: the chamber starts
    # full of the first mix)
    assert numpy.allclose(MixColours.delayedMixes(mixes, volumes, 5.0)[:, 1], [0, 0.5, 1, 0.5])
    # 10 mm3: exactly the previous extrusion's mix
    assert numpy.allclose(MixColours.delayedMixes(mixes, volumes, 10.0)[:, 1], [0, 0, 1, 1])


def test_mix_colours_blend_in_linear_light_like_the_engine_preview():
    rgb = MixColours.channelColours("#000000,#ffffff,#zz0000", 3, "#f2c500,#e0408a,#00a3e0")
    assert numpy.allclose(rgb[2], [0, 0xa3 / 255, 0xe0 / 255])  # a malformed colour falls back to the default
    colours = MixColours.mixColours(numpy.array([[1, 0, 0], [0, 1, 0], [0.5, 0.5, 0]]), rgb)
    assert numpy.allclose(colours[0], 0) and numpy.allclose(colours[1], 1)
    assert numpy.allclose(colours[2], 0.7354, atol=1e-3)  # sRGB of linear 0.5, as engine/mixing/Preview.cpp


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


@pytest.fixture(scope="module")
def socket_slice(engine, cube, tmp_path_factory):
    global_settings, extruders = resolved_settings("mixengine_makerpi_m2030x", "mixing_mode=gradient",
                                                   "mixing_gradient_start=20", "mixing_gradient_end=80",
                                                   "mixing_channel_colors=#00b4c8,#e6007e")
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


def test_every_line_of_the_layer_view_gets_the_mix_of_its_gcode_move(socket_slice):
    result, settings = socket_slice
    layers = layer_view(result)
    vertices = sum(cura_vertex_count(p) for layer in layers.values() for p in layer.polygons)
    cura_colours = numpy.tile(numpy.array([[1.0, 0.8, 0.1, 1.0]], dtype=numpy.float32), (vertices, 1))
    moves = MixGCode.read(result["gcode_list"], "eb_axes", 2)
    channel_rgb = MixColours.channelColours(settings["mixing_channel_colors"], 2, "")
    move_rgb = {i: MixColours.mixColours(moves.mixes[moves.layers[i].arrays()[1]], channel_rgb) for i in moves.order}
    out = LayerRecolour.recolour(layers, cura_colours, moves, move_rgb, MixGCode.viewLayerIds(moves))
    assert out is not None and out.matched == out.lines > 5000
    assert numpy.array_equal(cura_colours[:, 0], numpy.full(vertices, 1.0, dtype=numpy.float32))  # input untouched
    # per layer: the extrusion vertices carry the layer's colour, travel keeps Cura's
    start = 0
    for number in sorted(layers):
        for polygon in layers[number].polygons:
            types = polygon.types.reshape(-1)
            count = cura_vertex_count(polygon)
            block = out.colours[start:start + count]
            needed = numpy.ones((len(types), 2), dtype=bool)
            needed[1:, 0] = types[1:] != types[:-1]
            line_of_vertex = numpy.repeat(numpy.arange(len(types)), 2)[needed.ravel()]
            travel = numpy.isin(types[line_of_vertex], LayerRecolour.JUMP_TYPES)
            assert numpy.allclose(block[travel], [1.0, 0.8, 0.1, 1.0])
            if number == 0:
                assert numpy.allclose(block[~travel, :3], channel_rgb[0], atol=1e-6)  # channel A at the bottom
            if number == max(layers):
                assert numpy.allclose(block[~travel, :3], channel_rgb[1], atol=1e-6)  # B at the top
            start += count
    assert start == vertices
    # a vertex list that does not follow Cura's rule is left alone
    assert LayerRecolour.recolour(layers, cura_colours[:-1], moves, move_rgb, MixGCode.viewLayerIds(moves)) is None


def test_view_layer_ids_follow_cura_under_a_raft():
    """Under a raft CuraEngine writes ;LAYER:-8..-5 and then 0..: Cura's layer view numbers them 0..3 and 4..,
    so the ids the raft's air gap leaves out (-4..-1) take no place, and a print without a raft starts at 0."""
    chunks = [f";LAYER:{i}\nG1 X{10 + i} Y10 E{i + 20}\nG1 X{10 + i} Y20 E{i + 21} B0.1\n" for i in (-8, -7, -6, -5, 0, 1, 2)]
    ids = MixGCode.viewLayerIds(MixGCode.read(chunks, "eb_axes", 2))
    assert ids == {0: -8, 1: -7, 2: -6, 3: -5, 4: 0, 5: 1, 6: 2}
    plain = MixGCode.viewLayerIds(MixGCode.read(chunks[4:], "eb_axes", 2))
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
    assert "wireframe_enabled" in entries and "wireframe_strategy" in entries
    found = [("wireframe_strategy", "retract", "compensate", "global"),
             ("wireframe_enabled", True, False, "global"),
             ("wireframe_enabled", "True", "False", "cube.stl"), ("magic_spiralize", False, False, "global"),
             ("wireframe_strategy", "knot", "compensate", "global"), ("not_listed", 1, 2, "global")]
    rows = NotHonoured.offending(entries, found)
    assert [(r[0], r[1]) for r in rows] == [("wireframe_enabled", True), ("wireframe_strategy", "retract")]
    assert rows[0][3] == ["global", "cube.stl"]  # one row per key and value, every place named
    text = NotHonoured.messageText(rows, label={"wireframe_strategy": "WP Strategy",
                                                "wireframe_enabled": "Wire Printing"}.get)
    assert "WP Strategy = retract: wire printing is not built" in text
    assert "Wire Printing = True (global, cube.stl): wire printing is not built" in text
    assert NotHonoured.offending(entries, [("wireframe_enabled", False, False, "global")]) == []
    # a listed value that is the machine's own default is not the user's request (the engine's rule too)
    assert NotHonoured.offending(entries, [("wireframe_strategy", "retract", "retract", "global")]) == []
