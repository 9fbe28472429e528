"""The filament colours of a mixing printer, for the legend of the layer view (no Cura imports).

channelColours: mixing_channel_colors ("#rrggbb,#rrggbb,...") -> one sRGB row (0..1) per channel, a
missing or malformed entry taken from the defaults. The colours of the lines themselves are the engine's
(";PREDICTED_COLOR:" in the G-code, MixGCode.py): the plugin mixes no colours.
"""
import numpy


def parseHex(text):
    """"#rrggbb" -> [r, g, b] in 0..1, None when malformed."""
    text = (text or "").strip()
    if len(text) != 7 or text[0] != "#":
        return None
    try:
        return [int(text[i:i + 2], 16) / 255.0 for i in (1, 3, 5)]
    except ValueError:
        return None


def channelColours(text, channels, defaults):
    """(channels, 3) sRGB in 0..1."""
    given = (text or "").split(",")
    fallback = (defaults or "").split(",")
    rows = []
    for c in range(channels):
        rgb = parseHex(given[c]) if c < len(given) else None
        if rgb is None and c < len(fallback):
            rgb = parseHex(fallback[c])
        rows.append(rgb if rgb is not None else [0.5, 0.5, 0.5])
    return numpy.array(rows, dtype=numpy.float64).reshape(-1, 3)
