"""Issue 27 item 2, feathered paint (mixing_paint_blend): a 20 mm box painted yellow left / blue right (3MF
colorgroup, split at its middle, mixing_mode=color on the MakerPi M2030X profile) with an 8 mm blend asks, on its
outer walls, for share of B 0 left of the middle − 4 mm, 1 right of the middle + 4 mm and the straight ramp in
between (the boundary at the middle is 50/50). The asked share comes from that geometry, never from the engine.

  - ideal chamber (mixing_chamber_volume 0): each outer-wall move's commanded share of B (its B over E + B)
    is the ramp at the move's middle within 0.1;
  - mixing_paint_blend=0 writes the same bytes as a slice without the setting (hard edges as before);
  - a 40 mm³ chamber in 3 stages, replayed by chamber_replay.py: the fraction of the outer wall leaving the
    nozzle within 0.1 of the ramp and the purge are reported with a side view (outlet | asked) of the
    feathered edge: ≥ 95 % within 0.1, for at most 1.25 × the purge of the same box with a hard edge.
"""
import json

import pytest

import helpers
from chamber_replay import outer_wall_fraction, purge_volume, render_side_view, replay
from mixing_gcode import png_pixels, read_mixing_gcode
from paint3mf import write_painted_box

PROFILE = helpers.REPO / "settings" / "definitions" / "mixengine_makerpi_m2030x.def.json"
EXTRUDER = helpers.REPO / "settings" / "extruders" / "mixengine_makerpi_m2030x_extruder_0.def.json"
DIAMETER_MM = json.loads(EXTRUDER.read_text())["overrides"]["material_diameter"]["default_value"]
YELLOW_BLUE = "#ffff00,#0000ff"
BLEND_MM = 8.0
TOLERANCE = 0.1
COLOUR = ["mixing_mode=color", f"mixing_channel_colors={YELLOW_BLUE}", "mixing_paint_depth=30"]


@pytest.fixture(scope="module")
def box(tmp_path_factory):
    return write_painted_box(tmp_path_factory.mktemp("feathered") / "halves.3mf", "colorgroup", size=20.0,
                             height=10.0)


def slice_makerpi(model, out, *settings):
    args = ["slice", "-v", "-j", PROFILE]
    for s in settings:
        args += ["-s", s]
    proc = helpers.mixengine(*args, "-l", model, "-o", out)
    assert proc.returncode == 0, proc.stderr
    return proc


def outer_walls(moves):
    return [m for m in moves if m.xy and m.total > 0 and m.feature == "WALL-OUTER"]


def ramp_asked(walls):
    """asked(move) -> [A, B]: the ramp of geometry at the move's middle, centred on the outer walls' middle."""
    xs = [x for m in walls for x in (m.start[0], m.end[0])]
    centre = (min(xs) + max(xs)) / 2

    def asked(move):
        x = (move.start[0] + move.end[0]) / 2 - centre
        share = min(1.0, max(0.0, (x + BLEND_MM / 2) / BLEND_MM))
        return [1.0 - share, share]
    return asked


def test_ideal_chamber_outer_walls_follow_the_ramp(box, tmp_path, report):
    out = tmp_path / "feathered.gcode"
    proc = slice_makerpi(box, out, *COLOUR, "mixing_chamber_volume=0", f"mixing_paint_blend={BLEND_MM:g}")
    assert "painted edges feathered over 8.00 mm in " in proc.stderr, proc.stderr
    walls = outer_walls(read_mixing_gcode(out, "eb_axes").moves)
    asked = ramp_asked(walls)
    worst, in_ramp, pure = 0.0, 0, {0.0: 0, 1.0: 0}
    for m in walls:
        want, got = asked(m)[1], m.amounts[1] / m.total
        worst = max(worst, abs(got - want))
        in_ramp += 0.05 < want < 0.95
        if want in pure:
            pure[want] += abs(got - want) < 1e-3
    report(f"feathered paint, {BLEND_MM:g} mm blend, ideal chamber: {len(walls)} outer-wall moves, {in_ramp} in "
           f"the ramp; commanded share of B within {worst:.4f} of the ramp of geometry")
    assert worst <= TOLERANCE
    assert in_ramp > 100 and pure[0.0] > 100 and pure[1.0] > 100


def test_no_blend_is_the_hard_edge_byte_for_byte(box, tmp_path):
    plain, zero = tmp_path / "plain.gcode", tmp_path / "zero.gcode"
    slice_makerpi(box, plain, *COLOUR)
    proc = slice_makerpi(box, zero, *COLOUR, "mixing_paint_blend=0")
    assert "painted edges feathered" not in proc.stderr
    assert plain.read_bytes() == zero.read_bytes()


def test_negative_blend_is_an_error_naming_the_key(box, tmp_path):
    proc = helpers.mixengine("slice", "-j", PROFILE, *[a for s in COLOUR for a in ("-s", s)], "-s",
                             "mixing_paint_blend=-1", "-l", box, "-o", tmp_path / "bad.gcode")
    assert proc.returncode == 1 and "mixing_paint_blend" in proc.stderr, proc.stderr
    assert not (tmp_path / "bad.gcode").exists()


def test_feathered_edge_through_a_chamber(box, tmp_path, report):
    """Through a 40 mm³ chamber in 3 stages the feathered edge's outer walls leave the nozzle within 0.1 of
    the ramp (≥ 95 % of their length): the planner spreads the purge over the edge's band steps and leads
    the chamber across them. It purges no more than the same box with a hard edge (one full change a
    layer) plus a quarter."""
    hard = tmp_path / "hard.gcode"
    slice_makerpi(box, hard, *COLOUR, "mixing_chamber_volume=40", "mixing_chamber_stages=3")
    hard_purge = purge_volume(replay(read_mixing_gcode(hard, "eb_axes").moves, DIAMETER_MM, 40.0, 3))
    out = tmp_path / "chamber.gcode"
    slice_makerpi(box, out, *COLOUR, "mixing_chamber_volume=40", "mixing_chamber_stages=3",
                  f"mixing_paint_blend={BLEND_MM:g}")
    replayed = replay(read_mixing_gcode(out, "eb_axes").moves, DIAMETER_MM, 40.0, 3)
    asked = ramp_asked(outer_walls([r.move for r in replayed]))
    picture = tmp_path / "feathered_outer_walls.png"
    render_side_view(replayed, YELLOW_BLUE.split(","), picture, asked=asked)
    width, height, rows = png_pixels(picture)
    coloured = sum(px != (255, 255, 255) for row in rows for px in zip(row[::3], row[1::3], row[2::3]))
    fraction, length = outer_wall_fraction(replayed, asked, TOLERANCE)
    report(f"feathered paint, {BLEND_MM:g} mm blend, 40 mm3 chamber in 3 stages: {100 * fraction:.1f} % of "
           f"{length:.0f} mm outer wall within {TOLERANCE} of the ramp, purge {purge_volume(replayed):.0f} mm3 "
           f"(hard edge: {hard_purge:.0f} mm3); side view (outlet | asked): {picture}")
    assert coloured > width * height / 4
    assert fraction >= 0.95
    assert purge_volume(replayed) <= 1.25 * hard_purge
