"""Reading colour-mixing G-code back, independently of MixEngine (tests/python/test_mixing.py).

gcodeparser (PyPI) splits the lines into commands and parameters; on top of it a small model of each
firmware accumulates the filament per channel the way that firmware would:

  single, marlin_m163, marlin_m165, rrf_m567   one E axis (M82/M83, G90/G91, G92 E); the mix is
        the one the commands set (M163 S/P + M164 S<tool> + T<tool>; M165 A B C D H; M567 P E a:b)
  eb_axes      E and B; M82/M83 (and G91) switch both, G92 sets each letter given (MakerPi)
  klipper_b    E as Klipper's gcode_move (relative when G91 or M83); B is a manual_stepper axis:
               it follows G90/G91 only, G92 never touches it, MANUAL_STEPPER SET_POSITION sets it
               while unregistered and GCODE_AXIS=B registers it
  rrf_colon    E a:b[:c…] per move, accepted only in relative extrusion mode (as RepRapFirmware)

gcodeparser drops what follows ':' in a value and skips lines such as MANUAL_STEPPER, so those are
read from the raw line (GcodeLine.line_index). png_pixels() decodes the --preview picture (zlib and the
five PNG filters), again without MixEngine's code.
"""
import math
import re
import struct
import zlib
from dataclasses import dataclass, field

from gcodeparser import parse_gcode_lines

M165_LETTERS = "ABCDH"


@dataclass
class Move:
    layer: int
    z: float
    xy: bool
    amounts: list  # filament moved per channel on this line (mm), retractions negative
    feature: str = ""  # the ;TYPE: in force ("SUPPORT", "SKIRT", ...)
    start: tuple = (0.0, 0.0)  # XY where the move starts (mm)
    end: tuple = (0.0, 0.0)  # XY where it ends
    mesh: str = ""  # the last ;MESH: name

    @property
    def total(self):
        return sum(self.amounts)


@dataclass
class Reading:
    moves: list = field(default_factory=list)
    b_position: float = 0.0  # Klipper: the manual_stepper's final position
    mix_commands: int = 0

    def extrusions(self):
        """Moves that lay material: XY motion and filament forward."""
        return [m for m in self.moves if m.xy and m.total > 0]

    def layer_totals(self):
        """{layer: (z, [mm per channel])} over the extrusions."""
        out = {}
        for m in self.extrusions():
            z, sums = out.setdefault(m.layer, (m.z, [0.0] * len(m.amounts)))
            for c, a in enumerate(m.amounts):
                sums[c] += a
        return out


class FirmwareError(AssertionError):
    pass


def _colon_values(raw, letter):
    match = re.search(rf"\b{letter}(-?[\d.]+(?::-?[\d.]+)*)", raw.split(";")[0])
    return [float(v) for v in match.group(1).split(":")] if match else None


class _Reader:
    def __init__(self, dialect, channels):
        self.dialect, self.channels = dialect, channels
        self.abs_coord, self.abs_extrude = True, True
        self.pos = {"E": 0.0, "B": 0.0}
        self.layer, self.z, self.feature = None, 0.0, ""
        self.xy, self.mesh = (0.0, 0.0), ""
        # Power-on state: Marlin's virtual tool t is filament t and tool 0 is selected; RepRapFirmware's
        # default mix is the first drive only.
        self.vtools = {t: [1.0 if c == t else 0.0 for c in range(channels)] for t in range(channels)}
        self.collect, self.selected, self.mix = {}, 0, self.vtools[0]
        self.klipper_registered = False
        self.reading = Reading()

    # --- what each firmware does with one command ---
    def e_relative(self):
        return not self.abs_coord or not self.abs_extrude

    def b_relative(self):
        if self.dialect == "klipper_b":
            return not self.abs_coord  # G90/G91 only
        return self.e_relative()  # MakerPi: M82/M83 switch both

    def axis_move(self, letter, value, relative):
        old = self.pos[letter]
        self.pos[letter] = old + value if relative else value
        return self.pos[letter] - old

    def mix_command(self, cmd, p, raw):
        if cmd == ("M", 163):
            self.collect[int(p["S"])] = float(p["P"])
        elif cmd == ("M", 164):
            total = sum(self.collect.values())
            self.vtools[int(p["S"])] = [self.collect.get(c, 0.0) / total for c in range(self.channels)]
            self.collect = {}
            if self.selected == int(p["S"]):
                self.mix = self.vtools[self.selected]
        elif cmd[0] == "T" and self.dialect == "marlin_m163":
            self.selected = cmd[1]
            self.mix = self.vtools[self.selected]
        elif cmd == ("M", 165):
            weights = [float(p.get(letter, 0.0)) for letter in M165_LETTERS[: self.channels]]
            self.mix = [w / sum(weights) for w in weights]
        elif cmd == ("M", 567):
            weights = _colon_values(raw, "E")
            self.mix = weights + [0.0] * (self.channels - len(weights))
        else:
            return False
        self.reading.mix_commands += 1
        return True

    def klipper_command(self, raw):
        words = dict(w.split("=", 1) for w in raw.split()[1:] if "=" in w)
        if "GCODE_AXIS" in words:
            self.klipper_registered = words["GCODE_AXIS"] == "B"
        elif "SET_POSITION" in words:
            if self.klipper_registered:
                raise FirmwareError("SET_POSITION while registered as an axis")
            self.pos["B"] = float(words["SET_POSITION"])

    def move(self, p, raw):
        if "Z" in p:
            self.z = self.z + p["Z"] if not self.abs_coord else float(p["Z"])
        start = self.xy
        x = float(p["X"]) + (start[0] if not self.abs_coord else 0.0) if "X" in p else start[0]
        y = float(p["Y"]) + (start[1] if not self.abs_coord else 0.0) if "Y" in p else start[1]
        self.xy = (x, y)
        amounts = None
        if self.dialect == "rrf_colon" and "E" in p:
            values = _colon_values(raw, "E")
            if len(values) > 1 and not self.e_relative():
                raise FirmwareError("Multiple E parameters in G1 commands are not supported in absolute extrusion mode")
            if len(values) == 1:  # one value: the tool's mix (M567, by default the first drive only)
                delta = self.axis_move("E", values[0], self.e_relative())
                amounts = [delta * share for share in self.mix]
            else:
                amounts = values + [0.0] * (self.channels - len(values))
        elif self.dialect in ("eb_axes", "klipper_b") and ("E" in p or "B" in p):
            if "B" in p and self.dialect == "klipper_b" and not self.klipper_registered:
                raise FirmwareError("B move before the manual_stepper is registered as axis B")
            amounts = [self.axis_move("E", float(p["E"]), self.e_relative()) if "E" in p else 0.0,
                       self.axis_move("B", float(p["B"]), self.b_relative()) if "B" in p else 0.0]
        elif "E" in p:
            delta = self.axis_move("E", float(p["E"]), self.e_relative())
            amounts = [delta * share for share in self.mix]
        if amounts is not None and self.layer is not None:
            self.reading.moves.append(Move(self.layer, self.z, "X" in p or "Y" in p, amounts, self.feature, start,
                                           self.xy, self.mesh))

    def line(self, parsed, raw):
        if raw.startswith("MANUAL_STEPPER"):
            self.klipper_command(raw)
            return
        if parsed is None:
            return
        cmd, p = parsed.command, parsed.params
        if parsed.comment.startswith("LAYER:") and cmd[0] == ";":
            self.layer = int(parsed.comment[6:])
        elif parsed.comment.startswith("TYPE:") and cmd[0] == ";":
            self.feature = parsed.comment[5:].strip()
        elif parsed.comment.startswith("MESH:") and cmd[0] == ";":
            self.mesh = parsed.comment[5:]
        elif cmd in (("M", 82), ("M", 83)):
            self.abs_extrude = cmd[1] == 82
        elif cmd in (("G", 90), ("G", 91)):
            self.abs_coord = cmd[1] == 90
        elif cmd == ("G", 92):
            for letter in ("E", "B"):
                if letter in p and not (letter == "B" and self.dialect == "klipper_b"):
                    self.pos[letter] = float(p[letter])
        elif cmd in (("G", 0), ("G", 1)):
            self.move(p, raw)
        else:
            self.mix_command(cmd, p, raw)


def read_mixing_gcode(path, dialect, channels=2, b_start=0.0):
    """Interprets the G-code file as the firmware of `dialect` would. `b_start`: where a Klipper
    manual_stepper stands before the print (a previous print may have left it anywhere)."""
    text = open(path).read()
    lines = text.splitlines()
    parsed = {g.line_index: g for g in parse_gcode_lines(text, include_comments=True)}
    reader = _Reader(dialect, channels)
    reader.pos["B"] = b_start
    for i, raw in enumerate(lines):
        reader.line(parsed.get(i), raw.strip())
    reader.reading.b_position = reader.pos["B"]
    return reader.reading


def seed_share_b(color_a, color_b, percent):
    """Seed 001's three cases: the share of filament B at `percent` of the model height."""
    if percent <= color_a:
        return 0.0
    if percent > color_b:
        return 1.0
    return (percent - color_a) / (color_b - color_a)


def box_stl(path, size_x, size_y, size_z, centre_x=0.0):
    """An ASCII STL box with its bottom at z = 0, centred on x = centre_x, y = 0."""
    x0, x1 = centre_x - size_x / 2, centre_x + size_x / 2
    y0, y1, z0, z1 = -size_y / 2, size_y / 2, 0.0, size_z
    corners = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    out = ["solid box"]
    for a, b, c, d in quads:
        for tri in ((a, b, c), (a, c, d)):
            out.append("facet normal 0 0 0\nouter loop")
            out += ["vertex %g %g %g" % corners[i] for i in tri]
            out.append("endloop\nendfacet")
    out.append("endsolid box")
    path.write_text("\n".join(out) + "\n")
    return path


def relative_error(a, b):
    return abs(a - b) / max(abs(b), 1e-12)


def isclose_all(values, expected, tolerance):
    return all(math.isclose(v, e, abs_tol=tolerance) for v, e in zip(values, expected))


def png_pixels(path):
    """Width, height and RGB rows of an 8-bit RGB PNG, decoded here (zlib + the five PNG filters)."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        assert zlib.crc32(kind + body) == struct.unpack(">I", data[pos + 8 + length:pos + 12 + length])[0]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            assert (depth, color) == (8, 2)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * 3, [], bytearray(width * 3)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            left = line[x - 3] if x >= 3 else 0
            up, up_left = prev[x], prev[x - 3] if x >= 3 else 0
            if f == 1:
                line[x] = (line[x] + left) & 255
            elif f == 2:
                line[x] = (line[x] + up) & 255
            elif f == 3:
                line[x] = (line[x] + (left + up) // 2) & 255
            elif f == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                line[x] = (line[x] + (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, rows
