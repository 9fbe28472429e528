"""Structural checks of a G-code file shared by the reliability tests (no pytest import here).

check_gcode(path) returns a GcodeCheck:
  layer_count   the value of ;LAYER_COUNT: (None when absent)
  layers        the number of ;LAYER:n comment lines of the model (n >= 0; raft layers, negative, are not
                counted in ;LAYER_COUNT:, as CuraEngine writes it)
  problems      a list of readable defects, empty for a valid file:
                - gcodeparser (an independent parser, PyPI) fails on the file, or reads a motion value
                  (G0/G1/G2/G3/G92) that is not a finite number (it reads "Xnan" as a flag, "X1e400" as
                  two words);
                - a motion line, as written, holds a word that is not a letter and a plain decimal number;
                - more model ;LAYER: lines than ;LAYER_COUNT:, a model layer numbered at or above it, none at
                  all where ;LAYER_COUNT: is positive, or no ;LAYER_COUNT:. (As CuraEngine 4.13, a layer with
                  nothing to print is left out but still counted, so there may be fewer ;LAYER: lines.)
gcodeparser is pure Python (about 40k lines a second), so it reads the first GCODEPARSER_BYTES of the
file; the written-word check and the layer count cover the whole file with compiled regular expressions.
"""
import math
import re
from dataclasses import dataclass, field

GCODEPARSER_BYTES = 4 << 20
MOTION = {("G", 0), ("G", 1), ("G", 2), ("G", 3), ("G", 92)}
MOTION_LINE = re.compile(r"^(?:G[0-3]|G92)(?=[ \t;]|$)[^;\n]*", re.M)
GOOD_MOTION = re.compile(r"G\d+(?:[ \t]+[A-Z][-+]?(?:\d+\.?\d*|\.\d+))*[ \t]*")
LAYER_LINE = re.compile(r"^;LAYER:(\d+)[ \t]*$", re.M)  # model layers only: raft layers are negative
LAYER_COUNT = re.compile(r"^;LAYER_COUNT:(-?\d+)", re.M)
MAX_LISTED = 5


@dataclass
class GcodeCheck:
    layer_count: int | None = None
    layers: int = 0
    problems: list = field(default_factory=list)


def _gcodeparser_problems(text):
    from gcodeparser import parse_gcode_lines
    bad = []
    try:
        for line in parse_gcode_lines(text):
            if line.command in MOTION:
                for key, value in line.params.items():
                    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                        bad.append(f"line {line.line_index + 1}: {key}={value!r}")
    except ValueError as e:  # gcodeparser raises on words such as "X-" or "X1.2.3"
        return [f"gcodeparser cannot parse the file: {e}"]
    if bad:
        return [f"gcodeparser reads {len(bad)} non-finite motion values, first: " + "; ".join(bad[:MAX_LISTED])]
    return []


def check_gcode(path):
    result = GcodeCheck()
    text = open(path, errors="replace").read()
    head = text if len(text) <= GCODEPARSER_BYTES else text[:text.rfind("\n", 0, GCODEPARSER_BYTES) + 1]
    result.problems += _gcodeparser_problems(head)
    malformed = [m.group(0) for m in MOTION_LINE.finditer(text) if not GOOD_MOTION.fullmatch(m.group(0))]
    if malformed:
        result.problems.append(f"{len(malformed)} motion lines with a word that is not a finite number, first: "
                               + "; ".join(repr(line) for line in malformed[:MAX_LISTED]))
    count = LAYER_COUNT.search(text)
    result.layer_count = int(count.group(1)) if count else None
    numbers = [int(m.group(1)) for m in LAYER_LINE.finditer(text)]
    result.layers = len(numbers)
    if result.layer_count is None:
        result.problems.append("no ;LAYER_COUNT: line")
    elif result.layers > result.layer_count or (numbers and max(numbers) >= result.layer_count):
        result.problems.append(f";LAYER_COUNT:{result.layer_count} but {result.layers} model ;LAYER: lines"
                               f" up to {max(numbers)}")
    elif result.layer_count > 0 and not numbers:
        result.problems.append(f";LAYER_COUNT:{result.layer_count} but no model ;LAYER: line")
    return result
