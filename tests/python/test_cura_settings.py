"""Settings resolution against real Cura 4.13: the values MixEngine resolves from the definition
files must equal the values Cura itself sent to its engine in the Slice message.

The fixtures in tests/data/cura_slice/ were recorded with real Cura under Xvfb
(tests/e2e/run_cura.sh); each holds the machine, the user values set in Cura, the profile
containers Cura chose, and the global / per-extruder settings it sent. Values compare as text,
exactly: Cura sends Python's str() of each value ("235" for an int default, "0.35000000000000003",
"true" for a material's text), and so must MixEngine."""
import json
import subprocess
from pathlib import Path

import pytest

FIXTURES = Path(__file__).resolve().parents[1] / "data" / "cura_slice"
# Keys Cura sends that are no setting MixEngine resolves, each with the reason. Every other key must
# be in MixEngine's output with Cura's value: there is no tolerance.
#   time, date, day: the moment of the recording, not settings resolution.
VOLATILE = {"time", "date", "day"}
#   The definition categories: Stack.getAllKeys() includes them and Cura sends "0" for each.
CATEGORIES = {"blackmagic", "command_line_settings", "cooling", "dual", "experimental", "infill",
              "machine_settings", "material", "meshfix", "platform_adhesion", "resolution", "shell",
              "speed", "support", "top_bottom", "travel"}
#   Metadata of the global stack's material container, which in Cura is always empty_material
#   (StartSliceJob._buildReplacementTokens); no definition declares them and CuraEngine reads none.
GLOBAL_MATERIAL_METADATA = {"material_id": "empty_material", "material_type": "empty",
                            "material_name": "empty", "material_brand": ""}
# The profile choices made in Cura for a fixture, as command-line options (default: the machine's).
PROFILE_OPTIONS = {"ultimaker_s5_intent": ["--quality", "fast", "--intent", "engineering"],
                   "ultimaker_s5_user": ["--variant", "AA 0.4,BB 0.4", "--material", "generic_pla,generic_pva"]}


def _command(engine, fixture):
    args = [str(engine), "settings", "-j", fixture["machine"], "--profiles"]
    args += PROFILE_OPTIONS.get(fixture["name"], [])
    for key, value in fixture["user"].get("global", {}).items():
        args += ["-s", f"{key}={value}"]
    for nr, values in sorted(fixture["user"].get("extruders", {}).items()):
        args.append(f"-e{nr}")
        for key, value in values.items():
            args += ["-s", f"{key}={value}"]
    return args + ["--json"]


def _compare(cura, ours, scope, mismatches):
    compared = 0
    for key, value in cura.items():
        if key in VOLATILE:
            continue
        if key not in ours:
            if key in CATEGORIES and value == "0":
                continue
            if scope == "global" and GLOBAL_MATERIAL_METADATA.get(key) == value:
                continue
            mismatches.append(f"{scope}.{key}: Cura {value[:60]!r}, not in MixEngine's output")
            continue
        compared += 1
        if value != ours[key]:
            mismatches.append(f"{scope}.{key}: Cura {value[:60]!r} MixEngine {ours[key][:60]!r}")
    return compared


@pytest.mark.parametrize("name", sorted(path.stem for path in FIXTURES.glob("*.json")))
def test_resolved_settings_equal_what_cura_sends(engine, name, report):
    fixture = json.loads((FIXTURES / f"{name}.json").read_text())
    fixture["name"] = name
    run = subprocess.run(_command(engine, fixture), capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    ours = json.loads(run.stdout)
    mismatches = []
    compared = _compare(fixture["global_settings"], ours["global"], "global", mismatches)
    for extruder in fixture["extruders"]:
        compared += _compare(extruder["settings"], ours["extruders"][extruder["id"]], f"e{extruder['id']}", mismatches)
    report(f"cura settings {name}: {compared - len(mismatches)}/{compared} equal")
    for line in mismatches:
        report(f"    {line}")
    assert compared > 900
    assert not mismatches, f"{len(mismatches)} of {compared} differ:\n" + "\n".join(mismatches[:40])


def test_a_command_line_value_wins_over_the_profiles(engine):
    """With --profiles the S5's AA 0.4 profile sets speed_print 70; a -s value is what the user means to
    print, so it reaches every extruder (as a value set in Cura, which writes it to the extruder's own user
    container)."""
    fixture = json.loads((FIXTURES / "ultimaker_s5_default.json").read_text())
    base = [str(engine), "settings", "-j", fixture["machine"], "--profiles", "--json"]
    plain = json.loads(subprocess.run(base, capture_output=True, text=True, timeout=60, check=True).stdout)
    assert [float(e["speed_print"]) for e in plain["extruders"]] == [70.0, 70.0]
    changed = json.loads(subprocess.run(base[:-1] + ["-s", "speed_print=80", "--json"], capture_output=True,
                                        text=True, timeout=60, check=True).stdout)
    assert float(changed["global"]["speed_print"]) == 80.0
    assert [float(e["speed_print"]) for e in changed["extruders"]] == [80.0, 80.0]
