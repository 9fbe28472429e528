"""The Cura plugin's parts that run without Cura: setting fragments and printer overrides, the
backend-location switch, frame and rotation maths, engine lookup, package and install scripts.
(The plugin inside the real Cura 4.13 is tested by test_e2e_cura.py.)"""
import configparser
import json
import math
import os
import stat
import struct
import sys
import zipfile

import numpy
import pytest

import helpers

PLUGIN = helpers.REPO / "plugin"
SETTINGS = helpers.REPO / "settings"
sys.path.insert(0, str(PLUGIN))
import BackendLocation  # noqa: E402
import OrientMath  # noqa: E402
import PluginPaths  # noqa: E402
import SettingFragments  # noqa: E402


def read_definition(definition_id):
    """Like the plugin's resolver in Cura: our definitions first, then Cura's installed ones."""
    for folder in (SETTINGS / "definitions", helpers.CURA_DEFS):
        path = folder / f"{definition_id}.def.json"
        if path.is_file():
            return json.loads(path.read_text())
    return None


def fragment_keys():
    keys = []
    for path in PluginPaths.fragmentFiles(str(SETTINGS)):
        for key, definition in SettingFragments.categories(SettingFragments.loadFragment(path)):
            keys += SettingFragments.settingKeys(key, definition)
    return keys


# ---- setting fragments -------------------------------------------------------------------------
def test_fragments_give_every_mixengine_key_once():
    keys = fragment_keys()
    assert len(keys) == len(set(keys))
    for key in ("mixing", "mixing_mode", "mixing_dialect", "mixing_gradient_start", "mixing_gradient_end",
                "dual_orientation", "dual_orientation_optimize", "dual_orientation_method"):
        assert key in keys


def test_enum_options_keep_their_order_as_ordered_dicts():
    # Uranium's settings model turns only an OrderedDict into drop-down items
    fragment = SettingFragments.loadFragment(SETTINGS / "mixengine" / "mixing.def.json")
    mode = SettingFragments.findSetting("mixing", fragment["settings"]["mixing"], "mixing_mode")
    assert type(mode["options"]).__name__ == "OrderedDict" and list(mode["options"])[0] == "single"


def test_per_object_keys_follow_settable_per_mesh():
    mixing = dict(SettingFragments.categories(SettingFragments.loadFragment(SETTINGS / "mixengine" / "mixing.def.json")))
    per_mesh = SettingFragments.settablePerMesh("mixing", mixing["mixing"])
    assert "mixing_gradient_start" in per_mesh and "mixing_ratio" in per_mesh
    assert "mixing_mode" in per_mesh  # issue 16: a model's own mode (a cutting mesh's region)
    assert "mixing_dialect" not in per_mesh


@pytest.mark.parametrize("printer, expected", [
    ("mixengine_makerpi_m2030x", {"mixing_dialect": "eb_axes", "mixing_channels": 2}),
    ("mixengine_geeetech_a10m", {"mixing_dialect": "marlin_m163", "mixing_resolution": 128}),
    ("mixengine_cmykw_mixer", {"mixing_dialect": "marlin_m165", "mixing_channels": 5}),
])
def test_printer_overrides_of_mixengine_keys_walk_the_inherits_chain(printer, expected):
    if read_definition("fdmprinter") is None:
        pytest.skip("Cura's fdmprinter.def.json is not installed")
    overrides = SettingFragments.collectOverrides(printer, read_definition, fragment_keys())
    for key, value in expected.items():
        assert overrides[key]["default_value"] == value, key
    # only MixEngine keys, never Cura's own (Uranium applies those itself)
    assert "machine_width" not in overrides


def test_nearer_definition_wins_and_overrides_land_in_the_tree():
    files = {"root": {"overrides": {"mixing_dialect": {"default_value": "klipper_b", "enabled": "True"}}},
             "child": {"inherits": "root", "overrides": {"mixing_dialect": {"default_value": "rrf_m567"}}}}
    overrides = SettingFragments.collectOverrides("child", files.get, ["mixing_dialect"])
    assert overrides == {"mixing_dialect": {"default_value": "rrf_m567", "enabled": "True"}}
    category = {"type": "category", "children": {"mixing_dialect": {"type": "enum", "default_value": "eb_axes"}}}
    merged = SettingFragments.withOverrides("mixing", category, overrides)
    assert merged["children"]["mixing_dialect"]["default_value"] == "rrf_m567"
    assert category["children"]["mixing_dialect"]["default_value"] == "eb_axes"  # the source is not changed


def test_inherits_chain_stops_at_a_loop_or_a_missing_file():
    files = {"a": {"inherits": "b"}, "b": {"inherits": "a"}}
    assert SettingFragments.inheritsChain("a", files.get) == ["a", "b"]
    assert SettingFragments.inheritsChain("x", files.get) == []


# ---- backend location ----------------------------------------------------------------------------
class FakePreferences:
    def __init__(self, values, defaults):
        self.values, self.defaults = dict(values), defaults

    def getValue(self, key):
        return self.values.get(key, self.defaults.get(key))

    def setValue(self, key, value):
        self.values[key] = value

    def resetPreference(self, key):
        self.values.pop(key, None)


DEFAULTS = {BackendLocation.LOCATION: "/usr/bin/CuraEngine", BackendLocation.PREVIOUS: ""}


def test_activate_remembers_the_previous_engine_and_restore_gives_it_back():
    prefs = FakePreferences({BackendLocation.LOCATION: "/opt/MyEngine"}, DEFAULTS)
    respawned = []
    switch = BackendLocation.BackendLocation(prefs, "/p/mixengine", respawn=lambda: respawned.append(1))
    assert switch.activate() and respawned == [1]
    assert prefs.getValue(BackendLocation.LOCATION) == "/p/mixengine"
    assert prefs.getValue(BackendLocation.PREVIOUS) == "/opt/MyEngine"
    assert switch.restore() == "/opt/MyEngine"


def test_a_mixengine_left_in_cura_cfg_is_never_taken_for_the_previous_engine():
    # Cura was killed while the plugin was active: cura.cfg still names the old mixengine
    prefs = FakePreferences({BackendLocation.LOCATION: "/old/plugin/mixengine"}, DEFAULTS)
    switch = BackendLocation.BackendLocation(prefs, "/new/plugin/mixengine")
    switch.activate()
    assert prefs.getValue(BackendLocation.PREVIOUS) == ""
    assert switch.restore() == "/usr/bin/CuraEngine"  # Cura's own default


def test_restore_leaves_an_engine_someone_else_chose():
    prefs = FakePreferences({}, DEFAULTS)
    switch = BackendLocation.BackendLocation(prefs, "/p/mixengine")
    switch.activate()
    prefs.setValue(BackendLocation.LOCATION, "/opt/Other")
    assert switch.restore() == "/opt/Other"


# ---- engine lookup -------------------------------------------------------------------------------
def test_engine_lookup_order(tmp_path):
    bundled = tmp_path / "mixengine"
    bundled.write_text("#!/bin/sh\n")
    bundled.chmod(0o644)  # as Cura's own installer leaves it
    assert PluginPaths.findEngine("", str(tmp_path), environ={}) == (str(bundled), "bundled")
    assert os.stat(bundled).st_mode & stat.S_IXUSR
    assert PluginPaths.findEngine("", str(tmp_path), environ={"MIXENGINE_ENGINE": helpers.CURA_BIN})[0] == helpers.CURA_BIN
    missing = PluginPaths.findEngine(str(tmp_path / "nope"), str(tmp_path), environ={})
    assert missing[0] is None and "does not exist" in missing[1]
    # the orientation action needs mixengine itself, not the CuraEngine chosen for slicing
    assert PluginPaths.findEngine("", str(tmp_path), environ={"MIXENGINE_ENGINE": helpers.CURA_BIN},
                                  mixengine_only=True)[0] == str(bundled)


# ---- frames and rotations ------------------------------------------------------------------------
def rotation_about(axis, degrees):
    x, y, z = axis
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return ((c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s),
            (y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s),
            (z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)))


def quaternion_matrix(q):
    x, y, z, w = q
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def test_engine_z_rotation_is_a_scene_y_rotation():
    scene = OrientMath.engineToSceneRotation(rotation_about((0, 0, 1), 90))
    numpy.testing.assert_allclose(scene, rotation_about((0, 1, 0), 90), atol=1e-12)
    assert OrientMath.engineToScenePoint((1, 2, 3)) == (1, 3, -2)


@pytest.mark.parametrize("axis, degrees", [((0, 0, 1), 30), ((1, 0, 0), 179.9), ((0, 1, 0), 180),
                                           ((0.6, 0, 0.8), -120), ((0, 0.6, 0.8), 180), ((1, 0, 0), 0)])
def test_quaternion_from_matrix_round_trips(axis, degrees):
    m = rotation_about(axis, degrees)
    assert OrientMath.isRotation(m)
    numpy.testing.assert_allclose(quaternion_matrix(OrientMath.quaternionFromMatrix(m)), m, atol=1e-9)


def test_rotation_about_the_common_centre():
    r, centre = rotation_about((0, 1, 0), 90), (10.0, 0.0, 5.0)
    shift = OrientMath.translationAfterRotation(r, centre)
    p = (13.0, 2.0, 5.0)
    moved = [a + b for a, b in zip(OrientMath.apply(r, p), shift)]
    expected = [c + d for c, d in zip(centre, OrientMath.apply(r, [p[i] - centre[i] for i in range(3)]))]
    numpy.testing.assert_allclose(moved, expected, atol=1e-12)
    assert not OrientMath.isRotation(((1, 0, 0), (0, 1, 0), (0, 0, -1)))  # a mirror


def test_binary_stl_is_read_back_by_the_engine(engine, tmp_path):
    corners = numpy.array([[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 0], [0, 10, 0], [0, 0, 10],
                           [0, 0, 0], [0, 0, 10], [10, 0, 0], [10, 0, 0], [0, 0, 10], [0, 10, 0]], float)
    data = OrientMath.binaryStl(corners)
    assert len(data) == 84 + 4 * 50 and struct.unpack("<I", data[80:84]) == (4,)
    path = tmp_path / "tetra.stl"
    path.write_bytes(data)
    out = helpers.mixengine("orient", path, path, "--offset", "30,0")
    assert out.returncode == 0, out.stderr
    assert "(166.7 mm³, closed)" in out.stdout  # the tetrahedron's volume 10³/6, read back from the file


# ---- packaging and installing ----------------------------------------------------------------------
@pytest.fixture(scope="module")
def package(tmp_path_factory, engine):
    out = tmp_path_factory.mktemp("package")
    proc = helpers.run([sys.executable, PLUGIN / "package.py", "--engine", engine, "--out", out])
    assert proc.returncode == 0, proc.stderr
    return proc.stdout.strip()


def test_package_layout(package):
    version = json.loads((PLUGIN / "plugin.json").read_text())["version"]
    assert os.path.basename(package) == f"MixEngine-{version}.curapackage"
    with zipfile.ZipFile(package) as archive:
        names = set(archive.namelist())
        info = json.loads(archive.read("package.json"))
        plugin = json.loads(archive.read("files/plugins/MixEngine/plugin.json"))
        engine_mode = archive.getinfo("files/plugins/MixEngine/mixengine").external_attr >> 16
    assert info["package_id"] == "MixEngine" and info["package_type"] == "plugin"
    assert info["sdk_version"] == "7.9.0" and info["sdk_version_semver"] == "7.9.0"
    assert info["package_version"] == version == plugin["version"]
    assert plugin["api"] == 7 and plugin["supported_sdk_versions"] == ["7.9.0"]
    for name in ("__init__.py", "MixEngineExtension.py", "SettingsInjector.py", "OrientAction.py",
                 "MixPreview.py", "MixGCode.py", "MixColours.py", "LayerRecolour.py", "qml/MixLegend.qml",
                 "NotHonoured.py", "SettingsNotice.py", "MixReport.py", "MixReportNotice.py",
                 "settings/mixengine/not_honoured.json",
                 "settings/mixengine/mixing.def.json", "settings/mixengine/orientation.def.json",
                 "settings/definitions/mixengine_makerpi_m2030x.def.json",
                 "settings/extruders/mixengine_makerpi_m2030x_extruder_0.def.json"):
        assert "files/plugins/MixEngine/" + name in names, name
    assert not any(n.endswith(("package.py", "install.py", ".pyc")) for n in names)
    assert engine_mode & 0o111


def test_install_and_uninstall_into_a_home(package, tmp_path):
    home = tmp_path / "home"
    proc = helpers.run([sys.executable, PLUGIN / "install.py", package, "--home", home])
    assert proc.returncode == 0, proc.stderr
    data = home / ".local/share/cura/4.13"
    plugin = data / "plugins/MixEngine/MixEngine"
    assert (plugin / "plugin.json").is_file() and os.access(plugin / "mixengine", os.X_OK)
    assert json.loads((data / "packages.json").read_text())["installed"]["MixEngine"]["package_info"]["is_installed"]
    run = helpers.run([plugin / "mixengine", "help"])
    assert run.returncode == 0 and "orient" in run.stdout

    # Cura killed while the plugin was active: cura.cfg still names the bundled binary
    config = home / ".config/cura/4.13"
    config.mkdir(parents=True)
    (config / "cura.cfg").write_text(f"[general]\nversion = 7\n\n[backend]\nlocation = {plugin / 'mixengine'}\n\n"
                                     "[mixengine]\nprevious_backend_location = /opt/MyEngine\n")
    proc = helpers.run([sys.executable, PLUGIN / "install.py", "--uninstall", "--home", home])
    assert proc.returncode == 0, proc.stderr
    assert not (data / "plugins/MixEngine").exists()
    assert "MixEngine" not in json.loads((data / "packages.json").read_text())["installed"]
    cfg = configparser.ConfigParser(interpolation=None)
    cfg.read(config / "cura.cfg")
    assert cfg.get("backend", "location") == "/opt/MyEngine"


def test_install_refuses_another_package(tmp_path):
    other = tmp_path / "other.curapackage"
    with zipfile.ZipFile(other, "w") as archive:
        archive.writestr("package.json", json.dumps({"package_id": "Other", "package_type": "plugin"}))
    proc = helpers.run([sys.executable, PLUGIN / "install.py", other, "--home", tmp_path / "home"])
    assert proc.returncode != 0 and "not a MixEngine plugin package" in proc.stderr
    assert not (tmp_path / "home/.local/share/cura/4.13/plugins/MixEngine").exists()
