"""machine_gcode_flavor BFB and MACH3 written as CuraEngine 4.13 writes them (issue 19), compared byte for byte
with Debian's CuraEngine on side_by_side's "parity" model (the Ender-3, every resolved value given to both).

MACH3: extruder 0's axis is A instead of E (moves, primes, retractions, G92 resets); the header is ;FLAVOR:Mach3,
;TIME: and the bounds (no ;Filament used:). BFB (Bits From Bytes): RPM-driven extrusion — M108 S<rpm> / M101
before the first extrusion after a stop, M103 before the first travel after extruding, every move
"G1 X Y Z F", no E words, M227 auto-retraction after the start code, G11 before the last move onto an outer
wall, and every line the engine writes ends in CR LF (the user's start/end code keeps its own line ends).
"""
import re

import side_by_side as sbs

MODEL = "parity"


def _pair(flavor):
    overrides = {"machine_gcode_flavor": flavor}
    mix, cura = sbs.run_mixengine(MODEL, overrides), sbs.run_cura(MODEL, overrides)
    assert mix.rc == 0 and cura.rc == 0, (mix.stderr, cura.stderr)
    return mix.gcode.read_bytes(), cura.gcode.read_bytes()


def _between(data, start, end):
    """data from the first `start` up to (not including) the first `end` after it."""
    i = data.index(start)
    return data[i:data.index(end, i)]


def _engine_lines(text):
    """The lines of the print itself (from ;LAYER:0 to the last ;TIME_ELAPSED:)."""
    body = text[text.index(";LAYER:0"):text.rindex(";TIME_ELAPSED:")]
    return body.splitlines()


def test_mach3_writes_the_a_axis_as_curaengine():
    mix, cura = _pair("MACH3")
    assert mix.startswith(b";FLAVOR:Mach3\n;TIME:") and cura.startswith(b";FLAVOR:Mach3\n;TIME:")
    assert b";Filament used" not in mix and b";Layer height" not in mix
    # From the temperatures to the end of the start code, and the line after it: byte for byte.
    cura_start = _between(cura, b"M190 S60\n", b"G92 A0\n") + b"G92 A0\n"
    assert _between(mix, b"M190 S60\n", b";LAYER_COUNT").startswith(cura_start)
    for text in (mix.decode(), cura.decode()):
        lines = _engine_lines(text)
        moves = [line for line in lines if line.startswith(("G0", "G1"))]
        assert not any(re.search(r" E-?[0-9.]", line) for line in moves), "an E word in a MACH3 print"
        assert sum(bool(re.search(r" A-?[0-9.]+$", line)) for line in moves) > 1000
    # MixEngine's A words are exactly its E words of the Marlin print.
    marlin = sbs.run_mixengine(MODEL, {"machine_gcode_flavor": "RepRap (Marlin/Sprinter)"}).gcode.read_text()
    as_e = [re.sub(r" A(-?[0-9.]+)", r" E\1", line) for line in _engine_lines(mix.decode())]
    assert as_e == _engine_lines(marlin)


def test_bfb_writes_rpm_extrusion_and_crlf_as_curaengine():
    mix, cura = _pair("BFB")
    header = b";FLAVOR:BFB\r\n;TIME:"
    assert mix.startswith(header) and cura.startswith(header)
    assert b";Filament used" not in mix
    # The start: temperatures, the user's start code with its own line ends inside, the resets and M227.
    start = _between(cura, b"M190 S60\r\n", b";LAYER:0")
    assert _between(mix, b"M190 S60\r\n", b";LAYER:0") == start
    assert b";enable auto-retraction\r\nM227 S16640 P16640\r\nG92 E0\r\n;LAYER_COUNT:" in start
    # The end after the last layer: byte for byte (an empty CR LF line after the user's end code).
    assert mix[mix.rindex(b"M140 S0\r\nM107\r\n"):] == cura[cura.rindex(b"M140 S0\r\nM107\r\n"):]
    for data in (mix, cura):
        text = data.decode()
        assert "\n" not in text.replace("\r\n", "").split(";LAYER:0", 1)[1].rsplit("G91", 1)[0]
        lines = _engine_lines(text)
        moves = [line for line in lines if line.startswith("G")]
        assert all(re.fullmatch(r"G1 X-?[0-9.]+ Y-?[0-9.]+ Z[0-9.]+ F[0-9.]+|G11", m) for m in moves), \
            [m for m in moves if not re.fullmatch(r"G1 X-?[0-9.]+ Y-?[0-9.]+ Z[0-9.]+ F[0-9.]+|G11", m)][:3]
        commands = {line.split()[0] for line in lines if line and not line.startswith(";")}
        assert {"M101", "M103", "M108", "G11"} <= commands and "G0" not in commands and "G10" not in commands
        # The motor is started (M101) right after each speed change, and only after a stop (M103).
        running = True
        for i, line in enumerate(lines):
            if line.startswith("M108"):
                assert lines[i + 1] == "M101" and not running
            if line == "M101":
                assert not running
                running = True
            elif line == "M103":
                assert running
                running = False
            elif line == "G11":
                running = True
    # The skirt's first extrusion: the same RPM and corrected feedrate as CuraEngine's.
    first = lambda data: re.search(rb"M108 S([0-9.]+)\r\nM101\r\nG1 [^\r]* F([0-9.]+)\r\n", data).groups()
    assert first(mix) == first(cura) == (b"10", b"1199.8")
