"""Issue 18, parts 1 to 3 in `slice`: color mode (mixing_target_color), gradients between colours
(mixing_gradient_colors) and painted 3MF regions (colorgroup, basematerials, PrusaSlicer and OrcaSlicer
painted facets), read back from the G-code by the firmware models of mixing_gcode.py."""
import math

import pytest

import helpers
from mixing_gcode import box_stl, png_pixels, read_mixing_gcode
from paint3mf import write_painted_box
from test_mix_command import CMYW, mix, ratios

YELLOW_BLUE = "#ffff00,#0000ff"


def predicted(colors, ratio):
    return mix("--colors", colors, "--ratio", ratio)["predicted"]


def solved(colors, target):
    return ratios(mix("--colors", colors, "--target", target))


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("color_mode") / "cube.stl", 20, 20, 20)


def layer_share_b(path, dialect="eb_axes", channels=2):
    reading = read_mixing_gcode(path, dialect, channels=channels)
    return {layer: (z, amounts[1] / sum(amounts)) for layer, (z, amounts) in reading.layer_totals().items()}


def test_color_mode_prints_the_solved_mix_and_reports_it(cube, tmp_path):
    target = predicted(YELLOW_BLUE, "0.5:0.5")
    out = tmp_path / "c.gcode"
    proc = helpers.mixengine("slice", "-v", "-s", "mixing_mode=color", "-s", f"mixing_channel_colors={YELLOW_BLUE}",
                             "-s", f"mixing_target_color={target}", "-l", cube, "-o", out)
    assert proc.returncode == 0, proc.stderr
    cli = mix("--colors", YELLOW_BLUE, "--target", target)
    expected = ratios(cli)
    assert abs(expected[1] - 0.5) < 0.01  # the prediction of 50/50 solves back to it
    for layer, (z, share_b) in layer_share_b(out).items():
        assert abs(share_b - expected[1]) < 2e-3, (layer, share_b, expected)
    report = [line for line in proc.stderr.splitlines() if "target " + target in line]
    assert report and f"predicted {cli['predicted']}, dE00 {cli['dE00']}" in report[0], proc.stderr
    assert float(cli["dE00"]) < 1.0
    assert "[warning] mixing" not in proc.stderr


def test_out_of_gamut_target_is_one_warning_line(cube, tmp_path):
    proc = helpers.mixengine("slice", "-s", "mixing_mode=color", "-s", f"mixing_channel_colors={YELLOW_BLUE}",
                             "-s", "mixing_target_color=#ff0000", "-l", cube, "-o", tmp_path / "r.gcode")
    assert proc.returncode == 0, proc.stderr
    warnings = [line for line in proc.stderr.splitlines() if "outside the gamut" in line]
    assert len(warnings) == 1, proc.stderr
    assert f"'{cube}'" in warnings[0] and "#ff0000" in warnings[0] and "dE00 " in warnings[0]
    de = float(warnings[0].rsplit("dE00 ", 1)[1].rstrip(")"))
    assert de > 2.0


def test_bad_target_colour_is_an_error(cube, tmp_path):
    out = tmp_path / "bad.gcode"
    proc = helpers.mixengine("slice", "-s", "mixing_mode=color", "-s", "mixing_target_color=#ff80", "-l", cube,
                             "-o", out)
    assert proc.returncode == 1
    assert helpers.stderr_lines(proc) == [
        "mixengine: error: setting 'mixing_target_color': '#ff80' is not a colour like #ff8800"]
    assert not out.exists()


def test_gradient_between_colours_is_interpolated_in_the_mix(cube, tmp_path):
    top = predicted(YELLOW_BLUE, "0.2:0.8")
    out = helpers.slice_with(cube, tmp_path / "g.gcode", "mixing_mode=gradient",
                             f"mixing_channel_colors={YELLOW_BLUE}", f"mixing_gradient_colors=0=#ffff00; 100={top}")
    top_b = solved(YELLOW_BLUE, top)[1]
    shares = layer_share_b(out)
    for layer, (z, share_b) in shares.items():
        expected = top_b * min(z / 20.0, 1.0)  # the layer's top in percent of the 20 mm cube
        assert abs(share_b - expected) < 2e-3, (layer, z, share_b, expected)
    assert abs(shares[max(shares)][1] - top_b) < 2e-3


def test_gradient_colour_stops_with_four_channels_in_m165(cube, tmp_path):
    out = helpers.slice_with(cube, tmp_path / "g4.gcode", "mixing_mode=gradient", "mixing_dialect=marlin_m165",
                             "mixing_channels=4", f"mixing_channel_colors={CMYW}",
                             "mixing_gradient_colors=0=#00ffff; 50=#ff00ff; 100=#ffff00")
    reading = read_mixing_gcode(out, "marlin_m165", channels=4)
    totals = reading.layer_totals()
    first, last = totals[min(totals)][1], totals[max(totals)][1]
    assert first[0] / sum(first) > 0.95 and last[2] / sum(last) > 0.99  # first layer: 1.5 % of the way
    middle = [a for layer, (z, a) in totals.items() if abs(z - 10.0) < 0.11][0]
    assert middle[1] / sum(middle) > 0.97  # magenta at 50 %


def painted_moves(path, dialect, channels):
    """(x centre of the painted box, extrusions of the box with their mix) from the firmware model."""
    moves = [m for m in read_mixing_gcode(path, dialect, channels=channels).extrusions()
             if m.mesh.endswith("halves.3mf")]
    xs = [x for m in moves for x in (m.start[0], m.end[0])]
    centre = (min(xs) + max(xs)) / 2
    return centre, [(m, [a / m.total for a in m.amounts]) for m in moves]


PAINTED = [  # style, dialect, channel colours, extra settings, left mix, right mix
    ("colorgroup", "eb_axes", YELLOW_BLUE, [], [1, 0], [0, 1]),
    ("basematerials", "marlin_m163", YELLOW_BLUE, [], [1, 0], [0, 1]),
    ("prusa", "marlin_m165", CMYW, ["mixing_channels=4"], [1, 0, 0, 0], [0, 1, 0, 0]),
    ("orca", "eb_axes", YELLOW_BLUE, [], [1, 0], [0, 1]),
]


@pytest.mark.parametrize("style,dialect,colors,extra,left,right", PAINTED, ids=[p[0] for p in PAINTED])
def test_painted_halves_print_in_their_own_mix(tmp_path, style, dialect, colors, extra, left, right):
    model = write_painted_box(tmp_path / "halves.3mf", style)
    settings = ["mixing_mode=color", f"mixing_dialect={dialect}", f"mixing_channel_colors={colors}",
                "mixing_paint_depth=30", *extra]
    out = helpers.slice_with(model, tmp_path / "p.gcode", *settings)
    centre, moves = painted_moves(out, dialect, len(left))
    sides = {"left": 0, "right": 0}
    for m, shares in moves:
        xs = (m.start[0], m.end[0])
        if max(xs) < centre - 0.01:
            side, want = "left", left
        elif min(xs) > centre + 0.01:
            side, want = "right", right
        else:
            continue  # a piece that ends on the boundary
        assert all(abs(s - w) < 1e-3 for s, w in zip(shares, want)), (side, m, shares)
        sides[side] += 1
    assert sides["left"] > 100 and sides["right"] > 100, sides
    # moves crossing x = centre were cut there: no extrusion spans the boundary by more than 10 µm
    for m, shares in moves:
        lo, hi = sorted((m.start[0], m.end[0]))
        assert not (lo < centre - 0.01 and hi > centre + 0.01), m


def test_paint_depth_keeps_the_inside_in_the_target_colour(tmp_path):
    model = write_painted_box(tmp_path / "halves.3mf", "colorgroup")
    target = predicted(YELLOW_BLUE, "0.5:0.5")
    out = helpers.slice_with(model, tmp_path / "d.gcode", "mixing_mode=color", f"mixing_channel_colors={YELLOW_BLUE}",
                             "mixing_paint_depth=1.5", f"mixing_target_color={target}")
    centre, moves = painted_moves(out, "eb_axes", 2)
    xs = [x for m, _ in moves for x in (m.start[0], m.end[0])]
    ys = [y for m, _ in moves for y in (m.start[1], m.end[1])]
    y_centre = (min(ys) + max(ys)) / 2
    x_centre = (min(xs) + max(xs)) / 2

    def depth_of_middle(m):  # how far the middle of the move is from the nearest face of the box
        x, y = (m.start[0] + m.end[0]) / 2, (m.start[1] + m.end[1]) / 2
        return min(10 - abs(x - x_centre), 10 - abs(y - y_centre), m.z - 0.05, 10 - m.z + 0.05)

    deep = [(m, s) for m, s in moves if depth_of_middle(m) > 2.0]
    shallow = [(m, s) for m, s in moves if depth_of_middle(m) < 1.0]
    assert len(deep) > 20 and len(shallow) > 100
    for m, shares in deep:
        assert abs(shares[1] - 0.5) < 0.01, (m, shares)
    for m, shares in shallow:  # walls and skins within the paint: yellow (1:0) or blue (0:1)
        assert min(abs(shares[1]), abs(shares[1] - 1)) < 1e-3, (m, shares)


def test_preview_draws_the_painted_halves(tmp_path):
    model = write_painted_box(tmp_path / "halves.3mf", "colorgroup", left="#FFFF00", right="#0000FF")
    preview = tmp_path / "halves.png"
    proc = helpers.mixengine("slice", "-s", "mixing_mode=color", "-s", f"mixing_channel_colors={YELLOW_BLUE}",
                             "-s", "mixing_paint_depth=30", "-l", model, "-o", tmp_path / "h.gcode",
                             "--preview", preview)
    assert proc.returncode == 0, proc.stderr
    width, height, rows = png_pixels(preview)
    row = rows[height // 2]
    left = tuple(row[3 * (width // 3): 3 * (width // 3) + 3])
    right = tuple(row[3 * (2 * width // 3): 3 * (2 * width // 3) + 3])
    assert left[0] > 200 and left[1] > 200 and left[2] < 60, left  # yellow (shaded by depth at most 35 %)
    assert right[2] > 150 and right[0] < 40 and right[1] < 40, right  # blue


def plug_flow(shares, volumes, chamber_mm3):
    """The share leaving the nozzle during each extrusion when the chamber is plug flow: the average of the
    commanded `shares` (one per extrusion, in print order, `volumes` mm3 > 0) over the extrusion's own volume
    shifted back by `chamber_mm3`; before the first extrusion the chamber holds the first share."""
    import numpy

    ends = numpy.cumsum(volumes)
    starts = ends - volumes
    before_end = numpy.concatenate(([0.0], numpy.cumsum(shares * volumes)))[:-1]

    def integral(u):  # of the commanded share over the cumulative volume [0, u]
        i = numpy.clip(numpy.searchsorted(ends, u, side="left"), 0, len(ends) - 1)
        inside = before_end[i] + numpy.clip(u - starts[i], 0.0, None) * shares[i]
        return numpy.where(u > 0, inside, numpy.minimum(u, 0.0) * shares[0])

    return (integral(ends - chamber_mm3) - integral(starts - chamber_mm3)) / volumes


def delivered_share_b(path, chamber_mm3):
    """(moves, commanded B shares, B shares leaving the nozzle of a plug-flow chamber)."""
    import numpy

    area = math.pi * (2.85 / 2) ** 2  # fdmprinter's material_diameter
    extrusions = read_mixing_gcode(path, "eb_axes", channels=2).extrusions()
    commanded = numpy.array([m.amounts[1] / m.total for m in extrusions])
    volume = numpy.array([m.total * area for m in extrusions])
    return extrusions, commanded, plug_flow(commanded, volume, chamber_mm3)


def share_on_the_nozzle(extrusions, delivered):
    """The fraction of the painted box's moves (those clearly in one half) whose delivered mix is the half's."""
    painted = [i for i, m in enumerate(extrusions) if m.mesh.endswith("halves.3mf")]
    xs = [x for i in painted for x in (extrusions[i].start[0], extrusions[i].end[0])]
    centre = (min(xs) + max(xs)) / 2
    want = {}
    for i in painted:
        lo, hi = sorted((extrusions[i].start[0], extrusions[i].end[0]))
        if hi < centre - 0.01 or lo > centre + 0.01:
            want[i] = 0.0 if hi < centre else 1.0
    return sum(abs(delivered[i] - w) < 1e-3 for i, w in want.items()) / len(want), len(want)


def test_chamber_delay_applies_to_painted_regions(tmp_path, report):
    """With mixing_chamber_volume each region's mix is commanded early, so that what leaves the nozzle (the
    plug-flow model of the chamber, plug_flow) is mostly the region's mix; without the
    compensation far less of it would be. Per-move mixes cannot be exact where the pieces alternate faster
    than the chamber empties (a move is not cut where the delayed boundary falls)."""
    chamber_mm3 = 5.0
    model = write_painted_box(tmp_path / "halves.3mf", "colorgroup")
    common = ["mixing_mode=color", f"mixing_channel_colors={YELLOW_BLUE}", "mixing_paint_depth=30",
              "mixing_target_color=#ffff00"]
    shifted = helpers.slice_with(model, tmp_path / "c.gcode", *common, f"mixing_chamber_volume={chamber_mm3}")
    plain = helpers.slice_with(model, tmp_path / "p.gcode", *common)
    good, count = share_on_the_nozzle(*delivered_share_b(shifted, chamber_mm3)[::2])
    baseline, _ = share_on_the_nozzle(*delivered_share_b(plain, chamber_mm3)[::2])
    report(f"painted halves, {chamber_mm3} mm3 chamber: the region's mix leaves the nozzle on {100 * good:.1f} % of "
           f"{count} moves with the compensation, {100 * baseline:.1f} % without")
    assert good > 0.8 and good > baseline + 0.2
