"""Part order as CuraEngine 4.13: on a layer with several separate parts of one mesh, each part is printed whole
(walls, infill, skin) before the next, and the parts come in CuraEngine's z seam order (with the Ender-3's
z_seam_type "back" the part whose seam is nearest to the seam position first, on every layer).

The model is side_by_side.py's shelf: a slab, then two pillars (left at x < 0, right at x > 0 around the bed's
middle), then the deck. On the pillar layers the G-code is read here (a plain parse of G0/G1, independent of
gcode_model.py) and every extruding move is put in the left or the right part by its end point; per layer the
test compares with CuraEngine's G-code which part is printed first and how often printing crosses from one part
to the other. Cases: the plain print (the right pillar first), the seam moved to the bed's front-left corner
(z_seam_x/_y 0: the left pillar first) and z_seam_type "shortest" (parts from the head's position).
"""
import re

import pytest

import side_by_side as sbs

MODEL = "shelf"
PILLAR_LAYERS = range(12, 55)
CASES = {
    "plain": {},
    "seam_front_left": {"z_seam_x": "0", "z_seam_y": "0"},
    "seam_shortest": {"z_seam_type": "shortest"},
}  # 2.4 .. 11 mm: above the slab (2 mm), below the deck (12 mm)
_WORD = re.compile(r"([XYEZ])(-?\d+\.?\d*)")


def part_sequence(gcode_path, middle_x):
    """{layer: [side of each extruding move, 'L' or 'R', in print order]} for the mesh's moves."""
    layers, layer, in_mesh = {}, None, False
    x = y = e = 0.0
    for line in open(gcode_path):
        if line.startswith(";LAYER:"):
            layer = int(line[7:])
            layers[layer] = []
        elif line.startswith(";MESH:"):
            in_mesh = not line.startswith(";MESH:NONMESH")
        code = line.split(";", 1)[0].split()
        if not code:
            continue
        words = dict((k, float(v)) for k, v in _WORD.findall(line.split(";", 1)[0]))
        if code[0] == "G92":
            e = words.get("E", e)
        elif code[0] in ("G0", "G1"):
            x, y = words.get("X", x), words.get("Y", y)
            new_e = words.get("E", e)
            if new_e > e + 1e-6 and layer is not None and in_mesh and ("X" in words or "Y" in words):
                layers[layer].append("L" if x < middle_x else "R")
            e = new_e
    return layers


def crossings(sides):
    return sum(1 for a, b in zip(sides, sides[1:]) if a != b)


@pytest.fixture(scope="module", params=list(CASES))
def sequences(request):
    overrides = CASES[request.param]
    cura = sbs.run_cura(MODEL, overrides)
    mix = sbs.run_mixengine(MODEL, overrides)
    assert cura.rc == 0 and mix.rc == 0, (cura.stderr, mix.stderr)
    (middle_x, _), _, _ = sbs.machine(overrides)
    return part_sequence(cura.gcode, middle_x), part_sequence(mix.gcode, middle_x)


def test_each_part_printed_whole(sequences):
    cura, mix = sequences
    for layer in PILLAR_LAYERS:
        assert set(cura[layer]) == {"L", "R"}, f"layer {layer}: the shelf should have two pillars"
        assert crossings(cura[layer]) == 1, f"layer {layer}: CuraEngine prints each part whole"
        assert crossings(mix[layer]) == crossings(cura[layer]), f"layer {layer}: crossings between parts"


def test_first_part_as_cura(sequences):
    cura, mix = sequences
    firsts = [(layer, cura[layer][0], mix[layer][0]) for layer in PILLAR_LAYERS]
    assert [m for _, _, m in firsts] == [c for _, c, _ in firsts], firsts
