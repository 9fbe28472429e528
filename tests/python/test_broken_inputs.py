"""Issue 9 (reliability): every deliberately broken corpus file (test-corpus.md §4) and generated broken
inputs, each with one defined outcome. Cura repairs what it can, so MixEngine does too; what cannot be
repaired is one clear error; nothing ever crashes, hangs or leaves a file behind.

Outcomes (checked for every case, with fdmprinter's defaults, -l MODEL -o OUT/model.gcode):
  error   exit 1, exactly one stderr line "mixengine: error: ..." naming the file, and the output folder
          empty afterwards (no G-code, no "<out>.tmp-<pid>" file).
  sliced  exit 0 and a valid G-code: gcodeparser reads it, every motion value is a finite number, and
          the number of ;LAYER: lines equals ;LAYER_COUNT: >= 1; nothing but the G-code in the folder.
  warned  as sliced, and stderr has a "[warning]" line (the repair is reported).
  empty   nothing lies at a slice height above the build plate: exit 0 as CuraEngine 4.13 (test_oracle.py
          holds MixEngine to CuraEngine's exit code), ;LAYER_COUNT:0, and a "[warning]" saying
          "nothing to print" so the user learns why the file prints nothing.
Always: no crash signal, no exit code other than 0 or 1, and no hang (subprocess timeout TIMEOUT_S).

| case                              | defect                                          | outcome |
|-----------------------------------|-------------------------------------------------|---------|
| corpus empty.stl, zero_bytes.stl  | 0 bytes                                         | error   |
| header_only.stl                   | binary STL header with 0 triangles              | error   |
| short_header.stl                  | 40 bytes, shorter than a binary STL header      | error   |
| truncated.stl                     | last binary record cut short                    | error   |
| corpus HalfDonut.stl              | one trailing byte after the records             | warned  |
| corpus incorrectFaceCounter.bin   | header says 66 faces, file holds 4              | warned  |
| counter_too_low.stl               | header says 2 faces, file holds 12              | warned  |
| corpus wrongHeader.bin.stl        | binary file starting with "solid"               | sliced  |
| corpus notANumberNormal / missingNormal | NaN or missing normals (normals unused)   | warned  |
| nan_normals.stl                   | every binary normal NaN                         | warned  |
| corpus missingEndsolid            | ASCII without endsolid                          | warned  |
| corpus solidNameMismatch, wrongNormal(s) | harmless ASCII oddities                  | sliced  |
| corpus quad / fourVertices / twoVertices | ASCII facets with 4 or 2 vertices        | error   |
| corpus faceless.ascii.stl, ascii_garbage | no facets / not STL text                 | error   |
| corpus triamid.stl, flipped_faces.stl | inconsistent winding (slicing ignores it)   | sliced  |
| corpus Spider_binary.stl          | non-manifold, open, 56 degenerate facets        | warned  |
| corpus issue1580-zero-area-triangle, zero_area_facets.stl | zero-area facets (dropped) | sliced  |
| corpus sphereWithHole, missingFace, open_side.stl | open meshes (open pieces left out) | warned |
| no_bottom.stl                     | open box whose every section is a closed square | sliced  |
| all_degenerate.stl                | every facet has zero area                       | error   |
| nan_vertex.stl, inf_vertex.stl, nan_vertex.ascii.stl, obj_nan_vertex.obj | non-finite vertex | error |
| huge_coordinates.stl              | vertices at 1e30 mm                             | error   |
| far_too_large.stl                 | a 500 m cube: > 10x the 100 mm build volume     | error   |
| larger_than_volume.stl            | a 150 mm cube in the 100 mm build volume        | warned  |
| partly_below_bed.stl              | a cube from z -5 to 5 mm                        | warned  |
| corpus issue1580-back-to-back(2), below_bed.stl | the model lies below z = 0        | empty   |
| corpus singleFace, flat_triangle, floating_triangle | one flat triangle at z 0 or 5 mm | empty  |
| directory.stl                     | a directory, not a file                         | error   |
| unreadable.stl                    | no read permission (run as nobody when root)    | error   |
| missing.stl                       | no such file                                    | error   |
| model.ply                         | unsupported extension                           | error   |
| obj_index_out_of_range, obj_index_zero, obj_bad_index, obj_two_corners, obj_no_faces | bad OBJ | error |
| obj_negative_index.obj            | valid relative indices (control)                | sliced  |
| random_bytes.3mf, zip_garbage.3mf, truncated.3mf, index_out_of_range.3mf | broken 3MF | error   |
| cube.3mf                          | a valid 3MF (control)                           | sliced  |
"""
import io
import os
import shutil
import struct
import subprocess
import tempfile
import zipfile
from pathlib import Path

import pytest

import gcode_checks
import helpers

TIMEOUT_S = 120


# ---------------------------------------------------------------------------------------------------------
# Generated models

def cube_triangles(size=10.0, offset=(0.0, 0.0, 0.0)):
    """The 12 triangles of an axis-aligned cube, outward winding."""
    ox, oy, oz = offset
    s = size
    p = [(ox + x, oy + y, oz + z) for x, y, z in
         [(0, 0, 0), (s, 0, 0), (s, s, 0), (0, s, 0), (0, 0, s), (s, 0, s), (s, s, s), (0, s, s)]]
    faces = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
             (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    return [[p[i] for i in f] for f in faces]


def binary_stl(triangles, count=None, normal=(0.0, 0.0, 0.0)):
    data = bytearray(b"generated by test_broken_inputs".ljust(80, b" "))
    data += struct.pack("<I", len(triangles) if count is None else count)
    for t in triangles:
        data += struct.pack("<3f", *normal)
        for v in t:
            data += struct.pack("<3f", *v)
        data += b"\0\0"
    return bytes(data)


def ascii_stl(triangles, coordinate_text=None):
    lines = ["solid generated"]
    for i, t in enumerate(triangles):
        lines += ["  facet normal 0 0 0", "    outer loop"]
        for k, v in enumerate(t):
            text = " ".join(repr(c) for c in v)
            if coordinate_text and i == 0 and k == 1:
                text = coordinate_text
            lines.append(f"      vertex {text}")
        lines += ["    endloop", "  endfacet"]
    return ("\n".join(lines + ["endsolid generated"]) + "\n").encode()


def cube_obj(faces_text):
    verts = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (0, 0, 10), (10, 0, 10), (10, 10, 10), (0, 10, 10)]
    return ("".join(f"v {x} {y} {z}\n" for x, y, z in verts) + faces_text).encode()


CUBE_OBJ_FACES = "".join(f"f {a} {b} {c}\n" for a, b, c in
                         [(1, 3, 2), (1, 4, 3), (5, 6, 7), (5, 7, 8), (1, 2, 6), (1, 6, 5),
                          (2, 3, 7), (2, 7, 6), (3, 4, 8), (3, 8, 7), (4, 1, 5), (4, 5, 8)])


def three_mf(triangle_indices=None):
    """A minimal 3MF package (OPC zip) holding the 10 mm cube as one mesh object and one build item."""
    verts = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (0, 0, 10), (10, 0, 10), (10, 10, 10), (0, 10, 10)]
    tris = triangle_indices or [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
                                (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">'
             '<resources><object id="1" type="model" name="cube"><mesh><vertices>'
             + "".join(f'<vertex x="{x}" y="{y}" z="{z}"/>' for x, y, z in verts)
             + "</vertices><triangles>"
             + "".join(f'<triangle v1="{a}" v2="{b}" v3="{c}"/>' for a, b, c in tris)
             + '</triangles></mesh></object></resources><build><item objectid="1"/></build></model>')
    content_types = ('<?xml version="1.0" encoding="UTF-8"?>\n'
                     '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
                     '<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
                     '<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>'
                     '</Types>')
    rels = ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
            '<Relationship Target="/3D/3dmodel.model" Id="rel0" '
            'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>')
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("[Content_Types].xml", content_types)
        z.writestr("_rels/.rels", rels)
        z.writestr("3D/3dmodel.model", model)
    return buffer.getvalue()


def zip_with(name, text):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as z:
        z.writestr(name, text)
    return buffer.getvalue()


def _flipped(triangles):
    return [t if i % 2 else [t[0], t[2], t[1]] for i, t in enumerate(triangles)]


def _with_zero_area(triangles):
    return triangles + [[(0, 0, 0), (5, 0, 0), (10, 0, 0)], [(1, 1, 1), (1, 1, 1), (2, 2, 2)]]


NAN, INF = float("nan"), float("inf")
CUBE = cube_triangles()
GENERATED = {  # file name -> bytes (or a callable making the file in a folder)
    "zero_bytes.stl": b"",
    "header_only.stl": binary_stl([]),
    "short_header.stl": b"solid but only forty bytes long.........",
    "truncated.stl": binary_stl(CUBE)[:-20],
    "counter_too_low.stl": binary_stl(CUBE, count=2),
    "nan_normals.stl": binary_stl(CUBE, normal=(NAN, NAN, NAN)),
    "ascii_garbage.stl": b"solid nothing\nthis is not an STL file\n",
    "flipped_faces.stl": binary_stl(_flipped(CUBE)),
    "zero_area_facets.stl": binary_stl(_with_zero_area(CUBE)),
    "no_bottom.stl": binary_stl(CUBE[2:]),  # open, but every section is a closed square
    "open_side.stl": binary_stl(CUBE[:4] + CUBE[6:]),  # the y = 0 side missing: open sections
    "all_degenerate.stl": binary_stl([[(0, 0, 0), (5, 5, 5), (10, 10, 10)]] * 3),
    "nan_vertex.stl": binary_stl(CUBE[:-1] + [[(0, 0, 0), (NAN, 1, 1), (1, 0, 1)]]),
    "inf_vertex.stl": binary_stl(CUBE[:-1] + [[(0, 0, 0), (INF, 1, 1), (1, 0, 1)]]),
    "nan_vertex.ascii.stl": ascii_stl(CUBE, coordinate_text="nan 1 1"),
    "huge_coordinates.stl": binary_stl(cube_triangles(1e30)),
    "far_too_large.stl": binary_stl(cube_triangles(5e5)),
    "larger_than_volume.stl": binary_stl(cube_triangles(150.0, (-75.0, -75.0, 0.0))),
    "partly_below_bed.stl": binary_stl(cube_triangles(10.0, (0.0, 0.0, -5.0))),
    "below_bed.stl": binary_stl(cube_triangles(10.0, (0.0, 0.0, -20.0))),
    "flat_triangle.stl": binary_stl([[(0, 0, 0), (10, 0, 0), (0, 10, 0)]]),
    "floating_triangle.stl": binary_stl([[(0, 0, 5), (10, 0, 5), (0, 10, 5)]]),
    "model.ply": b"ply\nformat ascii 1.0\nend_header\n",
    "obj_index_out_of_range.obj": cube_obj(CUBE_OBJ_FACES + "f 1 2 9\n"),
    "obj_index_zero.obj": cube_obj(CUBE_OBJ_FACES + "f 0 1 2\n"),
    "obj_bad_index.obj": cube_obj(CUBE_OBJ_FACES + "f 1 two 3\n"),
    "obj_two_corners.obj": cube_obj(CUBE_OBJ_FACES + "f 1 2\n"),
    "obj_no_faces.obj": cube_obj(""),
    "obj_nan_vertex.obj": cube_obj(CUBE_OBJ_FACES + "v nan 0 0\n"),
    "obj_negative_index.obj": cube_obj(CUBE_OBJ_FACES.replace("f 1 3 2\n", "f -8 -6 -7\n")),
    "random_bytes.3mf": bytes((i * 7919 + 13) % 251 for i in range(4000)),
    "zip_garbage.3mf": zip_with("3D/3dmodel.model", "<model><garbage"),
    "truncated.3mf": three_mf()[:300],
    "index_out_of_range.3mf": three_mf([(0, 1, 2), (0, 2, 99)]),
    "cube.3mf": three_mf(),
    "directory.stl": lambda path: path.mkdir(),
    "missing.stl": lambda path: None,
}

CORPUS_OUTCOMES = {
    "empty.stl": "error", "faceless.ascii.stl": "error", "quad.ascii.stl": "error",
    "fourVertices.ascii.stl": "error", "twoVertices.ascii.stl": "error",
    "HalfDonut.stl": "warned", "incorrectFaceCounter.bin.stl": "warned", "notANumberNormal.ascii.stl": "warned",
    "missingNormal.ascii.stl": "warned", "missingEndsolid.ascii.stl": "warned", "Spider_binary.stl": "warned",
    "sphereWithHole.stl": "warned", "missingFace.ascii.stl": "warned",
    "wrongHeader.bin.stl": "sliced", "solidNameMismatch.ascii.stl": "sliced", "wrongNormal.ascii.stl": "sliced",
    "wrongNormals.ascii.stl": "sliced", "triamid.stl": "sliced", "issue1580-zero-area-triangle.stl": "sliced",
    "issue1580-back-to-back.stl": "empty", "issue1580-back-to-back2.stl": "empty", "singleFace.ascii.stl": "empty",
}
GENERATED_OUTCOMES = {
    "zero_bytes.stl": "error", "header_only.stl": "error", "short_header.stl": "error", "truncated.stl": "error",
    "counter_too_low.stl": "warned", "nan_normals.stl": "warned", "ascii_garbage.stl": "error",
    "flipped_faces.stl": "sliced", "zero_area_facets.stl": "sliced", "no_bottom.stl": "sliced",
    "open_side.stl": "warned",
    "all_degenerate.stl": "error", "nan_vertex.stl": "error", "inf_vertex.stl": "error",
    "nan_vertex.ascii.stl": "error", "huge_coordinates.stl": "error", "far_too_large.stl": "error",
    "larger_than_volume.stl": "warned", "partly_below_bed.stl": "warned", "below_bed.stl": "empty",
    "flat_triangle.stl": "empty", "floating_triangle.stl": "empty", "model.ply": "error",
    "obj_index_out_of_range.obj": "error", "obj_index_zero.obj": "error", "obj_bad_index.obj": "error",
    "obj_two_corners.obj": "error", "obj_no_faces.obj": "error", "obj_nan_vertex.obj": "error",
    "obj_negative_index.obj": "sliced", "random_bytes.3mf": "error", "zip_garbage.3mf": "error",
    "truncated.3mf": "error", "index_out_of_range.3mf": "error", "cube.3mf": "sliced",
    "directory.stl": "error", "missing.stl": "error",
}
assert set(GENERATED_OUTCOMES) == set(GENERATED)


# ---------------------------------------------------------------------------------------------------------
# Running and judging

def make_generated(name, folder):
    path = folder / name
    content = GENERATED[name]
    if callable(content):
        content(path)
    else:
        path.write_bytes(content)
    return path


def run_slice(model, out_dir, as_user=None):
    """Slices `model` into out_dir/model.gcode; returns the CompletedProcess. A hang fails the test."""
    out = out_dir / "model.gcode"
    cmd = [str(helpers.BIN), "slice", "-l", str(model), "-o", str(out)]
    if as_user is not None:
        cmd = ["setpriv", f"--reuid={as_user}", f"--regid={as_user}", "--clear-groups"] + cmd
    try:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        pytest.fail(f"mixengine did not finish within {TIMEOUT_S} s on {model.name} (hang)")


def judge(proc, model, out_dir, outcome):
    out = out_dir / "model.gcode"
    lines = helpers.stderr_lines(proc)
    where = f"{model.name}: rc {proc.returncode}, stderr: {proc.stderr[-800:]!r}"
    assert proc.returncode >= 0, f"killed by signal {-proc.returncode} — {where}"
    assert proc.returncode in (0, 1), f"exit code must be 0 or 1 — {where}"
    left = sorted(p.name for p in out_dir.iterdir())
    if outcome == "error":
        assert proc.returncode == 1, f"expected an error — {where}"
        assert len(lines) == 1, f"expected exactly one stderr line — {where}"
        assert lines[0].startswith("mixengine: error: "), where
        assert model.name in lines[0], f"the error does not name the file — {where}"
        assert left == [], f"files left in the output folder after an error: {left}"
        return
    assert proc.returncode == 0, f"expected a slice — {where}"
    assert left == ["model.gcode"], f"output folder holds {left}, expected only model.gcode"
    check = gcode_checks.check_gcode(out)
    assert not check.problems, f"{model.name}: invalid G-code: {check.problems}"
    warnings = [line for line in lines if line.startswith("[warning]")]
    if outcome == "empty":
        assert check.layer_count == 0, f"{model.name}: ;LAYER_COUNT:{check.layer_count}, expected 0"
        assert any("nothing to print" in w for w in warnings), f"no 'nothing to print' warning — {where}"
        return
    assert check.layer_count >= 1, f"{model.name}: ;LAYER_COUNT:{check.layer_count}"
    if outcome == "warned":
        assert warnings, f"expected a [warning] line — {where}"


@pytest.fixture
def folders(tmp_path):
    models, out = tmp_path / "in", tmp_path / "out"
    models.mkdir()
    out.mkdir()
    return models, out


@pytest.mark.parametrize("name", sorted(CORPUS_OUTCOMES))
def test_corpus_broken_file(engine, corpus, folders, name):
    models, out = folders
    model = models / name
    shutil.copyfile(corpus(f"broken/{name}"), model)  # a copy: the error must name exactly this path
    judge(run_slice(model, out), model, out, CORPUS_OUTCOMES[name])


@pytest.mark.parametrize("name", sorted(GENERATED_OUTCOMES))
def test_generated_broken_input(engine, folders, name):
    models, out = folders
    model = make_generated(name, models)
    if name == "missing.stl":
        assert not model.exists()
    judge(run_slice(model, out), model, out, GENERATED_OUTCOMES[name])


def test_unreadable_file(engine):
    """A file without read permission. root reads everything, so as root the engine runs as 'nobody'
    (setpriv) in a folder everyone may write."""
    as_user = None
    if os.geteuid() == 0:
        if shutil.which("setpriv") is None:
            pytest.skip("running as root without setpriv: cannot make a file unreadable")
        as_user = 65534
    folder = Path(tempfile.mkdtemp(prefix="mixengine-unreadable-"))
    try:
        folder.chmod(0o777)
        models, out = folder / "in", folder / "out"
        models.mkdir()
        out.mkdir()
        out.chmod(0o777)
        model = models / "unreadable.stl"
        model.write_bytes(binary_stl(CUBE))
        model.chmod(0)
        proc = run_slice(model, out, as_user)
        judge(proc, model, out, "error")
        assert "ermission" in proc.stderr, proc.stderr
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def test_error_leaves_an_existing_output_untouched(engine, folders):
    """An error must not replace or truncate a G-code already at the -o path."""
    models, out = folders
    target = out / "model.gcode"
    target.write_text("; previous result\n")
    model = make_generated("truncated.stl", models)
    proc = run_slice(model, out)
    assert proc.returncode == 1, proc.stderr
    assert target.read_text() == "; previous result\n"
    assert sorted(p.name for p in out.iterdir()) == ["model.gcode"]
