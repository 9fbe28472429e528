"""The yardsticks themselves: gcode_model.py reads E the way firmware does, and print_quality.py's rasters
and metrics give known answers on synthetic G-code (no engine involved)."""
import math

import numpy as np
import pytest

import gcode_model
import print_quality as pq

FILAMENT = 1.75
AREA = math.pi * (FILAMENT / 2) ** 2


def write(tmp_path, text, name="t.gcode"):
    path = tmp_path / name
    path.write_text(text)
    return path


def e_for(length, width=0.4, height=0.2):
    return length * width * height / AREA


ABSOLUTE = f"""\
;FLAVOR:Marlin
;TIME:100
M82
G92 E0
G1 F200 E3
G92 E0
;LAYER_COUNT:1
;LAYER:0
G0 X0 Y0 Z0.2
;TYPE:WALL-OUTER
G1 X10 Y0 E{e_for(10):.5f}
G1 E{e_for(10) - 5:.5f}
G0 X10 Y10
G1 E{e_for(10):.5f}
G1 X0 Y10 E{2 * e_for(10):.5f}
G92 E0
;TYPE:SKIRT
G1 X0 Y20 E{e_for(10):.5f}
G91
G1 E-2
G1 X5 Y5
G90
"""

RELATIVE = f"""\
;FLAVOR:Marlin
M83
G1 F200 E3
;LAYER_COUNT:1
;LAYER:0
G0 X0 Y0 Z0.2
;TYPE:WALL-OUTER
G1 X10 Y0 E{e_for(10):.5f}
G1 E-5
G0 X10 Y10
G1 E5
G1 X0 Y10 E{e_for(10):.5f}
;TYPE:SKIRT
G1 X0 Y20 E{e_for(10):.5f}
G1 E-2
"""


@pytest.mark.parametrize("text", [ABSOLUTE, RELATIVE], ids=["absolute", "relative"])
def test_reader_segments_exclude_retraction_and_prime(tmp_path, text):
    m = gcode_model.read(write(tmp_path, text))
    layer = m.layers[0]
    assert m.layer_count == 1 and m.header["FLAVOR"] == "Marlin"
    assert len(layer.e) == 3, "three extruding moves; the retract/prime pair is not a segment"
    assert [m.features[f] for f in layer.feature] == ["WALL-OUTER", "WALL-OUTER", "SKIRT"]
    np.testing.assert_allclose(layer.e, [e_for(10)] * 3, atol=1e-5)
    assert (layer.x0[1], layer.y0[1], layer.x1[1], layer.y1[1]) == (10, 10, 0, 10)
    assert layer.z_mm == pytest.approx(0.2) and layer.thickness_mm == pytest.approx(0.2)
    np.testing.assert_allclose(gcode_model.segment_widths_mm(m, layer, FILAMENT), 0.4, rtol=1e-4)
    assert m.net_e == pytest.approx(3 + 3 * e_for(10) - 2, abs=1e-4)  # start prime + lines - end retraction
    assert m.layer_extruded_e == pytest.approx(3 * e_for(10), abs=1e-4)


def test_reader_bounds_absolute_e_and_refuses_arcs(tmp_path):
    m = gcode_model.read(write(tmp_path, ABSOLUTE))
    assert m.max_abs_e_value == pytest.approx(5 - e_for(10), abs=1e-5)  # the retraction to E -4.667
    with pytest.raises(gcode_model.GcodeError):
        gcode_model.read(write(tmp_path, "G1 X1 Y1 E1\nG2 X2 Y2 I1 J0 E2\n", "arc.gcode"))


def test_volumetric_flavor_reads_e_as_volume(tmp_path):
    text = ";FLAVOR:UltiGCode\nM82\n;LAYER:0\nG0 X0 Y0 Z0.2\nG1 X10 Y0 E0.8\n"
    m = gcode_model.read(write(tmp_path, text))
    assert m.volumetric
    np.testing.assert_allclose(gcode_model.segment_widths_mm(m, m.layers[0], FILAMENT), 0.4)


def test_capsule_raster_area_is_exact_to_half_a_percent():
    rng = np.random.default_rng(5)
    import shapely
    n = 300
    x0, y0 = rng.uniform(0, 30, n), rng.uniform(0, 30, n)
    angle, length = rng.uniform(0, 2 * math.pi, n), rng.uniform(0, 8, n)
    x1, y1 = x0 + length * np.cos(angle), y0 + length * np.sin(angle)
    r = rng.uniform(0.15, 0.3, n)
    exact = shapely.union_all([shapely.LineString([(a, b), (c, d)]).buffer(w, quad_segs=64)
                               for a, b, c, d, w in zip(x0, y0, x1, y1, r)]).area
    grid = pq.Grid.around(-10, -10, 40, 40, pq.GRID_MM)
    raster = pq.rasterise_capsules(grid, x0, y0, x1, y1, r).sum() * pq.GRID_MM ** 2
    assert raster == pytest.approx(exact, rel=0.005)
    single = pq.rasterise_capsules(grid, np.array([0.0]), np.array([0.0]), np.array([10.0]), np.array([0.0]),
                                   np.array([0.2])).sum() * pq.GRID_MM ** 2
    assert single == pytest.approx(math.pi * 0.04 + 0.4 * 10, rel=0.01)


def test_polygon_raster_honours_holes():
    import shapely
    shape = shapely.Point(0, 0).buffer(12, quad_segs=64).difference(shapely.Point(1, 0).buffer(6, quad_segs=64))
    grid = pq.Grid.around(-13, -13, 13, 13, pq.GRID_MM)
    mask = pq.rasterise_polygons(grid, shape)
    assert mask.sum() * pq.GRID_MM ** 2 == pytest.approx(shape.area, rel=0.002)
    assert not mask[round((0 - grid.oy) / grid.g), round((1 - grid.ox) / grid.g)], "the hole's centre is empty"


def square_layers(inset, lines=25, size=10.0, width=0.4, layers=3):
    """G-code of `layers` layers, each `lines` concentric square loops of `width`, the outermost centred
    `inset` mm inside a size x size square centred on (50, 50)."""
    out = [";FLAVOR:Marlin", "M82", f";LAYER_COUNT:{layers}"]
    e = 0.0
    for n in range(layers):
        out += [f";LAYER:{n}", f"G0 X40 Y40 Z{0.2 * (n + 1):.3f}", "G92 E0", ";TYPE:WALL-OUTER"]
        e = 0.0
        for k in range(lines):
            half = size / 2 - inset - k * width
            if half <= 0:
                break
            corners = [(50 - half, 50 - half), (50 + half, 50 - half), (50 + half, 50 + half),
                       (50 - half, 50 + half), (50 - half, 50 - half)]
            out.append(f"G0 X{corners[0][0]:.3f} Y{corners[0][1]:.3f}")
            for x, y in corners[1:]:
                e += e_for(2 * half, width)
                out.append(f"G1 X{x:.3f} Y{y:.3f} E{e:.5f}")
    return "\n".join(out) + "\n"


@pytest.fixture(scope="module")
def cube_stl(tmp_path_factory):
    import trimesh
    mesh = trimesh.creation.box(extents=[10, 10, 0.6])
    mesh.apply_translation([0, 0, 0.3])
    path = tmp_path_factory.mktemp("mesh") / "slab.stl"
    mesh.export(path)
    return path


def test_solid_square_covers_its_section(tmp_path, cube_stl):
    m = gcode_model.read(write(tmp_path, square_layers(inset=0.2)))
    q = pq.measure(m, cube_stl, (50, 50), FILAMENT)
    assert [layer.index for layer in q.layers] == [0, 1, 2]
    assert q.total("section_mm2") == pytest.approx(300, rel=0.002)
    assert q.coverage > 0.99 and q.outside_ratio == 0.0


def test_outer_wall_without_inset_counts_as_outside(tmp_path, cube_stl):
    """An outer wall centred on the outline overshoots by half a line (0.2 mm); the 0.1 mm tolerance lets half
    of that through: 4 x 10 mm x 0.1 mm = 4 mm² per 100 mm² layer."""
    m = gcode_model.read(write(tmp_path, square_layers(inset=0.0)))
    q = pq.measure(m, cube_stl, (50, 50), FILAMENT)
    assert q.outside_ratio == pytest.approx(0.04, rel=0.1)


def test_missing_lines_lower_coverage(tmp_path, cube_stl):
    m = gcode_model.read(write(tmp_path, square_layers(inset=0.2, lines=2)))
    q = pq.measure(m, cube_stl, (50, 50), FILAMENT)
    # two loops of 0.4 mm: 4 x (9.6 + 8.8) x 0.4 = 29.44 mm² of 100 (corners counted once)
    assert q.coverage == pytest.approx(0.2944, abs=0.005)
