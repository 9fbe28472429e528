"""Issue 27 item 3, a colour shell over a plain core (mixing_core_ratio): a model's hidden extrusions (sparse
infill, inner walls) ask for the core's fixed mix, so only the visible shell carries the colour. Read back from
the G-code alone (mixing_gcode.py: the MakerPi's E and B words; chamber_replay.py: the independent chamber
replay), each slice compared with the same slice without the setting:

  - ideal chamber (mixing_chamber_volume 0), a 20 mm cube in a Z gradient with mixing_core_ratio=1:0: every
    infill and inner-wall move is commanded pure A (no B), and every outer-wall move is commanded exactly as
    without the core, move for move;
  - a 40 mm³ chamber in 3 stages, a 60 × 60 × 10 mm box at 40 % infill: the chamber changes to the core's mix
    and back inside the layers whose hidden volume holds two full changes, so the replayed core leaves the
    nozzle far nearer A than without the setting (its average share of A up by ≥ 0.2) while the outer walls
    stay within 0.1 of the gradient as before, and the slice says in one warning how much of the core took
    its mix;
  - a core ratio that is not a mix is one error line naming the key.
"""
import json

import helpers
from chamber_replay import outer_wall_fraction, replay
from mixing_gcode import box_stl, read_mixing_gcode

PROFILE = helpers.REPO / "settings" / "definitions" / "mixengine_makerpi_m2030x.def.json"
EXTRUDER = helpers.REPO / "settings" / "extruders" / "mixengine_makerpi_m2030x_extruder_0.def.json"
DIAMETER_MM = json.loads(EXTRUDER.read_text())["overrides"]["material_diameter"]["default_value"]
GRADIENT = ["mixing_mode=gradient", "mixing_gradient_start=20", "mixing_gradient_end=80",
            "mixing_channel_colors=#ffff00,#0000ff"]
CORE = ("FILL", "WALL-INNER")


def slice_makerpi(model, out, *settings):
    args = ["slice", "-j", PROFILE]
    for s in settings:
        args += ["-s", s]
    proc = helpers.mixengine(*args, "-l", model, "-o", out)
    assert proc.returncode == 0, proc.stderr
    return proc


def commanded(moves, features):
    """(start, end, share of B commanded) of the extruding moves of `features`, in print order."""
    return [(m.start, m.end, m.amounts[1] / m.total) for m in moves
            if m.xy and m.total > 0 and m.feature in features]


def test_ideal_chamber_prints_the_core_in_its_mix_and_the_shell_as_before(tmp_path):
    cube = box_stl(tmp_path / "cube.stl", 20, 20, 20)
    plain, cored = tmp_path / "plain.gcode", tmp_path / "cored.gcode"
    slice_makerpi(cube, plain, *GRADIENT, "mixing_chamber_volume=0")  # the profile estimates 30 mm³
    slice_makerpi(cube, cored, *GRADIENT, "mixing_chamber_volume=0", "mixing_core_ratio=1:0")
    plain_moves = read_mixing_gcode(plain, "eb_axes").moves
    cored_moves = read_mixing_gcode(cored, "eb_axes").moves
    core = commanded(cored_moves, CORE)
    assert len(core) > 1000 and all(share == 0.0 for _, _, share in core)
    shell, plain_shell = commanded(cored_moves, ("WALL-OUTER",)), commanded(plain_moves, ("WALL-OUTER",))
    assert [(a, b) for a, b, _ in shell] == [(a, b) for a, b, _ in plain_shell]
    # the same ratio, to the G-code's five decimals of filament
    assert max(abs(x - y) for (_, _, x), (_, _, y) in zip(shell, plain_shell)) < 1e-3
    assert max(share for _, _, share in commanded(plain_moves, CORE)) > 0.5  # without it the core follows


def core_share_of_a(replayed):
    core = [r for r in replayed if r.extruding and r.move.feature in CORE]
    return sum(r.net_mm3 * r.outlet[0] for r in core) / sum(r.net_mm3 for r in core)


def test_a_chamber_changes_to_the_core_where_the_layers_hold_room(tmp_path, report):
    box = box_stl(tmp_path / "box.stl", 60, 60, 10)
    chamber = ["mixing_chamber_volume=40", "mixing_chamber_stages=3", "infill_sparse_density=40"]
    plain, cored = tmp_path / "plain.gcode", tmp_path / "cored.gcode"
    slice_makerpi(box, plain, *GRADIENT, *chamber)
    proc = slice_makerpi(box, cored, *GRADIENT, *chamber, "mixing_core_ratio=1:0")
    warnings = [line for line in proc.stderr.splitlines() if "mixing_core_ratio" in line]
    assert len(warnings) == 1 and "of the core leaves the nozzle within 0.10 of its mix" in warnings[0], proc.stderr
    runs = {}
    for name, path in (("plain", plain), ("cored", cored)):
        replayed = replay(read_mixing_gcode(path, "eb_axes").moves, DIAMETER_MM, 40.0, 3)
        walls = [r for r in replayed if r.extruding and r.move.feature == "WALL-OUTER"]
        z_top = max(r.move.z for r in walls)

        def asked(move, z_top=z_top):
            share = min(1.0, max(0.0, (move.z / z_top - 0.2) / 0.6))
            return [1.0 - share, share]
        runs[name] = (core_share_of_a(replayed), outer_wall_fraction(replayed, asked, 0.1)[0])
    report(f"core ratio 1:0, 60 x 60 x 10 mm box, 40 % infill, 40 mm3 chamber: the core leaves the nozzle "
           f"{runs['plain'][0]:.2f} A without the setting, {runs['cored'][0]:.2f} A with it; outer walls within 0.1 "
           f"of the gradient {100 * runs['plain'][1]:.1f} % / {100 * runs['cored'][1]:.1f} %; {warnings[0]}")
    assert runs["cored"][0] >= runs["plain"][0] + 0.2
    assert runs["cored"][1] >= runs["plain"][1] - 0.01


def test_a_core_ratio_that_is_no_mix_names_the_key(tmp_path):
    cube = box_stl(tmp_path / "cube.stl", 20, 20, 20)
    proc = helpers.mixengine("slice", "-j", PROFILE, *[w for s in GRADIENT for w in ("-s", s)], "-s",
                             "mixing_core_ratio=white", "-l", cube, "-o", tmp_path / "bad.gcode")
    assert proc.returncode != 0
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and "mixing_core_ratio" in lines[0], proc.stderr
    assert not (tmp_path / "bad.gcode").exists()
