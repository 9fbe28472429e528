"""The engine's mixing report (";MIXING.*" header lines) read from the G-code, and the text of the Cura
message that tells the user what it says (no Cura imports; unit-tested).

In a mixing print MixEngine writes, at the end of the G-code header (the G-code prefix Cura receives
over the socket, the first chunk of scene.gcode_dict), for example:

    ;MIXING.CHAMBER:40.0 mm3 in 3 stages
    ;MIXING.VISIBLE_WITHIN_DE00_3:1.6%
    ;MIXING.VISIBLE_WITHIN_TOLERANCE:100.0% (0.100)
    ;MIXING.WORST:dE00 36.3 (share off by 0.098) at layer 2 X97.70 Y109.80 WALL-OUTER
    ;MIXING.PURGE_MM3:10452.0
    ;MIXING.CHANGES:148
    ;MIXING.PURGE_MM3_AT_TOLERANCE_0.200:6690.4 (needed at 0.100: 8816.2)
    ;MIXING.UNPURGED_MM3:120.0                  (only when some change could not be purged)
    ;MIXING.HINT:the models stand apart: ...    (only when one-at-a-time printing would remove the changes)

read() returns a Report (None when there is no such line: not a mixing print, or an older engine);
messageText() words it for the user, with grams beside every purge volume when the material's density
is known. A line whose value cannot be read is left out of the text (and counted in Report.malformed).
"""
import re

PREFIX = ";MIXING."
TITLE = "MixEngine: colour and purge"
VISIBLE = "the visible surface (outer walls, skin)"
TOLERANCE_LABEL = "Mix Transition Tolerance"  # mixing_transition_tolerance's label
SEQUENCE_SETTING = "print_sequence one_at_a_time"
SEQUENCE_WORDS = "Special Modes \u2192 Print Sequence \u2192 One at a Time"  # Cura's labels of that setting
FEATURES = {"WALL-OUTER": "outer wall", "WALL-INNER": "inner wall", "SKIN": "skin", "FILL": "infill",
            "SUPPORT": "support", "SUPPORT-INTERFACE": "support interface", "SKIRT": "skirt or brim",
            "PRIME-TOWER": "prime tower"}

_NUMBER = r"(-?\d+(?:\.\d+)?)"
_PERCENT = re.compile(r"^%s%%$" % _NUMBER)
_PERCENT_AT = re.compile(r"^(?:%s%%|n/a) \(%s\)$" % (_NUMBER, _NUMBER))
_CHAMBER = re.compile(r"^%s mm3 in (\d+) stages?$" % _NUMBER)
_WORST = re.compile(r"^dE00 %s \(share off by %s\) at layer (-?\d+) X%s Y%s (\S+)$" % ((_NUMBER,) * 2 + (_NUMBER,) * 2))
_LOOSER_KEY = re.compile(r"^PURGE_MM3_AT_TOLERANCE_%s$" % _NUMBER)
_LOOSER = re.compile(r"^%s \(needed at %s: %s\)$" % ((_NUMBER,) * 3))


class Report:
    """What the ;MIXING.* lines say; None where a line is absent or unreadable."""

    def __init__(self):
        self.lines = {}  # key (without ";MIXING.") -> value, as written
        self.chamber_mm3 = None  # 0 for the ideal chamber
        self.chamber_stages = None
        self.within_de00_3 = None  # percent of the visible surface; None also for "n/a" (no visible surface)
        self.within_tolerance = None  # percent
        self.tolerance = None
        self.no_visible_surface = False
        self.worst = None  # {"de00", "share_off", "layer", "x", "y", "feature"}
        self.purge_mm3 = None
        self.changes = None
        self.looser_tolerance = None  # twice the tolerance
        self.looser_mm3 = None  # what the changes would need at looser_tolerance
        self.needed_mm3 = None  # what they need at the tolerance
        self.unpurged_mm3 = None
        self.hint = None
        self.malformed = []  # keys whose value could not be read

    def asDict(self):
        return {k: v for k, v in vars(self).items()}


def headerLines(chunks):
    """{key: value} of the ;MIXING.key:value lines before the first layer (chunks: the G-code as Cura holds it,
    a list of strings, the prefix first; or one string)."""
    if isinstance(chunks, str):
        chunks = [chunks]
    found = {}
    for chunk in chunks or []:
        for line in chunk.splitlines():
            if line.startswith(";LAYER:"):
                return found
            if line.startswith(PREFIX) and ":" in line[len(PREFIX):]:
                key, value = line[len(PREFIX):].split(":", 1)
                found[key.strip()] = value.strip()
    return found


def read(chunks):
    """The Report of the G-code's ;MIXING.* lines, None when it has none."""
    lines = headerLines(chunks)
    if not lines:
        return None
    report = Report()
    report.lines = lines
    for key, value in lines.items():
        try:
            ok = _take(report, key, value)
        except ValueError:
            ok = False
        if not ok:
            report.malformed.append(key)
    return report


def _take(report, key, value):
    if key == "CHAMBER":
        if value.startswith("ideal"):
            report.chamber_mm3, report.chamber_stages = 0.0, 0
            return True
        m = _CHAMBER.match(value)
        if m:
            report.chamber_mm3, report.chamber_stages = float(m.group(1)), int(m.group(2))
        return bool(m)
    if key == "VISIBLE_WITHIN_DE00_3":
        if value == "n/a":
            report.no_visible_surface = True
            return True
        m = _PERCENT.match(value)
        if m:
            report.within_de00_3 = float(m.group(1))
        return bool(m)
    if key == "VISIBLE_WITHIN_TOLERANCE":
        m = _PERCENT_AT.match(value)
        if m:
            report.tolerance = float(m.group(2))
            if m.group(1) is None:
                report.no_visible_surface = True
            else:
                report.within_tolerance = float(m.group(1))
        return bool(m)
    if key == "WORST":
        if value == "none":
            return True
        m = _WORST.match(value)
        if m:
            report.worst = {"de00": float(m.group(1)), "share_off": float(m.group(2)), "layer": int(m.group(3)),
                            "x": m.group(4), "y": m.group(5), "feature": m.group(6)}
        return bool(m)
    if key == "PURGE_MM3":
        report.purge_mm3 = float(value)
        return True
    if key == "CHANGES":
        report.changes = int(value)
        return True
    if key == "UNPURGED_MM3":
        report.unpurged_mm3 = float(value)
        return True
    if key == "HINT":
        report.hint = value or None
        return bool(value)
    looser = _LOOSER_KEY.match(key)
    if looser:
        m = _LOOSER.match(value)
        if m:
            report.looser_tolerance = float(looser.group(1))
            report.looser_mm3, report.needed_mm3 = float(m.group(1)), float(m.group(3))
        return bool(m)
    return True  # a line this plugin does not know yet: not shown, not an error


# ---- the message ----------------------------------------------------------------------------
def number(value):
    """0.100 -> "0.1", 0.2 -> "0.2", 40.0 -> "40"."""
    return ("%.3f" % value).rstrip("0").rstrip(".")


def volume(mm3, density=None):
    """"13517 mm³ (16.8 g)": whole mm³ from 10 mm³ on; grams from the density (g/cm³) when known."""
    text = ("%.0f" if mm3 >= 10 or mm3 == 0 else "%.1f") % mm3 + " mm\u00b3"
    if density:
        grams = mm3 * density / 1000.0
        text += " (%s g)" % (("%.0f" if grams >= 100 else "%.1f" if grams >= 1 else "%.2f") % grams)
    return text


def feature(marker):
    return FEATURES.get(marker, marker.lower().replace("-", " "))


def hintText(hint):
    """The engine's hint in the user's words: the setting as Cura's panel names it, mm³, a capital and a stop."""
    text = hint.replace("(%s)" % SEQUENCE_SETTING, "(%s)" % SEQUENCE_WORDS)
    text = re.sub(r"\bmm3\b", "mm\u00b3", text)
    text = text[:1].upper() + text[1:]
    return text if text.endswith(".") else text + "."


def _chamber(report):
    if report.chamber_mm3 is None:
        return ""
    if report.chamber_mm3 == 0:
        return ", with an ideal mixing chamber (volume 0)"
    return ", with the %s mm\u00b3 mixing chamber (%d stages)" % (number(report.chamber_mm3), report.chamber_stages)


def _visible(report):
    if report.no_visible_surface:
        return "The print has no visible surface (outer walls, skin) to judge%s." % _chamber(report)
    parts = []
    if report.within_de00_3 is not None:
        parts.append("%s%% comes out within \u0394E00 3 of its colour" % number(report.within_de00_3))
    if report.within_tolerance is not None:
        parts.append("%s%% within the %s%s of its mix" % (
            number(report.within_tolerance), TOLERANCE_LABEL,
            " (%s)" % number(report.tolerance) if report.tolerance is not None else ""))
    if not parts:
        return None
    text = "Of %s, %s%s." % (VISIBLE, " and ".join(parts), _chamber(report))
    if report.worst:
        w = report.worst
        text += " Worst: \u0394E00 %s (shares off by %s) on the %s of layer %d at X%s Y%s." % (
            number(w["de00"]), number(w["share_off"]), feature(w["feature"]), w["layer"], w["x"], w["y"])
    return text


def _purge(report, density):
    if report.purge_mm3 is None:
        return None
    changes = report.changes
    if not report.purge_mm3 and not changes:
        if report.looser_mm3 is not None:  # planned: the mix changes inside layers, hidden extrusions absorb it
            return "No purge: the hidden extrusions (infill, inner walls, support, raft) absorb every change of mix."
        return "No purge: the mix does not change inside a layer."
    what = "%d change%s of mix inside layers" % (changes, "" if changes == 1 else "s") if changes else None
    if report.purge_mm3:
        text = "Purge: %s%s." % (volume(report.purge_mm3, density), " for " + what if what else "")
    else:
        text = "No purge for the %s." % what
    if report.looser_mm3 is not None and (report.looser_mm3 or report.needed_mm3):
        text += " At twice the tolerance (%s) the changes would need %s instead of %s." % (
            number(report.looser_tolerance), volume(report.looser_mm3, density), volume(report.needed_mm3, density))
    return text


def messageText(report, density=None):
    """The message for `report` (read()); density in g/cm³ (None or 0: volumes in mm³ only)."""
    lines = [_visible(report), _purge(report, density)]
    if report.unpurged_mm3:
        lines.append("Warning: %s of the changes could not be purged (no purge tower, or no room for one): "
                     "visible surfaces after them show the previous mix." % volume(report.unpurged_mm3, density))
    if report.hint:
        lines.append(hintText(report.hint))
    return "\n".join(line for line in lines if line)
