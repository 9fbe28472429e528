"""Colour mixing (issue 6, seed 001), checked from the G-code alone: every dialect is read back by an
independent model of its firmware (mixing_gcode.py, on top of PyPI's gcodeparser).

  - per layer, B / (A + B) follows the seed's three cases for its four printed examples, in absolute and
    relative extrusion, on every dialect (exactly up to the written resolution; the mix-command dialects up
    to the firmware resolution);
  - per move, A + B equals the single-colour E of the same slice (relative error <= 1e-5);
  - the B totals a Klipper host sees, and what it would see from MakerPi-style output;
  - N channels and multi-stop gradients, per-mesh heights, dual mode, the chamber delay, the seed's
    aliases, bad values (one-line error naming the setting, nothing written), the --preview picture.
"""
import math
from functools import lru_cache

import pytest

import helpers
from mixing_gcode import box_stl, png_pixels, read_mixing_gcode, relative_error, seed_share_b

SEED_EXAMPLES = [(0, 100), (20, 80), (50, 50), (80, 100)]
SPLIT_DIALECTS = ["eb_axes", "klipper_b", "rrf_colon"]  # an amount per channel on every move
COMMAND_DIALECTS = ["marlin_m163", "marlin_m165", "rrf_m567"]  # total E + mix commands
CUBE_MM = 20.0
RESOLUTION = 100


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("mixing") / "cube.stl", CUBE_MM, CUBE_MM, CUBE_MM)


@pytest.fixture(scope="module")
def sliced(engine, cube, tmp_path_factory):
    """sliced(*settings) -> path of the G-code for the cube with those -s settings (cached)."""
    out_dir = tmp_path_factory.mktemp("mixing_gcode")

    @lru_cache(maxsize=None)
    def run(*settings):
        return helpers.slice_with(cube, out_dir / f"{len(list(out_dir.iterdir()))}.gcode", *settings)

    return run


def mode_settings(relative):
    return (f"relative_extrusion={relative}",)


def gradient(dialect, a, b, relative):
    return mode_settings(relative) + ("mixing_mode=gradient", f"mixing_dialect={dialect}",
                                      f"mixing_gradient_start={a}", f"mixing_gradient_end={b}")


@pytest.mark.parametrize("relative", [False, True])
@pytest.mark.parametrize("dialect", SPLIT_DIALECTS + COMMAND_DIALECTS)
@pytest.mark.parametrize("a,b", SEED_EXAMPLES)
def test_layer_ratio_follows_the_three_cases(sliced, dialect, a, b, relative):
    # B starts wherever an earlier job left it: the G-code must set it (G92 B0, or Klipper's SET_POSITION).
    reading = read_mixing_gcode(sliced(*gradient(dialect, a, b, relative)), dialect, b_start=123.4)
    layers = reading.layer_totals()
    assert len(layers) > 100
    cases = set()
    for layer, (z, (amount_a, amount_b)) in sorted(layers.items()):
        percent = 100.0 * z / CUBE_MM
        cases.add(1 if percent <= a else 3 if percent > b else 2)
        ratio = amount_b / (amount_a + amount_b)
        # Exact up to the written resolution (two units of 1e-5 mm over the layer's filament), or for
        # mix commands up to the firmware resolution.
        tolerance = 2e-5 / (amount_a + amount_b) if dialect in SPLIT_DIALECTS else 0.5 / RESOLUTION + 1e-9
        assert ratio == pytest.approx(seed_share_b(a, b, percent), abs=tolerance), f"layer {layer} at z={z}"
    # Each example shows the cases the seed describes for it (50/50: a hard switch, no gradient).
    assert cases == {(0, 100): {2}, (20, 80): {1, 2, 3}, (50, 50): {1, 3}, (80, 100): {1, 2}}[(a, b)]
    if dialect in COMMAND_DIALECTS:
        # A mix command only when the quantised ratio changes: at most one per layer here.
        assert reading.mix_commands <= len(layers) * (4 if dialect == "marlin_m163" else 1) + 1


def single_moves(sliced, relative):
    return [m for m in read_mixing_gcode(sliced(*mode_settings(relative)), "single").moves]


@pytest.mark.parametrize("relative", [False, True])
@pytest.mark.parametrize("dialect", SPLIT_DIALECTS + COMMAND_DIALECTS)
def test_channels_add_up_to_the_single_colour_e(sliced, dialect, relative):
    """rrf_colon is always written relative, so its single-colour reference is the relative slice."""
    single = single_moves(sliced, relative or dialect == "rrf_colon")
    mixed = read_mixing_gcode(sliced(*gradient(dialect, 20, 80, relative)), dialect).moves
    single_ext = [m for m in single if m.xy and m.total > 0]
    mixed_ext = [m for m in mixed if m.xy and m.total > 0]
    assert len(mixed_ext) == len(single_ext) > 1000
    worst = max(relative_error(m.total, s.total) for m, s in zip(mixed_ext, single_ext))
    assert worst <= 1e-5, f"worst relative error {worst}"
    assert all(min(m.amounts) >= -1e-9 for m in mixed_ext), "a channel runs backwards on an extruding move"
    # Retractions and primes too: the same filament per line as the single-colour output.
    assert [round(m.total, 5) for m in mixed] == [round(s.total, 5) for s in single]


@pytest.mark.parametrize("relative", [False, True])
@pytest.mark.parametrize("dialect", ["eb_axes", "rrf_colon", "marlin_m163"])
def test_raft_is_printed_with_its_own_mix_and_adds_up(sliced, dialect, relative):
    """adhesion_type=raft: the raft's layers (;LAYER: below 0: base, interface, fdmprinter's two surface
    layers) are printed with mixing_raft_ratio — filament A by default, 0.3:0.7 when set — and the cube above
    follows its gradient from its own bottom, lifted by the raft; move by move A + B is still the
    single-colour E of the same slice with the same raft."""
    raft = ("adhesion_type=raft",)
    single = single_moves_of(sliced(*raft, *mode_settings(relative or dialect == "rrf_colon")))
    tolerance = 2e-5 if dialect in SPLIT_DIALECTS else 0.5 / RESOLUTION + 1e-9
    for raft_mix, raft_b in ((None, 0.0), ("0.3:0.7", 0.7)):
        extra = raft + ((f"mixing_raft_ratio={raft_mix}",) if raft_mix else ())
        reading = read_mixing_gcode(sliced(*extra, *gradient(dialect, 20, 80, relative)), dialect)
        layers = reading.layer_totals()
        assert sorted(layer for layer in layers if layer < 0) == [-9, -8, -7, -6]  # 5 filler layers unprinted
        for layer in (-9, -8, -7, -6):
            amount_a, amount_b = layers[layer][1]
            assert amount_b / (amount_a + amount_b) == pytest.approx(raft_b, abs=tolerance), layer
        lift = layers[1][0] - 0.4  # fdmprinter: layer 1 of the model is printed at 0.3 + 0.1 mm above its bottom
        assert lift == pytest.approx(0.71 + 0.3 - 0.15)  # raft 0.36 + 0.15 + 2 x 0.1, air gap, layer-0 overlap
        for layer, (z, (amount_a, amount_b)) in layers.items():
            if layer >= 1:
                expected = seed_share_b(20, 80, 100.0 * (z - lift) / CUBE_MM)
                assert amount_b / (amount_a + amount_b) == pytest.approx(expected, abs=tolerance), layer
        mixed = [m for m in reading.moves if m.xy and m.total > 0]
        assert len(mixed) == len(single) > 1000
        assert max(relative_error(m.total, s.total) for m, s in zip(mixed, single)) <= 1e-5


@pytest.mark.parametrize("dialect", ["eb_axes", "marlin_m163"])
def test_tree_support_and_draft_shield_are_printed_with_the_support_mix_and_add_up(engine, tmp_path, dialect):
    """Tree support and a draft shield under a gradient (the tee, side_by_side.py: a bar on a stem): every
    support line (;TYPE:SUPPORT / SUPPORT-INTERFACE) and the shield (;TYPE:SKIRT above layer 0) take
    mixing_support_ratio — filament A by default, 0.3:0.7 when set — while the tee's walls follow the
    gradient; move by move A + B is the single-colour E of the same slice."""
    import side_by_side as sbs
    tee = sbs.model_path("tee")
    helper = ("support_enable=True", "support_structure=tree", "draft_shield_enabled=True")
    single = single_moves_of(helpers.slice_with(tee, tmp_path / "single.gcode", *helper))
    def tolerance(m):  # five decimals per written amount, or the firmware's mix resolution
        return 2e-5 / m.total if dialect in SPLIT_DIALECTS else 0.5 / RESOLUTION + 1e-9

    for ratio, share_b in ((None, 0.0), ("0.3:0.7", 0.7)):
        extra = helper + gradient(dialect, 20, 80, False) + ((f"mixing_support_ratio={ratio}",) if ratio else ())
        reading = read_mixing_gcode(helpers.slice_with(tee, tmp_path / f"{dialect}{ratio}.gcode", *extra), dialect)
        moves = reading.extrusions()
        support = [m for m in moves if m.feature in ("SUPPORT", "SUPPORT-INTERFACE")]
        shield = [m for m in moves if m.feature == "SKIRT" and m.layer > 0]
        walls = [m for m in moves if m.feature == "WALL-OUTER"]
        assert len(support) > 100 and len(shield) > 50
        assert {m.layer for m in shield} == set(range(1, max(m.layer for m in moves) + 1))
        for m in support + shield:
            assert m.amounts[1] / m.total == pytest.approx(share_b, abs=tolerance(m)), (m.layer, m.feature)
        # the tee's walls: A at the bottom, B at the top
        assert min(abs(m.amounts[1] / m.total - 1.0) - tolerance(m) for m in walls) <= 0
        assert min(m.amounts[1] / m.total - tolerance(m) for m in walls) <= 0
        assert len(moves) == len(single) > 1000
        assert max(relative_error(m.total, s.total) for m, s in zip(moves, single)) <= 1e-5


def single_moves_of(path):
    return [m for m in read_mixing_gcode(path, "single").moves if m.xy and m.total > 0]


@pytest.mark.parametrize("relative", [False, True])
def test_klipper_host_sees_the_b_total(sliced, relative, report):
    """A Klipper host moves the manual_stepper to the absolute B positions it is sent (G92 cannot reset it).
    Whatever position a previous print left the stepper at, its final position is the B filament of the
    print: the single-colour E of each extrusion times the seed's B share of its layer."""
    path = sliced(*gradient("klipper_b", 20, 80, relative))
    reading = read_mixing_gcode(path, "klipper_b", b_start=1234.5)
    single = [m for m in single_moves(sliced, relative) if m.xy and m.total > 0]
    expected_b = sum(m.total * seed_share_b(20, 80, 100.0 * m.z / CUBE_MM) for m in single)
    # Retractions of B are put back by the following primes, except the one CuraEngine (and so MixEngine)
    # makes after the last layer: the print ends with that much B retracted.
    last = max(i for i, m in enumerate(reading.moves) if m.xy and m.total > 0)
    retracted_at_end = sum(m.amounts[1] for m in reading.moves[last + 1:])
    assert retracted_at_end < 0
    final_b = reading.b_position - retracted_at_end
    assert final_b == pytest.approx(expected_b, abs=1e-4)
    assert sum(m.amounts[1] for m in reading.extrusions()) == pytest.approx(expected_b, abs=1e-4)
    # MakerPi-style output (B relative under M83, G92 B0 resets) on the same Klipper host goes wrong.
    eb_path = sliced(*gradient("eb_axes", 20, 80, relative))
    text = eb_path.read_text().replace(";LAYER_COUNT:", "MANUAL_STEPPER STEPPER=b GCODE_AXIS=B\n;LAYER_COUNT:", 1)
    eb_on_klipper = eb_path.with_suffix(".klipper.gcode")
    eb_on_klipper.write_text(text)
    wrong = read_mixing_gcode(eb_on_klipper, "klipper_b").b_position
    report(f"mixing: Klipper B total (20/80, {'relative' if relative else 'absolute'} E): klipper_b output "
           f"{final_b:.5f} mm, expected {expected_b:.5f} mm; eb_axes output on Klipper {wrong:.5f} mm")
    assert abs(wrong - expected_b) > 1.0


def test_reprap_colon_forces_relative_extrusion(engine, cube, sliced, tmp_path):
    """relative_extrusion=False: the print is still written relative (M83 after the start code, M82 back
    before the end code, as CuraEngine does for relative extrusion), with a warning and a comment."""
    out = tmp_path / "colon.gcode"
    proc = helpers.mixengine("slice", "-s", "mixing_mode=gradient", "-s", "mixing_dialect=rrf_colon",
                             "-s", "relative_extrusion=False", "-l", cube, "-o", out)
    assert proc.returncode == 0
    assert "rrf_colon" in proc.stderr and "M83" in proc.stderr  # the warning says so
    text = out.read_text()
    lines = text.splitlines()
    first_colon = next(i for i, l in enumerate(lines) if l.startswith("G1") and ":" in l)
    modes = [l.split()[0] for l in lines[:first_colon] if l.startswith(("M82", "M83"))]
    assert modes[-1] == "M83"
    assert any(l.startswith(";MIXING:") and "M83" in l for l in lines[:first_colon])
    read_mixing_gcode(out, "rrf_colon")  # would raise like RepRapFirmware if a colon word met M82
    assert text == sliced(*gradient("rrf_colon", 0, 100, True)).read_text()


def test_marlin_m163_selects_its_virtual_tool_once(sliced):
    text = sliced(*gradient("marlin_m163", 0, 100, False)).read_text().splitlines()
    assert text.count("T0") == 1
    first = text.index("T0")
    assert text[first - 1] == "M164 S0" and text[first - 3].startswith("M163 S0 P")


def test_five_channels_along_stops(sliced):
    stops = "0=1:0:0:0:0; 25=0:1:0:0:0; 50=0:0:1:0:0; 75=0:0:0:0.5:0.5; 100=0:0:0:0:1"
    for dialect in ("rrf_colon", "marlin_m165"):
        path = sliced("mixing_mode=gradient", f"mixing_dialect={dialect}", "mixing_channels=5",
                      f"mixing_gradient_stops={stops}")
        layers = read_mixing_gcode(path, dialect, channels=5).layer_totals()
        for layer, (z, amounts) in layers.items():
            p = 100.0 * z / CUBE_MM
            k = min(int(p // 25), 3)
            t = (p - 25 * k) / 25
            heights = [[1, 0, 0, 0, 0], [0, 1, 0, 0, 0], [0, 0, 1, 0, 0], [0, 0, 0, .5, .5], [0, 0, 0, 0, 1]]
            expected = [heights[k][c] + (heights[k + 1][c] - heights[k][c]) * t for c in range(5)]
            if p <= 0:
                expected = heights[0]
            shares = [x / sum(amounts) for x in amounts]
            tolerance = 1e-5 if dialect == "rrf_colon" else 0.5 / RESOLUTION + 1e-9
            assert shares == pytest.approx(expected, abs=tolerance), f"{dialect} layer {layer} z={z}"


def test_dual_mode_fixed_ratio_per_mesh_and_percent_of_each_mesh(engine, tmp_path):
    tall = box_stl(tmp_path / "tall.stl", 10, 10, 20)
    short = box_stl(tmp_path / "short.stl", 10, 10, 10)
    out = tmp_path / "two.gcode"
    base = ["slice", "-s", "mixing_dialect=rrf_colon", "-s", "relative_extrusion=True"]
    proc = helpers.mixengine(*base, "-s", "mixing_mode=dual",
                             "-l", tall, "-s", "mesh_position_x=-15", "-s", "mixing_ratio=0.3:0.7",
                             "-l", short, "-s", "mesh_position_x=15", "-s", "mixing_ratio=0.9:0.1", "-o", out)
    assert proc.returncode == 0, proc.stderr
    shares = per_mesh_shares(out)
    assert all(share == pytest.approx(0.7, abs=tol) for share, tol in shares["tall"].values())
    assert all(share == pytest.approx(0.1, abs=tol) for share, tol in shares["short"].values())
    # Gradient in percent of each mesh's own height: at z = 10 mm the tall box is half way, the short one done.
    proc = helpers.mixengine(*base, "-s", "mixing_mode=gradient", "-l", tall, "-s", "mesh_position_x=-15",
                             "-l", short, "-s", "mesh_position_x=15", "-o", out)
    assert proc.returncode == 0, proc.stderr
    by_z = per_mesh_shares(out)
    for mesh, z, expected in (("tall", 10.0, 0.5), ("short", 10.0, 1.0), ("tall", 5.0, 0.25), ("short", 5.0, 0.5)):
        share, tol = by_z[mesh][z]
        assert share == pytest.approx(expected, abs=tol), (mesh, z)


def per_mesh_shares(path):
    """{mesh (file stem from ;MESH:): {layer z: (B / (A + B), two written units relative to A + B)}} over the
    extruding moves of rrf_colon G-code."""
    sums, mesh, z = {}, None, 0.0
    for raw in path.read_text().splitlines():
        if raw.startswith(";MESH:"):
            mesh = raw[6:].rsplit("/", 1)[-1].split(".")[0]
        elif raw.startswith("G0") and " Z" in raw:
            z = float(raw.split(" Z")[1].split()[0])
        elif raw.startswith("G1") and " X" in raw and " E" in raw:
            a, b = (float(v) for v in raw.split(" E")[1].split()[0].split(":"))
            total = sums.setdefault(mesh, {}).setdefault(round(z, 3), [0.0, 0.0])
            total[0] += a
            total[1] += b
    return {m: {zz: (b / (a + b), 2e-5 / (a + b)) for zz, (a, b) in layers.items()} for m, layers in sums.items()}


def test_chamber_delay_shifts_the_schedule_earlier(sliced):
    """Each extrusion commands the target of the material extruded `chamber` mm³ later (along the
    cumulative volume of the single-colour E), so the colour leaving the nozzle matches its height."""
    chamber_mm3 = 40.0
    area = math.pi * (2.85 / 2) ** 2  # fdmprinter's material_diameter
    single = [m for m in single_moves(sliced, True) if m.xy and m.total > 0]
    delayed = read_mixing_gcode(sliced(*gradient("eb_axes", 20, 80, True),
                                       f"mixing_chamber_volume={chamber_mm3}"), "eb_axes").extrusions()
    assert len(delayed) == len(single)
    starts, total = [], 0.0
    for m in single:
        starts.append(total)
        total += m.total
    targets = [seed_share_b(20, 80, 100.0 * m.z / CUBE_MM) for m in single]
    shift_mm = chamber_mm3 / area
    j, checked, changed = 0, 0, 0
    for i, m in enumerate(delayed):
        point = starts[i] + single[i].total / 2 + shift_mm
        while j + 1 < len(single) and starts[j + 1] <= point:
            j += 1
        near_boundary = j + 1 < len(single) and min(point - starts[j], starts[j + 1] - point) < 2e-4
        share = m.amounts[1] / m.total
        allowed = 2e-5 / m.total + 1e-9  # two written units of rounding on this move
        candidates = {targets[j]}
        if near_boundary:  # the engine sums exact volumes, this test the written (rounded) E words
            candidates |= {targets[k] for k in (j - 1, j + 1) if 0 <= k < len(targets)}
        assert any(abs(share - t) <= allowed for t in candidates), f"move {i}: {share} vs {targets[j]}"
        checked += 1
        changed += abs(targets[j] - targets[i]) > 1e-9
    assert checked == len(single) and changed > 100  # the shift really moved many mixes


def test_seed_aliases_give_the_same_gcode(sliced):
    canonical = sliced("mixing_mode=gradient", "mixing_gradient_start=20", "mixing_gradient_end=80")
    aliased = sliced("colorMixing=2", "colorA=20", "colorB=80")
    mode_alias = sliced("colorMode=gradient", "colorA=20", "colorB=80")
    assert aliased.read_text() == canonical.read_text() == mode_alias.read_text()
    assert any(line.startswith("G1") and " B" in line for line in canonical.read_text().splitlines())


def test_single_mode_is_plain_gcode(sliced):
    default = sliced().read_text()
    assert sliced("mixing_mode=single", "mixing_dialect=marlin_m163", "mixing_chamber_volume=30").read_text() \
        == default
    assert sliced("colorMode=0").read_text() == default
    for line in default.split(";LAYER:0\n", 1)[1].splitlines():
        assert not (line.startswith("G1") and (" B" in line or ":" in line)), line
        assert not line.startswith(("M163", "M164", "M165", "M567", "MANUAL_STEPPER")), line


@pytest.mark.parametrize("setting,needle", [
    (("mixing_mode=gradient", "mixing_gradient_start=80", "mixing_gradient_end=20"), "mixing_gradient_start"),
    (("colorMode=2", "colorA=80", "colorB=20"), "mixing_gradient_start"),
    (("mixing_mode=dual", "mixing_ratio=0.3:0.6"), "mixing_ratio"),
    (("mixing_mode=gradient", "mixing_gradient_stops=0=0.5:0.4; 100=0:1"), "mixing_gradient_stops"),
    (("mixing_mode=dual", "mixing_dialect=marlin_m163", "mixing_channels=3", "machine_extruder_count=2"),
     "mixing_channels"),
    (("mixing_mode=dual", "mixing_channels=3"), "mixing_channels"),
    (("mixing_mode=dual", "mixing_dialect=bambu"), "mixing_dialect"),
    (("colorMode=9",), "colorMode"),
])
def test_bad_values_are_one_line_errors_and_nothing_is_written(engine, cube, tmp_path, setting, needle):
    out = tmp_path / "bad.gcode"
    preview = tmp_path / "bad.png"
    args = ["slice"]
    for s in setting:
        args += ["-s", s]
    proc = helpers.mixengine(*args, "-l", cube, "-o", out, "--preview", preview)
    lines = helpers.stderr_lines(proc)
    assert proc.returncode == 1 and len(lines) == 1 and f"'{needle}'" in lines[0], proc.stderr
    assert not out.exists() and not preview.exists()
    assert list(tmp_path.iterdir()) == [], "a temporary file was left behind"


def mix_prediction(colors, ratio):
    """The pigment model's colour of a mix, from `mixengine mix` (8-bit sRGB)."""
    proc = helpers.mixengine("mix", "--colors", colors, "--ratio", ratio)
    assert proc.returncode == 0, proc.stderr
    text = next(line.split()[1] for line in proc.stdout.splitlines() if line.startswith("predicted"))
    return tuple(int(text[i:i + 2], 16) for i in (1, 3, 5))


def test_preview_shows_the_gradient_from_a_to_b(engine, cube, tmp_path):
    out, png = tmp_path / "p.gcode", tmp_path / "p.png"
    proc = helpers.mixengine("slice", "-s", "colorMode=2", "-s", "colorA=20", "-s", "colorB=80",
                             "-s", "mixing_channel_colors=#ffff00,#0000ff", "-l", cube, "-o", out, "--preview", png)
    assert proc.returncode == 0, proc.stderr
    width, height, rows = png_pixels(png)
    assert 700 <= max(width, height) <= 800

    def pixel(fraction_from_bottom):
        y = height - 1 - 10 - int(fraction_from_bottom * (height - 20))
        x = width // 2
        return tuple(rows[y][3 * x:3 * x + 3])

    # The front face, a little darker than the nearest extrusion (the brim) by the depth shading.
    low, high, mid = pixel(0.1), pixel(0.9), pixel(0.5)
    assert low[0] == low[1] > 200 and low[2] == 0     # below 20 %: A (yellow) only
    assert high[0] == high[1] == 0 and high[2] > 200  # above 80 %: B (blue) only
    # Half way: the colour the pigment model predicts for the even mix (`mixengine mix`, #038b55 —
    # yellow and blue paints make green, not the grey of a linear-light blend), a little darker by
    # the depth shading; what leaves an ideal chamber (volume 0) is what the G-code commands.
    even = mix_prediction("#ffff00,#0000ff", "0.5:0.5")
    assert mid[1] > mid[0] + 60 and mid[1] > mid[2] + 20, mid
    assert all(0.85 * e - 2 <= m <= e + 2 for m, e in zip(mid, even)), (mid, even)
    assert tuple(rows[2][0:3]) == (230, 230, 230)  # background margin
