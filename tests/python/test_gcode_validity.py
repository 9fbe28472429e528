"""Issue 5: every G-code MixEngine produces parses with an independent parser (PyPI gcodeparser) and stays
inside the build volume; in absolute extrusion mode E never grows beyond E_BOUND_MM between G92 resets;
absolute and relative extrusion feed the same filament; numbers are written compactly.

Settings are side_by_side.py's (the Ender-3, 235 x 235 x 250 mm, 0.2 mm layers, resolved values for
every key) plus one variant each: the flavors, relative extrusion, brim / none (skirt is the Ender-3's
default), support (on side_by_side's generated "tee", whose bar overhangs). The models of
test_compare_cura.py are checked with the default settings (their MixEngine runs are shared within one
pytest process).
"""
import math
import re

import pytest

import side_by_side as sbs

# E bound: E words are written with 5 decimals (1e-5 mm). A firmware keeping E in a 32-bit float (24-bit
# mantissa) resolves 2^-14 mm = 6.1e-5 mm at 1000 mm but 1.2e-4 mm from 2048 mm on, i.e. it starts to lose
# the written precision to rounding of whole 1e-4 steps. 1000 mm of filament (about 2.4 cm³ at 1.75 mm) per
# G92 reset keeps every E word exact to 1e-4 mm. Volumetric flavors write mm³: the bound is the same
# filament length times the filament's cross-section.
E_BOUND_MM = 1000.0
POSITION_SLACK_MM = 1e-3    # positions are written with 3 decimals

VARIANTS = {
    "marlin_absolute": ("cube20", {}),
    "marlin_relative": ("cube20", {"relative_extrusion": "True"}),
    "reprap": ("cube20", {"machine_gcode_flavor": "RepRap (RepRap)"}),
    "griffin": ("cube20", {"machine_gcode_flavor": "Griffin"}),
    "ultigcode": ("cube20", {"machine_gcode_flavor": "UltiGCode"}),
    "volumetric": ("cube20", {"machine_gcode_flavor": "RepRap (Volumetric)"}),
    "brim": ("cube20", {"adhesion_type": "brim"}),
    "no_adhesion": ("cube20", {"adhesion_type": "none"}),
    "support": ("tee", {"support_enable": "True"}),
    "tube": ("tube", {}),
    "knot2": ("knot2", {}),
    "armadillo52k": ("armadillo52k", {}),
}
VOLUMETRIC = ("UltiGCode", "RepRap (Volumetric)")
WORD = re.compile(r"([A-Za-z])(\S*)")


def _sliced(corpus, name):
    model, overrides = VARIANTS[name]
    if model not in sbs.GENERATED:
        corpus(model)
    run = sbs.run_mixengine(model, overrides)
    assert run.rc == 0, f"mixengine failed for {name} (rc {run.rc}): {run.stderr[-500:]}"
    return run, overrides


def _parse(path):
    """gcodeparser's reading of the file: {line index: [GcodeLine]} and the file's lines."""
    from gcodeparser import parse_gcode_lines
    text = open(path).read()
    parsed = {}
    for line in parse_gcode_lines(text):
        parsed.setdefault(line.line_index, []).append(line)
    return parsed, text.splitlines()


def _parse_errors(parsed, lines):
    """Lines whose command gcodeparser misses or misreads: each code line must give exactly one command
    equal to its first word, and for G0/G1/G92 exactly the line's words with the numbers they spell."""
    errors = []
    for i, text in enumerate(lines):
        code = text.split(";", 1)[0].strip()
        got = parsed.get(i, [])
        if not code:
            if got:
                errors.append((i + 1, text, "command in a comment line"))
            continue
        words = code.split()
        if len(got) != 1 or got[0].command_str != words[0].upper():
            errors.append((i + 1, text, [g.command_str for g in got]))
            continue
        if words[0].upper() in ("G0", "G1", "G92"):
            want = {}
            for w in words[1:]:
                m = WORD.fullmatch(w)
                want[m.group(1).upper() if m else w] = m.group(2) if m else None
            params = got[0].params
            ok = set(params) == set(want) and all(
                isinstance(params[k], (int, float)) and not isinstance(params[k], bool)
                and _number(want[k]) is not None and math.isclose(params[k], _number(want[k]), abs_tol=1e-9)
                for k in want)
            if not ok:
                errors.append((i + 1, text, params))
    return errors


def _number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def _walk(parsed, volume):
    """Moves outside the volume [(line, X, Y, Z)], the largest |E| written in absolute mode, net E fed."""
    (x0, x1), (y0, y1), (z0, z1) = volume
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    rel_xyz = rel_e = False
    e = net = max_abs = 0.0
    outside = []
    for index in sorted(parsed):
        for line in parsed[index]:
            cmd, p = line.command, line.params
            if cmd in (("G", 90), ("G", 91)):
                rel_xyz = rel_e = cmd[1] == 91
            elif cmd in (("M", 82), ("M", 83)):
                rel_e = cmd[1] == 83
            elif cmd == ("G", 28):
                for k in "XYZ":
                    if k in p or not any(a in p for a in "XYZ"):
                        pos[k] = 0.0
            elif cmd == ("G", 92):
                for k in "XYZ":
                    if k in p:
                        pos[k] = float(p[k])
                if "E" in p or not p:
                    e = float(p.get("E", 0.0))
            elif cmd in (("G", 0), ("G", 1)):
                for k in "XYZ":
                    if k in p:
                        pos[k] = pos[k] + float(p[k]) if rel_xyz else float(p[k])
                if any(k in p for k in "XYZ") and not (
                        x0 - POSITION_SLACK_MM <= pos["X"] <= x1 + POSITION_SLACK_MM
                        and y0 - POSITION_SLACK_MM <= pos["Y"] <= y1 + POSITION_SLACK_MM
                        and z0 - POSITION_SLACK_MM <= pos["Z"] <= z1 + POSITION_SLACK_MM):
                    outside.append((index + 1, pos["X"], pos["Y"], pos["Z"]))
                if "E" in p:
                    value = float(p["E"])
                    delta = value if rel_e else value - e
                    if not rel_e:
                        max_abs = max(max_abs, abs(value))
                    e += delta
                    net += delta
    return outside, max_abs, net


def _volume(g):
    w, d, h = (float(g[k]) for k in ("machine_width", "machine_depth", "machine_height"))
    if g.get("machine_center_is_zero", "False").lower() == "true":
        return (-w / 2, w / 2), (-d / 2, d / 2), (0.0, h)
    return (0.0, w), (0.0, d), (0.0, h)


@pytest.mark.parametrize("name", sorted(VARIANTS))
def test_parses_and_stays_in_build_volume(engine, corpus, report, name):
    run, overrides = _sliced(corpus, name)
    g, e = sbs.resolve(overrides)
    parsed, lines = _parse(run.gcode)
    errors = _parse_errors(parsed, lines)
    assert not errors, f"{name}: {len(errors)} lines gcodeparser does not read as written, e.g. {errors[:5]}"
    assert any(line.command == ("G", 1) for group in parsed.values() for line in group), f"{name}: no G1 at all"
    outside, max_abs, net = _walk(parsed, _volume(g))
    bound = E_BOUND_MM
    if g["machine_gcode_flavor"] in VOLUMETRIC:
        bound *= math.pi * (float(e["material_diameter"]) / 2) ** 2
    report(f"validity {name}: {len(lines)} lines, largest absolute E {max_abs:.3f} (bound {bound:.0f}), "
           f"net E {net:.1f}, {len(outside)} moves outside the build volume")
    assert not outside, f"{name}: {len(outside)} moves outside {_volume(g)} (line, X, Y, Z): {outside[:5]}"
    assert max_abs <= bound, f"{name}: absolute E reaches {max_abs:.3f} > {bound:.0f} between G92 resets"


def test_absolute_and_relative_extrusion_feed_the_same_filament(engine, corpus):
    """Seed 004: both modes give the same total. Each relative E word is rounded to 1e-5; a writer that
    carries the rounding remainder stays within 1e-5 of the absolute total, one that does not drifts by up
    to 5e-6 per move: 0.01 mm + 0.01 % covers the first and is far below a lost or doubled move."""
    totals = {}
    for name in ("marlin_absolute", "marlin_relative"):
        run, _ = _sliced(corpus, name)
        parsed, _ = _parse(run.gcode)
        totals[name] = _walk(parsed, ((-math.inf, math.inf),) * 3)[2]
    a, r = totals["marlin_absolute"], totals["marlin_relative"]
    assert abs(a - r) <= 0.01 + 1e-4 * abs(a), f"net E: absolute {a:.5f} mm, relative {r:.5f} mm"


@pytest.mark.parametrize("name", ["marlin_absolute", "marlin_relative", "volumetric", "support"])
def test_numbers_are_compact(engine, corpus, name):
    """Issue 5: XYZ with at most 3 decimals, E with at most 5, no trailing zeros, never '-0'. Checked on the
    moves after ;LAYER_COUNT: except lines of the machine's start/end code (written as the machine's
    definition spells them, e.g. the Ender-3's 'G1 X0 Y235.0')."""
    run, overrides = _sliced(corpus, name)
    g, e = sbs.resolve(overrides)
    verbatim = {line.strip() for k in ("machine_start_gcode", "machine_end_gcode", "machine_extruder_start_code",
                                       "machine_extruder_end_code") for values in (g, e)
                for line in values.get(k, "").splitlines()}
    bad, started = [], False
    with open(run.gcode) as f:
        for number, text in enumerate(f, 1):
            if text.startswith(";LAYER_COUNT:"):
                started = True
            code = text.split(";", 1)[0].split()
            if not started or not code or code[0] not in ("G0", "G1") or text.strip() in verbatim:
                continue
            for w in code[1:]:
                letter, digits = w[0], w[1:]
                decimals = len(digits.split(".", 1)[1]) if "." in digits else 0
                limit = {"X": 3, "Y": 3, "Z": 3, "E": 5}.get(letter)
                negative_zero = re.fullmatch(r"-0*\.?0*", digits) is not None
                trailing = "." in digits and digits.endswith(("0", "."))
                if negative_zero or trailing or (limit is not None and decimals > limit) or "e" in digits.lower():
                    bad.append((number, text.strip()))
                    break
    assert not bad, f"{name}: {len(bad)} moves with badly formatted numbers, e.g. {bad[:5]}"
