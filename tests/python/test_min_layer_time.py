"""The minimum layer time as CuraEngine 4.13 applies it (ExtruderPlan::forceMinimalLayerTime): a layer is slowed
when its naive estimate — every move's distance / speed, plus retraction_amount / retraction_retract_speed for
each retracted travel — is under cool_min_layer_time, and then every extrusion by one factor (the slowest at
cool_min_speed when the factor would take it lower). Both engines slice parity.py's slivers scene (seven small
parts on an Ender-3, every layer short) and the F words are read back from their G-code."""
import collections
import re

import pytest

import helpers
import parity

SCENE = parity.SCENES["ender3_slivers"]
# The F words both engines write for the unslowed extrusions (speed_print 50, walls, skin 25, infill 50 mm/s)
# and the retraction's: F words outside these are slowed extrusions.
REGULAR = {1500.0, 3000.0}


def print_speeds(path):
    """{layer: set of F words on extrusions (G1 with X or Y and E)} above the first two (speed_slowdown_layers)."""
    out = collections.defaultdict(set)
    layer, speed = None, None
    with open(path) as f:
        for line in f:
            if line.startswith(";LAYER:"):
                layer = int(line[7:])
                continue
            code = line.split(";")[0]
            found = re.search(r" F([\d.]+)", code)
            if found:
                speed = float(found.group(1))
            if layer is not None and layer >= 2 and code.startswith("G1") and " E" in code and \
                    (" X" in code or " Y" in code):
                out[layer].add(speed)
    return out


def slice_both(tmp_path, settings):
    got = {}
    for name, binary in (("CuraEngine", helpers.CURA_BIN), ("MixEngine", helpers.BIN)):
        out = tmp_path / f"{name}.gcode"
        proc = helpers.run([binary, "slice", *SCENE.slice_args(settings), "-o", out], env=helpers.CURA_ENV)
        assert proc.returncode == 0, proc.stderr[-500:]
        got[name] = print_speeds(out)
    return got


def test_slowed_layers_are_those_curaengine_slows(tmp_path, report):
    """Retractions count in the estimate: the layers whose moves alone take just under 10 s but which retract
    a dozen times are not slowed (layers 2, 3, 11 to 14 here), as in CuraEngine."""
    got = slice_both(tmp_path, {})
    slowed = {name: {layer for layer, speeds in per_layer.items() if not speeds <= REGULAR}
              for name, per_layer in got.items()}
    layers = set(got["CuraEngine"]) & set(got["MixEngine"])
    differ = sorted((slowed["CuraEngine"] ^ slowed["MixEngine"]) & layers)
    report(f"min layer time on slivers: {len(slowed['CuraEngine'] & layers)} layers slowed by CuraEngine, "
           f"{len(slowed['MixEngine'] & layers)} by MixEngine, differing on {differ}")
    assert len(differ) <= len(layers) // 10, differ
    for layer in (2, 3, 11, 12, 13, 14):
        assert layer not in slowed["CuraEngine"] and layer not in slowed["MixEngine"], layer


def test_one_factor_for_every_extrusion(tmp_path):
    """On layers slowed down to cool_min_speed (the top of the pins) the walls print at 10 mm/s and the infill at
    twice that: one factor for all, not every line clamped on its own."""
    got = slice_both(tmp_path, {})
    for name, per_layer in got.items():
        top = [layer for layer, speeds in per_layer.items() if 600.0 in speeds]
        assert top, name
        for layer in top:
            assert per_layer[layer] <= {600.0, 1200.0, 1500.0}, (name, layer, per_layer[layer])


@pytest.mark.parametrize("setting", ["speed_print=75", "speed_wall=37.5", "speed_wall_0=37.5", "speed_topbottom=37.5",
                                     "speed_infill=75", "small_feature_max_length=1", "small_hole_max_size=1"])
def test_faster_speeds_change_the_slivers_print_as_curaengine(setting):
    key, value = setting.split("=")
    verdict = parity.judge({}, key, value, SCENE)
    assert verdict == "honoured", verdict
