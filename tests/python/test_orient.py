"""`mixengine orient` and the slice hook, end to end (issue 7, seed 000).

The exact volumes MixEngine reports (CGAL) are checked against manifold3d, an independent boolean
library, and the FFT estimates against the exact values (within 2 % of the parts' volume)."""
import json
import struct
from pathlib import Path

import numpy as np
import pytest

import helpers


def write_box(path, origin, size):
    """A closed axis-aligned box as binary STL (outward facets)."""
    corners = [(origin[0] + size[0] * ((i >> 2) & 1), origin[1] + size[1] * ((i >> 1) & 1),
                origin[2] + size[2] * (i & 1)) for i in range(8)]
    quads = [(0, 2, 6, 4), (1, 5, 7, 3), (0, 4, 5, 1), (2, 3, 7, 6), (0, 1, 3, 2), (4, 6, 7, 5)]
    tris = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return write_stl(path, np.array(corners, dtype=float), np.array(tris))


def write_stl(path, vertices, faces):
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(faces)))
        for tri in faces:
            f.write(struct.pack("<3f", 0, 0, 0))
            for i in tri:
                f.write(struct.pack("<3f", *vertices[i]))
            f.write(b"\0\0")
    return path


def manifold_of(path):
    import manifold3d
    import trimesh
    mesh = trimesh.load(path, force="mesh")
    return manifold3d.Manifold(manifold3d.Mesh(vert_properties=np.asarray(mesh.vertices, dtype=np.float32),
                                               tri_verts=np.asarray(mesh.faces, dtype=np.uint32)))


def split_pair(source, out_dir):
    """Two closed parts of one closed model: below and above the middle of its height (manifold3d)."""
    import trimesh
    whole = manifold_of(source)
    lo, hi = whole.bounding_box()[2], whole.bounding_box()[5]
    below, above = whole.split_by_plane((0, 0, 1), (lo + hi) / 2)
    paths = []
    for name, part in (("lower", below), ("upper", above)):
        m = part.to_mesh()
        path = Path(out_dir) / f"{Path(source).stem}_{name}.stl"
        trimesh.Trimesh(m.vert_properties[:, :3], m.tri_verts).export(path)
        paths.append(path)
    return paths


def independent_v(path_a, path_b, shift):
    """vol(A ∩ (A + v)) + vol(B ∩ (B − v)) by manifold3d."""
    a, b = manifold_of(path_a), manifold_of(path_b)
    v = np.asarray(shift, dtype=float)
    return (a ^ a.translate(tuple(v))).volume() + (b ^ b.translate(tuple(-v))).volume()


def orient(engine, *args):
    proc = helpers.mixengine("orient", *args)
    assert proc.returncode == 0, proc.stderr
    return proc


@pytest.fixture
def boxes(tmp_path):
    return (write_box(tmp_path / "red.stl", (0, 0, 0), (60, 30, 30)),
            write_box(tmp_path / "blue.stl", (0, 30, 0), (60, 30, 30)))


def test_seed_case_on_the_10_degree_grid(engine, boxes, tmp_path):
    report = tmp_path / "grid.json"
    proc = orient(engine, *boxes, "--offset", "35,0", "--method", "grid", "--report", report)
    doc = json.loads(report.read_text())
    assert (doc["latitude_deg"], doc["longitude_deg"]) == (0, 60)
    assert doc["exact"] and doc["v_after_mm3"] == pytest.approx(0, abs=1e-6)
    assert doc["v_before_mm3"] == pytest.approx(45000, rel=1e-9)
    assert doc["map"]["values_mm3"][5] == pytest.approx(7174.5, abs=0.1)  # longitude 50: not zero
    assert "latitude 0.00°, longitude 60.00°" in proc.stdout


def test_sphere_search_writes_rotated_parts_and_plot(engine, boxes, tmp_path):
    import trimesh
    out = tmp_path / "out"
    proc = orient(engine, *boxes, "--offset", "35,0", "--report", tmp_path / "r.json", "--plot",
                  tmp_path / "v.png", "--write", out)
    doc = json.loads((tmp_path / "r.json").read_text())
    assert doc["v_after_mm3"] == pytest.approx(0, abs=1e-6)
    assert doc["picked_by"] in ("flat face", "low height", "low overhang")
    assert (tmp_path / "v.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    written = sorted(out.glob("*_oriented.stl"))
    assert len(written) == 2, proc.stdout
    meshes = [trimesh.load(p, force="mesh") for p in written]
    assert [m.volume for m in meshes] == pytest.approx([54000, 54000], rel=1e-6)
    assert min(m.bounds[0][2] for m in meshes) == pytest.approx(0, abs=1e-3)  # still on the bed
    # In the written (rotated) frame the nozzle offset is plain +x: no interference left.
    assert independent_v(*written, (35, 0, 0)) == pytest.approx(0, abs=1e-3)
    assert independent_v(*boxes, (35, 0, 0)) == pytest.approx(45000, rel=1e-6)


def check_pair(engine, a, b, offset, tmp_path, report):
    path = tmp_path / f"r{offset}.json"
    orient(engine, a, b, "--offset", f"{offset},0", "--report", path)
    doc = json.loads(path.read_text())
    assert doc["exact"], doc["warnings"]
    volume = sum(p["volume_mm3"] for p in doc["parts"])
    for when in ("before", "after"):
        exact, estimate = doc[f"v_{when}_mm3"], doc[f"v_{when}_estimate_mm3"]
        assert abs(exact - estimate) <= 0.02 * volume, (when, exact, estimate)
    assert doc["v_after_mm3"] <= doc["v_before_mm3"] + 1e-6
    shift = np.asarray(doc["direction"]) * offset
    assert independent_v(a, b, shift) == pytest.approx(doc["v_after_mm3"], rel=1e-3, abs=0.05)
    report(f"orient {Path(a).stem}+{Path(b).stem} d={offset} mm: V {doc['v_before_mm3']:.1f} -> "
           f"{doc['v_after_mm3']:.1f} mm³ (FFT {doc['v_after_estimate_mm3']:.1f}), parts {volume:.0f} mm³, "
           f"{doc['time_s']['total']:.2f} s")


@pytest.mark.parametrize("offset", [35, 22, 12])
def test_knot2_fft_agrees_with_exact(engine, corpus, tmp_path, report, offset):
    check_pair(engine, corpus("knot2_a"), corpus("knot2_b"), offset, tmp_path, report)


@pytest.mark.parametrize("offset", [35, 22, 12])
def test_armadillo_split_fft_agrees_with_exact(engine, corpus, tmp_path, report, offset):
    a, b = split_pair(corpus("armadillo52k"), tmp_path)
    check_pair(engine, a, b, offset, tmp_path, report)


def test_one_part_has_nothing_to_optimise(engine, boxes, tmp_path):
    proc = orient(engine, boxes[0], "--offset", "35,0", "--report", tmp_path / "r.json")
    assert "nothing to optimise" in proc.stdout
    assert json.loads((tmp_path / "r.json").read_text())["status"] == "nothing_to_optimise"


def test_open_part_warns_and_uses_voxels(engine, boxes, tmp_path):
    corners = np.array([(60 * ((i >> 2) & 1), 30 * ((i >> 1) & 1), 30 * (i & 1)) for i in range(8)], float)
    quads = [(0, 2, 6, 4), (0, 4, 5, 1), (2, 3, 7, 6), (0, 1, 3, 2), (4, 6, 7, 5)]  # no top
    open_box = write_stl(tmp_path / "open.stl", corners,
                         np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]))
    proc = orient(engine, open_box, boxes[1], "--offset", "35,0", "--report", tmp_path / "r.json")
    doc = json.loads((tmp_path / "r.json").read_text())
    assert not doc["exact"]
    assert "open" in proc.stderr and "voxel measure" in proc.stderr
    assert doc["v_before_mm3"] == pytest.approx(45000, rel=0.01)


def test_bad_input_is_one_line(engine, boxes):
    proc = helpers.mixengine("orient", *boxes)
    assert proc.returncode == 1 and "--offset" in proc.stderr
    proc = helpers.mixengine("orient", *boxes, "--offset", "35")
    assert proc.returncode == 1 and "X,Y" in proc.stderr
    proc = helpers.mixengine("orient", *boxes, "--offset", "0,0")
    assert proc.returncode == 1 and "zero" in proc.stderr


def test_machine_offset_from_extruder_trains(engine, boxes, tmp_path):
    """Ultimaker S5: the right nozzle is 22 mm from the left one."""
    orient(engine, *boxes, "-j", "ultimaker_s5", "--report", tmp_path / "r.json")
    assert json.loads((tmp_path / "r.json").read_text())["offset_mm"] == [22, 0, 0]


def test_slice_hook_rotates_before_placement(engine, tmp_path):
    """dual_orientation_optimize in `layers` (slice only): the long box turns so that the 35 mm
    offset crosses its 30 mm side; the footprint changes from 60 × 40 to 40 × 60."""
    a = write_box(tmp_path / "long.stl", (0, 0, 0), (60, 30, 30))
    b = write_box(tmp_path / "cube.stl", (0, 30, 0), (10, 10, 10))
    footprints = []
    for optimise in ("false", "true"):
        out = tmp_path / f"layers_{optimise}"
        proc = helpers.mixengine("layers", "-v", "-j", "ultimaker_s5", "-s", f"dual_orientation_optimize={optimise}",
                                 "-e1", "-s", "machine_nozzle_offset_x=35", "-e0", "-l", a, "-e1", "-l", b,
                                 "-o", out)
        assert proc.returncode == 0, proc.stderr
        points = np.array([p for ring in helpers.read_layers(out)[0]["outlines"] for p in ring])
        footprints.append(tuple(np.round(points.max(axis=0) - points.min(axis=0), 1)))
        if optimise == "true":
            assert "dual_orientation_optimize: latitude" in proc.stderr
            assert "-> 0.0 mm3 (exact)" in proc.stderr
    assert footprints[0] == (60.0, 40.0)
    assert footprints[1] == (40.0, 60.0)
