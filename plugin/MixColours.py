"""Colours of filament mixes, and the mix that leaves a mixing chamber (no Cura imports).

- channelColours: mixing_channel_colors ("#rrggbb,#rrggbb,...") -> one RGB row (0..1) per channel, a
  missing or malformed entry taken from the defaults, as the engine's preview picture does.
- mixColours: the colour of each mix, the channels weighted in linear light (the engine's --preview).
- delayedMixes: what leaves the nozzle. The chamber holds `chamber_mm3` of material (plug flow), so
  the material of an extrusion was mixed `chamber_mm3` of extrusion earlier: its mix is the average of
  the commanded mixes over its own volume shifted back by the chamber volume. Before the first
  extrusion the chamber is taken to be full of the first mix.
"""
import numpy


def _parseHex(text):
    text = text.strip()
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
        rgb = _parseHex(given[c]) if c < len(given) else None
        if rgb is None and c < len(fallback):
            rgb = _parseHex(fallback[c])
        rows.append(rgb if rgb is not None else [0.5, 0.5, 0.5])
    return numpy.array(rows, dtype=numpy.float64).reshape(-1, 3)


def toLinear(srgb):
    srgb = numpy.asarray(srgb, dtype=numpy.float64)
    return numpy.where(srgb <= 0.04045, srgb / 12.92, ((srgb + 0.055) / 1.055) ** 2.4)


def toSrgb(linear):
    linear = numpy.clip(numpy.asarray(linear, dtype=numpy.float64), 0.0, 1.0)
    return numpy.where(linear <= 0.0031308, linear * 12.92, 1.055 * linear ** (1 / 2.4) - 0.055)


def mixColours(mixes, channel_rgb):
    """(n, channels) shares -> (n, 3) sRGB colours in 0..1."""
    mixes = numpy.asarray(mixes, dtype=numpy.float64).reshape(len(mixes), -1)
    channels = min(mixes.shape[1], len(channel_rgb))
    sums = mixes[:, :channels].sum(axis=1, keepdims=True)
    weights = mixes[:, :channels] / numpy.where(sums > 0, sums, 1.0)
    return toSrgb(weights @ toLinear(channel_rgb[:channels]))


def delayedMixes(mixes, volumes_mm3, chamber_mm3):
    """(n, channels) commanded mixes of n extrusions in print order with their volumes -> the (n,
    channels) mixes that leave the nozzle through a chamber of `chamber_mm3`."""
    mixes = numpy.asarray(mixes, dtype=numpy.float64)
    volumes = numpy.maximum(numpy.asarray(volumes_mm3, dtype=numpy.float64), 0.0)
    if chamber_mm3 <= 0 or len(mixes) == 0:
        return mixes
    ends = numpy.cumsum(volumes)  # cumulative volume at the end of each extrusion
    starts = ends - volumes
    integral_at_ends = numpy.cumsum(mixes * volumes[:, None], axis=0)

    def integral(u):
        """Integral of the commanded mix over cumulative volume [0, u] (u may be negative)."""
        u = numpy.asarray(u, dtype=numpy.float64)
        before = numpy.minimum(u, 0.0)[:, None] * mixes[0]  # the chamber's first contents
        index = numpy.clip(numpy.searchsorted(ends, u, side="left"), 0, len(ends) - 1)
        previous = numpy.where(index[:, None] > 0, integral_at_ends[numpy.maximum(index - 1, 0)], 0.0)
        inside = numpy.clip(u - starts[index], 0.0, None)[:, None] * mixes[index]
        return numpy.where((u > 0)[:, None], previous + inside, before)

    low, high = starts - chamber_mm3, ends - chamber_mm3
    span = (high - low)[:, None]
    averaged = (integral(high) - integral(low)) / numpy.where(span > 0, span, 1.0)
    # zero-volume extrusions: the mix at that point of the stream
    point = numpy.clip(numpy.searchsorted(ends, low, side="right"), 0, len(ends) - 1)
    at_point = numpy.where((low < 0)[:, None], mixes[0], mixes[point])
    return numpy.where(span > 0, averaged, at_point)
