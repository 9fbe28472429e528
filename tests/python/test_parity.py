"""Issue 19, issue 28: every setting Cura shows acts as CuraEngine 4.13's does, or is listed as not honoured yet.

For every flippable setting of fdmprinter / fdmextruder (parity.py: the Ender-3, 0.2 mm layers, on three models —
the parity model with pillars, a bridge, overhangs, a thin fin and a tube; a shelf with wide overhangs and
support standing on the model; seven thin parts), each changed value is sliced by both engines with the same
resolved values, and MixEngine's print must change as CuraEngine's does (parity.verdict: direction, size within
1/3..3 times CuraEngine's change, commands, features, temperatures and the speed / fan / acceleration / jerk
values written; no clear change where CuraEngine's print stays the same). Every enum setting's options that
CuraEngine prints differently must print differently in MixEngine (test_enum_options_print_differently). The
settings that do not yet are settings/mixengine/not_honoured.json — the same list the engine warns from — and
each listed entry is a strict expected failure: when a listed setting starts to act, its test fails until the
entry is removed, so the list can only shrink and cannot lie.

The same rule runs on a second printer, the Ultimaker S5 with one part per extruder (parity.DualScene), for the
settings that matter with two extruders (test_setting_acts_as_in_curaengine_with_two_extruders). A key is listed
when it is not honoured in any scene; an entry marked "multi_extruder_only" is expected to fail in the
two-extruder scene only.

A setting no scene can judge (Cura never shows it, CuraEngine's G-code does not change with it, it only
matters with two extruders) is skipped with its reason, and test_every_setting_is_judged_or_named counts and
names them all in the report; a setting no context switches on fails it. CuraEngine's results are cached in
~/.cache/mixengine-compare/parity; a fresh run slices each changed value once with each engine, two at a time.
"""
import pytest

import parity

_DEFS = parity.definitions()
KEYS = sorted(parity.SINGLE.keys())
DUAL_KEYS = sorted(parity.DUAL.keys())
ENUM_KEYS = [k for k in KEYS if _DEFS[k].get("type") == "enum"]
LISTED = parity.load_not_honoured()
SINGLE_TESTS = ("test_setting_acts_as_in_curaengine", "test_enum_options_print_differently")


def _param(key, scene):
    """KEY as a strict xfail when the list says it is not honoured (whatever the value) in SCENE."""
    entry = LISTED.get(key)
    applies = entry is not None and (scene is parity.DUAL or not entry[2])
    if applies and entry[0] is None:  # every changed value is listed
        return pytest.param(key, marks=pytest.mark.xfail(strict=True, reason=f"not honoured yet: {entry[1]}"))
    return key


def _selected(request, test_names):
    """The keys of the TEST_NAMES tests selected in this run (None: every key, when none is selected)."""
    keys = {item.callspec.params["key"] for item in request.session.items
            if item.originalname in test_names and hasattr(item, "callspec")}
    return keys or None


def _sweep(scenes, keys, report):
    """{key: [outcome + "scene"]} of every changed value of KEYS on SCENES, judged two at a time."""
    by_key = {}
    for scene in scenes:
        results = parity.run_all(keys=keys, scene=scene)
        counts = {}
        for outcome in results.values():
            kind = outcome["verdict"].split(":")[0]
            counts[kind] = counts.get(kind, 0) + 1
            by_key.setdefault(outcome["key"], []).append(dict(outcome, scene=scene.name))
        report(f"parity ({scene.name}): {len(results)} changed values of {len({o['key'] for o in results.values()})} "
               f"settings: " + ", ".join(f"{n} {kind}" for kind, n in sorted(counts.items())))
    return by_key


@pytest.fixture(scope="session")
def verdicts(engine, request, report):
    """The outcomes of the single-extruder scenes (the Ender-3 with each of parity.SINGLES' models)."""
    return _sweep(parity.SINGLES, _selected(request, SINGLE_TESTS), report)


@pytest.fixture(scope="session")
def dual_verdicts(engine, request, report):
    """The outcomes of the two-extruder scene (the Ultimaker S5, one part per extruder)."""
    return _sweep([parity.DUAL], _selected(request, ("test_setting_acts_as_in_curaengine_with_two_extruders",)),
                  report)


@pytest.mark.parametrize("key", [_param(k, parity.SINGLE) for k in KEYS])
def test_setting_acts_as_in_curaengine(verdicts, key):
    """KEY changes MixEngine's print as it changes CuraEngine's on each of the three models: in the same
    direction and by a size within 1/3..3 times CuraEngine's, with the commands, features and speed / fan /
    acceleration / jerk values CuraEngine writes, and not at all where CuraEngine's print does not change."""
    _check(verdicts, key, parity.SINGLE)


@pytest.mark.parametrize("key", [_param(k, parity.DUAL) for k in DUAL_KEYS])
def test_setting_acts_as_in_curaengine_with_two_extruders(dual_verdicts, key):
    """The settings that matter with two extruders (parity.DualScene), on the Ultimaker S5 with one part per
    extruder: the same rule and the same list as the single-extruder test."""
    _check(dual_verdicts, key, parity.DUAL)


def _enum_param(key):
    """KEY as a strict xfail when the list marks its options as substituted (printed as another option)."""
    if key in LISTED and LISTED[key][3]:
        return pytest.param(key, marks=pytest.mark.xfail(strict=True, reason=f"listed: {LISTED[key][1]}"))
    return key


@pytest.mark.parametrize("key", [_enum_param(k) for k in ENUM_KEYS])
def test_enum_options_print_differently(verdicts, key):
    """No option is substituted by another: two options of KEY that CuraEngine prints differently print
    differently in MixEngine too (on every model; parity.enum_substitutions)."""
    found = []
    for scene in parity.SINGLES:
        outcomes = [o for o in verdicts.get(key, []) if o["scene"] == scene.name]
        if outcomes:
            pairs = parity.enum_substitutions([(o["value"], o["digests"]) for o in outcomes], outcomes[0]["current"])
            found += [f"{scene.name}: {pair}" for pair in pairs]
    assert not found, f"{key}: " + "; ".join(found)


def _check(verdicts, key, scene):
    outcomes = verdicts.get(key, [])
    judged = [o for o in outcomes if not o["verdict"].startswith(("cura-unchanged", "cura-failed"))]
    if not judged:
        pytest.skip(f"not judged: {unjudged_reason(key, outcomes, scene)}")
    applies = key in LISTED and (scene is parity.DUAL or not LISTED[key][2])
    listed_values = LISTED[key][0] if applies else ()
    unexpected = [f"{o['scene']}: {key}={o['value']}: {o['verdict']}" for o in judged
                  if o["verdict"] != "honoured" and (listed_values is None or o["value"] not in listed_values)]
    assert not unexpected, "; ".join(unexpected)
    if listed_values and not LISTED[key][3]:  # a per-value entry: the listed values must still be wrong
        wrong = {o["value"] for o in judged if o["value"] in listed_values and o["verdict"] != "honoured"}
        now_honoured = sorted({o["value"] for o in judged if o["value"] in listed_values} - wrong)
        assert not now_honoured, (f"{key}: {now_honoured} now act as in CuraEngine; remove them from "
                                  f"{parity.NOT_HONOURED.name}")


def unjudged_reason(key, outcomes, scene):
    """Why KEY got no verdict in SCENE: Cura never shows it, no context switches it on, no value to try,
    or CuraEngine's G-code does not change with it (or CuraEngine fails with it)."""
    node = _DEFS[key]
    if str(node.get("enabled", True)).startswith("False") or " and False" in str(node.get("enabled")):
        return "Cura never shows it (its enabled formula is False)"
    if not outcomes:
        if parity.context_for(key, scene) is None:
            return "no context of the scene switches it on"
        return f"no changed value to try for its type ({node.get('type')})"
    if all(o["verdict"].startswith("cura-failed") for o in outcomes):
        return "CuraEngine fails to slice every changed value"
    scenes = sorted({o.get("scene", scene.name) for o in outcomes})
    return f"CuraEngine's G-code does not change with it ({', '.join(scenes)})"


def test_every_setting_is_judged_or_named(verdicts, dual_verdicts, report):
    """Every setting Cura can show is judged in some scene, or named in the report with its reason; a setting
    that no context of any scene switches on is a gap in parity.CONTEXTS and fails this test."""
    unjudged = {}
    for key in sorted(set(KEYS) | set(DUAL_KEYS)):
        judged = [o for o in verdicts.get(key, []) + dual_verdicts.get(key, [])
                  if not o["verdict"].startswith(("cura-unchanged", "cura-failed"))]
        if judged:
            continue
        scene = parity.SINGLE if key in KEYS else parity.DUAL
        reasons = {unjudged_reason(key, verdicts.get(key, []), parity.SINGLE) if key in KEYS else None,
                   unjudged_reason(key, dual_verdicts.get(key, []), parity.DUAL) if key in DUAL_KEYS else None}
        reasons.discard(None)
        switched_on = [r for r in reasons if r != "no context of the scene switches it on"]
        unjudged[key] = switched_on[0] if switched_on else unjudged_reason(key, [], scene)
    by_reason = {}
    for key, reason in unjudged.items():
        by_reason.setdefault(reason, []).append(key)
    report(f"parity: {len(unjudged)} of {len(set(KEYS) | set(DUAL_KEYS))} settings not judged:")
    for reason, keys in sorted(by_reason.items()):
        report(f"    {reason} ({len(keys)}): {', '.join(keys)}")
    never_on = by_reason.get("no context of the scene switches it on", [])
    assert not never_on, f"no context switches these on (add one to parity.CONTEXTS): {never_on}"


def test_the_list_names_real_settings():
    """Every entry of not_honoured.json is a setting of Cura's definitions (no stale or misspelt keys)."""
    assert set(LISTED) <= set(_DEFS), sorted(set(LISTED) - set(_DEFS))


def test_the_verdict_can_fail():
    """The comparison itself: a MixEngine print that does not change, or changes the other way, is caught."""
    base = {"digest": "a", "figures": dict.fromkeys(parity.THRESHOLDS, 100.0), "commands": ["M104"],
            "types": ["FILL"], "temps": ["M104 S200"]}
    more = dict(base, digest="b", figures=dict(base["figures"], filament=110.0))
    less = dict(base, digest="c", figures=dict(base["figures"], filament=90.0))
    hotter = dict(base, digest="d", temps=["M104 S200", "M104 S210"])
    assert parity.verdict(base, more, base, base).startswith("not honoured: MixEngine's G-code does not change")
    assert parity.verdict(base, more, base, less).startswith("not honoured: filament")
    assert parity.verdict(base, more, base, more) == "honoured"
    assert parity.verdict(base, base, base, base) == "cura-unchanged"
    assert "M104 S210" in parity.verdict(base, hotter, base, more)


def test_the_verdict_judges_size_values_and_changes_cura_does_not_make():
    """Size: MixEngine's change must lie within 1/3..3 times CuraEngine's; values: a speed CuraEngine starts
    writing (F2400 = 40 mm/s, a setting's value) must be written by MixEngine too; a clear change where
    CuraEngine's G-code stays the same is not honoured."""
    base = {"digest": "a", "figures": dict.fromkeys(parity.THRESHOLDS, 100.0), "commands": ["G1"],
            "types": ["FILL"], "temps": [], "values": ["F1500"]}

    def changed(digest, filament, values=("F1500",)):
        return dict(base, digest=digest, figures=dict(base["figures"], filament=filament), values=list(values))
    assert parity.verdict(base, changed("b", 110), base, changed("c", 112)) == "honoured"
    assert parity.verdict(base, changed("b", 110), base, changed("c", 104)) == "honoured"  # x0.4
    assert "size" in parity.verdict(base, changed("b", 110), base, changed("c", 102))  # x0.2
    assert "size" in parity.verdict(base, changed("b", 110), base, changed("c", 140))  # x4
    assert parity.verdict(base, changed("b", 100.6), base, changed("c", 100.15)) == "honoured"  # x0.25 but 0.45 apart: no clear gap
    given = (parity.given_values({"speed_wall": "40"}), parity.given_values({"speed_wall": "25"}))
    faster = changed("b", 110, ("F1500", "F2400"))
    assert parity.verdict(base, faster, base, changed("c", 110, ("F1500", "F2400")), given=given) == "honoured"
    assert "F2400" in parity.verdict(base, faster, base, changed("c", 110, ("F1500", "F2700")), given=given)
    assert parity.verdict(base, faster, base, changed("c", 110, ("F1500",)),
                          given=(parity.given_values({"speed_wall": "41"}), given[1])) == "honoured"  # not its value
    assert parity.verdict(base, changed("b", 110, ()), base, changed("c", 110), given=given).endswith(
        "CuraEngine stops writing ['F1500'], MixEngine does not")
    assert parity.verdict(base, base, base, changed("c", 90)).startswith(
        "not honoured: filament MixEngine -10 where CuraEngine's G-code does not change")
    assert parity.verdict(base, base, base, changed("c", 100.1)) == "cura-unchanged"  # not a clear change


def test_substituted_enum_options_are_found():
    """Two options CuraEngine prints differently that MixEngine prints the same are named; options that both
    engines print alike are not."""
    outcomes = [("lines", {"cura_base": "c0", "cura": "c1", "mix_base": "m0", "mix": "m1"}),
                ("lightning", {"cura_base": "c0", "cura": "c2", "mix_base": "m0", "mix": "m1"}),
                ("cross", {"cura_base": "c0", "cura": "c1", "mix_base": "m0", "mix": "m1"})]
    assert parity.enum_substitutions(outcomes, "grid") == ["cross prints as lightning", "lightning prints as lines"]


def test_the_two_extruder_verdict_compares_set_temperatures_only():
    """In the two-extruder scene a standby temperature CuraEngine computes from its own time estimates
    (M104 T1 S153.9) is not compared, a temperature a setting gives (M104 T1 S150) is."""
    base = {"digest": "a", "figures": dict.fromkeys(parity.THRESHOLDS, 100.0), "commands": ["M104"],
            "types": ["FILL"], "temps": ["M104 S100 T1", "M109 S200"]}
    cura = dict(base, digest="b", temps=["M104 S150 T1", "M104 S153.9 T1", "M109 S200"])
    mix_close = dict(base, digest="c", temps=["M104 S150 T1", "M104 S161.4 T1", "M109 S200"])
    mix_without = dict(base, digest="d", temps=["M104 S161.4 T1", "M109 S200"])
    set_values = {0.0, 100.0, 150.0, 200.0}
    assert parity.verdict(base, cura, base, mix_close, set_temperatures=set_values) == "honoured"
    assert "M104 S150 T1" in parity.verdict(base, cura, base, mix_without, set_temperatures=set_values)
    assert "M104 S153.9 T1" in parity.verdict(base, cura, base, mix_close)  # the single-extruder rule


def test_the_two_extruder_scene_gives_both_trains_and_both_parts():
    """Both engines get every global value, each train's own values after its -eN, and each part after
    its train with its extruder_nr (CuraEngine parents a model's settings to the last -e given)."""
    args = [str(a) for a in parity.DUAL.slice_args({"material_standby_temperature": "150"})]
    assert args[:2] == ["-j", str(parity.DUAL.machine)]
    e0, e1 = args.index("-e0"), args.index("-e1")
    models = [i for i, a in enumerate(args) if a == "-l"]
    assert len(models) == 2 and e0 < models[0] < e1 < models[1]
    assert args[models[0] + 1].endswith("dual_a.stl") and args[models[0] + 2:models[0] + 4] == ["-s", "extruder_nr=0"]
    assert args[models[1] + 1].endswith("dual_b.stl") and args[-2:] == ["-s", "extruder_nr=1"]
    assert "material_standby_temperature=150.0" in args[:e0]  # a global user value, seen by both trains
    assert "machine_nozzle_offset_x=22.0" in args[e1:models[1]]
    flip = [str(a) for a in parity.DUAL.slice_args({"machine_nozzle_offset_x": "33"})]  # a train's own key:
    assert "machine_nozzle_offset_x=33.0" in flip[flip.index("-e1"):]                 # the second train's
