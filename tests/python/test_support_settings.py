"""Normal support's detail settings against Debian's CuraEngine 4.13 (issue 19), on side_by_side's "parity" model
(the Ender-3 with support_enable, every resolved value given to both engines): support_brim_enable,
support_skip_some_zags, gradual_support_infill_steps and support_infill_sparse_thickness change both engines'
prints the same way; on the "shelf" model the interface, zigzag, conical, tree and raft surface settings move both
prints by a similar amount (SIZE_CASES). Figures are read from the G-code (parity.signature: E moves, lengths, ;TYPE: markers).
"""
import re

import pytest

import parity
import side_by_side as sbs

MODEL = "parity"
SUPPORT = {"support_enable": "True"}


def _gcodes(overrides):
    settings = dict(SUPPORT, **overrides)
    mix, cura = sbs.run_mixengine(MODEL, settings), sbs.run_cura(MODEL, settings)
    assert mix.rc == 0 and cura.rc == 0, (mix.stderr, cura.stderr)
    return mix.gcode, cura.gcode


def _figures(path):
    return parity.signature(path)["figures"]


def _layer0_extrusion_by_type(path):
    """{;TYPE: name: extruded XY length in mm} on layer 0."""
    text = path.read_text()
    layer = text[text.index(";LAYER:0\n"):text.index(";LAYER:1\n")]
    lengths, kind, x, y, e = {}, None, 0.0, 0.0, 0.0
    for line in layer.splitlines():
        if line.startswith(";TYPE:"):
            kind = line[6:]
        words = dict(re.findall(r"([XYE])(-?[0-9.]+)", line.split(";")[0]))
        if not line.startswith(("G0", "G1")):
            continue
        nx, ny, ne = float(words.get("X", x)), float(words.get("Y", y)), float(words.get("E", e))
        if ne > e and (nx, ny) != (x, y):
            lengths[kind] = lengths.get(kind, 0.0) + ((nx - x) ** 2 + (ny - y) ** 2) ** 0.5
        x, y, e = nx, ny, ne
    return lengths


def test_support_brim_replaces_the_first_layers_support_as_in_curaengine():
    # The Ender-3's definitions turn the support brim on; off, the first layer prints support instead.
    mix_on, cura_on = _gcodes({})
    mix_off, cura_off = _gcodes({"support_brim_enable": "False"})
    for on, off in ((mix_on, mix_off), (cura_on, cura_off)):
        with_brim, without = _layer0_extrusion_by_type(on), _layer0_extrusion_by_type(off)
        assert "SUPPORT" not in with_brim  # the brim's 10 loops fill this model's small first support area
        assert without.get("SUPPORT", 0) > 5
        assert with_brim["SKIRT"] - without["SKIRT"] > 20  # the brim loops are printed with the skirt
    # Filament goes the same way in both engines (CuraEngine −1.9 mm, MixEngine −2.3 mm when switched off).
    d_cura = _figures(cura_off)["filament"] - _figures(cura_on)["filament"]
    d_mix = _figures(mix_off)["filament"] - _figures(mix_on)["filament"]
    assert d_cura < -0.5 and d_mix < -0.5


def test_support_skip_some_zags_leaves_out_the_same_connections_as_curaengine():
    mix_base, cura_base = _gcodes({})
    mix_skip, cura_skip = _gcodes({"support_skip_some_zags": "True"})
    d_cura = _figures(cura_skip)["extrude_len"] - _figures(cura_base)["extrude_len"]
    d_mix = _figures(mix_skip)["extrude_len"] - _figures(mix_base)["extrude_len"]
    assert d_cura < -10
    assert abs(d_mix - d_cura) < 0.05 * abs(d_cura)  # measured: both −38.0 mm


def test_gradual_support_and_thicker_support_layers_print_less_as_in_curaengine():
    mix_base, cura_base = _gcodes({})
    for overrides in ({"gradual_support_infill_steps": "1"}, {"support_infill_sparse_thickness": "0.4"}):
        mix, cura = _gcodes(overrides)
        for flipped, base in ((mix, mix_base), (cura, cura_base)):
            assert _figures(flipped)["extrude_len"] - _figures(base)["extrude_len"] < -100, overrides
    # Two layers thick: the lines of every other layer carry twice the flow (E per mm doubles), laid out
    # as for a line twice as wide (farther from the edge), so the filament drops as in CuraEngine
    # (measured: both −6.37 mm).
    mix, cura = _gcodes({"support_infill_sparse_thickness": "0.4"})
    d_cura = _figures(cura)["filament"] - _figures(cura_base)["filament"]
    d_mix = _figures(mix)["filament"] - _figures(mix_base)["filament"]
    assert d_cura < -1.0
    assert abs(d_mix - d_cura) < 0.05 * abs(d_cura), (d_mix, d_cura)


# ---------------------------------------------------------------------------------------------------------
# The size of the change on the shelf (side_by_side's "shelf": wide overhangs, a bridge over a slab so that
# support stands on the model, a cantilever over the bed, a slope): each setting must move MixEngine's
# filament and extruded length the way it moves CuraEngine's, by between a third and three times as much,
# wherever CuraEngine's change passes parity.THRESHOLDS' absolute part (0.5 mm of filament, 5 mm extruded;
# the relative part would ignore every interface setting on a print this large).
SHELF = "shelf"
SIZE_CASES = [
    ({}, "support_roof_enable", "False"),
    ({}, "support_roof_pattern", "triangles"),
    ({}, "support_roof_pattern", "concentric"),
    ({}, "support_roof_pattern", "zigzag"),
    ({}, "support_bottom_pattern", "triangles"),
    ({}, "support_bottom_pattern", "concentric"),
    ({}, "support_bottom_pattern", "zigzag"),
    ({}, "support_bottom_height", "1.2"),
    ({}, "support_bottom_offset", "-0.4"),
    ({}, "support_roof_offset", "-0.4"),
    ({}, "support_connect_zigzags", "False"),
    ({"adhesion_type": "raft"}, "raft_surface_line_width", "0.6"),
    ({}, "support_conical_enabled", "True"),
    ({"support_structure": "tree"}, "support_tree_branch_distance", "1.5"),
    ({"support_structure": "tree"}, "support_tree_collision_resolution", "0.3"),
]


def _shelf_deltas(context, key, value):
    base, flipped = dict(SUPPORT, **context), dict(SUPPORT, **context, **{key: value})
    out = {}
    for engine, run in (("cura", sbs.run_cura), ("mix", sbs.run_mixengine)):
        a, b = run(SHELF, base), run(SHELF, flipped)
        assert a.rc == 0 and b.rc == 0, (a.stderr, b.stderr)
        fa, fb = _figures(a.gcode), _figures(b.gcode)
        out[engine] = {m: (fb[m] - fa[m], fa[m]) for m in ("filament", "extrude_len")}
    return out



@pytest.mark.parametrize("context,key,value", SIZE_CASES,
                         ids=[f"{c[1]}={c[2]}" for c in (getattr(c, "values", c) for c in SIZE_CASES)])
def test_support_setting_moves_the_shelf_print_as_much_as_curaengine(context, key, value):
    deltas = _shelf_deltas(context, key, value)
    clear = 0
    for metric in ("filament", "extrude_len"):
        d_cura, base = deltas["cura"][metric]
        d_mix = deltas["mix"][metric][0]
        if abs(d_cura) < parity.THRESHOLDS[metric][1]:
            continue
        clear += 1
        assert d_cura * d_mix > 0 and 1 / 3 <= d_mix / d_cura <= 3, (metric, d_cura, d_mix)
    assert clear > 0, deltas  # the shelf shows each of these settings
