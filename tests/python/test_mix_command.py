"""Issue 18, part 4: `mixengine mix` (target colour → ratios through the pigment model, predicted colour,
ΔE00). The ΔE00 figures are checked against color_check.py, a CIEDE2000 written apart from the
engine's Little CMS."""
import math

import helpers
from color_check import delta_e00, lab_of_hex

CMYW = "#00ffff,#ff00ff,#ffff00,#ffffff"
# Targets whose ΔE00 the report prints: the channels themselves, mixes inside the gamut, and
# colours pigments cannot reach (saturated orange, red, blue, green).
TARGETS = ["#00ffff", "#ff00ff", "#ffff00", "#ffffff", "#ff8000", "#ff0000", "#0000ff", "#008000",
           "#804000", "#7f7f7f", "#ffc0cb", "#40e0d0"]


def mix(*args):
    proc = helpers.mixengine("mix", *args)
    assert proc.returncode == 0, proc.stderr
    fields = {}
    for line in proc.stdout.splitlines():
        key, _, value = line.partition(" ")
        fields[key] = value.strip()
    return fields


def ratios(fields):
    return [float(r) for r in fields["ratios"].split(":")]


def test_sharma_pairs_check_the_independent_cie2000():
    assert abs(delta_e00((50, 2.6772, -79.7751), (50, 0, -82.7485)) - 2.0425) < 1e-4
    assert abs(delta_e00((50, 2.5, 0), (73, 25, -18)) - 27.1492) < 1e-4


def test_a_channel_colour_is_all_of_that_channel():
    for channel, colour in enumerate(CMYW.split(",")):
        fields = mix("--colors", CMYW, "--target", colour)
        shares = ratios(fields)
        assert shares[channel] == 1.0 and sum(shares) == 1.0, fields
        assert fields["predicted"] == colour
        assert fields["dE00"] == "0.00"


def test_a_predicted_half_and_half_solves_back_to_half_and_half():
    predicted = mix("--colors", "#ffff00,#0000ff", "--ratio", "0.5:0.5")["predicted"]
    fields = mix("--colors", "#ffff00,#0000ff", "--target", predicted)
    assert abs(ratios(fields)[0] - 0.5) < 0.01, fields
    assert float(fields["dE00"]) < 0.5


def test_yellow_and_blue_predict_a_green():
    predicted = mix("--colors", "#ffff00,#0000ff", "--ratio", "0.5:0.5")["predicted"]
    r, g, b = (int(predicted[i:i + 2], 16) for i in (1, 3, 5))
    assert g > r and g > b, predicted
    lab = lab_of_hex(predicted)
    hue = math.degrees(math.atan2(lab[2], lab[1])) % 360
    assert 120 < hue < 180 and math.hypot(lab[1], lab[2]) > 30, (predicted, lab)


def test_delta_e_of_the_solved_colours(report):
    report(f"mix --colors {CMYW}: target -> ratios, predicted, dE00 (engine) / dE00 (color_check.py)")
    for target in TARGETS:
        fields = mix("--colors", CMYW, "--target", target)
        reported = float(fields["dE00"].split()[0])
        independent = delta_e00(lab_of_hex(target), lab_of_hex(fields["predicted"]))
        report(f"  {target} -> {fields['ratios']}  {fields['predicted']}  dE00 {reported:.2f} / {independent:.2f}")
        # the engine's ΔE is against the unrounded prediction, color_check's against its 8-bit hex
        assert abs(reported - independent) < 0.6, (target, fields, independent)
        assert ("outside the mixable gamut" in fields["dE00"]) == (reported > 2.0)
        assert abs(sum(ratios(fields)) - 1) < 1e-3


def test_bad_colours_are_one_error_line():
    for args, message in [
        (["--colors", "#00ffff,#ff00ff", "--target", "orange"], "--target: 'orange' is not a colour like #ff8800"),
        (["--colors", "#00ffff", "--target", "#ff8000"], "--colors: 1 colours given, 2 to 5 are mixed"),
        (["--colors", "#00ffff,#ff00ff"], "mix: give either --target"),
    ]:
        proc = helpers.mixengine("mix", *args)
        assert proc.returncode == 1
        lines = helpers.stderr_lines(proc)
        assert len(lines) == 1 and message in lines[0], lines
        assert proc.stdout == ""
