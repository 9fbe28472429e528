"""Issue 26, "calibration a user can do": `mixengine calibrate-chamber` writes a thin tower that switches hard from
one filament to the other and back at known heights, with mixing_chamber_volume forced to 0, and prints how to read
the chamber's volume and stage count from it.

Checked from the G-code alone (mixing_gcode.py reads the firmware's words back, independently of the engine):
  - the switch heights the guide prints are where the G-code switches: the tower's extrusions carry B share 0 at
    and below the first switch, exactly 1 up to the second, exactly 0 above — even when the profile or the
    command line sets a chamber volume (the calibration print forces it to 0);
  - the printed extrusion per mm of tower height is the G-code's own filament per mm of height (E and B words
    times the filament's cross-section), within 0.5 %;
  - the table's heights for N = 3 are the analytic step response 1 - e^-t (1 + t + t^2/2), t = v N / V, solved
    here by bisection, divided by that volume per mm;
  - the guide is also at the top of the G-code as ;CALIBRATION: lines; --filaments and --band move the switches
    (five channels, M165); bad input is a one-line error and writes nothing; --help writes nothing.
"""
import json
import math
import re

import pytest

import helpers
from mixing_gcode import read_mixing_gcode

TOWER = "chamber_calibration_tower"
MAKERPI = "mixengine_makerpi_m2030x"
EXTRUDER = helpers.REPO / "settings" / "extruders" / "mixengine_makerpi_m2030x_extruder_0.def.json"
DIAMETER_MM = json.loads(EXTRUDER.read_text())["overrides"]["material_diameter"]["default_value"]


def calibrate(tmp_path, *args, name="tower.gcode"):
    out = tmp_path / name
    proc = helpers.mixengine("calibrate-chamber", *args, "-o", out, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout, out


def guide_switches(stdout):
    match = re.search(r"up to ([\d.]+) mm, .* from ([\d.]+) to ([\d.]+) mm", stdout)
    assert match, stdout
    first, first_again, second = (float(g) for g in match.groups())
    assert first == first_again
    return first, second


def guide_per_mm(stdout):
    match = re.search(r"Extrusion per mm of tower height: ([\d.]+) mm3/mm", stdout)
    assert match, stdout
    return float(match.group(1))


def tower_moves(path, dialect="eb_axes", channels=2):
    moves = [m for m in read_mixing_gcode(path, dialect, channels).extrusions() if m.mesh == TOWER]
    assert moves, "no extrusion of the tower in the G-code"
    return moves


def three_tank_volume(volume, fraction):
    """v with 1 - e^-t (1 + t + t^2/2) = fraction, t = 3 v / volume."""
    lo, hi = 0.0, 100.0
    for _ in range(200):
        mid = (lo + hi) / 2
        response = 1 - math.exp(-mid) * (1 + mid + mid * mid / 2)
        lo, hi = (mid, hi) if response < fraction else (lo, mid)
    return (lo + hi) / 2 * volume / 3


def test_switches_are_hard_and_where_the_guide_says(engine, tmp_path, report):
    # a chamber on the command line must not reach the G-code: the print is what the chamber alone blurs
    stdout, gcode = calibrate(tmp_path, "-j", MAKERPI, "-s", "mixing_chamber_volume=40", "-s",
                              "mixing_chamber_stages=3")
    first, second = guide_switches(stdout)
    assert (first, second) == (10.0, 25.0)
    moves = tower_moves(gcode)
    below = [m for m in moves if m.z <= first + 1e-9]
    between = [m for m in moves if first + 1e-9 < m.z <= second + 1e-9]
    above = [m for m in moves if m.z > second + 1e-9]
    assert below and between and above
    assert all(m.amounts[1] == 0.0 and m.amounts[0] > 0 for m in below)
    assert all(m.amounts[0] == 0.0 and m.amounts[1] > 0 for m in between)
    assert all(m.amounts[1] == 0.0 and m.amounts[0] > 0 for m in above)
    # and the switch is at the printed height: the last A move ends there
    assert max(m.z for m in below) == pytest.approx(first, abs=1e-6)
    assert max(m.z for m in between) == pytest.approx(second, abs=1e-6)
    # the chamber of the command line is what the guide compares against
    assert "mixing_chamber_volume 40 mm3, mixing_chamber_stages 3" in stdout
    report(f"calibrate-chamber (MakerPi): {len(below)} moves A up to {first} mm, {len(between)} B to {second} mm, "
           f"{len(above)} A above; B share exactly 0 / 1 / 0")


def test_volume_per_mm_is_the_gcodes_own(engine, tmp_path, report):
    stdout, gcode = calibrate(tmp_path, "-j", MAKERPI)
    per_mm = guide_per_mm(stdout)
    area = math.pi * DIAMETER_MM ** 2 / 4
    first, second = guide_switches(stdout)
    moves = tower_moves(gcode)
    for lo, hi in ((first, second), (second, second + 10), (first / 2, first)):
        filament = sum(m.total for m in moves if lo < m.z <= hi)
        measured = filament * area / (hi - lo)
        assert measured == pytest.approx(per_mm, rel=0.005), (lo, hi, measured, per_mm)
    report(f"calibrate-chamber: {per_mm} mm3/mm printed, G-code between the switches "
           f"{sum(m.total for m in moves if first < m.z <= second) * area / (second - first):.3f} mm3/mm")


def test_table_follows_the_three_tank_step_response(engine, tmp_path):
    stdout, _ = calibrate(tmp_path, "-j", MAKERPI)
    per_mm = guide_per_mm(stdout)
    rows = {}
    for line in stdout.splitlines():
        fields = line.split()
        if len(fields) == 5 and all(re.fullmatch(r">?[\d.]+", f) for f in fields):
            rows[(int(fields[0]), float(fields[1]))] = fields[2:]
    assert len(rows) == 6 * 9
    for volume in (10, 20, 40, 60, 100):
        cells = rows[(3, float(volume))]
        for cell, fraction in zip(cells, (0.1, 0.5, 0.9)):
            assert float(cell) == pytest.approx(three_tank_volume(volume, fraction) / per_mm, abs=0.006), \
                (volume, fraction, cell)
    # 90 % of one stage of 120 mm3 lies beyond the 15 mm band: marked, not a number
    assert rows[(1, 120.0)][2].startswith(">")


def test_guide_is_in_the_gcode_header(engine, tmp_path):
    stdout, gcode = calibrate(tmp_path, "-j", MAKERPI)
    text = gcode.read_text()
    comments = [line[len(";CALIBRATION: "):] for line in text.splitlines() if line.startswith(";CALIBRATION: ")]
    printed = stdout.splitlines()
    assert printed[0].startswith("G-code written to ")
    assert comments == printed[1:]
    assert text.index(";CALIBRATION:") < text.index(";LAYER:0\n")
    assert text.startswith(";FLAVOR:Marlin\n")


def test_filaments_and_band_on_five_channels(engine, tmp_path):
    stdout, gcode = calibrate(tmp_path, "-j", "mixengine_cmykw_mixer", "--filaments", "4,5", "--band", "8")
    first, second = guide_switches(stdout)
    assert (first, second) == (10.0, 18.0)
    assert "filament 4 (#262626)" in stdout and "filament 5 (#f4f4f4)" in stdout
    for m in tower_moves(gcode, "marlin_m165", 5):
        shares = [a / m.total for a in m.amounts]
        expected = 4 if first < m.z <= second + 1e-9 else 3
        assert shares[expected] == pytest.approx(1.0, abs=1e-12), (m.z, shares)


@pytest.mark.parametrize("args, words", [
    (["-l", "cube.stl", "-o", "x.gcode"], ["-l", "not taken"]),
    ([], ["-o"]),
    (["--filaments", "1,3", "-o", "x.gcode"], ["--filaments", "mixing_channels"]),
    (["--filaments", "2,2", "-o", "x.gcode"], ["--filaments"]),
    (["--band", "1", "-o", "x.gcode"], ["--band"]),
    (["-s", "adhesion_type=raft", "-o", "x.gcode"], ["raft"]),
])
def test_bad_input_is_one_line_and_writes_nothing(engine, tmp_path, args, words):
    proc = helpers.run([engine, "calibrate-chamber", "-j", MAKERPI, *args], cwd=tmp_path, timeout=60)
    assert proc.returncode == 1
    lines = helpers.stderr_lines(proc)
    assert len(lines) == 1 and all(w in lines[0] for w in words), proc.stderr
    assert list(tmp_path.iterdir()) == []


def test_help_names_the_command_and_writes_nothing(engine, tmp_path):
    proc = helpers.run([engine, "calibrate-chamber", "--help"], cwd=tmp_path, timeout=30)
    assert proc.returncode == 0 and proc.stderr == ""
    assert proc.stdout.startswith("usage:\nmixengine calibrate-chamber")
    assert "calibrate-chamber" in helpers.mixengine("help").stdout
    assert list(tmp_path.iterdir()) == []


MIXING_PROFILES = {  # the estimates written into each profile (settings/definitions), checked as resolved
    "mixengine_makerpi_m2030x": (30.0, 3),
    "mixengine_geeetech_a10m": (30.0, 3),
    "mixengine_rrf_mixing": (30.0, 3),
    "mixengine_cmykw_mixer": (20.0, 3),
}


@pytest.mark.parametrize("machine", sorted(MIXING_PROFILES))
def test_profiles_carry_chamber_estimates_said_to_be_estimates(engine, tmp_path, machine):
    proc = helpers.mixengine("settings", "-j", machine, "--json")
    assert proc.returncode == 0, proc.stderr
    resolved = json.loads(proc.stdout)["global"]
    volume, stages = MIXING_PROFILES[machine]
    assert (float(resolved["mixing_chamber_volume"]), int(resolved["mixing_chamber_stages"])) == (volume, stages)
    doc = json.loads((helpers.REPO / "settings" / "definitions" / f"{machine}.def.json").read_text())
    note = doc["metadata"]["mixengine_chamber_estimate"]
    assert f"mixing_chamber_volume {volume:g} mm³" in note and f"mixing_chamber_stages {stages}" in note
    assert "estimate" in note and "calibrate-chamber" in note
    # and the calibration print says what the profile predicts
    stdout, _ = calibrate(tmp_path, "-j", machine)
    assert f"mixing_chamber_volume {volume:g} mm3, mixing_chamber_stages {stages}" in stdout
