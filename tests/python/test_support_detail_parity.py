"""Support details against Debian's CuraEngine 4.13 on parity.py's Ender-3 scenes: each changed setting must move
MixEngine's print as it moves CuraEngine's (parity.verdict: size within 1/3..3 times, the same features, and the
acceleration / jerk / fan values written).

- ender3_shelf (wide overhangs, a bridge over a slab so that support stands on the model, a cantilever, a slope):
  zig_zaggify_support (the support lines joined along the area's edge), minimum_roof_area /
  minimum_interface_area (small roof and floor islands stay plain support), support_roof_offset /
  support_interface_offset (the roof grown within the support), acceleration_support_bottom /
  jerk_support_bottom (the floors on the slab print with their own M204 / M205), support_supported_skin_fan_speed
  (the skin right above the support prints with that fan);
- ender3_slivers (thin walls, a wedge, pins, a small hole): support_enable prints no support on either engine,
  but turns the parts' outlines into their outer walls' (CuraEngine's print outline), which travel avoids.
"""
import pytest

import parity

SHELF = parity.SCENES["ender3_shelf"]
SLIVERS = parity.SCENES["ender3_slivers"]
SUPPORT = {"support_enable": "True"}

CASES = [
    (SHELF, {**SUPPORT, "support_pattern": "lines"}, "zig_zaggify_support", "True"),
    (SHELF, SUPPORT, "minimum_roof_area", "15"),
    (SHELF, SUPPORT, "minimum_interface_area", "15"),
    (SHELF, SUPPORT, "support_roof_offset", "1"),
    (SHELF, {**SUPPORT, "acceleration_enabled": "True", "support_interface_enable": "True"},
     "acceleration_support_bottom", "750"),
    (SHELF, {**SUPPORT, "jerk_enabled": "True", "support_interface_enable": "True"}, "jerk_support_bottom", "12"),
    (SHELF, {**SUPPORT, "support_fan_enable": "True"}, "support_supported_skin_fan_speed", "60"),
    (SLIVERS, {}, "support_enable", "True"),
]


@pytest.mark.parametrize("scene, context, key, value", CASES,
                         ids=[f"{c[0].name}-{c[2]}={c[3]}" for c in CASES])
def test_support_detail_acts_as_in_curaengine(scene, context, key, value):
    verdict = parity.judge(context, key, value, scene)
    assert verdict == "honoured", verdict
