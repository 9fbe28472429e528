"""Issue 15: adaptive layers, fuzzy skin, make overhang printable and mold with colour mixing, and fuzzy skin's
reproducibility.

On the MakerPi (E and B axes) with a gradient over the tee's height (side_by_side.py), each of these switched on: every move's
E + B equals the single-colour E of the same slice (read back with mixing_gcode.py, a model of the firmware),
move for move, and B's share still grows with the height. Fuzzy skin draws its points from a seeded generator:
two slices give the same G-code, and the outer wall really is rougher (longer) than without it.
"""
import pytest

import helpers
import side_by_side as sbs
from mixing_gcode import read_mixing_gcode

MODES = {
    "adaptive": ["adaptive_layer_height_enabled=True"],
    "fuzzy": ["magic_fuzzy_skin_enabled=True"],
    "conical": ["conical_overhang_enabled=True"],
    "mold": ["mold_enabled=True", "mold_width=3"],
}
GRADIENT = ["mixing_mode=gradient", "mixing_gradient_start=0", "mixing_gradient_end=100"]


def _slice(engine, model, out, settings, threads=2):
    args = [engine, "slice", f"-m{threads}", "-j", "mixengine_makerpi_m2030x", "-s", "layer_height=0.2"]
    for s in settings:
        args += ["-s", s]
    proc = helpers.run([*args, "-l", model, "-o", out])
    assert proc.returncode == 0, proc.stderr
    return proc


@pytest.mark.parametrize("mode", list(MODES))
def test_mixing_adds_up_to_the_single_colour_extrusion(engine, tmp_path, mode):
    model = sbs.model_path("tee")  # the T profile: 90-degree overhangs under its bar (side_by_side.py)
    single, mixed = tmp_path / "single.gcode", tmp_path / "mixed.gcode"
    proc = _slice(engine, model, single, MODES[mode])
    assert "has no effect in MixEngine yet" not in proc.stderr, proc.stderr
    _slice(engine, model, mixed, MODES[mode] + GRADIENT)
    one = read_mixing_gcode(single, "single").extrusions()
    two = read_mixing_gcode(mixed, "eb_axes").extrusions()
    assert len(one) == len(two) > 500
    for a, b in zip(one, two):
        assert b.total == pytest.approx(a.total, abs=2e-5)
    low = [m for m in two if m.layer == 10]
    high = [m for m in two if m.layer == max(m.layer for m in two) - 10]
    assert sum(m.amounts[1] for m in high) / sum(m.total for m in high) > \
        sum(m.amounts[1] for m in low) / sum(m.total for m in low) + 0.5


def test_fuzzy_skin_is_reproducible_and_rough(engine, corpus, tmp_path):
    model = corpus("cube20")
    a, b, plain = tmp_path / "a.gcode", tmp_path / "b.gcode", tmp_path / "plain.gcode"
    _slice(engine, model, a, MODES["fuzzy"], threads=2)
    _slice(engine, model, b, MODES["fuzzy"], threads=1)  # the same points whatever the thread count
    _slice(engine, model, plain, [])
    assert a.read_text() == b.read_text()

    def outer_wall_moves(path):
        blocks = path.read_text().split(";TYPE:WALL-OUTER")[1:]
        return sum(1 for block in blocks for line in block.split(";TYPE:")[0].splitlines()
                   if line.startswith("G1 X") or (line.startswith("G1 F") and " X" in line))

    # a 20 mm cube's outer wall: 4 moves a layer plain, about 78 mm / 0.8 mm with fuzzy skin
    assert outer_wall_moves(a) > 10 * outer_wall_moves(plain)
