"""Printer profiles (issue 8): settings/definitions/*.def.json and settings/extruders/*.def.json.

  - the files are plain Cura 4.13 definitions: every overridden key is a key of Cura's fdmprinter /
    fdmextruder or one of MixEngine's own (settings/mixengine/*.def.json), with a valid value;
  - they deserialise in the real Uranium 4.13 Cura runs on (uranium_profiles.py under /usr/bin/python3):
    registry metadata, the inherits chain, and the values as written; Uranium's only complaints are the
    MixEngine keys it does not know (the plugin adds those), exactly those;
  - each profile slices a cube with `mixengine slice -j <id>` and its G-code carries the printer's
    dialect, read back by the firmware models of mixing_gcode.py: E/B words (MakerPi), M163/M164 at
    1/128 steps (Geeetech A10M), M567 with E a:b and relative extrusion (RepRapFirmware), five channels
    in M165 (CMYK+W), T0/T1 with the 18 mm nozzle offset and a shared prime tower (dual nozzle).
"""
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

import helpers
from mixing_gcode import box_stl, read_mixing_gcode, seed_share_b

SETTINGS = helpers.REPO / "settings"
DEFINITIONS = SETTINGS / "definitions"
EXTRUDERS = SETTINGS / "extruders"
SYSTEM_PYTHON = Path("/usr/bin/python3")
CUBE_MM = 20.0

MARLIN = "RepRap (Marlin/Sprinter)"
RRF = "RepRap (RepRap)"
# What each machine must be (written here independently of the files).
MACHINES = {
    "mixengine_makerpi_m2030x": dict(name="MakerPi M2030X", flavor=MARLIN, extruders=1, size=(190, 205, 306),
                                     manufacturer="MakerPi", dialect="eb_axes", channels=2),
    "mixengine_geeetech_a10m": dict(name="Geeetech A10M", flavor=MARLIN, extruders=1, size=(220, 220, 260),
                                    manufacturer="Geeetech", dialect="marlin_m163", channels=2, resolution=128),
    "mixengine_rrf_mixing": dict(name="RepRapFirmware Mixing Printer", flavor=RRF, extruders=1,
                                 size=(200, 200, 200), manufacturer="MixEngine", dialect="rrf_m567", channels=2,
                                 resolution=1000),
    "mixengine_cmykw_mixer": dict(name="CMYK+W Mixer", flavor=MARLIN, extruders=1, size=(220, 220, 250),
                                  manufacturer="MixEngine", dialect="marlin_m165", channels=5, resolution=100),
    "mixengine_dual_nozzle": dict(name="Dual Nozzle Printer", flavor=MARLIN, extruders=2, size=(220, 220, 250),
                                  manufacturer="MixEngine", offsets=[(0.0, 0.0), (18.0, 0.0)]),
}
MIXING = [m for m, spec in MACHINES.items() if "dialect" in spec]
FLAVOR_HEADER = {MARLIN: ";FLAVOR:Marlin", RRF: ";FLAVOR:RepRap"}


# ---------------------------------------------------------------- the files themselves

def load(path):
    return json.loads(Path(path).read_text())


def tree_keys(settings):
    """{key: definition} of a Cura settings tree (categories included)."""
    out = {}
    for key, node in settings.items():
        out[key] = node
        out.update(tree_keys(node.get("children", {})))
    return out


CURA_MACHINE_KEYS = tree_keys(load(helpers.CURA_DEFS / "fdmprinter.def.json")["settings"])
CURA_EXTRUDER_KEYS = tree_keys(load(helpers.CURA_DEFS / "fdmextruder.def.json")["settings"])
MIXENGINE_KEYS = {}
for fragment in sorted((SETTINGS / "mixengine").glob("*.def.json")):
    MIXENGINE_KEYS.update(tree_keys(load(fragment)["settings"]))


def chain(definition_id):
    """The definition files of `definition_id` from the leaf up to (not including) fdmprinter."""
    out = []
    while definition_id not in ("fdmprinter", "fdmextruder"):
        doc = load(DEFINITIONS / f"{definition_id}.def.json")
        out.append(doc)
        definition_id = doc["inherits"]
    return out


def merged(definition_id):
    """(metadata, {key: override}) as Uranium merges them: the leaf wins over its parents."""
    metadata, overrides = {}, {}
    for doc in reversed(chain(definition_id)):
        metadata.update(doc.get("metadata", {}))
        for key, props in doc.get("overrides", {}).items():
            overrides.setdefault(key, {}).update(props)
    return metadata, overrides


def written(definition_id, key):
    return merged(definition_id)[1][key]["default_value"]


def all_definition_files():
    return sorted(DEFINITIONS.glob("*.def.json")) + sorted(EXTRUDERS.glob("*.def.json"))


def test_every_profile_is_there():
    ids = {p.name[:-len(".def.json")] for p in DEFINITIONS.glob("*.def.json")}
    assert set(MACHINES) | {"mixengine_mixing_base"} == ids


@pytest.mark.parametrize("machine", sorted(MACHINES))
def test_definition_keys_and_metadata(machine):
    spec = MACHINES[machine]
    docs = chain(machine)
    assert all(doc["version"] == 2 and doc["name"] for doc in docs)
    metadata, overrides = merged(machine)
    assert metadata["visible"] is True and metadata["author"] == "MixEngine"
    assert metadata["manufacturer"] == spec["manufacturer"]
    assert metadata["file_formats"] == "text/x-gcode"
    assert metadata["has_materials"] is True and metadata["preferred_material"] == "generic_pla"
    # Cura resolves preferred_material generic_pla to generic_pla_175 for 1.75 mm filament.
    assert (Path("/usr/share/cura/resources/materials") / "generic_pla_175.xml.fdm_material").is_file()
    trains = metadata["machine_extruder_trains"]
    assert sorted(trains) == [str(i) for i in range(spec["extruders"])]
    for key, props in overrides.items():
        known = CURA_MACHINE_KEYS.get(key) or MIXENGINE_KEYS.get(key)
        assert known is not None, f"{machine}: '{key}' is neither a Cura setting nor a MixEngine setting"
        assert set(props) <= {"default_value", "value", "minimum_value", "maximum_value"}, (key, props)
        if "options" in known and "default_value" in props:
            assert props["default_value"] in known["options"], (key, props)
    values = {k: p.get("default_value") for k, p in overrides.items()}
    assert values["machine_name"] == spec["name"]
    assert values["machine_gcode_flavor"] == spec["flavor"]
    assert values["machine_extruder_count"] == spec["extruders"]
    assert (values["machine_width"], values["machine_depth"], values["machine_height"]) == spec["size"]
    if "dialect" in spec:
        assert values["mixing_dialect"] == spec["dialect"] and values["mixing_channels"] == spec["channels"]
        assert values.get("mixing_resolution", 100) == spec.get("resolution", 100)
        colours = values["mixing_channel_colors"].split(",")
        assert len(colours) == spec["channels"] and all(re.fullmatch(r"#[0-9a-f]{6}", c) for c in colours)
    # Start/end code: only tokens Cura's frontend can fill in (a {key} or {key, extruder}).
    for code_key in ("machine_start_gcode", "machine_end_gcode"):
        for token in re.findall(r"\{([^}]*)\}", values[code_key]):
            assert token.split(",")[0].strip() in CURA_MACHINE_KEYS, f"{code_key}: {{{token}}}"


@pytest.mark.parametrize("machine", sorted(MACHINES))
def test_extruder_trains(machine):
    spec = MACHINES[machine]
    for position, extruder_id in merged(machine)[0]["machine_extruder_trains"].items():
        doc = load(EXTRUDERS / f"{extruder_id}.def.json")
        assert doc["version"] == 2 and doc["inherits"] == "fdmextruder"
        assert doc["metadata"] == {"machine": machine, "position": position}
        props = doc["overrides"]
        for key in props:
            assert key in CURA_EXTRUDER_KEYS, f"{extruder_id}: '{key}' is not an fdmextruder setting"
        assert props["extruder_nr"]["default_value"] == int(position)
        assert props["material_diameter"]["default_value"] == 1.75
        if "offsets" in spec:
            offset = (props["machine_nozzle_offset_x"]["default_value"],
                      props["machine_nozzle_offset_y"]["default_value"])
            assert offset == spec["offsets"][int(position)]
            assert props["machine_extruder_start_code"]["default_value"]
            assert props["machine_extruder_end_code"]["default_value"]


# ---------------------------------------------------------------- the real Uranium 4.13

@pytest.fixture(scope="module")
def uranium(tmp_path_factory):
    """Runs uranium_profiles.py under the system Python on every definition and extruder id."""
    packages = Path("/usr/lib/python3/dist-packages")
    if not SYSTEM_PYTHON.is_file() or not (packages / "UM").is_dir() or not (packages / "cura").is_dir():
        pytest.skip("Debian's cura / python3-uranium 4.13 are not installed (install.sh installs them)")
    root = tmp_path_factory.mktemp("uranium")
    resources = root / "resources"
    for folder, files in (("definitions", DEFINITIONS.glob("*.def.json")), ("extruders", EXTRUDERS.glob("*.def.json"))):
        (resources / folder).mkdir(parents=True)
        for f in files:
            shutil.copy(f, resources / folder / f.name)
    ids = [p.name[:-len(".def.json")] for p in all_definition_files()]
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}
    home = root / "home"  # Uranium writes its cache, database and plugin list under HOME / XDG folders
    env.update(HOME=str(home), XDG_CONFIG_HOME=str(home / "config"), XDG_DATA_HOME=str(home / "data"),
               XDG_CACHE_HOME=str(home / "cache"), PYTHONDONTWRITEBYTECODE="1")
    proc = subprocess.run([SYSTEM_PYTHON, "-W", "ignore", Path(__file__).with_name("uranium_profiles.py"),
                           resources, *ids], capture_output=True, text=True, env=env, timeout=600, cwd=root)
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout)


def test_uranium_loads_every_file_without_errors(uranium, report):
    assert uranium["errors"] == []
    ids = [p.name[:-len(".def.json")] for p in all_definition_files()]
    assert sorted(uranium["definitions"]) == sorted(ids)
    assert sorted(uranium["registry_metadata"]) == sorted(ids)
    assert uranium["is_definition_class"]
    # Besides the MixEngine keys (checked per machine below), Uranium only notes that it could not pickle a
    # definition into its cache (a RecursionError in Uranium's cache, CURA-4024; Cura's own
    # ultimaker_original_dual gives the same).
    other = [w for w in uranium["warnings"] if "Unable to override setting " not in w]
    assert all("failed to pickle" in w for w in other), other
    report(f"profiles: real Uranium 4.13 loaded {len(ids)} files ({len(MACHINES)} machines, "
           f"{len(ids) - len(MACHINES) - 1} extruder trains, 1 abstract base), 0 errors")


@pytest.mark.parametrize("machine", sorted(MACHINES))
def test_uranium_sees_the_machine_as_written(uranium, machine):
    spec = MACHINES[machine]
    loaded = uranium["definitions"][machine]
    values, metadata = loaded["values"], loaded["metadata"]
    for key in ("machine_name", "machine_gcode_flavor", "machine_extruder_count", "machine_width",
                "machine_depth", "machine_height", "machine_start_gcode", "machine_end_gcode"):
        assert values[key] == written(machine, key), key
    assert values["machine_extruder_count"] == spec["extruders"]
    assert values["machine_gcode_flavor"] == spec["flavor"] and values["machine_name"] == spec["name"]
    # The registry's metadata (what Cura's machine list reads) carries the inherited entries too.
    registry = uranium["registry_metadata"][machine]
    for md in (metadata, registry):
        assert md["visible"] is True and md["author"] == "MixEngine" and md["type"] == "machine"
        assert md["file_formats"] == "text/x-gcode" and md["preferred_material"] == "generic_pla"
        assert md["has_materials"] is True
        assert md["machine_extruder_trains"] == merged(machine)[0]["machine_extruder_trains"]
    # A value formula evaluated by Uranium on this definition: RepRap firmware extrudes relative.
    assert uranium["definitions"][machine]["relative_extrusion"] is (spec["flavor"] == RRF)
    assert values["prime_tower_enable"] is (spec["extruders"] > 1)
    # Uranium ignores (with a warning) exactly the overrides of MixEngine's keys, which the plugin adds.
    expected = {k for k in merged(machine)[1] if k in MIXENGINE_KEYS}
    assert set(loaded["override_warnings"]) == expected
    assert not expected or "dialect" in spec


def test_uranium_sees_the_base_as_abstract(uranium):
    base = uranium["registry_metadata"]["mixengine_mixing_base"]
    assert base["visible"] is False and base["inherits"] == "fdmprinter"
    assert uranium["definitions"]["mixengine_mixing_base"]["values"]["machine_extruder_count"] == 1


@pytest.mark.parametrize("machine", sorted(MACHINES))
def test_uranium_sees_the_extruder_trains(uranium, machine):
    spec = MACHINES[machine]
    for position, extruder_id in merged(machine)[0]["machine_extruder_trains"].items():
        loaded = uranium["definitions"][extruder_id]
        assert loaded["override_warnings"] == []
        md = uranium["registry_metadata"][extruder_id]
        assert md["type"] == "extruder" and md["machine"] == machine and md["position"] == position
        values = loaded["values"]
        assert values["extruder_nr"] == int(position) and values["material_diameter"] == 1.75
        if "offsets" in spec:
            assert (values["machine_nozzle_offset_x"], values["machine_nozzle_offset_y"]) == \
                spec["offsets"][int(position)]
            assert values["machine_extruder_start_code"] and values["machine_extruder_end_code"]


# ---------------------------------------------------------------- slicing with each profile

@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("profiles") / "cube.stl", CUBE_MM, CUBE_MM, CUBE_MM)


def slice_with(machine, out, *args):
    proc = helpers.mixengine("slice", "-j", machine, *args, "-o", out)
    assert proc.returncode == 0, proc.stderr
    return out.read_text()


def extrusion_centre(text):
    """Centre (x, y) of the written XY positions of the extruding G1 moves inside ;LAYER: blocks."""
    xs, ys, in_layers, x, y = [], [], False, None, None
    for line in text.splitlines():
        if line.startswith(";LAYER:"):
            in_layers = True
        words = dict(re.findall(r"([XYE])(-?[\d.]+)", line.split(";")[0])) if line.startswith("G1") else {}
        x, y = float(words.get("X", x or 0)), float(words.get("Y", y or 0))
        if in_layers and "X" in words and "E" in words:
            xs.append(x)
            ys.append(y)
    return (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2


def gradient_shares(reading, channel=1):
    """[(percent of the cube height, share of `channel`)] per layer."""
    out = []
    for layer, (z, amounts) in sorted(reading.layer_totals().items()):
        out.append((100.0 * z / CUBE_MM, amounts[channel] / sum(amounts)))
    return out


def check_two_stop_gradient(reading, tolerance):
    shares = gradient_shares(reading)
    assert len(shares) > 60
    for percent, share in shares:
        assert share == pytest.approx(seed_share_b(20, 80, percent), abs=tolerance), percent


# The mixing profiles carry an estimated mixing_chamber_volume, which commands every mix earlier by that volume
# (test_mixing.py::test_chamber_delay_shifts_the_schedule_earlier); the dialect checks here read the seed's
# schedule itself, so they slice with an ideal chamber.
IDEAL_CHAMBER = ("-s", "mixing_chamber_volume=0")
GRADIENT = ("-s", "mixing_mode=gradient", "-s", "mixing_gradient_start=20", "-s", "mixing_gradient_end=80",
            *IDEAL_CHAMBER)


def test_makerpi_writes_e_and_b_words(engine, cube, tmp_path):
    text = slice_with("mixengine_makerpi_m2030x", tmp_path / "m.gcode", *GRADIENT, "-l", cube)
    assert text.startswith(FLAVOR_HEADER[MARLIN])
    assert ";MakerPi M2030X colour mixing" in text and "G1 X150 Y5 E8 B8 F900" in text
    layers = text.split(";LAYER:0\n", 1)[1]
    assert re.search(r"^G1 .*X[\d.]+ Y[\d.]+ E[\d.]+ B[\d.]+", layers, re.M)
    assert "G92 E0 B0" in layers
    assert not re.search(r"^M16[345]|^M567", text, re.M)
    check_two_stop_gradient(read_mixing_gcode(tmp_path / "m.gcode", "eb_axes", b_start=55.0), 2e-3)
    # The machine's own bed: the cube is centred on 190 x 205 mm.
    assert extrusion_centre(text) == pytest.approx((95.0, 102.5), abs=0.2)


def test_geeetech_writes_m163_m164_in_128ths(engine, cube, tmp_path):
    text = slice_with("mixengine_geeetech_a10m", tmp_path / "g.gcode", *GRADIENT, "-l", cube)
    assert text.startswith(FLAVOR_HEADER[MARLIN])
    body = text.split(";LAYER:0\n", 1)[0].split("G1 X200 Y5 E20 F1000 ;purge line", 1)[1] + \
        text.split(";LAYER:0\n", 1)[1]
    factors = [float(p) for p in re.findall(r"^M163 S[01] P([\d.]+)$", body, re.M)]
    assert len(factors) > 2 * 60
    # Every factor is a whole number of 128ths (written with 6 decimals): an 8-bit Marlin's resolution.
    assert all(abs(f - round(f * 128) / 128) <= 5e-7 + 1e-12 for f in factors)
    assert any(round(f * 128) % 2 == 1 for f in factors), "only 64ths: the 128-step resolution is not used"
    assert re.search(r"^M164 S0$", body, re.M) and not re.search(r"^G1 .* B[\d.]+", body, re.M)
    # The start code purges with a 50/50 mix in T0; the firmware model follows it, and the first layer
    # must still be filament A only (the slice's own mix comes before its first extrusion).
    reading = read_mixing_gcode(tmp_path / "g.gcode", "marlin_m163")
    check_two_stop_gradient(reading, 0.5 / 128 + 1e-9)
    assert gradient_shares(reading)[0][1] == 0.0
    assert extrusion_centre(text) == pytest.approx((110.0, 110.0), abs=0.2)


def test_reprap_mixing_writes_m567_relative(engine, cube, tmp_path):
    text = slice_with("mixengine_rrf_mixing", tmp_path / "r.gcode", *GRADIENT, "-l", cube)
    assert text.startswith(FLAVOR_HEADER[RRF])
    head, layers = text.split(";LAYER:0\n", 1)
    assert [line.split()[0] for line in head.splitlines() if line.startswith(("M82", "M83"))][-1] == "M83"
    mixes = re.findall(r"^M567 P0 E([\d.]+):([\d.]+)$", layers, re.M)
    assert len(mixes) > 60
    assert all(float(a) + float(b) == pytest.approx(1.0, abs=1e-9) for a, b in mixes)
    # Thousandths: RepRapFirmware takes any fraction, the profile asks for 1000 steps.
    assert any(round(float(b) * 1000) % 10 for a, b in mixes)
    check_two_stop_gradient(read_mixing_gcode(tmp_path / "r.gcode", "rrf_m567"), 0.5 / 1000 + 1e-9)
    assert extrusion_centre(text) == pytest.approx((100.0, 100.0), abs=0.2)


def test_cmykw_mixer_drives_five_channels(engine, cube, tmp_path):
    stops = "0=1:0:0:0:0; 25=0:1:0:0:0; 50=0:0:1:0:0; 75=0:0:0:1:0; 100=0:0:0:0:1"
    text = slice_with("mixengine_cmykw_mixer", tmp_path / "c.gcode", "-s", "mixing_mode=gradient",
                      "-s", f"mixing_gradient_stops={stops}", *IDEAL_CHAMBER, "-l", cube)
    layers = text.split(";LAYER:0\n", 1)[1]
    m165 = re.findall(r"^M165 A([\d.]+) B([\d.]+) C([\d.]+) D([\d.]+) H([\d.]+)$", layers, re.M)
    assert len(m165) > 60 and len(m165) == layers.count("M165")
    reading = read_mixing_gcode(tmp_path / "c.gcode", "marlin_m165", channels=5)
    corners = [[1, 0, 0, 0, 0], [0, 1, 0, 0, 0], [0, 0, 1, 0, 0], [0, 0, 0, 1, 0], [0, 0, 0, 0, 1]]
    used = set()
    for layer, (z, amounts) in reading.layer_totals().items():
        p = 100.0 * z / CUBE_MM
        k = min(int(p // 25), 3)
        t = (p - 25 * k) / 25
        expected = [corners[k][c] + (corners[k + 1][c] - corners[k][c]) * t for c in range(5)]
        shares = [a / sum(amounts) for a in amounts]
        assert shares == pytest.approx(expected, abs=0.5 / 100 + 1e-9), f"layer {layer}"
        used |= {c for c in range(5) if shares[c] > 0.2}
    assert used == {0, 1, 2, 3, 4}  # cyan, magenta, yellow, black and white all print


@pytest.mark.parametrize("machine", MIXING)
def test_mixing_printers_default_to_plain_gcode(engine, cube, tmp_path, machine):
    """mixing_mode stays `single` unless the user asks: filament A alone, no mix words or commands."""
    text = slice_with(machine, tmp_path / "s.gcode", "-l", cube)
    layers = text.split(";LAYER:0\n", 1)[1]
    assert text.startswith(FLAVOR_HEADER[MACHINES[machine]["flavor"]])
    assert not re.search(r"^(M163|M164|M165|M567)|^G1 .*( B[\d.]+|E[\d.]+:)", layers, re.M)


@pytest.mark.parametrize("machine", sorted(MACHINES))
def test_engine_resolves_the_profile(engine, machine):
    proc = helpers.mixengine("settings", "-j", machine, "--json")
    assert proc.returncode == 0, proc.stderr
    resolved = json.loads(proc.stdout)
    glob, extruders = resolved["global"], resolved["extruders"]
    spec = MACHINES[machine]
    assert glob["machine_name"] == spec["name"] and glob["machine_gcode_flavor"] == spec["flavor"]
    assert len(extruders) == spec["extruders"]
    assert [float(e["material_diameter"]) for e in extruders] == [1.75] * spec["extruders"]
    if "dialect" in spec:
        assert glob["mixing_dialect"] == spec["dialect"]
        assert int(glob["mixing_channels"]) == spec["channels"]
        assert int(glob["mixing_resolution"]) == spec.get("resolution", 100)


def material_guid(name):
    text = (Path("/usr/share/cura/resources/materials") / f"{name}.xml.fdm_material").read_text()
    return re.search(r"<GUID>([^<]+)</GUID>", text).group(1)


@pytest.mark.parametrize("machine", sorted(MACHINES))
def test_profiles_stack_cura_materials(engine, machine):
    """With --profiles the engine stacks Cura's materials as Cura would: preferred_material generic_pla
    on 1.75 mm filament is generic_pla_175 for every extruder train."""
    proc = helpers.mixengine("settings", "-j", machine, "--profiles", "--json")
    assert proc.returncode == 0, proc.stderr
    extruders = json.loads(proc.stdout)["extruders"]
    assert [e["material_guid"] for e in extruders] == [material_guid("generic_pla_175")] * len(extruders)


# ---------------------------------------------------------------- the dual-nozzle printer

def tool_paths(text):
    """{tool: {"mesh": [(x, y)], "tower": [(x, y)]}} of the written end points of extruding G1 moves."""
    out, tool, kind, e, x, y = {}, 0, None, 0.0, 0.0, 0.0
    relative = False
    for line in text.split(";LAYER:0\n", 1)[1].splitlines():
        code = line.split(";")[0].strip()
        if line.startswith(";TYPE:"):
            kind = "tower" if line == ";TYPE:PRIME-TOWER" else "mesh" if line[6:].startswith(("WALL", "SKIN", "FILL")) \
                else None
        elif re.fullmatch(r"T\d", code):
            tool = int(code[1])
        elif code.startswith(("M82", "M83")):
            relative = code.startswith("M83")
        elif code.startswith("G92") and " E" in code:
            e = float(re.search(r"E(-?[\d.]+)", code).group(1))
        elif code.startswith(("G0", "G1")):
            words = dict(re.findall(r"([XYE])(-?[\d.]+)", code))
            x, y = float(words.get("X", x)), float(words.get("Y", y))
            if "E" in words:
                new_e = e + float(words["E"]) if relative else float(words["E"])
                if new_e > e and "X" in words and kind:
                    out.setdefault(tool, {"mesh": [], "tower": []})[kind].append((x, y))
                e = new_e
    return out


def box(points):
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return min(xs), max(xs), min(ys), max(ys)


def test_dual_nozzle_offsets_the_second_nozzle(engine, tmp_path, report):
    a = box_stl(tmp_path / "a.stl", 10, 10, 5)
    b = box_stl(tmp_path / "b.stl", 10, 10, 5)
    text = slice_with("mixengine_dual_nozzle", tmp_path / "d.gcode", "-e0", "-l", a, "-s", "mesh_position_x=-20",
                      "-e1", "-l", b, "-s", "mesh_position_x=20")
    assert text.startswith(FLAVOR_HEADER[MARLIN])
    paths = tool_paths(text)
    assert set(paths) == {0, 1}
    offset_x = MACHINES["mixengine_dual_nozzle"]["offsets"][1][0]
    # Cube A (T0) is written where it lies; cube B (T1) 18 mm to the left of where it lies, so the right
    # nozzle, 18 mm right of the left one, lays it at x = 110 + 20.
    a_box, b_box = box(paths[0]["mesh"]), box(paths[1]["mesh"])
    assert ((a_box[0] + a_box[1]) / 2, (a_box[2] + a_box[3]) / 2) == pytest.approx((90.0, 110.0), abs=0.3)
    assert ((b_box[0] + b_box[1]) / 2, (b_box[2] + b_box[3]) / 2) == \
        pytest.approx((130.0 - offset_x, 110.0), abs=0.3)
    # Both nozzles prime on the one tower (T0 its outer rings, T1 the inner ones): the written centres differ
    # by the offset, the centre on the bed does not, and the tower stands on the bed for both nozzles.
    tower0, tower1 = box(paths[0]["tower"]), box(paths[1]["tower"])
    centre0 = ((tower0[0] + tower0[1]) / 2, (tower0[2] + tower0[3]) / 2)
    centre1 = ((tower1[0] + tower1[1]) / 2 + offset_x, (tower1[2] + tower1[3]) / 2)
    assert centre1 == pytest.approx(centre0, abs=0.3)
    assert tower1[0] + offset_x > tower0[0] and tower1[1] + offset_x < tower0[1]  # inside T0's rings
    assert 0 <= tower0[0] and tower0[1] + offset_x <= 220 and 0 <= tower0[2] and tower0[3] <= 220
    assert tower0[1] - tower0[0] == pytest.approx(15.0, abs=0.5)  # prime_tower_size of the profile
    # The tool change carries the profile's extruder end/start code and, as CuraEngine writes it, after T1 and
    # its start code: M109 for T1, then T0 left at a standby temperature no lower than the profile's 160 °C
    # (as low as T0 can get and still be back in time: planning/SwitchTemperatures.h).
    lines = text.splitlines()
    first_t1 = lines.index("T1")
    before, after = lines[first_t1 - 4:first_t1], lines[first_t1 + 1:first_t1 + 8]
    assert ";left nozzle (T0) done" in before
    assert ";right nozzle (T1, 18 mm right of T0) in use" in after and "M117 Right nozzle" in after
    wait = next(i for i, line in enumerate(after) if line.startswith("M109 S"))
    standby = next(i for i, line in enumerate(after) if line.startswith("M104 T0 S"))
    assert wait < standby and 160 <= float(after[standby].split("S")[1]) <= 210, after
    assert text.count("\nT1\n") == text.count("M117 Right nozzle") > 1
    report(f"profiles: dual nozzle T0 cube centre x {((a_box[0] + a_box[1]) / 2):.2f}, T1 cube written at "
           f"x {((b_box[0] + b_box[1]) / 2):.2f} (offset {offset_x} mm), tower x {tower0[0]:.1f}..{tower0[1]:.1f}")


def test_dual_nozzle_offset_feeds_the_orientation_pass(engine, tmp_path):
    a = box_stl(tmp_path / "a.stl", 10, 10, 5)
    b = box_stl(tmp_path / "b.stl", 10, 10, 5)
    proc = helpers.mixengine("orient", a, b, "-j", "mixengine_dual_nozzle", "--report", tmp_path / "r.json")
    assert proc.returncode == 0, proc.stderr
    assert json.loads((tmp_path / "r.json").read_text())["offset_mm"] == [18, 0, 0]
