"""Issue 15: spiralize ("vase mode", magic_spiralize, smooth_spiralized_contours) as CuraEngine 4.13 prints it.

Side by side with Debian's CuraEngine (side_by_side.py: the Ender-3, 0.2 mm layers, every resolved value given
to both engines) on the corpus cylinder: the same ;LAYER_COUNT:, filament within 3 %, and the same features per
layer — the bottom layers (initial_bottom_layers) with skin, infill and inner walls, every layer above only
the outer wall. Read back with gcode_model.py (our own reader): from initial_bottom_layers + 1 on, Z rises
along each layer's outer wall and never falls, by one layer height per layer, without a Z move of its own.

With colour mixing (the MakerPi's E and B axes, a gradient over the vase's height) each move's E + B equals
the single-colour E of the same slice, and the share of B rises along the spiral within a layer (the mix
follows the height each move ends at). The gradient vase's side view (--preview) is saved to
out/spiralize/vase_gradient.png.
"""
import shutil

import numpy as np
import pytest

import gcode_model
import helpers
import side_by_side as sbs
from mixing_gcode import png_pixels, read_mixing_gcode

MODEL = "cylinder1000"  # a 1000-facet cylinder from the corpus
SPIRAL = {"magic_spiralize": "True"}
BOTTOM_LAYERS = 4  # the Ender-3's initial_bottom_layers at 0.2 mm (bottom_thickness 0.8 mm)
FILAMENT_TOLERANCE = 0.03
PICTURE = helpers.REPO / "out" / "spiralize" / "vase_gradient.png"


@pytest.fixture(scope="module")
def runs(engine, corpus):
    corpus(MODEL)
    mix, cura = sbs.run_mixengine(MODEL, SPIRAL), sbs.run_cura(MODEL, SPIRAL)
    assert cura.rc == 0, cura.stderr
    assert mix.rc == 0, mix.stderr
    return mix, cura


def features_per_layer(path):
    model = gcode_model.read(path)
    return model, {index: {model.features[f] for f in set(layer.feature.tolist())}
                   for index, layer in model.layers.items()}


def test_layer_count_and_filament_as_curaengine(runs, report):
    mix, cura = runs
    mm, cm = gcode_model.read(mix.gcode), gcode_model.read(cura.gcode)
    got, want = mix.filament_mm(), cura.filament_mm()
    report(f"spiralize {MODEL}: layers mixengine {mm.layer_count} / CuraEngine {cm.layer_count}; filament "
           f"{got:.0f} / {want:.0f} mm ({100 * (got - want) / want:+.2f} %)")
    assert mm.layer_count == cm.layer_count
    assert abs(got - want) <= FILAMENT_TOLERANCE * want


def test_bottom_layers_as_usual_then_only_the_outer_wall(runs):
    mix, cura = runs
    _, mine = features_per_layer(mix.gcode)
    _, theirs = features_per_layer(cura.gcode)
    for index in range(BOTTOM_LAYERS):
        assert ("WALL-INNER" in mine[index]) == (index % 2 == 1), index  # 5 walls more on odd layers
        assert mine[index] == theirs[index], index
    for index in range(BOTTOM_LAYERS, max(mine) + 1):
        assert mine[index] == {"WALL-OUTER"} == theirs[index], index


def test_z_rises_along_the_spiral(runs):
    mix, _ = runs
    model = gcode_model.read(mix.gcode)
    height = 0.2
    layers = [model.layers[i] for i in sorted(model.layers) if i > BOTTOM_LAYERS]
    zs = np.concatenate([layer.z for layer in layers])
    assert np.all(np.diff(zs) >= -1e-9), "Z falls somewhere along the spiral"
    assert np.max(np.diff(zs)) <= 0.01, "Z jumps (a layer change of its own)"
    for layer in layers[:-1]:  # each layer rises by one layer height, from the layer's own z
        first_layer_z = (layer.index + 1) * height
        assert layer.z.min() == pytest.approx(first_layer_z, abs=0.005), layer.index
        assert layer.z.max() == pytest.approx(first_layer_z + height, abs=1e-6), layer.index
    text = mix.gcode.read_text()
    spiral_part = text[text.index(f";LAYER:{BOTTOM_LAYERS + 1}\n"):]
    assert "G0 F600 Z" not in spiral_part.split(";LAYER:")[1]


def test_smooth_contours_moves_the_points(engine, corpus):
    """On a shape whose outline changes from layer to layer (the low-poly bunny) the smoothed spiral's points
    lie between the two layers' walls: other points, the same layers and nearly the same filament."""
    corpus("bunny_lowpoly")
    smooth = sbs.run_mixengine("bunny_lowpoly", SPIRAL)  # smooth_spiralized_contours is on by default
    plain = sbs.run_mixengine("bunny_lowpoly", dict(SPIRAL, smooth_spiralized_contours="False"))
    a, b = gcode_model.read(plain.gcode), gcode_model.read(smooth.gcode)
    assert a.layer_count == b.layer_count
    layer = BOTTOM_LAYERS + 50
    # without smoothing a short line first joins the layer's own wall, then its points are the wall's own
    assert len(a.layers[layer].x1) == len(b.layers[layer].x1) + 1
    assert not np.array_equal(a.layers[layer].x1[1:], b.layers[layer].x1)
    assert smooth.filament_mm() == pytest.approx(plain.filament_mm(), rel=0.02)


def _slice(engine, stl, out, *settings, preview=None):
    args = [engine, "slice", "-j", "mixengine_makerpi_m2030x", "-s", "magic_spiralize=True",
            "-s", "layer_height=0.2"]
    for s in settings:
        args += ["-s", s]
    args += ["-l", stl, "-o", out]
    if preview:
        args += ["--preview", preview]
    proc = helpers.run(args)
    assert proc.returncode == 0, proc.stderr


def test_gradient_vase_adds_up_and_follows_z(engine, corpus, tmp_path):
    stl = corpus(MODEL)
    single, mixed, png = tmp_path / "single.gcode", tmp_path / "mixed.gcode", tmp_path / "vase.png"
    _slice(engine, stl, single)
    # an ideal chamber: the move-by-move comparison with the single-filament slice needs the commanded mix
    # unshifted (the profile's estimated mixing_chamber_volume commands it earlier and cuts moves there)
    _slice(engine, stl, mixed, "mixing_mode=gradient", "mixing_gradient_start=0",
           "mixing_gradient_end=100", "mixing_channel_colors=#e03020,#2040e0", "mixing_chamber_volume=0",
           preview=png)
    one = read_mixing_gcode(single, "single").extrusions()
    two = read_mixing_gcode(mixed, "eb_axes").extrusions()
    assert len(one) == len(two) > 1000
    for a, b in zip(one, two):
        assert b.total == pytest.approx(a.total, abs=2e-5)
        assert a.z == pytest.approx(b.z)
    layer = max(m.layer for m in two) // 2  # mid-height: B's share grows along the layer's spiral
    shares = [m.amounts[1] / m.total for m in two if m.layer == layer and m.total > 1e-3]
    zs = [m.z for m in two if m.layer == layer and m.total > 1e-3]
    assert zs[-1] > zs[0] and shares[-1] > shares[0]
    assert 0.3 < shares[0] < 0.7
    width, height, _ = png_pixels(png)
    assert width > 0 and height > 0
    PICTURE.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy(png, PICTURE)
