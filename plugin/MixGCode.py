"""The extrusions of a mixing print and the colour the engine predicts for each, read from its G-code
(no Cura imports).

Cura holds the G-code of a slice as a list of chunks (scene.gcode_dict): the header, the start code,
one chunk per layer starting with ";LAYER:n", the end code. This reads, per layer and in print order,
every move that extrudes while moving in X/Y: where it ends (mm, machine frame), its amount (filament
units of the E axis: mm, or mm3 for volumetric flavours) and the colour in force.

The colour is the engine's own: in a mixing print it writes ";PREDICTED_COLOR:#rrggbb" before an
extruding move whenever the predicted colour of what leaves the nozzle (its pigment model, after the
mixing chamber) changes, and before the first extrusion of every layer; that colour holds for every
extruding move until the next such comment. This module computes no colour: a move before any such
comment (an older engine) or after a malformed one has none.

Whether a move extrudes depends on how the dialect of mixing.def.json carries the filament:

  eb_axes      E and B words on every move; M82/M83, G90/G91 and G92 act on both
  klipper_b    E as usual, B a Klipper manual_stepper: follows G90/G91 only (not M82/M83), never
               reset by G92; MANUAL_STEPPER ... SET_POSITION= sets it
  rrf_colon    "E a:b[:c...]" words, relative
  marlin_m163, marlin_m165, rrf_m567
               a mix command sets the shares of the following moves; E is the total

Moves outside a ";LAYER:" chunk (start and end code, purge lines) set the state but are not listed.
"""
import re

import numpy

DIALECTS = ("eb_axes", "klipper_b", "rrf_colon", "marlin_m163", "marlin_m165", "rrf_m567")
PREDICTED = ";PREDICTED_COLOR:"
_HEX = re.compile(r"#[0-9a-fA-F]{6}")


class LayerMoves:
    """The extruding X/Y moves of one layer, in print order."""

    def __init__(self, layer_id):
        self.layer_id = layer_id
        self.xy = []  # (x, y) end points, mm
        self.amount = []  # axis units (mm of filament, or mm3), all channels together
        self.colour = []  # index into GCodeMoves.colours, -1: no predicted colour

    def arrays(self):
        return (numpy.asarray(self.xy, dtype=numpy.float64).reshape(-1, 2),
                numpy.asarray(self.amount, dtype=numpy.float64), numpy.asarray(self.colour, dtype=numpy.int64))


class GCodeMoves:
    """Result of read(): layers (id -> LayerMoves) in print order and the distinct predicted colours."""

    def __init__(self):
        self.layers = {}
        self.order = []  # layer ids in print order
        self.colours = []  # "#rrggbb" (lower case), in order of first appearance
        self._colour_index = {}
        self.malformed = 0  # PREDICTED_COLOR comments without a #rrggbb

    def colourIndex(self, text):
        if text not in self._colour_index:
            self._colour_index[text] = len(self.colours)
            self.colours.append(text)
        return self._colour_index[text]

    def colourTable(self):
        """(distinct colours, 3) sRGB in 0..1; row i is colour index i."""
        rows = [[int(h[i:i + 2], 16) / 255.0 for i in (1, 3, 5)] for h in self.colours]
        return numpy.array(rows, dtype=numpy.float64).reshape(-1, 3)

    def moveColours(self):
        """{layer id: (k, 3) sRGB of each extruding move}, NaN where a move has no predicted colour."""
        table = numpy.vstack((self.colourTable(), numpy.full((1, 3), numpy.nan)))  # index -1: the NaN row
        return {i: table[numpy.asarray(self.layers[i].colour, dtype=numpy.int64)] for i in self.order}

    def extrusions(self):
        return sum(len(self.layers[i].xy) for i in self.order)

    def predicted(self):
        """How many extruding moves have a predicted colour."""
        return sum(sum(1 for c in self.layers[i].colour if c >= 0) for i in self.order)


def _words(line):
    """{letter: text} of a G-code line without its comment."""
    code = line.split(";", 1)[0].split()
    return code[0].upper() if code else "", {w[0].upper(): w[1:] for w in code[1:] if w}


def _float(text, default=0.0):
    try:
        return float(text)
    except (TypeError, ValueError):
        return default


class _Reader:
    def __init__(self, dialect):
        self.dialect = dialect
        self.result = GCodeMoves()
        self.xy = [0.0, 0.0]
        self.axes_relative = False  # G91 (X, Y, Z, and E: relative when G91 or M83, as Klipper and the
        self.extrude_relative = False  # M83   firmware models of tests/python/mixing_gcode.py read it)
        self.e = 0.0
        self.b = 0.0
        self.colour = -1  # the predicted colour in force
        self.layer = None

    # ---- state commands --------------------------------------------------------------------
    def command(self, code, words, line):
        if code in ("G0", "G1"):
            self.move(words)
        elif code in ("G90", "G91"):
            self.axes_relative = code == "G91"
        elif code in ("M82", "M83"):
            self.extrude_relative = code == "M83"
        elif code == "G92":
            self.setPosition(words)
        elif code == "MANUAL_STEPPER" and "SET_POSITION=" in line.upper():
            self.b = _float(line.upper().split("SET_POSITION=", 1)[1].split()[0])

    def setPosition(self, words):
        for axis, index in (("X", 0), ("Y", 1)):
            if axis in words:
                self.xy[index] = _float(words[axis])
        if "E" in words and ":" not in words["E"]:
            self.e = _float(words["E"])
        if "B" in words and self.dialect != "klipper_b":
            self.b = _float(words["B"])

    def predictedColour(self, line):
        found = _HEX.match(line[len(PREDICTED):].strip())
        if found is None:
            self.result.malformed += 1
            self.colour = -1
        else:
            self.colour = self.result.colourIndex(found.group(0).lower())

    # ---- moves -----------------------------------------------------------------------------
    def axisDelta(self, words, letter, current, relative):
        if letter not in words:
            return 0.0, current
        value = _float(words[letter])
        return (value, current + value) if relative else (value - current, value)

    def amounts(self, words):
        """Per-axis forward amounts of the move."""
        if self.dialect == "rrf_colon" and ":" in words.get("E", ""):
            return [_float(p) for p in words["E"].split(":")]
        e_relative = self.axes_relative or self.extrude_relative
        d_e, self.e = self.axisDelta(words, "E", self.e, e_relative)
        if self.dialect in ("eb_axes", "klipper_b"):
            # E/B: M82/M83 switch both; Klipper's manual_stepper B follows G90/G91 only
            b_relative = e_relative if self.dialect == "eb_axes" else self.axes_relative
            d_b, self.b = self.axisDelta(words, "B", self.b, b_relative)
            return [d_e, d_b]
        return [d_e]  # mix commands: E is the total

    def move(self, words):
        amounts = self.amounts(words)
        start = list(self.xy)
        for axis, index in (("X", 0), ("Y", 1)):
            if axis in words:
                value = _float(words[axis])
                self.xy[index] = self.xy[index] + value if self.axes_relative else value
        if self.layer is None or self.xy == start:
            return
        total = sum(max(a, 0.0) for a in amounts)
        if total <= 1e-9:
            return
        self.layer.xy.append(tuple(self.xy))
        self.layer.amount.append(total)
        self.layer.colour.append(self.colour)

    # ---- chunks ----------------------------------------------------------------------------
    def chunk(self, text):
        self.layer = None  # the end code is a chunk of its own
        for line in text.splitlines():
            if not line:
                continue
            first = line[0]
            if first == ";":
                if line.startswith(";LAYER:"):
                    self.startLayer(line)
                elif line.startswith(PREDICTED):
                    self.predictedColour(line)
                continue
            if first not in "GMgm" and not line.startswith("MANUAL_STEPPER"):
                continue
            code, words = _words(line)
            self.command(code, words, line)

    def startLayer(self, line):
        try:
            layer_id = int(line[7:].strip())
        except ValueError:
            return
        if layer_id not in self.result.layers:
            self.result.layers[layer_id] = LayerMoves(layer_id)
            self.result.order.append(layer_id)
        self.layer = self.result.layers[layer_id]


def read(chunks, dialect):
    """The extruding moves of `chunks` (Cura's list of G-code chunks, or [whole file]) per layer, each with
    the predicted colour in force."""
    if dialect not in DIALECTS:
        raise ValueError("unknown mixing dialect %r" % dialect)
    reader = _Reader(dialect)
    for text in chunks:
        reader.chunk(text)
    return reader.result


def viewLayerIds(result):
    """{abs layer number of Cura's layer view: G-code layer id}, numbered as Cura 4.13's ProcessSlicedLayersJob
    numbers the layers it receives: from the lowest id, with the ids at and above 0 moved down to follow the
    negative (raft) ones directly, so the ids a raft's air gap leaves out take no place in the view."""
    ids = sorted(i for i in result.order if result.layers[i].xy)
    if not ids:
        return {}
    negative = sum(1 for i in ids if i < 0)
    lowest = ids[0]
    return {(i + negative if i >= 0 and negative else i - lowest): i for i in ids}
