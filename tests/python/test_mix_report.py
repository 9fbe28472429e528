"""Issue 26, without Cura: the engine's mixing report (";MIXING.*" header lines) read by the plugin
(plugin/MixReport.py) and worded for the user, exactly; the lines where Cura finds them (the G-code prefix the
engine sends over the socket, two cubes at different ratios); and MixReportNotice in Cura's own Python: one
message per mixing slice, replaced by the next, hidden when a new slice starts and when a slice without the
report comes. The message in the real Cura is checked in test_e2e_cura.py.
"""
import json
import re
import subprocess
import sys

import pytest

import helpers
from cura_socket import resolved_settings, slice_over_socket
from mixing_gcode import box_stl

sys.path.insert(0, str(helpers.REPO / "plugin"))
import MixReport  # noqa: E402

YELLOW_BLUE = "#ffff00,#0000ff"
PLA = 1.24  # g/cm³, Cura's generic PLA (fdm_materials)

# the header of two cubes at 1:0 and 0:1 (settings/README.md, "The mixing chamber")
TWO_CUBES = """;FLAVOR:Marlin
;TIME:11805
;Generated with MixEngine 0.1.0
;MIXING.CHAMBER:40.0 mm3 in 3 stages
;MIXING.VISIBLE_WITHIN_DE00_3:1.6%
;MIXING.VISIBLE_WITHIN_TOLERANCE:100.0% (0.100)
;MIXING.WORST:dE00 36.3 (share off by 0.098) at layer 2 X97.70 Y109.80 WALL-OUTER
;MIXING.PURGE_MM3:10452.0
;MIXING.CHANGES:148
;MIXING.PURGE_MM3_AT_TOLERANCE_0.200:6690.4 (needed at 0.100: 8816.2)
;MIXING.HINT:the models stand apart: printing them one at a time (print_sequence one_at_a_time) would remove \
the 148 changes of mix and the 10452 mm3 of purge
"""
TWO_CUBES_TEXT = (
    "Of the visible surface (outer walls, skin), 1.6% comes out within ΔE00 3 of its colour and 100% within the "
    "Mix Transition Tolerance (0.1) of its mix, with the 40 mm³ mixing chamber (3 stages). Worst: ΔE00 36.3 "
    "(shares off by 0.098) on the outer wall of layer 2 at X97.70 Y109.80.\n"
    "Purge: 10452 mm³ (13.0 g) for 148 changes of mix inside layers. At twice the tolerance (0.2) the changes "
    "would need 6690 mm³ (8.3 g) instead of 8816 mm³ (10.9 g).\n"
    "The models stand apart: printing them one at a time (Special Modes → Print Sequence → One at a Time) would "
    "remove the 148 changes of mix and the 10452 mm³ of purge.")


def test_two_cubes_report_in_plain_words_with_grams():
    report = MixReport.read([TWO_CUBES, ";LAYER:0\nG1 X1 E1\n"])
    assert report.malformed == []
    assert (report.chamber_mm3, report.chamber_stages, report.within_de00_3, report.within_tolerance,
            report.tolerance) == (40.0, 3, 1.6, 100.0, 0.1)
    assert report.worst == {"de00": 36.3, "share_off": 0.098, "layer": 2, "x": "97.70", "y": "109.80",
                            "feature": "WALL-OUTER"}
    assert (report.purge_mm3, report.changes, report.looser_tolerance, report.looser_mm3, report.needed_mm3,
            report.unpurged_mm3) == (10452.0, 148, 0.2, 6690.4, 8816.2, None)
    assert report.hint.startswith("the models stand apart")
    assert MixReport.messageText(report, PLA) == TWO_CUBES_TEXT


def test_without_a_density_the_volumes_are_in_mm3_only():
    text = MixReport.messageText(MixReport.read(TWO_CUBES), None)
    assert text.splitlines()[1] == ("Purge: 10452 mm³ for 148 changes of mix inside layers. At twice the tolerance "
                                    "(0.2) the changes would need 6690 mm³ instead of 8816 mm³.")
    assert text.splitlines()[0] == TWO_CUBES_TEXT.splitlines()[0] and " g)" not in text
    assert MixReport.messageText(MixReport.read(TWO_CUBES), 0) == text


def test_unpurged_changes_are_a_warning():
    """No purge tower: the changes are not purged; what that leaves is said, the hint as the engine wrote it."""
    header = """;MIXING.CHAMBER:40.0 mm3 in 3 stages
;MIXING.VISIBLE_WITHIN_DE00_3:1.6%
;MIXING.VISIBLE_WITHIN_TOLERANCE:9.2% (0.100)
;MIXING.WORST:dE00 99.2 (share off by 0.957) at layer 0 X105.20 Y112.30 WALL-OUTER
;MIXING.PURGE_MM3:0.0
;MIXING.CHANGES:394
;MIXING.PURGE_MM3_AT_TOLERANCE_0.200:7450.7 (needed at 0.100: 10287.5)
;MIXING.UNPURGED_MM3:17846.4
"""
    assert MixReport.messageText(MixReport.read(header), PLA) == (
        "Of the visible surface (outer walls, skin), 1.6% comes out within ΔE00 3 of its colour and 9.2% within "
        "the Mix Transition Tolerance (0.1) of its mix, with the 40 mm³ mixing chamber (3 stages). Worst: ΔE00 "
        "99.2 (shares off by 0.957) on the outer wall of layer 0 at X105.20 Y112.30.\n"
        "No purge for the 394 changes of mix inside layers. At twice the tolerance (0.2) the changes would need "
        "7451 mm³ (9.2 g) instead of 10288 mm³ (12.8 g).\n"
        "Warning: 17846 mm³ (22.1 g) of the changes could not be purged (no purge tower, or no room for one): "
        "visible surfaces after them show the previous mix.")
    small = header.replace("UNPURGED_MM3:17846.4", "UNPURGED_MM3:4.25").replace("PURGE_MM3:0.0", "PURGE_MM3:7.5")
    assert MixReport.messageText(MixReport.read(small), PLA).splitlines()[1:] == [
        "Purge: 7.5 mm³ (0.01 g) for 394 changes of mix inside layers. At twice the tolerance (0.2) the changes "
        "would need 7451 mm³ (9.2 g) instead of 10288 mm³ (12.8 g).",
        "Warning: 4.2 mm³ (0.01 g) of the changes could not be purged (no purge tower, or no room for one): "
        "visible surfaces after them show the previous mix."]


def test_a_gradient_without_changes_and_an_ideal_chamber():
    gradient = """;MIXING.CHAMBER:40.0 mm3 in 3 stages
;MIXING.VISIBLE_WITHIN_DE00_3:100.0%
;MIXING.VISIBLE_WITHIN_TOLERANCE:100.0% (0.100)
;MIXING.WORST:dE00 0.9 (share off by 0.003) at layer 0 X66.17 Y105.77 SKIN
;MIXING.PURGE_MM3:0.0
;MIXING.CHANGES:0
"""
    assert MixReport.messageText(MixReport.read(gradient), PLA) == (
        "Of the visible surface (outer walls, skin), 100% comes out within ΔE00 3 of its colour and 100% within "
        "the Mix Transition Tolerance (0.1) of its mix, with the 40 mm³ mixing chamber (3 stages). Worst: ΔE00 0.9 "
        "(shares off by 0.003) on the skin of layer 0 at X66.17 Y105.77.\n"
        "No purge: the mix does not change inside a layer.")
    ideal = """;MIXING.CHAMBER:ideal (mixing_chamber_volume 0)
;MIXING.VISIBLE_WITHIN_DE00_3:n/a
;MIXING.VISIBLE_WITHIN_TOLERANCE:n/a (0.250)
;MIXING.WORST:none
;MIXING.PURGE_MM3:0.0
;MIXING.CHANGES:0
"""
    report = MixReport.read(ideal)
    assert report.malformed == [] and report.no_visible_surface and report.tolerance == 0.25
    assert MixReport.messageText(report, PLA) == (
        "The print has no visible surface (outer walls, skin) to judge, with an ideal mixing chamber (volume 0).\n"
        "No purge: the mix does not change inside a layer.")


def test_only_the_header_is_read_and_unreadable_lines_are_left_out():
    assert MixReport.read([";FLAVOR:Marlin\n;TIME:5\n", ";LAYER:0\n;MIXING.PURGE_MM3:5\n"]) is None
    assert MixReport.read([]) is None and MixReport.read(None) is None
    header = TWO_CUBES.replace("WORST:dE00 36.3", "WORST:dE 36.3").replace("CHANGES:148", "CHANGES:many")
    header += ";MIXING.SOMETHING_NEW:42\n"
    report = MixReport.read(header)
    assert sorted(report.malformed) == ["CHANGES", "WORST"] and report.lines["SOMETHING_NEW"] == "42"
    lines = MixReport.messageText(report, None).splitlines()
    assert "Worst" not in lines[0] and lines[1].startswith("Purge: 10452 mm³. At twice the tolerance")
    # a hint in other words is shown as written, with mm³ and a capital
    assert MixReport.hintText("printing them one at a time saves 5 mm3") == "Printing them one at a time saves 5 mm³."


# ---- the engine's own report, as Cura receives it -----------------------------------------------------------
@pytest.fixture(scope="module")
def two_cubes_over_the_socket(engine, tmp_path_factory):
    """Two 20 mm cubes 40 mm apart in one mesh group at 1:0 and 0:1 (per-object mixing_ratio, as Cura sends
    per-model settings), a 40 mm³ chamber in 3 stages."""
    work = tmp_path_factory.mktemp("mix_report")
    left = box_stl(work / "left.stl", 20, 20, 20, centre_x=-20)
    right = box_stl(work / "right.stl", 20, 20, 20, centre_x=20)
    global_settings, extruders = resolved_settings(
        "mixengine_makerpi_m2030x", "mixing_mode=dual", "mixing_chamber_volume=40", "mixing_chamber_stages=3",
        f"mixing_channel_colors={YELLOW_BLUE}")
    objects = [{"name": str(path), "stl": str(path), "settings": {"extruder_nr": "0", "mixing_ratio": ratio}}
               for path, ratio in ((left, "1:0"), (right, "0:1"))]
    result = slice_over_socket(engine, work, global_settings, extruders, [{"settings": {}, "objects": objects}])
    assert result["exit_code"] == 0 and result["finished"]
    return result["gcode_list"]


def test_the_report_comes_in_the_gcode_prefix(two_cubes_over_the_socket, report):
    chunks = two_cubes_over_the_socket
    prefix = chunks[0]
    assert prefix.startswith(";FLAVOR:") and ";MIXING.HINT:" in prefix
    assert not any(";MIXING." in chunk for chunk in chunks[1:])
    from_prefix = MixReport.read([prefix])
    assert vars(from_prefix) == vars(MixReport.read(chunks)) and from_prefix.malformed == []
    written = dict(re.findall(r"^;MIXING\.([A-Z0-9_.]+):(.*)$", prefix, re.M))
    purge, changes = float(written["PURGE_MM3"]), int(written["CHANGES"])
    assert purge > 0 and changes > 0
    text = MixReport.messageText(from_prefix, PLA)
    assert (f"Purge: {purge:.0f} mm³ ({purge * PLA / 1000:.1f} g) for {changes} changes of mix inside layers."
            in text)
    assert text.splitlines()[-1] == (
        f"The models stand apart: printing them one at a time (Special Modes → Print Sequence → One at a Time) "
        f"would remove the {changes} changes of mix and the {purge:.0f} mm³ of purge.")
    report("mixing report message for two cubes over the socket:\n" + text)


# ---- MixReportNotice in Cura's own Python ------------------------------------------------------------------
CURA_NOTICE_SCRIPT = r"""
import importlib, json, sys, types
plugin_dir, mixing, other, plain = json.loads(sys.stdin.read())
package = types.ModuleType("mixengine_plugin")  # the plugin's modules without its __init__ (no Cura app here)
package.__path__ = [plugin_dir]
sys.modules["mixengine_plugin"] = package
Notice = importlib.import_module("mixengine_plugin.MixReportNotice")
from UM.Backend.Backend import BackendState


class Message:  # UM's Message needs a running application; this one records what the notice does
    made = []
    def __init__(self, text, lifetime=30, title=None, **kwargs):
        self.text, self.lifetime, self.title, self.visible = text, lifetime, title, False
        Message.made.append(self)
    def show(self): self.visible = True
    def hide(self): self.visible = False
    def getText(self): return self.text


Notice.Message = Message


class Signal:
    def connect(self, f): self.f = f


class Material:
    def __init__(self, metadata): self.metadata = metadata
    def getMetaDataEntry(self, key, default=None): return self.metadata.get(key, default)


def extruder(properties, enabled=True):
    return types.SimpleNamespace(isEnabled=enabled, material=Material({"properties": properties} if properties else {}))


class App:
    def __init__(self):
        self.backend = types.SimpleNamespace(backendStateChange=Signal())
        self.scene = types.SimpleNamespace(gcode_dict={})
        self.stack = types.SimpleNamespace(extruderList=[extruder({"density": "1.24", "diameter": 1.75})])
    def getBackend(self): return self.backend
    def getController(self): return types.SimpleNamespace(getScene=lambda: self.scene)
    def getMultiBuildPlateModel(self): return types.SimpleNamespace(activeBuildPlate=0)
    def getGlobalContainerStack(self): return self.stack


app = App()
notice = Notice.MixReportNotice(app)
notice.connect()
emit = app.backend.backendStateChange.f
steps = []


def record(name):
    steps.append({"step": name, "visible": [m.text for m in Message.made if m.visible], "made": len(Message.made),
                  "state": notice.last["state"], "density": notice.last.get("density"),
                  "status_visible": notice.status()["visible"],
                  "title": Message.made[-1].title if Message.made else None,
                  "lifetime": Message.made[-1].lifetime if Message.made else None})


record("start")
app.scene.gcode_dict[0] = mixing
emit(BackendState.Processing)
emit(BackendState.Done)
record("mixing slice done")
emit(BackendState.NotStarted)
record("a setting changed")
emit(BackendState.Processing)
app.scene.gcode_dict[0] = other
emit(BackendState.Done)
record("second mixing slice done")
emit(BackendState.Done)  # "slice unnecessary": Cura reports Done again for the same G-code
record("done again")
app.scene.gcode_dict[0] = plain
emit(BackendState.Processing)
emit(BackendState.Done)
record("single-colour slice done")
app.stack.extruderList = [extruder({}), extruder({"density": 1.24}, enabled=False)]  # no density known
app.scene.gcode_dict[0] = mixing
emit(BackendState.Done)
record("mixing slice, material without density")
app.stack.extruderList = [extruder({"density": 1.24}), extruder({"density": 1.04})]
emit(BackendState.Done)
record("two materials")
app.scene.gcode_dict = {}
emit(BackendState.Done)
record("no G-code")
print(json.dumps(steps))
"""


def test_one_message_per_mixing_slice_in_cura_python():
    other = TWO_CUBES.replace("PURGE_MM3:10452.0", "PURGE_MM3:5000.0")
    plain = [";FLAVOR:Marlin\n;TIME:5\n", ";LAYER:0\nG1 X1 E1\n"]
    proc = subprocess.run(["/usr/bin/python3", "-c", CURA_NOTICE_SCRIPT], capture_output=True, text=True,
                          input=json.dumps([str(helpers.REPO / "plugin"), [TWO_CUBES, ";LAYER:0\n"], [other], plain]),
                          timeout=120)
    assert proc.returncode == 0, proc.stderr
    steps = {s["step"]: s for s in json.loads(proc.stdout.strip().splitlines()[-1])}
    assert steps["start"]["visible"] == [] and steps["start"]["state"] == "no slice yet"
    done = steps["mixing slice done"]
    assert done["visible"] == [TWO_CUBES_TEXT] and done["made"] == 1 and done["status_visible"]
    assert (done["state"], done["density"], done["title"], done["lifetime"]) == ("shown", 1.24, MixReport.TITLE, 0)
    changed = steps["a setting changed"]
    assert changed["visible"] == [] and changed["state"] == "hidden: a new slice"
    second = steps["second mixing slice done"]
    assert second["made"] == 2 and second["visible"] == [MixReport.messageText(MixReport.read(other), 1.24)]
    assert "Purge: 5000 mm³ (6.2 g)" in second["visible"][0]
    again = steps["done again"]
    assert again["visible"] == second["visible"] and again["made"] == 3  # replaced, still one
    single = steps["single-colour slice done"]
    assert single["visible"] == [] and single["state"] == "not a mixing slice" and not single["status_visible"]
    unknown = steps["mixing slice, material without density"]
    assert unknown["density"] is None and unknown["visible"] == [MixReport.messageText(MixReport.read(TWO_CUBES))]
    assert steps["two materials"]["density"] is None and len(steps["two materials"]["visible"]) == 1
    assert steps["no G-code"]["visible"] == [] and steps["no G-code"]["state"] == "not a mixing slice"


def test_changes_absorbed_by_hidden_extrusions_need_no_purge():
    """Support beside a model in another mix (the knot with support, issue 26): the changes are planned (the
    looser-tolerance line is there) and the hidden extrusions absorb them all."""
    absorbed = """;MIXING.CHAMBER:40.0 mm3 in 3 stages
;MIXING.VISIBLE_WITHIN_DE00_3:100.0%
;MIXING.VISIBLE_WITHIN_TOLERANCE:100.0% (0.100)
;MIXING.WORST:dE00 0.0 (share off by 0.000) at layer 0 X121.46 Y102.05 WALL-OUTER
;MIXING.PURGE_MM3:0.0
;MIXING.CHANGES:0
;MIXING.PURGE_MM3_AT_TOLERANCE_0.200:0.0 (needed at 0.100: 0.0)
"""
    text = MixReport.messageText(MixReport.read(absorbed), PLA)
    assert text.endswith("\nNo purge: the hidden extrusions (infill, inner walls, support, raft) absorb every change "
                         "of mix."), text
