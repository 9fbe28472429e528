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
- yellow to blue (issue 26): the MakerPi with channel colours #ffff00,#0000ff and a gradient over the whole
  cube. Material Color draws the colours the engine predicts and writes into the G-code
  (";PREDICTED_COLOR:", its pigment model): the middle of the cube is green, not the grey of a linear-light
  blend (cura_yellow_blue_material_color.png, and ..._layer99.png with the layer slider at the middle).
- two cubes (issue 26): the MakerPi in dual mode, two 20 mm cubes side by side at mixing_ratio 1:0 and 0:1 (per
  model), a 40 mm³ chamber: one Cura message says what the engine's ;MIXING.* header says, the purge in mm³ and
  grams (the density of Cura's material) and that printing the cubes one at a time would remove the changes
  (cura_two_cubes_mixing_report.png). A gradient's message says there is no purge; a single-colour print has none.
- CMYK+W: the 5-channel M165 mixer with a multi-stop gradient (cura_cmykw_material_color.png).
- raft: the MakerPi with a raft under a gradient (cura_raft_material_color.png): raft layers below 0, filament A.
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
import sys
from pathlib import Path

import numpy
import pytest
import trimesh
from PIL import Image

import helpers
from mixing_gcode import read_mixing_gcode, seed_share_b

sys.path.insert(0, str(helpers.REPO / "plugin"))
import MixReport  # noqa: E402

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
         "single": ARTIFACTS / "cura_single_material_color.png",
         "raft": ARTIFACTS / "cura_raft_material_color.png",
         "yellow_blue": ARTIFACTS / "cura_yellow_blue_material_color.png",
         "yellow_blue_middle": ARTIFACTS / "cura_yellow_blue_material_color_layer99.png",
         "two_cubes": ARTIFACTS / "cura_two_cubes_mixing_report.png"}
# the 3D view in the 1600 x 1000 screenshots: below the stage menu, right of the mix legend (whose swatches
# carry the channel colours), left of the print settings panel
VIEW_ROWS, VIEW_COLS = slice(170, 900), slice(260, 1040)
PART_ROWS = slice(240, 900)  # the same without the far edge of the build plate (drawn in blue at the top left)
# Cura's layers3d.shader draws a line of material colour c as c * (0.2 + N.L) + u_minimumAlbedo (0.1): every
# pixel of a line is 0.1 plus a multiple of its colour, so (pixel - 0.1) has the chromaticity of the colour
ALBEDO = 0.1

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
    # issue 16: a model (e.g. a cutting mesh's region) may have its own mixing_mode
    assert probe["mixing_gradient_start"]["settable_per_mesh"] and probe["mixing_mode"]["settable_per_mesh"]
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


# ---- yellow to blue: the engine's pigment colours in Cura's layer view (issue 26) -------------------------------
YELLOW_BLUE = "#ffff00,#0000ff"
MIDDLE_LAYER = 99  # of the 20 mm cube at 0.1 mm (Fine): z 9.95..10.05 mm


def written_colours(chunks):
    """{layer id: the ;PREDICTED_COLOR: values the engine wrote in that layer, in order}."""
    out = {}
    for chunk in chunks:
        if chunk.startswith(";LAYER:"):
            layer = int(chunk.split("\n", 1)[0][7:])
            out[layer] = [c.lower() for c in re.findall(r"^;PREDICTED_COLOR:(#[0-9a-fA-F]{6})\s*$", chunk, re.M)]
    return out


def rgb_of(hex_colour):
    return numpy.array([int(hex_colour[i:i + 2], 16) / 255 for i in (1, 3, 5)])


def chromaticity(rgb):
    """(r, g, b) / (r + g + b) of the colour a pixel was drawn in (the pixel minus the minimum albedo)."""
    q = numpy.clip(numpy.asarray(rgb, dtype=float) - ALBEDO, 1e-6, None)
    return q / q.sum(axis=-1, keepdims=True)


def part_mask(image):
    """The pixels of printed lines in the 3D view: coloured, unlike the grey plate, ghost and background."""
    part = image[PART_ROWS, VIEW_COLS]
    return part.max(axis=2) - part.min(axis=2) > 0.08


def is_green(rgb):
    r, g, b = rgb
    return g > r + 0.2 and g > b + 0.1


@pytest.fixture(scope="module")
def yellow_blue(tmp_path_factory, package):
    work = tmp_path_factory.mktemp("cura_yellow_blue")
    job = {"name": "cura_yellow_blue", "machine": "mixengine_makerpi_m2030x",
           # no chamber (the printer's default is an estimated 30 mm³): one mix per layer, the gradient's own
           "global": {"mixing_mode": "gradient", "mixing_gradient_start": 0, "mixing_gradient_end": 100,
                      "mixing_channel_colors": YELLOW_BLUE, "mixing_chamber_volume": 0},
           "models": [{"path": box(work / "cube20.stl", (20, 20, 20))}], "plugin_status": "MixEngine",
           "gcode_output": str(work / "gcode.json"), "preview": True,
           "screenshots": [{"path": str(SHOTS["yellow_blue"]), "layer_view_type": 0, "layer": None},
                           {"path": str(SHOTS["yellow_blue_middle"]), "layer_view_type": 0, "layer": MIDDLE_LAYER}],
           "camera": CAMERA}
    summary, status, fixture = run_cura(job, work, package)
    assert summary["backend_state"] == "Done"
    chunks = json.loads((work / "gcode.json").read_text())["chunks"]
    return {"status": status, "fixture": fixture, "chunks": chunks}


def test_cura_shows_the_predicted_colour_of_every_line(yellow_blue):
    """Every extrusion line of Cura's layer view is coloured from the ;PREDICTED_COLOR: the engine wrote for its
    move; the legend lists the channels."""
    preview = yellow_blue["status"]["plugin_status_end"]["preview"]
    assert preview["state"] == "coloured", preview
    assert preview["coloured"] == preview["matched"] == preview["lines"] > 1000, preview
    assert preview["predicted_moves"] == preview["moves"] and preview["malformed_comments"] == 0, preview
    written = written_colours(yellow_blue["chunks"])
    assert all(written.values()) and preview["distinct_colours"] == len({c for w in written.values() for c in w})
    channels = yellow_blue["status"]["plugin_status_end"]["legend"]["channels"]
    assert channels == [{"name": "A", "color": "#ffff00"}, {"name": "B", "color": "#0000ff"}]


def test_a_gradient_changes_no_mix_inside_a_layer_and_says_so(yellow_blue):
    """The mixing report's message after a Z gradient: how much of the surface comes out right, and no purge."""
    texts = [t for t in yellow_blue["status"]["visible_messages"] if "Of the visible surface" in t]
    assert len(texts) == 1, yellow_blue["status"]["visible_messages"]
    assert texts[0].endswith("<br>No purge: the mix does not change inside a layer."), texts[0]
    assert yellow_blue["status"]["plugin_status_end"]["mixing_report"]["message"] == texts[0]


def test_a_yellow_to_blue_gradient_is_green_in_the_middle_of_cura_layer_view(yellow_blue, engine, report):
    """Issue 26: with the layer slider at the middle of the cube, the cut edge of the print shows the colour the
    engine predicted for that layer (the chromaticity of the pixels, shading taken out, within 0.02 of the
    written colour's), and that colour is green (G well above R and B), as `mixengine mix` predicts for the
    50:50 mix; a linear-light blend of yellow and blue, what the plugin used to draw, would be grey."""
    written = written_colours(yellow_blue["chunks"])
    assert abs(MIDDLE_LAYER - (len(written) - 1) / 2) <= 1, len(written)  # the middle of the cube
    assert len(set(written[MIDDLE_LAYER])) == 1, written[MIDDLE_LAYER]  # one mix per layer (no chamber)
    middle = written[MIDDLE_LAYER][0]
    assert is_green(rgb_of(middle)), middle
    mix = helpers.mixengine("mix", "--colors", YELLOW_BLUE, "--ratio", "0.5:0.5")
    assert mix.returncode == 0, mix.stderr
    half = re.search(r"^predicted\s+(#[0-9a-f]{6})$", mix.stdout, re.M).group(1)
    assert numpy.abs(rgb_of(middle) - rgb_of(half)).max() <= 12 / 255, (middle, half)  # about 50:50 there
    # the cut: the first printed pixels below the top of the part, in the middle of its width
    image = screenshot(SHOTS["yellow_blue_middle"])
    mask = part_mask(image)
    columns = numpy.flatnonzero(mask.any(axis=0))
    left, right = numpy.percentile(columns, 30), numpy.percentile(columns, 70)
    edge = []
    for col in range(int(left), int(right) + 1):
        rows = numpy.flatnonzero(mask[:, col])
        if len(rows):
            edge += [image[PART_ROWS.start + r, VIEW_COLS.start + col] for r in range(rows[0] + 2, rows[0] + 8)
                     if mask[r, col]]
    assert len(edge) > 300, len(edge)
    seen = numpy.median(chromaticity(numpy.array(edge)), axis=0)
    expected = chromaticity(rgb_of(middle) + ALBEDO)
    assert numpy.abs(seen - expected).max() <= 0.02, (seen, expected)
    assert seen[1] > seen[0] + 0.2 and seen[1] > seen[2] + 0.1, seen  # green
    grey = chromaticity(numpy.full(3, 0.735) + ALBEDO)  # yellow and blue blended in linear light
    report(f"Cura e2e yellow to blue: {SHOTS['yellow_blue_middle']}: layer {MIDDLE_LAYER} drawn with chromaticity "
           f"{numpy.round(seen, 3).tolist()}, the engine's {middle} {numpy.round(expected, 3).tolist()} "
           f"(a linear blend: {numpy.round(grey, 3).tolist()}); median pixel "
           f"{numpy.round(numpy.median(numpy.array(edge), axis=0) * 255).astype(int).tolist()}")


def test_yellow_to_blue_in_cura_runs_yellow_green_blue_from_bottom_to_top(yellow_blue, report):
    """The whole cube in Material Color: each printed pixel is given the layer whose written colour has the
    nearest chromaticity; yellow's layers sit at the bottom of the picture, the middle (green) layers above
    them, blue's at the top, and the pixels fit the written colours closely."""
    written = written_colours(yellow_blue["chunks"])
    layers = sorted(written)
    table = chromaticity(numpy.array([rgb_of(written[i][0]) for i in layers]) + ALBEDO)
    image = screenshot(SHOTS["yellow_blue"])
    mask = part_mask(image)
    rows = numpy.nonzero(mask)[0] + PART_ROWS.start
    pixels = chromaticity(image[PART_ROWS, VIEW_COLS][mask])
    distance = numpy.abs(pixels[:, None, :] - table[None, :, :]).max(axis=2)
    nearest = numpy.array(layers)[distance.argmin(axis=1)]
    fit = distance.min(axis=1)
    assert len(pixels) > 20000 and numpy.mean(fit <= 0.03) > 0.9, (len(pixels), numpy.mean(fit <= 0.03))
    third = len(layers) / 3
    bottom, centre, top = (rows[(nearest >= lo) & (nearest < hi)] for lo, hi in
                           ((0, third), (len(layers) / 2 - 10, len(layers) / 2 + 10), (2 * third, len(layers))))
    assert min(len(bottom), len(centre), len(top)) > 1000, (len(bottom), len(centre), len(top))
    assert numpy.median(bottom) > numpy.median(centre) > numpy.median(top)  # rows grow downwards
    report(f"Cura e2e yellow to blue: {SHOTS['yellow_blue']}: {len(pixels)} printed pixels, "
           f"{100 * numpy.mean(fit <= 0.03):.1f} % within 0.03 of a written colour's chromaticity; median rows "
           f"bottom third {numpy.median(bottom):.0f}, middle {numpy.median(centre):.0f}, "
           f"top third {numpy.median(top):.0f}")


# ---- two cubes at different ratios: the mixing report in one Cura message (issue 26) ------------------------
MATERIALS = Path("/usr/share/cura/resources/materials")


def material_density(material_id):
    """The density (g/cm³) in the fdm_materials file of the material Cura used (read here, not by the plugin)."""
    text = (MATERIALS / f"{material_id}.xml.fdm_material").read_text()
    return float(re.search(r"<density>([\d.]+)</density>", text).group(1))


def outer_wall_colour(chunk, mesh):
    """The ;PREDICTED_COLOR: in force where `mesh`'s outer wall starts in a layer's chunk (or the first one
    written inside it)."""
    colour, current_mesh, feature = None, None, None
    for line in chunk.splitlines():
        if line.startswith(";MESH:"):
            current_mesh = line[6:]
        elif line.startswith(";TYPE:"):
            feature = line[6:]
        elif line.startswith(";PREDICTED_COLOR:"):
            colour = line[17:].strip().lower()
        elif current_mesh == mesh and feature == "WALL-OUTER" and line.startswith("G1") and colour:
            return colour
    raise AssertionError(f"no outer wall of {mesh}")


@pytest.fixture(scope="module")
def two_cubes(tmp_path_factory, package):
    """Two 20 mm cubes loaded one after the other (Cura places the second beside the first), per-model
    mixing_ratio 1:0 and 0:1, a 40 mm³ chamber in 3 stages, yellow and blue."""
    work = tmp_path_factory.mktemp("cura_two_cubes")
    job = {"name": "cura_two_cubes", "machine": "mixengine_makerpi_m2030x",
           "global": {"mixing_mode": "dual", "mixing_chamber_volume": 40, "mixing_chamber_stages": 3,
                      "mixing_channel_colors": YELLOW_BLUE},
           "models": [{"path": box(work / "left.stl", (20, 20, 20)), "settings": {"mixing_ratio": "1:0"}},
                      {"path": box(work / "right.stl", (20, 20, 20)), "settings": {"mixing_ratio": "0:1"}}],
           "plugin_status": "MixEngine", "gcode_output": str(work / "gcode.json"), "preview": True,
           "screenshots": [{"path": str(SHOTS["two_cubes"]), "layer_view_type": 0, "layer": None}],
           "camera": {"position": [-40, 250, 220], "look_at": [35, 0, -10]}}
    summary, status, fixture = run_cura(job, work, package)
    assert summary["backend_state"] == "Done"
    chunks = json.loads((work / "gcode.json").read_text())["chunks"]
    return {"status": status, "fixture": fixture, "chunks": chunks}


def test_two_cubes_apart_show_the_purge_and_the_one_at_a_time_hint(two_cubes, report):
    """After the slice, one Cura message says what the engine's ;MIXING.* header says: the purge in mm³ and in
    grams (the density of Cura's material) and that printing the cubes one at a time would remove the changes."""
    status, chunks = two_cubes["status"], two_cubes["chunks"]
    objects = two_cubes["fixture"]["objects"]
    assert sorted(o["settings"]["mixing_ratio"] for o in objects) == ["0:1", "1:0"]  # per model, as Cura sent it
    written = dict(re.findall(r"^;MIXING\.([A-Z0-9_.]+):(.*)$", chunks[0], re.M))  # the G-code prefix
    purge, changes = float(written["PURGE_MM3"]), int(written["CHANGES"])
    assert purge > 0 and changes > 0 and "the models stand apart" in written["HINT"], written
    density = material_density(two_cubes["fixture"]["material"])
    texts = [t for t in status["visible_messages"] if "Purge:" in t]
    assert len(texts) == 1, status["visible_messages"]
    text = texts[0]
    assert f"Purge: {purge:.0f} mm³ ({purge * density / 1000:.1f} g) for {changes} changes of mix inside layers." \
        in text
    assert ("printing them one at a time (Special Modes → Print Sequence → One at a Time) would remove the "
            f"{changes} changes of mix") in text
    mixing = status["plugin_status_end"]["mixing_report"]
    assert mixing["state"] == "shown" and mixing["visible"] and mixing["density"] == density, mixing
    # the plugin's words for this G-code (Cura's Message turns the line breaks into <br>)
    assert text == mixing["message"] == MixReport.messageText(MixReport.read(chunks), density).replace("\n", "<br>")
    # the Preview behind the message: the yellow cube, and the blue one in the colour the engine predicts for its
    # outer wall (blue with what the chamber still holds of yellow)
    top = [c for c in chunks if c.startswith(";LAYER:")][-1]
    wall = outer_wall_colour(top, "right.stl")
    image = screenshot(SHOTS["two_cubes"])
    yellow, blue = len(pixels_of(image, "#ffff00")[0]), len(pixels_of(image, wall)[0])
    assert yellow > 2000 and blue > 2000, (yellow, blue, wall)
    report(f"Cura e2e two cubes: {SHOTS['two_cubes']}; the message:\n" + text.replace("<br>", "\n"))


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


# ---- a raft under a gradient (issue 15): raft layers in the Preview, printed with filament A ----------------
def test_raft_under_a_gradient_shows_in_the_preview_with_filament_a(tmp_path, package, report):
    """Cura asks for a raft on the mixing printer: MixEngine prints the raft's layers (numbered below zero as
    CuraEngine numbers them) with mixing_raft_ratio (filament A), Cura's layer view holds every layer, and
    the Material Color screenshot shows the raft, 15 mm wider than the cube on each side, in channel A's colour."""
    job = {"name": "cura_raft", "machine": "mixengine_makerpi_m2030x",
           # no chamber (the printer's default is an estimated 30 mm³), so the raft's layers are filament A alone
           "global": {"mixing_mode": "gradient", "mixing_gradient_start": 0, "mixing_gradient_end": 100,
                      "mixing_channel_colors": f"{CHANNEL_A},{CHANNEL_B}", "adhesion_type": "raft",
                      "mixing_chamber_volume": 0},
           "models": [{"path": box(tmp_path / "cube20.stl", (20, 20, 20))}], "plugin_status": "MixEngine",
           "gcode_output": str(tmp_path / "gcode.json"), "preview": True,
           "screenshots": [{"path": str(SHOTS["raft"]), "layer_view_type": 0}], "camera": CAMERA}
    summary, status, fixture = run_cura(job, tmp_path, package)
    assert summary["backend_state"] == "Done" and fixture["global_settings"]["adhesion_type"] == "raft"
    chunks = json.loads((tmp_path / "gcode.json").read_text())["chunks"]
    ids = [int(c.split("\n", 1)[0][7:]) for c in chunks if c.startswith(";LAYER:")]
    raft_ids = [i for i in ids if i < 0]
    # base, interface, 2 surfaces; as in CuraEngine the ids left for the air gap's filler layers are not written
    assert len(raft_ids) == 4 and raft_ids == list(range(raft_ids[0], raft_ids[0] + 4))
    assert ids[4:] == list(range(len(ids) - 4))
    preview = status["plugin_status_end"]["preview"]
    assert status["scene_layers"] == len(ids) == preview["layers"]
    assert preview["state"] == "coloured" and preview["matched"] == preview["lines"], preview  # every line by its mix
    gcode = tmp_path / "cura.gcode"
    gcode.write_text("".join(chunks))
    totals = read_mixing_gcode(gcode, "eb_axes").layer_totals()
    for layer in raft_ids:
        _, (a, b) = totals[layer]
        assert a > 0 and b == pytest.approx(0, abs=1e-6), layer  # the raft: filament A only
    image = screenshot(SHOTS["raft"])
    a_rows, a_cols = pixels_of(image, CHANNEL_A)
    b_rows, b_cols = pixels_of(image, CHANNEL_B)
    assert len(a_rows) > 3000 and len(b_rows) > 3000, (len(a_rows), len(b_rows))
    raft_width = numpy.percentile(a_cols, 99) - numpy.percentile(a_cols, 1)  # teal: the raft and the cube's foot
    cube_width = numpy.percentile(b_cols, 99) - numpy.percentile(b_cols, 1)  # the magenta top of the cube
    assert raft_width > 1.5 * cube_width, (raft_width, cube_width)
    report(f"Cura e2e raft: {SHOTS['raft']} ({len(raft_ids)} raft layers below 0, raft {raft_width:.0f} px "
           f"wide under a {cube_width:.0f} px cube)")


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
    # no mixing report in a single-colour print, so no message about it
    assert end["mixing_report"]["state"] == "not a mixing slice" and not end["mixing_report"]["visible"]
    assert not [t for t in status["visible_messages"] if "Of the visible surface" in t]


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
