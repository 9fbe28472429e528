"""End to end: the real Cura 4.13 under Xvfb with the MixEngine plugin installed from its .curapackage.

tests/e2e/cura_driver.py runs Cura in a temporary HOME, installs the package with plugin/install.py,
and the CuraHarness plugin drives the session without clicks (tests/e2e/README.md):

- gradient: add the MakerPi M2030X mixing printer (E/B dialect, from the plugin's definitions), load
  a 20 mm cube, set mixing_mode=gradient 20 %..80 % globally and a gradient start of 40 % on the cube
  (per-object setting), slice with the bundled mixengine, check the
  G-code Cura holds (scene.gcode_dict), the preview data (LayerOptimized) and the Preview stage
  screenshot (build/e2e/cura_gradient_preview.png), and that backend/location is given back.
- orientation: the package installed by Cura's own installer this time; the 18 mm dual-nozzle printer,
  a bar on each nozzle, the menu item "Optimize dual-nozzle orientation", its undo and redo, then a slice;
  then "Uninstall" as the Marketplace does it, and Cura's own engine is back in cura.cfg.

Skipped only when xvfb-run or /usr/bin/cura is missing.
"""
import json
import os
import re
import shutil

import numpy
import pytest
import trimesh
from PIL import Image

import helpers
from mixing_gcode import read_mixing_gcode, seed_share_b

DRIVER = helpers.REPO / "tests" / "e2e" / "cura_driver.py"
ARTIFACTS = helpers.BIN.parent / "e2e"
CURA_PYTHON = "/usr/bin/python3"
TIMEOUT_S = 300
PLUGIN_DIR_TAIL = os.path.join("plugins", "MixEngine", "MixEngine", "mixengine")

pytestmark = pytest.mark.skipif(not shutil.which("xvfb-run") or not os.path.exists("/usr/bin/cura"),
                                reason="needs xvfb-run and /usr/bin/cura (apt-get install cura xvfb xauth)")


@pytest.fixture(scope="module")
def package(tmp_path_factory, engine):
    out = tmp_path_factory.mktemp("curapackage")
    proc = helpers.run([CURA_PYTHON, helpers.REPO / "plugin" / "package.py", "--engine", engine, "--out", out])
    assert proc.returncode == 0, proc.stderr
    return proc.stdout.strip()


def box(path, extents):
    mesh = trimesh.creation.box(extents=extents)
    mesh.apply_translation((0, 0, extents[2] / 2))
    mesh.export(path)
    return str(path)


def run_cura(job, workdir, package, *extra):
    """Runs one job; returns (driver summary, harness status, Slice fixture or None)."""
    name = job["name"]
    job_path = workdir / f"{name}.job.json"
    job_path.write_text(json.dumps(job))
    logs = workdir / "logs"
    proc = helpers.run([CURA_PYTHON, DRIVER, job_path, "--out-dir", workdir, "--log-dir", logs,
                        "--plugin-package", package, "--timeout", TIMEOUT_S, *extra], timeout=TIMEOUT_S + 60)
    lines = [line for line in proc.stdout.splitlines() if line.startswith("{")]
    assert lines, f"driver printed no summary:\n{proc.stdout}\n{proc.stderr}"
    summary = json.loads(lines[-1])
    status_path = logs / f"{name}.status.json"
    status = json.loads(status_path.read_text()) if status_path.exists() else {}
    fixture_path = workdir / f"{name}.json"
    fixture = json.loads(fixture_path.read_text()) if fixture_path.exists() else None
    assert summary["ok"], f"Cura run failed: {summary}\nsee {logs}/{name}.cura.log"
    return summary, status, fixture


# ---- gradient on the E/B mixing printer -------------------------------------------------------------
@pytest.fixture(scope="module")
def gradient(tmp_path_factory, package):
    work = tmp_path_factory.mktemp("cura_gradient")
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    previous = work / "CuraEngine-previous"  # the location a user had before the plugin
    os.symlink(helpers.CURA_BIN, previous)
    job = {"name": "cura_gradient", "machine": "mixengine_makerpi_m2030x",
           "global": {"mixing_mode": "gradient", "mixing_gradient_start": 20, "mixing_gradient_end": 80},
           # the cube overrides the gradient start per object (settable_per_mesh): its gradient runs 40..80 %
           "models": [{"path": box(work / "cube20.stl", (20, 20, 20)), "settings": {"mixing_gradient_start": 40}}],
           "probe_settings": ["mixing_mode", "mixing_dialect", "mixing_channel_colors", "mixing_gradient_start",
                              "mixing_gradient_end", "dual_orientation_optimize"],
           "plugin_status": "MixEngine", "gcode_output": str(work / "gcode.json"), "preview": True,
           "screenshot": str(ARTIFACTS / "cura_gradient_preview.png"), "disable_plugins": ["MixEngine"],
           "camera": {"position": [-45, 70, 110], "look_at": [14, 6, 0]}}
    # the screenshot also shows the print settings panel, custom mode, Colour Mixing expanded
    panel = ["--cfg", "view/settings_visible=True", "--cfg", "cura/active_mode=1",
             "--cfg", "cura/categories_expanded=mixing", "--cfg", "view/settings_list_height=760"]
    summary, status, fixture = run_cura(job, work, package, "--cfg-backend", previous, *panel)
    chunks = json.loads((work / "gcode.json").read_text())["chunks"]
    gcode = work / "cura.gcode"
    gcode.write_text("".join(chunks))
    return {"summary": summary, "status": status, "fixture": fixture, "chunks": chunks, "gcode": gcode,
            "previous": str(previous), "log": (work / "logs" / "cura_gradient.cura.log").read_text()}


def expected_layers(gradient):
    """CuraEngine's layer count for the 20 mm cube with the layer heights Cura sent."""
    sent = gradient["fixture"]["global_settings"]
    return helpers.expected_layer_count(20.0, h0_um=round(float(sent["layer_height_0"]) * 1000),
                                        h_um=round(float(sent["layer_height"]) * 1000))


def test_cura_sliced_with_the_bundled_mixengine(gradient, report):
    status = gradient["status"]
    assert gradient["summary"]["backend_state"] == "Done"
    assert status["engine_command"][0].endswith(PLUGIN_DIR_TAIL), status["engine_command"]
    assert status["engine_command"][1] == "connect"
    report(f"Cura e2e gradient: engine {status['engine_command'][0]}, events {gradient['summary']['events_s']}")


def test_mixing_settings_exist_show_and_carry_the_printer_defaults(gradient):
    probe, sent = gradient["status"]["settings_probe"], gradient["fixture"]["global_settings"]
    assert probe["definition"] == "mixengine_makerpi_m2030x"
    for key in ("mixing_mode", "mixing_dialect", "mixing_gradient_start", "dual_orientation_optimize"):
        assert probe[key]["defined"] and probe[key]["visible"], key
    # the printer's overrides of MixEngine keys, which Uranium drops, were applied by the plugin
    assert probe["mixing_dialect"]["default_value"] == "eb_axes"
    assert probe["mixing_channel_colors"]["default_value"] == "#f4f4f4,#d7263d"
    assert probe["mixing_gradient_start"]["settable_per_mesh"] and not probe["mixing_mode"]["settable_per_mesh"]
    assert probe["mixing_mode"]["options_type"] == "OrderedDict"  # else the drop-down shows no items
    assert (sent["mixing_mode"], sent["mixing_gradient_start"], sent["mixing_gradient_end"]) == ("gradient", "20", "80")
    assert sent["mixing_dialect"] == "eb_axes"
    assert gradient["fixture"]["objects"][0]["settings"]["mixing_gradient_start"] == "40"  # per object


def test_gcode_in_cura_has_layers_header_and_e_b_words(gradient):
    chunks = gradient["chunks"]
    header = chunks[0]
    assert header.startswith(";FLAVOR:Marlin\n")
    time_s = int(re.search(r"^;TIME:(\d+)$", header, re.M).group(1))
    filament_m = float(re.search(r"^;Filament used: ([\d.]+)m", header, re.M).group(1))
    assert 0 < time_s != 6666 and filament_m > 0
    layer_count = int(re.search(r"^;LAYER_COUNT:(\d+)$", "".join(chunks), re.M).group(1))
    layers = [c for c in chunks if c.startswith(";LAYER:")]
    assert [int(c.split("\n", 1)[0][7:]) for c in layers] == list(range(layer_count))  # one chunk per layer
    assert layer_count == expected_layers(gradient)
    extrusions = [line for c in layers for line in c.splitlines() if line.startswith("G1 ") and " X" in line and " E" in line]
    assert extrusions and all(" B" in line for line in extrusions)


def test_b_share_rises_with_height_as_the_per_object_gradient_says(gradient):
    totals = read_mixing_gcode(gradient["gcode"], "eb_axes").layer_totals()
    shares = [(z, b / (a + b)) for layer, (z, (a, b)) in sorted(totals.items()) if layer >= 0]
    assert len(shares) == expected_layers(gradient)
    assert all(s2 >= s1 - 1e-9 for (_, s1), (_, s2) in zip(shares, shares[1:]))
    assert shares[0][1] == pytest.approx(0, abs=1e-6) and shares[-1][1] == pytest.approx(1, abs=1e-6)
    for z, share in shares:
        assert share == pytest.approx(seed_share_b(40, 80, z / 20 * 100), abs=0.02), z


def test_preview_data_reached_cura(gradient):
    status, layers = gradient["status"], len([c for c in gradient["chunks"] if c.startswith(";LAYER:")])
    assert status["layer_optimized_received"] == layers
    assert sorted(status["layer_optimized_ids"]) == list(range(layers))
    assert status["scene_layers"] == layers  # Cura built its layer view from them


def test_screenshot_shows_the_sliced_preview(gradient, report):
    path = ARTIFACTS / "cura_gradient_preview.png"
    image = numpy.asarray(Image.open(path).convert("RGB")).astype(int)
    assert image.shape == (1000, 1600, 3)
    # the layer view draws outer walls in the line-type red; Cura's empty scene has no such pixels
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    red = int(((r > 200) & (g < 80) & (b < 80)).sum())
    assert red > 500, red
    report(f"Cura e2e screenshot: {path} ({red} wall-red pixels)")


def test_backend_location_given_back_on_shutdown(gradient):
    assert gradient["summary"]["cfg_backend_location"] == gradient["previous"]
    assert "[MixEngine] shutdown (plugin disabled): backend/location back to " + gradient["previous"] in gradient["log"]


# ---- the orientation menu item on the dual-nozzle printer ------------------------------------------------
def test_orientation_menu_item_rotates_undoably(tmp_path, package, report):
    job = {"name": "cura_orient", "machine": "mixengine_dual_nozzle",
           "models": [{"path": box(tmp_path / "bar_a.stl", (30, 10, 10)), "extruder": 0},
                      {"path": box(tmp_path / "bar_b.stl", (30, 10, 10)), "extruder": 1}],
           "actions": [{"plugin": "MixEngine", "menu": "Optimize dual-nozzle orientation", "undo": True, "redo": True}],
           "plugin_status": "MixEngine", "remove_packages": ["MixEngine"]}
    # this time Cura's own installer unpacks the package (as after dropping it on the window); it drops the
    # executable bit of the bundled binary, which the plugin sets again
    summary, status, fixture = run_cura(job, tmp_path, package, "--via-cura")
    assert status["plugin_status"]["engine_how"] == "bundled"
    action = status["actions"][0]
    result = action["result"]
    assert result["status"] == "ok", result
    assert result["command"][0].endswith(PLUGIN_DIR_TAIL) and result["command"][1] == "orient"
    assert "--offset" in result["command"] and result["command"][result["command"].index("--offset") + 1] == "18,0"
    rep = result["report"]
    assert rep["v_before_mm3"] > 0 and rep["v_after_mm3"] < rep["v_before_mm3"]
    rotation = numpy.array(result["scene_rotation"])
    for name, before in action["before"].items():
        before, after = numpy.array(before), numpy.array(action["after"][name])
        numpy.testing.assert_allclose(after[:3, :3], rotation @ before[:3, :3], atol=1e-5)
        numpy.testing.assert_allclose(numpy.array(action["after_undo"][name]), before, atol=1e-5)
        numpy.testing.assert_allclose(numpy.array(action["after_redo"][name]), after, atol=1e-5)
    assert summary["backend_state"] == "Done" and len(fixture["objects"]) == 2
    # uninstalled from the Marketplace before closing: Cura's own engine is back in cura.cfg (its default)
    log = (tmp_path / "logs" / "cura_orient.cura.log").read_text()
    assert "[MixEngine] shutdown (plugin scheduled for removal): backend/location back to /usr/bin/CuraEngine" in log
    assert summary["cfg_backend_location"] is None
    report(f"Cura e2e orientation: V {rep['v_before_mm3']:.0f} -> {rep['v_after_mm3']:.0f} mm³ "
           f"in {action['seconds']} s, rotation {numpy.round(rotation, 3).tolist()}")
