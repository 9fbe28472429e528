"""What leaves the nozzle of a mixing hotend, replayed from the G-code alone (issue 26; test_chamber.py).

The chamber is `stages` equal stirred tanks in series holding `volume_mm3` together. With τ the volume
pushed through in units of one tank (volume_mm3 / stages), tank k (1..N) follows

    dc_k/dτ = c_{k-1} - c_k,      c_0 = the inlet mix (the net new filament of the move),

and the nozzle gives out c_N. This module integrates that system numerically, move by move, with the
classical fourth-order Runge-Kutta method in steps of at most STEP_TAU (plus the integral of c_N, for the
average mix that leaves during a move). It shares nothing with the engine's closed form
(engine/mixing/chamber/ChamberModel.cpp); test_chamber.py checks it against the analytic step response
e^-τ (1 + τ + τ²/2) of three tanks and the mean residence volume of a ramp.

Only net new filament moves the melt: per channel a retraction (a negative amount) adds to that channel's
debt, a positive amount pays the debt first and only the excess enters the chamber. The chamber starts full
of the mix of the print's first net extrusion (the start code primes it).

The moves come from mixing_gcode.read_mixing_gcode (the independent firmware models); filament mm become
mm³ with the filament's cross-section.
"""
import math
import struct
import zlib
from dataclasses import dataclass

STEP_TAU = 0.05  # the largest RK4 step, in tank volumes (local error ~ STEP_TAU⁵ / 120)


def filament_area(diameter_mm):
    return math.pi * diameter_mm * diameter_mm / 4.0


def share_distance(a, b):
    """The largest difference of any channel's share (the unit of mixing_transition_tolerance)."""
    return max(abs(x - y) for x, y in zip(a, b))


class Chamber:
    """N stirred tanks in series, integrated with RK4. `tanks[0]` is next to the inlet, `tanks[-1]` at the
    nozzle; each is a list of channel shares."""

    def __init__(self, volume_mm3, stages, initial, step_tau=STEP_TAU):
        self.volume, self.stages, self.step_tau = float(volume_mm3), int(stages), step_tau
        self.tanks = [list(map(float, initial)) for _ in range(self.stages)]

    def outlet(self):
        return list(self.tanks[-1])

    def push(self, inlet, volume_mm3):
        """Pushes `volume_mm3` of the constant mix `inlet`; returns the average mix that left meanwhile."""
        if volume_mm3 <= 0:
            return self.outlet()
        if self.volume <= 0:  # an ideal chamber: what enters leaves at once
            self.tanks = [list(inlet) for _ in range(self.stages)]
            return list(inlet)
        tau = volume_mm3 / (self.volume / self.stages)
        steps = max(1, math.ceil(tau / self.step_tau))
        h = tau / steps
        left = []
        for channel, c_in in enumerate(inlet):
            state = [tank[channel] for tank in self.tanks]
            integral = 0.0
            for _ in range(steps):
                state, gained = _rk4(state, c_in, h)
                integral += gained
            for tank, value in zip(self.tanks, state):
                tank[channel] = value
            left.append(integral / tau)
        return left


def _derivative(state, c_in):
    return [(state[k - 1] if k else c_in) - state[k] for k in range(len(state))]


def _rk4(state, c_in, h):
    """One RK4 step of the tanks and of ∫ c_N dτ over it."""
    n = len(state)
    k1 = _derivative(state, c_in)
    s2 = [state[i] + 0.5 * h * k1[i] for i in range(n)]
    k2 = _derivative(s2, c_in)
    s3 = [state[i] + 0.5 * h * k2[i] for i in range(n)]
    k3 = _derivative(s3, c_in)
    s4 = [state[i] + h * k3[i] for i in range(n)]
    k4 = _derivative(s4, c_in)
    new = [state[i] + h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(n)]
    gained = h / 6.0 * (state[-1] + 2 * s2[-1] + 2 * s3[-1] + s4[-1])  # RK4 on q' = c_N
    return new, gained


def full_change_volume(volume_mm3, stages, tolerance, channels=2, dv_mm3=0.01):
    """The volume of pure B pushed into a chamber full of pure A until the outlet is within `tolerance` of
    B, by replaying small pushes (linear interpolation inside the last one). The step response of tanks in
    series rises monotonically, so the first crossing is final."""
    a = [1.0] + [0.0] * (channels - 1)
    b = [0.0, 1.0] + [0.0] * (channels - 2)
    chamber = Chamber(volume_mm3, stages, a)
    pushed, before = 0.0, share_distance(chamber.outlet(), b)
    while before > tolerance:
        chamber.push(b, dv_mm3)
        after = share_distance(chamber.outlet(), b)
        if after <= tolerance:
            return pushed + dv_mm3 * (before - tolerance) / (before - after)
        pushed, before = pushed + dv_mm3, after
    return pushed


@dataclass
class Replayed:
    move: object  # mixing_gcode.Move
    net_mm3: float  # net new melt this move pushed into the chamber
    inlet: list  # the mix of that net melt (the outlet's when there is none)
    outlet: list  # the average mix that left the nozzle during the move

    @property
    def extruding(self):
        return self.move.xy and self.move.total > 0

    @property
    def length(self):
        (x0, y0), (x1, y1) = self.move.start, self.move.end
        return math.hypot(x1 - x0, y1 - y0)


def net_amounts(moves):
    """Per move, the net new filament per channel (mm): retraction debts paid first, channel by channel."""
    channels = len(moves[0].amounts) if moves else 0
    debt, out = [0.0] * channels, []
    for m in moves:
        net = []
        for c, amount in enumerate(m.amounts):
            if amount < 0:
                debt[c] -= amount
                net.append(0.0)
            else:
                paid = min(debt[c], amount)
                debt[c] -= paid
                net.append(amount - paid)
        out.append(net)
    return out


def replay(moves, diameter_mm, volume_mm3, stages):
    """[Replayed] for every move of a mixing_gcode.Reading, in print order."""
    area = filament_area(diameter_mm)
    nets = net_amounts(moves)
    first = next((n for n in nets if sum(n) > 0), None)
    if first is None:
        return []
    chamber = Chamber(volume_mm3, stages, [a / sum(first) for a in first])
    out = []
    for m, net in zip(moves, nets):
        total = sum(net)
        if total > 0:
            inlet = [a / total for a in net]
            left = chamber.push(inlet, total * area)
        else:
            inlet = left = chamber.outlet()
        out.append(Replayed(m, total * area, inlet, left))
    return out


def outer_wall_fraction(replayed, asked, tolerance):
    """(fraction of the ;TYPE:WALL-OUTER length whose outlet is within `tolerance` of asked(move), that
    length in mm). `asked(move)` gives the mix the model wants there, from geometry."""
    good = total = 0.0
    for r in replayed:
        if r.extruding and r.move.feature == "WALL-OUTER":
            total += r.length
            if share_distance(r.outlet, asked(r.move)) <= tolerance:
                good += r.length
    return (good / total if total else 0.0), total


def purge_volume(replayed):
    """The net melt of the purge tower (;TYPE:PRIME-TOWER), mm³."""
    return sum(r.net_mm3 for r in replayed if r.move.feature == "PRIME-TOWER")


def model_volume(replayed):
    """The net melt of everything but the purge tower, mm³."""
    return sum(r.net_mm3 for r in replayed if r.move.feature != "PRIME-TOWER")


def blend(colors, mix):
    """A plain linear blend of the channel colours (#rrggbb) by share: a diagnostic colour, not a pigment model."""
    rgb = [tuple(int(c.lstrip("#")[i:i + 2], 16) for i in (0, 2, 4)) for c in colors]
    total = sum(max(s, 0.0) for s in mix) or 1.0
    return tuple(round(sum(max(s, 0.0) / total * col[i] for s, col in zip(mix, rgb))) for i in range(3))


def render_side_view(replayed, colors, path, feature="WALL-OUTER", px_per_mm=20, asked=None):
    """A picture of the `feature` lines seen from the front (X right, Z up; the nearest line, smallest Y,
    hides those behind it), coloured by the outlet mix. With `asked`, a second panel on the right shows the
    asked mix of the same lines. Written as an RGB PNG; returns (width, height)."""
    lines = [r for r in replayed if r.extruding and r.move.feature == feature]
    if not lines:
        raise ValueError(f"no {feature} extrusions to draw")
    layer_z = sorted({(r.move.layer, r.move.z) for r in lines})
    bottom = {}
    for i, (layer, z) in enumerate(layer_z):
        bottom[layer] = layer_z[i - 1][1] if i else max(0.0, z - 0.2)
    xs = [x for r in lines for x in (r.move.start[0], r.move.end[0])]
    x0, x1 = min(xs) - 1.0, max(xs) + 1.0
    z0, z1 = 0.0, max(z for _, z in layer_z) + 1.0
    panel_w, height = math.ceil((x1 - x0) * px_per_mm), math.ceil((z1 - z0) * px_per_mm)
    panels = 2 if asked else 1
    gap = px_per_mm
    width = panels * panel_w + (panels - 1) * gap
    depth = [[math.inf] * width for _ in range(height)]
    image = [[(255, 255, 255)] * width for _ in range(height)]
    for r in lines:
        (sx, sy), (ex, ey) = r.move.start, r.move.end
        row_top = height - 1 - int((r.move.z - z0) * px_per_mm)
        row_bottom = height - 1 - int((bottom[r.move.layer] - z0) * px_per_mm)
        rows = range(max(0, row_top), min(height, max(row_bottom, row_top + 1)))
        samples = max(1, math.ceil(r.length * px_per_mm * 2))
        shades = [(0, blend(colors, r.outlet))]
        if asked:
            shades.append((panel_w + gap, blend(colors, asked(r.move))))
        for s in range(samples + 1):
            t = s / samples
            x, y = sx + (ex - sx) * t, sy + (ey - sy) * t
            col = min(panel_w - 1, int((x - x0) * px_per_mm))
            for row in rows:
                if y < depth[row][col]:
                    for offset, rgb in shades:
                        depth[row][col + offset] = y
                        image[row][col + offset] = rgb
    _write_png(path, width, height, image)
    return width, height


def render_top_view(replayed, colors, path, layer, feature="SKIN", px_per_mm=10, asked=None):
    """A picture of layer `layer`'s `feature` lines seen from above (X right, Y up), coloured by the outlet
    mix; with `asked`, a second panel on the right shows the asked mix. Returns (width, height)."""
    lines = [r for r in replayed if r.extruding and r.move.feature == feature and r.move.layer == layer]
    if not lines:
        raise ValueError(f"no {feature} extrusions on layer {layer} to draw")
    xs = [x for r in lines for x in (r.move.start[0], r.move.end[0])]
    ys = [y for r in lines for y in (r.move.start[1], r.move.end[1])]
    x0, y0 = min(xs) - 1.0, min(ys) - 1.0
    panel_w = math.ceil((max(xs) + 1.0 - x0) * px_per_mm)
    height = math.ceil((max(ys) + 1.0 - y0) * px_per_mm)
    panels = 2 if asked else 1
    width = panels * panel_w + (panels - 1) * px_per_mm
    image = [[(255, 255, 255)] * width for _ in range(height)]
    for r in lines:
        (sx, sy), (ex, ey) = r.move.start, r.move.end
        shades = [(0, blend(colors, r.outlet))]
        if asked:
            shades.append((panel_w + px_per_mm, blend(colors, asked(r.move))))
        samples = max(1, math.ceil(r.length * px_per_mm * 2))
        for k in range(samples + 1):
            t = k / samples
            col = min(panel_w - 1, int((sx + (ex - sx) * t - x0) * px_per_mm))
            row = height - 1 - min(height - 1, int((sy + (ey - sy) * t - y0) * px_per_mm))
            for offset, rgb in shades:
                image[row][col + offset] = rgb
    _write_png(path, width, height, image)
    return width, height


def _write_png(path, width, height, image):
    raw = b"".join(b"\x00" + bytes(v for rgb in row for v in rgb) for row in image)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))
    with open(path, "wb") as f:
        f.write(data)
