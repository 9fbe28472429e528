"""The cross patterns (infill_pattern cross / cross_3d, support_pattern cross) against CuraEngine 4.13.

Both engines get the same resolved settings (side_by_side.py: the Ender-3, 0.2 mm layers). The pattern's own
figures — the filament and the length extruded under ;TYPE:FILL (infill) or ;TYPE:SUPPORT (support), read
back segment by segment — must be within 10 % of CuraEngine's, on the generated parity model and on the
corpus's armadillo52k; and MixEngine's pattern must not be the lines it printed before the cross patterns
were built: the G-code differs from infill_pattern / support_pattern lines', and the directions the pattern is
printed in (shares of its length per degree, mod 180°) are far from the lines', and its shares along the
curve's own directions (0°, 45°, 90°, 135°) close to CuraEngine's.
cross_infill_pocket_size must change cross_3d's infill the way it changes CuraEngine's, and a density image
(cross_infill_density_image, cross_support_density_image: a grey PNG, lighter to the right) must thin the
pattern as it thins CuraEngine's.
"""
import struct
import zlib

import numpy as np
import pytest

import gcode_model
import side_by_side as sbs

TOLERANCE = 0.10

CASES = {  # name -> (model, overrides, ;TYPE: of the pattern, the overrides that print lines instead)
    "parity_cross": ("parity", {"infill_pattern": "cross"}, "FILL", {"infill_pattern": "lines"}),
    "parity_cross_3d": ("parity", {"infill_pattern": "cross_3d"}, "FILL", {"infill_pattern": "lines"}),
    "armadillo_cross": ("armadillo52k", {"infill_pattern": "cross"}, "FILL", {"infill_pattern": "lines"}),
    "armadillo_cross_3d": ("armadillo52k", {"infill_pattern": "cross_3d"}, "FILL", {"infill_pattern": "lines"}),
    "parity_support_cross": ("parity", {"support_enable": "True", "support_pattern": "cross"}, "SUPPORT",
                             {"support_enable": "True", "support_pattern": "lines"}),
}


def feature_figures(path, feature):
    """(filament mm, extruded length mm) of the segments printed under ;TYPE:feature."""
    model = gcode_model.read(path)
    filament = length = 0.0
    for layer in model.layers.values():
        mask = model.feature_mask(layer, (feature,))
        filament += float(layer.e[mask].sum())
        length += float(layer.lengths()[mask].sum())
    return filament, length


def direction_shares(path, feature):
    """{direction in whole degrees mod 180: share of the length printed under ;TYPE:feature}."""
    model = gcode_model.read(path)
    lengths = {}
    for layer in model.layers.values():
        mask = model.feature_mask(layer, (feature,))
        dx, dy = (layer.x1 - layer.x0)[mask], (layer.y1 - layer.y0)[mask]
        angles = np.rint(np.degrees(np.arctan2(dy, dx))).astype(int) % 180
        for angle, length in zip(angles, np.hypot(dx, dy)):
            lengths[int(angle)] = lengths.get(int(angle), 0.0) + float(length)
    total = sum(lengths.values())
    return {angle: length / total for angle, length in lengths.items()}


def _variation(a, b):
    """Total variation distance between two direction distributions (0: the same, 1: nothing shared)."""
    return 0.5 * sum(abs(a.get(d, 0.0) - b.get(d, 0.0)) for d in set(a) | set(b))


def _rel(got, want):
    return (got - want) / want


def _load(corpus, name):
    if name not in sbs.GENERATED:
        corpus(name)


@pytest.mark.parametrize("case", list(CASES))
def test_cross_pattern_within_10_percent_of_curaengine(engine, corpus, report, case):
    name, overrides, feature, _ = CASES[case]
    _load(corpus, name)
    mix, cura = sbs.run_mixengine(name, overrides), sbs.run_cura(name, overrides)
    assert mix.rc == 0 and cura.rc == 0, (mix.stderr[-300:], cura.stderr[-300:])
    (mix_e, mix_len), (cura_e, cura_len) = feature_figures(mix.gcode, feature), feature_figures(cura.gcode, feature)
    report(f"{case}: {feature} filament mixengine {mix_e:.0f} / CuraEngine {cura_e:.0f} mm "
           f"({100 * _rel(mix_e, cura_e):+.1f} %), length {mix_len:.0f} / {cura_len:.0f} mm "
           f"({100 * _rel(mix_len, cura_len):+.1f} %)")
    assert cura_e > 50
    assert abs(_rel(mix_e, cura_e)) <= TOLERANCE
    assert abs(_rel(mix_len, cura_len)) <= TOLERANCE


@pytest.mark.parametrize("case", list(CASES))
def test_cross_pattern_is_not_lines(engine, corpus, case):
    name, overrides, feature, lines = CASES[case]
    _load(corpus, name)
    cross, plain = sbs.run_mixengine(name, overrides), sbs.run_mixengine(name, lines)
    assert cross.rc == 0 and plain.rc == 0
    assert cross.gcode.read_bytes() != plain.gcode.read_bytes()
    # The directions the pattern is printed in (mod 180°) are far from the lines' and close to CuraEngine's.
    plain_shares = direction_shares(plain.gcode, feature)
    cross_shares = direction_shares(cross.gcode, feature)
    cura_shares = direction_shares(sbs.run_cura(name, overrides).gcode, feature)
    assert _variation(cross_shares, plain_shares) > 0.25
    # the curve's own directions (the pieces along the area's edge may lie otherwise)
    for direction in (0, 45, 90, 135):
        assert abs(cross_shares.get(direction, 0.0) - cura_shares.get(direction, 0.0)) < 0.02, direction


def test_pocket_size_moves_cross_3d_as_in_curaengine(engine):
    """cross_infill_pocket_size from its default (the line distance, 2 mm) down to 0 (no pockets): the curve's
    right-angled corners are no longer cut, so both engines print more (above about 1.3 mm the cut is a third
    of the curve's segments, whatever the pocket size, in both)."""
    base = {"infill_pattern": "cross_3d"}
    pocketed = dict(base, cross_infill_pocket_size="0")
    deltas = {}
    for label, run in (("mixengine", sbs.run_mixengine), ("CuraEngine", sbs.run_cura)):
        before, after = feature_figures(run("parity", base).gcode, "FILL"), feature_figures(run("parity", pocketed).gcode, "FILL")
        deltas[label] = after[1] - before[1]
    assert deltas["CuraEngine"] != 0
    ratio = deltas["mixengine"] / deltas["CuraEngine"]
    assert 1 / 3 <= ratio <= 3, deltas


def _grey_png(path, width=64, height=32):
    """A grey PNG, white on the left to 25 % grey on the right (density 0 to 0.25: below w/d on the left,
    the full depth on the right), lighter towards the top."""
    rows = b"".join(b"\0" + bytes(round(255 * (1 - 0.25 * x / (width - 1) * (0.5 + y / (2 * height - 2))))
                                   for x in range(width)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows))
                     + chunk(b"IEND", b""))
    return path


@pytest.mark.parametrize("key, overrides, feature", [
    ("cross_infill_density_image", {"infill_pattern": "cross"}, "FILL"),
    ("cross_support_density_image", {"support_enable": "True", "support_pattern": "cross"}, "SUPPORT"),
])
def test_density_image_thins_the_pattern_as_in_curaengine(engine, tmp_path, key, overrides, feature):
    image = _grey_png(tmp_path / "density.png")
    with_image = dict(overrides, **{key: str(image)})
    figures = {}
    for label, run in (("mixengine", sbs.run_mixengine), ("CuraEngine", sbs.run_cura)):
        uniform, thinned = run("parity", overrides), run("parity", with_image)
        assert uniform.rc == 0 and thinned.rc == 0, thinned.stderr[-300:]
        figures[label] = (feature_figures(uniform.gcode, feature)[0], feature_figures(thinned.gcode, feature)[0])
    cura_uniform, cura_thinned = figures["CuraEngine"]
    assert cura_thinned < 0.97 * cura_uniform
    assert abs(_rel(figures["mixengine"][1], cura_thinned)) <= 0.02
