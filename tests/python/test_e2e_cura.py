"""End to end: the real Cura 4.13 under Xvfb with the MixEngine plugin installed from its .curapackage.

tests/e2e/cura_driver.py runs Cura in a temporary HOME, installs the package with plugin/install.py,
and the CuraHarness plugin drives the session without clicks (tests/e2e/README.md):

- gradient: add the MakerPi M2030X mixing printer (E/B dialect, from the plugin's definitions), load
  a 20 mm cube, set mixing_mode=gradient 40 %..80 % globally and a gradient start of 20 % on the cube
  (per-object setting: the cube prints 20 %..80 %), channel colours of clearly different hue; slice with
  the bundled mixengine, check the G-code Cura holds (scene.gcode_dict), the preview data
  (LayerOptimized), the Preview screenshots (build/e2e/): Material Color shows the mix
  (cura_gradient_material_color.png: channel A at the bottom, B at the top, the legend of the channels),
  the layer slider at the middle (cura_gradient_material_color_layer99.png: no B yet), Line Type
  unchanged (cura_gradient_line_type.png); and that backend/location is given back.
- CMYK+W: the 5-channel M165 mixer with a multi-stop gradient (cura_cmykw_material_color.png).
- single colour: the MakerPi in single mode stays one colour (cura_single_material_color.png), and
  wire printing, which MixEngine does not act on yet, is named in one Cura message (not_honoured.json).
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
CAMERA = {"position": [-45, 70, 110], "look_at": [14, 6, 0]}  # scene frame (Y up): the cube left of the panel
CHANNEL_A, CHANNEL_B = "#00b4c8", "#e6007e"  # teal and magenta: hues 186 and 327 degrees
SHOTS = {"material": ARTIFACTS / "cura_gradient_material_color.png",
         "layer99": ARTIFACTS / "cura_gradient_material_color_layer99.png",
         "line_type": ARTIFACTS / "cura_gradient_line_type.png",
         "cmykw": ARTIFACTS / "cura_cmykw_material_color.png",
         "single": ARTIFACTS / "cura_single_material_color.png"}
# the 3D view in the 1600 x 1000 screenshots: below the stage menu, right of the mix legend (whose swatches
# carry the channel colours), left of the print settings panel
VIEW_ROWS, VIEW_COLS = slice(170, 900), slice(260, 1040)

pytestmark = pytest.mark.skipif(not shutil.which("xvfb-run") or not os.path.exists("/usr/bin/cura"),
                                reason="needs xvfb-run and /usr/bin/cura (apt-get install cura xvfb xauth)")


@pytest.fixture(scope="module")
def package(tmp_path_factory, engine):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
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
           "global": {"mixing_mode": "gradient", "mixing_gradient_start": 40, "mixing_gradient_end": 80,
                      "mixing_channel_colors": f"{CHANNEL_A},{CHANNEL_B}"},
           # the cube overrides the gradient start per object (settable_per_mesh): its gradient runs 20..80 %
           "models": [{"path": box(work / "cube20.stl", (20, 20, 20)), "settings": {"mixing_gradient_start": 20}}],
           "probe_settings": ["mixing_mode", "mixing_dialect", "mixing_channel_colors", "mixing_gradient_start",
                              "mixing_gradient_end", "dual_orientation_optimize"],
           "plugin_status": "MixEngine", "gcode_output": str(work / "gcode.json"), "preview": True,
           "screenshots": [{"path": str(SHOTS["material"]), "layer_view_type": 0},
                           {"path": str(SHOTS["layer99"]), "layer_view_type": 0, "layer": 99},
                           {"path": str(SHOTS["line_type"]), "layer_view_type": 1, "layer": None}],
           "disable_plugins": ["MixEngine"], "camera": CAMERA}
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
    assert (sent["mixing_mode"], sent["mixing_gradient_start"], sent["mixing_gradient_end"]) == ("gradient", "40", "80")
    assert sent["mixing_dialect"] == "eb_axes"
    assert gradient["fixture"]["objects"][0]["settings"]["mixing_gradient_start"] == "20"  # per object


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
        assert share == pytest.approx(seed_share_b(20, 80, z / 20 * 100), abs=0.02), z


def test_preview_data_reached_cura(gradient):
    status, layers = gradient["status"], len([c for c in gradient["chunks"] if c.startswith(";LAYER:")])
    assert status["layer_optimized_received"] == layers
    assert sorted(status["layer_optimized_ids"]) == list(range(layers))
    assert status["scene_layers"] == layers  # Cura built its layer view from them


def screenshot(path):
    image = numpy.asarray(Image.open(path).convert("RGB")).astype(float) / 255
    assert image.shape == (1000, 1600, 3)
    return image


def hsv(image):
    """Hue (degrees), saturation and value of every pixel."""
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    v, low = image.max(axis=2), image.min(axis=2)
    chroma = v - low
    safe = numpy.where(chroma > 0, chroma, 1)
    h = numpy.where(v == r, (g - b) / safe % 6, numpy.where(v == g, (b - r) / safe + 2, (r - g) / safe + 4)) * 60
    return numpy.where(chroma > 0, h, 0), numpy.where(v > 0, chroma / numpy.where(v > 0, v, 1), 0), v


def hue_of(hex_colour):
    return float(hsv(numpy.array([[[int(hex_colour[i:i + 2], 16) / 255 for i in (1, 3, 5)]]]))[0][0, 0])


def pixels_of(image, hex_colour, tolerance_deg=15):
    """Rows and columns of the 3D view's pixels that have the hue of `hex_colour` (saturated ones)."""
    h, s, v = hsv(image[VIEW_ROWS, VIEW_COLS])
    distance = numpy.abs((h - hue_of(hex_colour) + 180) % 360 - 180)
    rows, cols = numpy.nonzero((distance <= tolerance_deg) & (s > 0.45) & (v > 0.25))
    return rows + VIEW_ROWS.start, cols + VIEW_COLS.start


def test_line_type_screenshot_is_cura_own(gradient, report):
    image = screenshot(SHOTS["line_type"]) * 255
    # the layer view draws outer walls in the line-type red; Cura's empty scene has no such pixels
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    red = int(((r > 200) & (g < 80) & (b < 80)).sum())
    assert red > 500, red
    magenta = len(pixels_of(image / 255, CHANNEL_B)[0])  # the mix is drawn only by Material Color
    assert magenta < 50, magenta
    report(f"Cura e2e Line Type screenshot: {SHOTS['line_type']} ({red} wall-red pixels)")


def test_material_color_shows_channel_a_at_the_bottom_and_b_at_the_top(gradient, report):
    """Issue 17: Cura's own Material Color scheme draws every line in the colour of its mix."""
    image = screenshot(SHOTS["material"])
    a_rows, _ = pixels_of(image, CHANNEL_A)
    b_rows, _ = pixels_of(image, CHANNEL_B)
    assert len(a_rows) > 3000 and len(b_rows) > 3000, (len(a_rows), len(b_rows))
    rows = numpy.concatenate([a_rows, b_rows])
    top, bottom = numpy.percentile(rows, 1), numpy.percentile(rows, 99)
    band = 0.1 * (bottom - top)
    near_bottom = (a_rows > bottom - band).sum(), (b_rows > bottom - band).sum()
    near_top = (a_rows < top + band).sum(), (b_rows < top + band).sum()
    assert near_bottom[0] > 9 * near_bottom[1], near_bottom  # channel A's colour near the bottom of the cube
    assert near_top[1] > 9 * near_top[0], near_top  # channel B's near the top
    assert numpy.median(a_rows) > numpy.median(b_rows) + 2 * band
    # every extrusion line of the layer view was matched to the G-code move that printed it
    preview = gradient["status"]["plugin_status_end"]["preview"]
    assert preview["state"] == "coloured" and preview["matched"] == preview["lines"] > 1000, preview
    assert preview["layers"] == expected_layers(gradient)
    report(f"Cura e2e Material Color: {SHOTS['material']} (A pixels median row {numpy.median(a_rows):.0f}, "
           f"B {numpy.median(b_rows):.0f}; {preview['lines']} lines coloured in {preview['seconds']} s)")


def test_mix_follows_the_layer_slider(gradient):
    """At layer 99 of the 20..80 % cube (z = 9.95 mm, B share 0.5) no line is B-coloured yet."""
    full = len(pixels_of(screenshot(SHOTS["material"]), CHANNEL_B)[0])
    a_rows, _ = pixels_of(screenshot(SHOTS["layer99"]), CHANNEL_A)
    b_rows, _ = pixels_of(screenshot(SHOTS["layer99"]), CHANNEL_B)
    assert len(b_rows) < 0.02 * full, (len(b_rows), full)
    assert len(a_rows) > 3000


def test_legend_lists_the_channels_in_the_material_color_screenshot(gradient):
    image = screenshot(SHOTS["material"])
    for colour in (CHANNEL_A, CHANNEL_B):  # the swatches, left of the 3D view
        h, s, v = hsv(image[150:450, 0:VIEW_COLS.start])
        distance = numpy.abs((h - hue_of(colour) + 180) % 360 - 180)
        assert ((distance <= 10) & (s > 0.6)).sum() > 50, colour
    channels = gradient["status"]["plugin_status_end"]["legend"]["channels"]
    assert channels == [{"name": "A", "color": CHANNEL_A}, {"name": "B", "color": CHANNEL_B}]


def test_cura_print_information_shows_the_time_by_feature(gradient, report):
    """Issue 17, part 2: Cura's print information gets the breakdown, adding up to the print time."""
    times, total = gradient["status"]["print_times_per_feature"], gradient["status"]["print_time_s"]
    for feature in ("Outer Wall", "Inner Walls", "Skin", "Infill", "Skirt", "Travel"):
        assert times[feature] > 0, (feature, times)
    assert times["Other"] == 0 and times["Support"] == 0 and times["Prime Tower"] == 0
    assert abs(sum(times.values()) - total) <= len(times)  # each Duration is rounded to whole seconds
    header_s = int(re.search(r"^;TIME:(\d+)$", gradient["chunks"][0], re.M).group(1))
    assert abs(total - header_s) <= 1
    report("Cura print information (s): " + ", ".join(f"{k} {v}" for k, v in times.items() if v))


def test_backend_location_given_back_on_shutdown(gradient):
    assert gradient["summary"]["cfg_backend_location"] == gradient["previous"]
    assert "[MixEngine] shutdown (plugin disabled): backend/location back to " + gradient["previous"] in gradient["log"]


# ---- five channels, multi-stop: the CMYK+W mixer (Marlin M165) ----------------------------------------------
CMYKW_STOPS = "0=1:0:0:0:0; 30=0:1:0:0:0; 60=0:0:1:0:0; 80=0:0:0:1:0; 100=0:0:0:0:1"  # C, M, Y, K, W


def test_cmykw_multi_stop_gradient_in_material_color(tmp_path, package, report):
    job = {"name": "cura_cmykw", "machine": "mixengine_cmykw_mixer",
           "global": {"mixing_mode": "gradient", "mixing_gradient_stops": CMYKW_STOPS},
           "models": [{"path": box(tmp_path / "cube20.stl", (20, 20, 20))}], "plugin_status": "MixEngine",
           "preview": True, "screenshots": [{"path": str(SHOTS["cmykw"]), "layer_view_type": 0}], "camera": CAMERA}
    summary, status, fixture = run_cura(job, tmp_path, package)
    assert summary["backend_state"] == "Done" and fixture["global_settings"]["mixing_dialect"] == "marlin_m165"
    end = status["plugin_status_end"]
    assert end["preview"]["state"] == "coloured" and end["preview"]["matched"] == end["preview"]["lines"]
    colours = fixture["global_settings"]["mixing_channel_colors"].split(",")  # the printer's C, M, Y, K, W
    assert [c["color"] for c in end["legend"]["channels"]] == colours and len(colours) == 5
    assert end["legend"]["shown"]  # Material Color on, in the Preview
    image = screenshot(SHOTS["cmykw"])
    medians = []
    for colour in colours[:3]:
        rows, _ = pixels_of(image, colour, tolerance_deg=12)
        assert len(rows) > 1500, colour
        medians.append(float(numpy.median(rows)))
    assert medians[0] > medians[1] > medians[2], medians  # cyan lowest, then magenta, then yellow (rows grow down)
    # above the yellow band come black and white: no cyan, magenta or yellow pixel there
    yellow_rows, yellow_cols = pixels_of(image, colours[2], tolerance_deg=12)
    above = numpy.percentile(yellow_rows, 1) - 5
    for colour in colours[:2]:
        rows, cols = pixels_of(image, colour, tolerance_deg=12)
        inside = (cols > numpy.percentile(yellow_cols, 5)) & (cols < numpy.percentile(yellow_cols, 95))
        assert ((rows < above) & inside).sum() < 50, colour
    report(f"Cura e2e CMYK+W: {SHOTS['cmykw']} (C/M/Y median rows {[round(m) for m in medians]})")


# ---- single colour on the mixing printer, and a setting MixEngine does not act on -----------------------
def test_single_colour_print_stays_one_colour_and_unsupported_settings_are_named(tmp_path, package):
    job = {"name": "cura_single", "machine": "mixengine_makerpi_m2030x",
           "global": {"wireframe_enabled": True},  # settings/mixengine/not_honoured.json lists it
           "models": [{"path": box(tmp_path / "cube20.stl", (20, 20, 20))}], "plugin_status": "MixEngine",
           "preview": True, "screenshots": [{"path": str(SHOTS["single"]), "layer_view_type": 0}], "camera": CAMERA}
    summary, status, fixture = run_cura(job, tmp_path, package)
    assert summary["backend_state"] == "Done" and fixture["global_settings"]["mixing_mode"] == "single"
    end = status["plugin_status_end"]
    assert end["preview"]["state"] == "not a mixing slice" and not end["legend"]["shown"]
    h, s, v = hsv(screenshot(SHOTS["single"])[VIEW_ROWS, VIEW_COLS])
    coloured = (s > 0.45) & (v > 0.25)
    assert coloured.sum() > 20000  # the cube and its brim
    hues = numpy.exp(1j * numpy.radians(h[coloured]))
    spread = numpy.degrees(numpy.sqrt(-2 * numpy.log(abs(hues.mean()))))  # circular standard deviation
    assert spread < 8, spread  # one colour: Cura's material colour
    # one Cura message names the setting MixEngine does not act on yet
    texts = [t for t in status["visible_messages"] if "MixEngine does not act on" in t]
    assert len(texts) == 1 and "Wire Printing" in texts[0] and "wire printing is not built" in texts[0], texts
    assert [row[0] for row in end["not_honoured"]] == ["wireframe_enabled"]


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
