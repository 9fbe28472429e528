"""Support towers (support_use_towers and support_tower_*) against Debian's CuraEngine 4.13, on side_by_side's
"hook" model: a 2 mm arm out of a wall whose end hangs 3 mm down, so that the end's lowest layer is a small part
with nothing under it. The Ender-3's definitions turn towers off; here they are switched on. Under the end both
engines print a tower of support_tower_diameter that widens going down at support_tower_roof_angle; its outline
is compared layer by layer (the extent of the support lines), the filament from the G-code (parity.signature).
"""
import re

import pytest

import parity
import side_by_side as sbs

MODEL = "hook"
TOWERS = {"support_enable": "True", "support_use_towers": "True"}


def _runs(overrides, model=MODEL):
    settings = dict(TOWERS, **overrides)
    mix, cura = sbs.run_mixengine(model, settings), sbs.run_cura(model, settings)
    assert mix.rc == 0 and cura.rc == 0, (mix.stderr, cura.stderr)
    return mix.gcode, cura.gcode


def _support_extent(path, layer):
    """(x min, x max, y min, y max) in mm of the support extrusions on `layer`."""
    text = path.read_text()
    section = text[text.index(f";LAYER:{layer}\n"):text.index(f";LAYER:{layer + 1}\n")]
    points, kind, x, y, e = [], None, None, None, 0.0
    for line in section.splitlines():
        if line.startswith(";TYPE:"):
            kind = line[6:]
        if not line.startswith(("G0", "G1")):
            continue
        words = dict(re.findall(r"([XYE])(-?[0-9.]+)", line.split(";")[0]))
        nx = float(words["X"]) if "X" in words else x  # None until the layer's first move names it
        ny = float(words["Y"]) if "Y" in words else y
        ne = float(words.get("E", e))
        if ne > e and None not in (x, y, nx, ny) and (nx, ny) != (x, y) and kind and kind.startswith("SUPPORT"):
            points += [(x, y), (nx, ny)]
        x, y, e = nx, ny, ne
    if not points:
        return None
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return min(xs), max(xs), min(ys), max(ys)


def _filament(path):
    return parity.signature(path)["figures"]["filament"]


@pytest.mark.parametrize("overrides", [
    {},
    {"support_tower_diameter": "4", "support_tower_maximum_supported_diameter": "4"},
    {"support_tower_roof_angle": "30"},
    {"support_use_towers": "False"},
    {"support_tower_maximum_supported_diameter": "1.5"},  # the 2 x 2 mm end is too big for a tower
], ids=["default", "diameter_4", "roof_angle_30", "off", "max_diameter_1_5"])
def test_the_tower_under_the_hanging_end_has_curaengines_outline(overrides):
    mix, cura = _runs(overrides)
    # Layer 10: the full tower; layer 24: its roof, still widening (the end's lowest layer is layer 30).
    for layer in (10, 24):
        assert _support_extent(mix, layer) == pytest.approx(_support_extent(cura, layer), abs=0.01), layer


def test_towers_add_filament_in_both_engines():
    mix_on, cura_on = _runs({})
    mix_off, cura_off = _runs({"support_use_towers": "False"})
    x0, x1, _, _ = _support_extent(mix_on, 10)
    assert x1 - x0 == pytest.approx(2.69, abs=0.01)  # the 3 mm tower less the xy distance, wider than the end's 2 mm
    # Measured: CuraEngine 362.8 → 368.0 mm, MixEngine 336.7 → 354.6 mm (MixEngine fills the end's 2 mm column
    # without towers more sparsely than CuraEngine, so its step is larger).
    assert _filament(cura_on) - _filament(cura_off) > 2
    assert _filament(mix_on) - _filament(mix_off) > 2
    assert _filament(mix_on) == pytest.approx(_filament(cura_on), rel=0.05)


def test_a_pins_small_support_becomes_a_tower_as_in_curaengine():
    # side_by_side's "pin": without towers neither engine supports the 1.2 mm pin; with them its small support
    # island (support six layers up, no model below) starts a tower that widens to about the diameter.
    mix_off, cura_off = _runs({"support_use_towers": "False"}, "pin")
    mix_on, cura_on = _runs({}, "pin")
    for layer in (5, 20, 30):
        assert _support_extent(mix_off, layer) is None and _support_extent(cura_off, layer) is None
        mix, cura = _support_extent(mix_on, layer), _support_extent(cura_on, layer)
        # Measured on layer 5: CuraEngine 2.85 mm wide, MixEngine 2.66 mm (two roof steps of 0.09 mm less).
        assert mix == pytest.approx(cura, abs=0.2), layer
    assert _support_extent(mix_on, 40) is None and _support_extent(cura_on, 40) is None  # above the pin
    # Measured: CuraEngine 294.4 → 310.3 mm, MixEngine 294.4 → 309.0 mm.
    assert _filament(mix_off) == pytest.approx(_filament(cura_off), rel=0.01)
    assert _filament(mix_on) - _filament(mix_off) == pytest.approx(_filament(cura_on) - _filament(cura_off), rel=0.15)
