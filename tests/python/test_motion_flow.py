"""Issue 15, motion and flow: coasting, the wipe script between layers, flow-rate compensation and bridge
settings, as CuraEngine 4.13 prints them, on a mixing printer too.

Each feature's parity with CuraEngine is test_parity.py's (one setting flipped at a time on the parity model);
its exact moves are unit tests (tests/unit/planning/Coasting_test.cpp, ...). Here: the G-code a user gets
with each switched on — and on a mixing printer the channels still add up, move by move, to the filament of
the single-colour print with the same settings (retractions and primes included).
"""
from functools import lru_cache

import pytest

import helpers
import side_by_side as sbs
from mixing_gcode import box_stl, read_mixing_gcode, relative_error

SPLIT_DIALECTS = ["eb_axes", "klipper_b", "rrf_colon"]
COMMAND_DIALECTS = ["marlin_m163", "rrf_m567"]

FEATURES = {
    "coasting": ("coasting_enable=True",),
    "flow-rate compensation": ("flow_rate_max_extrusion_offset=0.5",),
    "wipe script": ("clean_between_layers=True", "wipe_hop_enable=True", "wipe_retraction_extra_prime_amount=0.5"),
}


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("motion") / "cube.stl", 20.0, 20.0, 10.0)


@pytest.fixture(scope="module")
def sliced(engine, cube, tmp_path_factory):
    """sliced(*settings) -> path of the G-code for the cube with those -s settings (cached)."""
    out_dir = tmp_path_factory.mktemp("motion_gcode")

    @lru_cache(maxsize=None)
    def run(*settings):
        return helpers.slice_with(cube, out_dir / f"{len(list(out_dir.iterdir()))}.gcode", *settings)

    return run


def gradient(dialect, relative):
    return (f"relative_extrusion={relative}", "mixing_mode=gradient", f"mixing_dialect={dialect}",
            "mixing_gradient_start=20", "mixing_gradient_end=80")


@pytest.mark.parametrize("relative", [False, True])
@pytest.mark.parametrize("dialect", SPLIT_DIALECTS + COMMAND_DIALECTS)
@pytest.mark.parametrize("feature", sorted(FEATURES))
def test_channels_add_up_to_the_single_colour_e(sliced, feature, dialect, relative):
    """rrf_colon is always written relative, so its single-colour reference is the relative slice."""
    settings = FEATURES[feature]
    single_relative = relative or dialect == "rrf_colon"
    single = read_mixing_gcode(sliced(*settings, f"relative_extrusion={single_relative}"), "single").moves
    mixed = read_mixing_gcode(sliced(*settings, *gradient(dialect, relative)), dialect).moves
    plain = read_mixing_gcode(sliced(f"relative_extrusion={single_relative}"), "single").moves
    assert [round(m.total, 5) for m in single] != [round(m.total, 5) for m in plain], "the feature changes nothing"
    mixed_ext = [m for m in mixed if m.xy and m.total > 0]
    single_ext = [m for m in single if m.xy and m.total > 0]
    assert len(mixed_ext) == len(single_ext) > 500
    assert max(relative_error(m.total, s.total) for m, s in zip(mixed_ext, single_ext)) <= 1e-5
    assert [round(m.total, 5) for m in mixed] == [round(s.total, 5) for s in single]


def _lines(path):
    return [line.split(";", 1)[0].strip() for line in open(path) if line.strip() and not line.startswith(";")]


def test_coasting_travels_over_the_end_of_each_wall(sliced):
    """coasting_enable: an outer wall loop of the 20 mm cube (0.4 mm line, 0.2 mm layers, fdmprinter's
    coasting_volume 0.064 mm³) stops extruding 0.8 mm before its end and travels the rest at
    coasting_speed 90 % of the wall speed."""
    lines = _lines(sliced("coasting_enable=True"))
    plain = _lines(sliced())
    coasts = [i for i, line in enumerate(lines) if line.startswith("G0 F1620 ")]  # 0.9 × 30 mm/s × 60
    assert len(coasts) > 100
    assert not any(line.startswith("G0 F1620 ") for line in plain)
    first = coasts[0]
    assert lines[first - 1].startswith("G1 ") and " E" in lines[first - 1]


def test_wipe_script_between_layers(sliced):
    """clean_between_layers: after more than max_extrusion_before_wipe (10 mm³) the next layer starts with the
    script — fdmprinter's: retract 6.5 mm, lift 1 mm, brush at x = 100 mm five times 20 mm at
    speed_travel (120 mm/s), back, prime."""
    with open(sliced("clean_between_layers=True", "wipe_hop_enable=True")) as f:
        text = f.read()
    begin = text.count(";WIPE_SCRIPT_BEGIN")
    assert begin == text.count(";WIPE_SCRIPT_END") > 40
    block = text.split(";WIPE_SCRIPT_BEGIN\n", 2)[1].split(";WIPE_SCRIPT_END", 1)[0].splitlines()
    assert [line.split(" X")[0] for line in block[2:8]] == ["G0 F7200", "G0", "G0", "G0", "G0", "G0"]
    xs = [float(line.split(" X")[1].split()[0]) for line in block[2:8]]
    assert xs == [100, 120, 100, 120, 100, 120]
    assert block[0].startswith("G1 F1500 E") and block[1].startswith("G1 F600 Z")
    assert block[-1].startswith("G1 F1500 E")


def test_flow_rate_compensation_offsets_e_from_each_feature(sliced):
    """flow_rate_max_extrusion_offset: each feature's first line sets the offset (speed × mm³/mm, at most the
    maximum: 0.5 mm here) and every following extrusion and travel word carries it; retractions do not."""
    text = open(sliced("flow_rate_max_extrusion_offset=0.5")).read()
    assert ";FLOW_RATE_COMPENSATED_OFFSET = 0.500000" in text
    assert "FLOW_RATE" not in open(sliced()).read()
    travels_with_e = [line for line in _lines(sliced("flow_rate_max_extrusion_offset=0.5"))
                      if line.startswith("G0 ") and " X" in line and " E" in line]
    assert len(travels_with_e) > 100


@pytest.mark.parametrize("dialect", ["eb_axes", "marlin_m163"])
def test_bridged_skin_on_the_parity_model(engine, tmp_path, dialect):
    """bridge_settings_enabled on the parity model (two pillars with a 16 mm deck): the deck's first layer is
    printed as bridge skin — ;TYPE:SKIN then ;BRIDGE, at bridge_skin_speed (fdmprinter: 15 mm/s, F900), with
    bridge_fan_speed — and the second and third layers above it with their own fan (0 %: M107); on a mixing
    printer the channels add up to the single-colour print's filament move by move."""
    model = sbs.model_path("parity")
    single = helpers.slice_with(model, tmp_path / "single.gcode", "bridge_settings_enabled=True")
    text = open(single).read()
    blocks = text.split(";BRIDGE\n")[1:]
    assert len(blocks) >= 3
    assert any("G1 F900 X" in block.split(";TYPE:", 1)[0] for block in blocks)
    assert any(block.startswith("M107") for block in blocks)
    assert ";BRIDGE" not in open(helpers.slice_with(model, tmp_path / "plain.gcode")).read()
    mixed = helpers.slice_with(model, tmp_path / "mixed.gcode", "bridge_settings_enabled=True",
                               *gradient(dialect, False))
    single_moves = read_mixing_gcode(single, "single").moves
    mixed_moves = read_mixing_gcode(mixed, dialect).moves
    assert [round(m.total, 5) for m in mixed_moves] == [round(s.total, 5) for s in single_moves]
