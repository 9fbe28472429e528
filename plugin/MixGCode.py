"""The filament mix of every extrusion, read from the G-code the engine wrote (no Cura imports).

Cura holds the G-code of a slice as a list of chunks (scene.gcode_dict): the header, the start code,
one chunk per layer starting with ";LAYER:n", the end code. This reads, per layer and in print order,
every move that extrudes while moving in X/Y: where it ends (mm, machine frame), its mix (shares of
the channels, adding up to 1) and its amount (filament units of the E axis: mm, or mm3 for
volumetric flavours). Each dialect of mixing.def.json carries the mix its own way:

  eb_axes      E and B words on every move; M82/M83, G90/G91 and G92 act on both
  klipper_b    E as usual, B a Klipper manual_stepper: follows G90/G91 only (not M82/M83), never
               reset by G92; MANUAL_STEPPER ... SET_POSITION= sets it
  rrf_colon    "E a:b[:c...]" words, relative
  marlin_m163  "M163 S<i> P<w>" ... "M164": the mix of the following moves, E the total
  marlin_m165  "M165 A B C D H I" (DIRECT_MIXING_IN_G1): the mix of the following moves, E the total
  rrf_m567     "M567 P<tool> E a:b[:c...]": the mix of the following moves, E the total

Moves outside a ";LAYER:" chunk (start and end code, purge lines) set the state but are not listed.
"""
import numpy

DIALECTS = ("eb_axes", "klipper_b", "rrf_colon", "marlin_m163", "marlin_m165", "rrf_m567")
M165_LETTERS = "ABCDHI"  # Marlin's mixing channel letters of M165


class LayerMoves:
    """The extruding X/Y moves of one layer, in print order."""

    def __init__(self, layer_id):
        self.layer_id = layer_id
        self.xy = []  # (x, y) end points, mm
        self.mix = []  # index into GCodeMixes.mixes
        self.amount = []  # axis units (mm of filament, or mm3)

    def arrays(self):
        return (numpy.asarray(self.xy, dtype=numpy.float64).reshape(-1, 2),
                numpy.asarray(self.mix, dtype=numpy.int64), numpy.asarray(self.amount, dtype=numpy.float64))


class GCodeMixes:
    """Result of read(): layers (id -> LayerMoves) in print order and the distinct mixes."""

    def __init__(self, channels):
        self.channels = channels
        self.layers = {}
        self.order = []  # layer ids in print order
        self._mixes = {}  # rounded tuple -> index

    def mixIndex(self, shares):
        total = sum(shares)
        if total <= 0:
            return None
        key = tuple(round(s / total, 4) for s in shares[:self.channels]) + (0.0,) * (self.channels - len(shares))
        if key not in self._mixes:
            self._mixes[key] = len(self._mixes)
        return self._mixes[key]

    @property
    def mixes(self):
        """(distinct mixes, channels) array; row i is mix index i."""
        table = numpy.zeros((len(self._mixes), self.channels))
        for key, index in self._mixes.items():
            table[index] = key
        return table

    def hasMix(self):
        return bool(self._mixes) and any(self.layers[i].xy for i in self.order)


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
    def __init__(self, dialect, channels):
        self.dialect = dialect
        self.result = GCodeMixes(channels)
        self.channels = channels
        self.xy = [0.0, 0.0]
        self.axes_relative = False  # G91 (X, Y, Z, and E: relative when G91 or M83, as Klipper and the
        self.extrude_relative = False  # M83   firmware models of tests/python/mixing_gcode.py read it)
        self.e = 0.0
        self.b = 0.0
        self.state_mix = [1.0] + [0.0] * (channels - 1)  # mix-command dialects: the mix in force
        self.m163 = [0.0] * max(channels, 6)
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
        elif code in ("M163", "M164", "M165", "M567"):
            self.mixCommand(code, words)
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

    def mixCommand(self, code, words):
        if code == "M163":
            index = int(_float(words.get("S"), -1))
            if 0 <= index < len(self.m163):
                self.m163[index] = _float(words.get("P"))
        elif code == "M164":
            self.state_mix = list(self.m163[:self.channels])
        elif code == "M165":
            self.state_mix = [_float(words.get(letter)) for letter in M165_LETTERS[:self.channels]]
        elif code == "M567" and "E" in words:
            self.state_mix = [_float(part) for part in words["E"].split(":")]

    # ---- moves -----------------------------------------------------------------------------
    def axisDelta(self, words, letter, current, relative):
        if letter not in words:
            return 0.0, current
        value = _float(words[letter])
        return (value, current + value) if relative else (value - current, value)

    def amounts(self, words):
        """Per-channel forward amounts of the move (None: the state's mix with total E)."""
        if self.dialect == "rrf_colon" and ":" in words.get("E", ""):
            return [_float(p) for p in words["E"].split(":")]
        e_relative = self.axes_relative or self.extrude_relative
        d_e, self.e = self.axisDelta(words, "E", self.e, e_relative)
        if self.dialect in ("eb_axes", "klipper_b"):
            # E/B: M82/M83 switch both; Klipper's manual_stepper B follows G90/G91 only
            b_relative = e_relative if self.dialect == "eb_axes" else self.axes_relative
            d_b, self.b = self.axisDelta(words, "B", self.b, b_relative)
            return [d_e, d_b]
        return [d_e * s for s in self.state_mix]

    def move(self, words):
        shares = self.amounts(words)
        start = list(self.xy)
        for axis, index in (("X", 0), ("Y", 1)):
            if axis in words:
                value = _float(words[axis])
                self.xy[index] = self.xy[index] + value if self.axes_relative else value
        if self.layer is None or self.xy == start:
            return
        forward = [max(s, 0.0) for s in shares]
        total = sum(forward)
        if total <= 1e-9:
            return
        index = self.result.mixIndex(forward)
        self.layer.xy.append(tuple(self.xy))
        self.layer.mix.append(index)
        self.layer.amount.append(total)

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
                continue
            if first not in "GMgmM" and not line.startswith("MANUAL_STEPPER"):
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


def read(chunks, dialect, channels):
    """The extruding moves of `chunks` (Cura's list of G-code chunks, or [whole file]) per layer."""
    if dialect not in DIALECTS:
        raise ValueError("unknown mixing dialect %r" % dialect)
    reader = _Reader(dialect, max(1, int(channels)))
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
