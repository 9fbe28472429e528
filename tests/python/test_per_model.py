"""Issue 16: Cura's per-model settings — infill meshes, cutting meshes, support meshes, support blockers and
the mesh-combining settings — side by side with Debian's CuraEngine 4.13 on scenes of our own
(permodel_scenes.py: the same resolved Ender-3 settings and the same -l/-s per-model arguments for both).

Per scene: both engines succeed, the same ;LAYER_COUNT:, filament within FILAMENT_TOLERANCE, and each
feature's extrusion (;TYPE:, read back with gcode_model.py) within FEATURE_TOLERANCE of CuraEngine's (or
within FEATURE_FLOOR_MM of filament for small amounts). Then what each modifier is for: an infill mesh
prints less than the same body printed as a second model and a support blocker removes support. Last,
colour mixing: a cutting mesh with its own mixing_ratio or gradient prints its region in its own mix,
read back from the E and B words.

The skirt around support on the plate is compared apart (test_skirt_around_support) and not in the
per-feature test of those scenes; with a support mesh alone CuraEngine's is still longer (a strict xfail).
"""
import re

import pytest

import permodel_scenes as scenes

INFILL_100 = {"infill_mesh": "True", "infill_mesh_order": "1", "infill_sparse_density": "100"}
SCENES = {  # name -> ([(part, per-model values)], global overrides)
    # the new-user scene: a 30 mm box with a 100 % infill-mesh cylinder (r 8 mm, z 5..25) inside
    "infill_mesh": ([("box30", {}), ("cyl8_in_box", INFILL_100)], {}),
    "infill_mesh_alone": ([("cyl8_in_box", INFILL_100)], {}),
    # a second infill mesh, later in infill_mesh_order, overlapping the first: 5 % infill and one wall where
    # it is inside the box's infill and the first cylinder's
    "infill_mesh_order": ([("box30", {}), ("cyl8_in_box", INFILL_100),
                           ("cyl6_shifted", {"infill_mesh": "True", "infill_mesh_order": "2",
                                             "infill_sparse_density": "5", "wall_line_count": "1"})], {}),
    "tee_support": ([("tee", {})], {"support_enable": "True"}),
    # a support blocker over the right half of the tee's overhangs
    "anti_overhang": ([("tee", {}), ("blocker_right", {"anti_overhang_mesh": "True"})], {"support_enable": "True"}),
    "anti_overhang_alone": ([("blocker_right", {"anti_overhang_mesh": "True"})], {"support_enable": "True"}),
    # support meshes next to a box, no support_enable: a pillar on the plate kept in place, and a block in
    # the air (z 8..12) dropped down to the plate
    "support_mesh_in_place": ([("box20x10", {}), ("pillar_beside", {"support_mesh": "True",
                                                                     "support_mesh_drop_down": "False"})], {}),
    "support_mesh_drop_down": ([("box20x10", {}), ("float_beside", {"support_mesh": "True"})], {}),
    "support_mesh_alone": ([("pillar_beside", {"support_mesh": "True"})], {}),
    # a cylinder through the box cuts out a region with one wall and 60 % infill of its own
    "cutting_mesh": ([("box30", {}), ("cyl8_through", {"cutting_mesh": "True", "infill_sparse_density": "60",
                                                        "wall_line_count": "1"})], {}),
    "cutting_mesh_alone": ([("cyl8_through", {"cutting_mesh": "True"})], {}),
    # two boxes overlapping by 8 mm: as they are (multiple_mesh_overlap only), carved, carved in one order
    "overlap": ([("box_left", {}), ("box_right", {})], {}),
    "carve_alternate": ([("box_left", {}), ("box_right", {})], {"carve_multiple_volumes": "True"}),
    "carve_one_order": ([("box_left", {}), ("box_right", {})],
                        {"carve_multiple_volumes": "True", "alternate_carve_order": "False"}),
    "no_overlap": ([("box_left", {"multiple_mesh_overlap": "0"}), ("box_right", {"multiple_mesh_overlap": "0"})],
                   {}),
    # one mesh of two overlapping shells: united (meshfix_union_all) or even-odd (the overlap left empty)
    "union_all": ([("two_shells", {})], {}),
    "no_union_all": ([("two_shells", {"meshfix_union_all": "False"})], {}),
    # a box open on one side: nothing closes (the open pieces are left out, also with extensive stitching)
    # unless meshfix_keep_open_polygons closes them by their chords
    "open_box": ([("open_box", {})], {}),
    "open_box_extensive_stitching": ([("open_box", {"meshfix_extensive_stitching": "True"})], {}),
    "open_box_keep_open": ([("open_box", {"meshfix_keep_open_polygons": "True"})], {}),
}
SKIRT_AROUND_SUPPORT = {"tee_support", "anti_overhang", "support_mesh_in_place", "support_mesh_drop_down",
                        "support_mesh_alone"}
SKIRT_GAP = "CuraEngine's skirt around support on the plate is longer (toolpaths/adhesion/Adhesion.h, not issue 16)"
FILAMENT_TOLERANCE = 0.03
FEATURE_TOLERANCE = 0.08
FEATURE_FLOOR_MM = 15.0


@pytest.fixture(scope="module")
def runs(engine, tmp_path_factory):
    out = tmp_path_factory.mktemp("permodel")
    cache = {}

    def get(name):
        if name not in cache:
            parts, overrides = SCENES[name]
            mix, cura = scenes.run_mixengine(parts, out, overrides), scenes.run_cura(parts, out, overrides)
            assert cura.rc == 0, f"CuraEngine failed on {name}: {cura.stderr[-800:]}"
            assert mix.rc == 0, f"mixengine failed on {name}: {mix.stderr[-800:]}"
            cache[name] = (mix, cura)
        return cache[name]
    return get


OPEN_LAYERS_GAP = ("a layer with only open pieces counts as printing in MixEngine (toolpaths/EmptyLayers.h), "
                   "CuraEngine drops it unless in surface mode: 50 empty layers against none")


SUPPORT_MESH_TOP = ("a support mesh alone: CuraEngine's ;LAYER_COUNT: counts the mesh's 60 layers though it writes 58 "
                    "(its support stops below the top); MixEngine counts the 59 it writes (its support reaches a "
                    "layer higher)")
LAYER_GAPS = {"open_box": OPEN_LAYERS_GAP, "open_box_extensive_stitching": OPEN_LAYERS_GAP,
              "support_mesh_alone": SUPPORT_MESH_TOP}


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=LAYER_GAPS[n]))
                                  if n in LAYER_GAPS else n for n in SCENES])
def test_layer_count_as_curaengine(runs, name, report):
    mix, cura = runs(name)
    report(f"per-model {name}: layers {mix.layer_count()} (CuraEngine {cura.layer_count()}), filament "
           f"{mix.filament_mm():.0f} mm (CuraEngine {cura.filament_mm():.0f} mm)")
    assert mix.layer_count() == cura.layer_count()


@pytest.mark.parametrize("name", list(SCENES))
def test_filament_as_curaengine(runs, name):
    mix, cura = runs(name)
    assert mix.filament_mm() == pytest.approx(cura.filament_mm(), rel=FILAMENT_TOLERANCE, abs=1.0)


@pytest.mark.parametrize("name", list(SCENES))
def test_extrusion_per_feature_as_curaengine(runs, name):
    mix, cura = runs(name)
    ours, theirs = mix.by_feature(), cura.by_feature()
    bad = {}
    for feature in sorted(set(ours) | set(theirs)):
        if feature == "SKIRT" and name in SKIRT_AROUND_SUPPORT:
            continue  # test_skirt_around_support
        a, b = ours.get(feature, 0.0), theirs.get(feature, 0.0)
        if abs(a - b) > max(FEATURE_TOLERANCE * b, FEATURE_FLOOR_MM):
            bad[feature] = (round(a, 1), round(b, 1))
    assert not bad, f"{name}: feature (MixEngine mm, CuraEngine mm): {bad}"


def test_infill_mesh_is_not_printed_as_a_second_body(runs):
    """The cylinder only densifies the box's infill: less filament than box + cylinder sliced as two models."""
    mix, _ = runs("infill_mesh")
    alone, _ = runs("infill_mesh_alone")
    assert alone.layer_count() == 0 and alone.filament_mm() == 0.0
    two_bodies = scenes.run_mixengine([("box30", {}), ("cyl8_in_box", {"infill_sparse_density": "100"})],
                                      mix.gcode.parent)
    assert mix.filament_mm() < 0.97 * two_bodies.filament_mm()


def test_support_blocker_removes_support(runs, report):
    with_blocker, cura_with = runs("anti_overhang")
    without, cura_without = runs("tee_support")
    ours = with_blocker.by_feature().get("SUPPORT", 0.0) / without.by_feature()["SUPPORT"]
    theirs = cura_with.by_feature().get("SUPPORT", 0.0) / cura_without.by_feature()["SUPPORT"]
    report(f"support blocker: support extrusion x{ours:.2f} (CuraEngine x{theirs:.2f})")
    assert ours < 0.7 and ours == pytest.approx(theirs, abs=0.1)


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=SKIRT_GAP))
                                  if n == "support_mesh_alone" else n for n in sorted(SKIRT_AROUND_SUPPORT)])
def test_skirt_around_support(runs, name):
    mix, cura = runs(name)
    assert mix.by_feature()["SKIRT"] == pytest.approx(cura.by_feature()["SKIRT"], rel=FEATURE_TOLERANCE)


# ---- colour mixing: a cutting mesh's region in its own mix ----------------------------------------------
MIX_PRINT = {"mixing_mode": "dual", "mixing_ratio": "1:0", "mixing_dialect": "eb_axes"}  # the box: filament A


def eb_extrusions(path):
    """[(mesh, x, y, z, e, b)] of every extruding XY move, read from absolute E and B words (G92 resets)."""
    out, mesh, pos, axes = [], None, {"X": 0.0, "Y": 0.0, "Z": 0.0}, {"E": 0.0, "B": 0.0}
    for line in open(path):
        if line.startswith(";MESH:"):
            mesh = line[6:].strip()
            continue
        words = dict((w[0], float(w[1:])) for w in line.split(";")[0].split()[1:] if len(w) > 1)
        code = line.split(" ", 1)[0].strip()
        if code == "G92":
            axes.update({k: v for k, v in words.items() if k in axes})
        elif code in ("G0", "G1"):
            moved = any(k in words and words[k] != pos[k] for k in ("X", "Y"))
            de, db = words.get("E", axes["E"]) - axes["E"], words.get("B", axes["B"]) - axes["B"]
            pos.update({k: v for k, v in words.items() if k in pos})
            axes.update({k: v for k, v in words.items() if k in axes})
            if moved and de + db > 1e-9:
                out.append((mesh, pos["X"], pos["Y"], pos["Z"], de, db))
    return out


def region_shares(mix, cutter):
    """B shares of the cutting mesh's moves and of the others' (by ;MESH:), with the moves' radii."""
    moves = eb_extrusions(mix.gcode)
    assert re.search(r"^G1 .* E[\d.]+ B[\d.]+$", mix.gcode.read_text(), re.M), "no E and B words"
    x0, y0 = 235 / 2, 235 / 2  # the Ender-3's bed centre: the parts' origin
    inside = [(((x - x0) ** 2 + (y - y0) ** 2) ** 0.5, z, b / (e + b)) for m, x, y, z, e, b in moves
              if m and m.endswith(cutter)]
    outside = [(((x - x0) ** 2 + (y - y0) ** 2) ** 0.5, z, b / (e + b)) for m, x, y, z, e, b in moves
               if not (m and m.endswith(cutter))]
    return inside, outside


def test_cutting_mesh_region_prints_its_own_ratio(engine, tmp_path, report):
    parts = [("box30", {}), ("cyl8_through", {"cutting_mesh": "True", "mixing_ratio": "0:1"})]
    mix = scenes.run_mixengine(parts, tmp_path, MIX_PRINT)
    assert mix.rc == 0, mix.stderr
    inside, outside = region_shares(mix, "cyl8_through.stl")
    assert inside and outside
    assert all(share == pytest.approx(1.0) for _, _, share in inside)    # the region: filament B alone
    assert all(share == pytest.approx(0.0) for _, _, share in outside)   # the rest of the box: A alone
    assert max(r for r, _, _ in inside) < 8.1 and min(r for r, _, _ in outside) > 7.9  # where the cylinder is
    report(f"cutting-mesh mix: {len(inside)} moves inside r 8 mm all B, {len(outside)} outside all A")


def test_cutting_mesh_region_follows_its_own_gradient(engine, tmp_path):
    """The print is dual (A); the cylinder (z 5..25) cuts a region with a gradient over its own height."""
    parts = [("box30", {}), ("cyl8_in_box", {"cutting_mesh": "True", "mixing_mode": "gradient",
                                              "mixing_gradient_start": "0", "mixing_gradient_end": "100"})]
    mix = scenes.run_mixengine(parts, tmp_path, MIX_PRINT)
    assert mix.rc == 0, mix.stderr
    inside, outside = region_shares(mix, "cyl8_in_box.stl")
    assert all(share == pytest.approx(0.0) for _, _, share in outside)
    per_layer = {}  # z -> [e, b] of the region (single moves carry E and B rounded to 5 decimals)
    for m, _, _, z, e, b in eb_extrusions(mix.gcode):
        if m and m.endswith("cyl8_in_box.stl"):
            sums = per_layer.setdefault(round(z, 3), [0.0, 0.0])
            sums[0], sums[1] = sums[0] + e, sums[1] + b
    zs = sorted(per_layer)
    assert zs[0] == pytest.approx(5.2, abs=0.01) and zs[-1] == pytest.approx(25.0, abs=0.01)
    for z, (e, b) in per_layer.items():  # a layer's mix: the gradient at its top, in % of the cylinder's height
        assert b / (e + b) == pytest.approx((z - 5.0) / 20.0, abs=0.011), z


def test_a_model_mix_in_a_single_filament_print_is_named(engine, tmp_path):
    parts = [("box30", {}), ("cyl8_through", {"cutting_mesh": "True", "mixing_mode": "dual",
                                               "mixing_ratio": "0:1"})]
    mix = scenes.run_mixengine(parts, tmp_path)
    assert mix.rc == 0 and not re.search(r"^G1 .* B[\d.]+", mix.gcode.read_text(), re.M)
    assert "mixing_mode dual of a model is not used: mixing is off for the print" in mix.stderr


# ---- over Cura's socket: the same per-object settings in the Slice message ----------------------------
@pytest.mark.parametrize("name", ["infill_mesh", "anti_overhang", "support_mesh_drop_down", "cutting_mesh"])
def test_per_object_settings_over_the_socket_as_on_the_command_line(engine, tmp_path, name):
    """Cura's per-object settings (Object.settings of the Slice message, cura_frontend.py on the real libArcus)
    give the G-code the -l/-s command line gives."""
    from cura_socket import slice_over_socket
    from test_connect import without_volatile_lines
    import side_by_side as sbs
    parts, overrides = SCENES[name]
    cli = scenes.run_mixengine(parts, tmp_path, overrides)
    assert cli.rc == 0, cli.stderr
    global_values, extruder_values = sbs.resolve(overrides)
    objects = [{"name": str(scenes.part_path(p)), "stl": str(scenes.part_path(p)),
                "settings": {"extruder_nr": "0", **scenes.mesh_values(values)}} for p, values in parts]
    r = slice_over_socket(engine, tmp_path, global_values, {"0": extruder_values},
                          [{"settings": {}, "objects": objects}])
    assert r["exit_code"] == 0, r["stderr"]
    # On a mismatch, say what crossed the socket: a CI run once lacked three whole layers, never seen since.
    received = f"messages received {r['counts']}, socket errors {r['errors']}, engine: {r['stderr'][-600:]}"
    assert without_volatile_lines("".join(r["gcode_list"])) == without_volatile_lines(cli.gcode.read_text()), \
        received
