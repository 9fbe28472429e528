"""Issue 16 end to end: the real Cura 4.13 under Xvfb (tests/e2e/cura_driver.py, the MixEngine plugin installed
from its package, as test_e2e_cura.py) slices a T whose bar overhangs 11 mm on both sides, support on, with
MixEngine — once as it is and once with a support blocker on the right overhang, added by the toolbar's
Support Blocker tool itself (its 10 mm anti_overhang_mesh cube on the model at a point, the scripted
equivalent of the click: job "support_blockers", tests/e2e/README.md).

Shows: Cura sends the blocker as a second object with anti_overhang_mesh; MixEngine (the bundled engine)
slices it; the support in the G-code Cura holds shrinks (per ;TYPE:SUPPORT, read with gcode_model.py), on the
right side only; the Line Type preview is saved (build/e2e/cura_support_blocker.png, and the run without the
blocker beside it) and shows less support-cyan than without the blocker.
"""
import json

import numpy
import pytest

import permodel_scenes as scenes
from test_e2e_cura import ARTIFACTS, PLUGIN_DIR_TAIL, package, pytestmark, run_cura, screenshot  # noqa: F401

SHOTS = {"plain": ARTIFACTS / "cura_tee_support.png", "blocker": ARTIFACTS / "cura_support_blocker.png"}
CAMERA = {"position": [0, 45, 95], "look_at": [0, 10, 0]}  # in front of the T, a little above
BLOCKER = {"model": 0, "position": [10, 16, 0]}  # under the bar's right half: a 10 mm cube at x 5..15, y 11..21


@pytest.fixture(scope="module")
def tee_runs(tmp_path_factory, package):  # noqa: F811
    work = tmp_path_factory.mktemp("cura_blocker")
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    runs = {}
    for name, blockers in (("plain", []), ("blocker", [BLOCKER])):
        job = {"name": f"cura_tee_{name}", "machine": "creality_ender3", "global": {"support_enable": True},
               "models": [{"path": str(scenes.part_path("tee"))}], "gcode_output": str(work / f"{name}.json"),
               "preview": True, "camera": CAMERA,
               "screenshots": [{"path": str(SHOTS[name]), "layer_view_type": 1, "layer": None}]}
        if blockers:
            job["support_blockers"] = blockers
        summary, status, fixture = run_cura(job, work, package)
        gcode = work / f"{name}.gcode"
        gcode.write_text("".join(json.loads((work / f"{name}.json").read_text())["chunks"]))
        runs[name] = {"summary": summary, "status": status, "fixture": fixture,
                      "result": scenes.Result(0, gcode, {}, "")}
    return runs


def support_x(result):
    """x (mm, bed frame) of the middle of every SUPPORT segment and its E."""
    model = result.model
    wanted = [i for i, f in enumerate(model.features) if f == "SUPPORT"]
    xs, es = [], []
    for layer in model.layers.values():
        mask = numpy.isin(layer.feature, wanted)
        xs.append((layer.x0[mask] + layer.x1[mask]) / 2)
        es.append(layer.e[mask])
    return numpy.concatenate(xs), numpy.concatenate(es)


def test_cura_sends_the_blocker_and_mixengine_slices_it(tee_runs):
    run = tee_runs["blocker"]
    assert run["summary"]["backend_state"] == "Done"
    assert run["status"]["engine_command"][0].endswith(PLUGIN_DIR_TAIL), run["status"]["engine_command"]
    assert run["status"]["support_blockers"] == [{"name": "Eraser", "anti_overhang_mesh": True}]
    objects = run["fixture"]["objects"]  # every object Cura sent (tests/data/cura_slice/README.md)
    assert len(objects) == 2
    assert [o["settings"].get("anti_overhang_mesh") for o in objects].count("True") == 1


def test_support_blocker_removes_the_support_under_it(tee_runs, report):
    plain_x, plain_e = support_x(tee_runs["plain"]["result"])
    blocked_x, blocked_e = support_x(tee_runs["blocker"]["result"])
    middle = 235 / 2  # the T stands in the middle of the Ender-3's bed
    left = lambda x, e: float(e[x < middle].sum())  # noqa: E731
    right = lambda x, e: float(e[x > middle].sum())  # noqa: E731
    report(f"Cura e2e support blocker: support {blocked_e.sum():.0f} mm of filament against {plain_e.sum():.0f} "
           f"without (right side {right(blocked_x, blocked_e):.0f} / {right(plain_x, plain_e):.0f}), "
           f"screenshots {SHOTS['blocker']} and {SHOTS['plain']}")
    assert plain_e.sum() > 100
    assert blocked_e.sum() < 0.8 * plain_e.sum()
    assert right(blocked_x, blocked_e) < 0.5 * right(plain_x, plain_e)
    assert left(blocked_x, blocked_e) == pytest.approx(left(plain_x, plain_e), rel=0.05)  # the left side kept


def test_preview_shows_less_support(tee_runs, report):
    """Cura's Line Type scheme draws support pale cyan (the skirt is saturated cyan): under the bar's right
    half (where the blocker is) the support is gone from the picture, under its left half it is unchanged."""
    def support_pixels(path):
        image = (screenshot(path) * 255).astype(int)
        r, g, b = image[..., 0], image[..., 1], image[..., 2]
        pale = (r > 90) & (r < 210) & (g > 200) & (b > 200) & (g - r > 40)
        under_bar = pale[420:705]  # between the bar's underside and the plate in the 1600 x 1000 picture
        return int(under_bar[:, 500:720].sum()), int(under_bar[:, 880:1100].sum())  # left, right of the stem
    (plain_left, plain_right), (left, right) = support_pixels(SHOTS["plain"]), support_pixels(SHOTS["blocker"])
    report(f"Cura e2e support blocker preview: support pixels right of the stem {right} (without blocker "
           f"{plain_right}), left {left} ({plain_left})")
    assert plain_right > 20000 and plain_left > 20000
    assert right < 0.1 * plain_right
    assert left == pytest.approx(plain_left, rel=0.05)
