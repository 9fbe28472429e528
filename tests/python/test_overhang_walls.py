"""Overhanging walls (wall_overhang_angle with wall_overhang_speed_factor) move MixEngine's print as they move
CuraEngine 4.13's (parity.verdict: same direction, a size within 1/3..3 times CuraEngine's change, the same F
values written). The parity sweep flips wall_overhang_speed_factor only at the default angle (90: no overhang,
neither engine changes), so the speed factor is judged here with overhang detection switched on, and the
angle with a speed factor other than 100 %.

Measured when this was built: on the shelf at 54° and 50 %, both engines print 841.7 mm of outer wall at half
speed (F750, 60 moves), at 30° 896.4 mm (64 moves); on the parity model 66.4 mm of outer wall and 63.2 mm of
inner wall, in both engines; with support on the shelf, 724.9 mm (57 moves) in both (supported overhang keeps its
speed, as CuraEngine).
"""
import pytest

import parity

ANGLE = {"wall_overhang_angle": "54"}
SLOW = {"wall_overhang_speed_factor": "50"}

CASES = [
    ("ender3", ANGLE, "wall_overhang_speed_factor", "50"),
    ("ender3_shelf", ANGLE, "wall_overhang_speed_factor", "50"),
    ("ender3", SLOW, "wall_overhang_angle", "54"),
    ("ender3_shelf", SLOW, "wall_overhang_angle", "30"),
    ("ender3_shelf", dict(ANGLE, support_enable="True"), "wall_overhang_speed_factor", "50"),
]


@pytest.mark.parametrize("scene,context,key,value", CASES, ids=[f"{s}-{k}={v}" for s, _, k, v in CASES])
def test_overhanging_walls_move_print_as_curaengine(engine, scene, context, key, value):
    verdict = parity.judge(context, key, value, parity.SCENES[scene])
    assert verdict == "honoured", f"{key}={value} on {scene} {context}: {verdict}"
