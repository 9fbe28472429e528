#!/usr/bin/env python3
"""Derives the test models from CACHE/raw (filled by fetch.sh) and writes CACHE/manifest.json.

    python derive.py CACHE_DIR [--force]

Recipes: shared/reference/test-corpus.md §5. Every derived model is a binary STL, centred in XY
with its minimum Z at 0. knot2_a / knot2_b are the two bodies of knot2 in knot2's own frame, so
loading both reproduces knot2. The broken/odd inputs of §4 are copied byte for byte into
CACHE/broken/. Existing outputs are kept unless --force is given.
"""
import json
import shutil
import sys
import time
from pathlib import Path

import numpy as np
import trimesh

RAW_BROKEN = {  # name in CACHE/broken -> file under CACHE/raw
    "Spider_binary.stl": "assimp/Spider_binary.stl",
    "sphereWithHole.stl": "assimp/sphereWithHole.stl",
    "HalfDonut.stl": "numpy-stl/HalfDonut.stl",
    "triamid.stl": "numpy-stl/triamid.stl",
    "empty.stl": "openscad/empty.stl",
    "issue1580-back-to-back.stl": "openscad/issue1580-back-to-back.stl",
    "issue1580-back-to-back2.stl": "openscad/issue1580-back-to-back2.stl",
    "issue1580-zero-area-triangle.stl": "openscad/issue1580-zero-area-triangle.stl",
    "incorrectFaceCounter.bin.stl": "stl-models/incorrectFaceCounter.bin.stl",
    "wrongHeader.bin.stl": "stl-models/wrongHeader.bin.stl",
    "faceless.ascii.stl": "stl-models/faceless.ascii.stl",
}
ASCII_BROKEN = ["fourVertices", "missingEndsolid", "missingFace", "missingNormal", "notANumberNormal",
                "quad", "singleFace", "solidNameMismatch", "twoVertices", "wrongNormal", "wrongNormals"]
RAW_BROKEN.update({f"{n}.ascii.stl": f"stl-models/{n}.ascii.stl" for n in ASCII_BROKEN})


def load(path):
    return trimesh.load(path, force="mesh", process=True)


def placed(mesh, offset=None):
    """Centre in XY and put min Z at 0 (or apply a given offset); returns (mesh, offset)."""
    if offset is None:
        lo, hi = mesh.bounds
        offset = np.array([-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]])
    mesh = mesh.copy()
    mesh.apply_translation(offset)
    return mesh, offset


def scaled(path, factor):
    mesh = load(path)
    mesh.apply_scale(factor)
    return mesh


def armadillo(raw, passes):
    mesh = scaled(raw / "cgal/armadillo.off", 0.5)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0]))  # Y up -> Z up
    for _ in range(passes):
        mesh = mesh.subdivide_loop(iterations=1)
    return mesh


def cylinder(segments=1000, radius=10.0, height=10.0):
    """A closed prism over a regular polygon: 4 * segments triangles."""
    t = np.arange(segments) * 2 * np.pi / segments
    ring = np.column_stack([radius * np.cos(t), radius * np.sin(t)])
    verts = np.vstack([np.column_stack([ring, np.zeros(segments)]),
                       np.column_stack([ring, np.full(segments, height)]),
                       [[0, 0, 0], [0, 0, height]]])
    i = np.arange(segments)
    j = (i + 1) % segments
    top, bot_c, top_c = segments, 2 * segments, 2 * segments + 1
    faces = np.vstack([np.column_stack([i, j, j + top]), np.column_stack([i, j + top, i + top]),
                       np.column_stack([np.full(segments, bot_c), j, i]),
                       np.column_stack([np.full(segments, top_c), i + top, j + top])])
    return trimesh.Trimesh(verts, faces, process=True)


def knot_parts(raw):
    mesh = scaled(raw / "cgal/knot2.off", 100)
    whole, offset = placed(mesh)
    bodies = sorted(mesh.split(only_watertight=False), key=lambda b: tuple(b.centroid))
    return [whole] + [placed(b, offset)[0] for b in bodies]


def recipes(raw):
    """name -> (raw files needed, builder returning a mesh or list of meshes)."""
    return {
        "cube20": (["prusa-slicer/box.stl"], lambda: scaled(raw / "prusa-slicer/box.stl", 0.8)),
        "bunny_lowpoly": (["prusa-slicer/bunny.stl"], lambda: load(raw / "prusa-slicer/bunny.stl")),
        "cylinder1000": ([], cylinder),
        "armadillo52k": (["cgal/armadillo.off"], lambda: armadillo(raw, 0)),
        "armadillo208k": (["cgal/armadillo.off"], lambda: armadillo(raw, 1)),
        "armadillo832k": (["cgal/armadillo.off"], lambda: armadillo(raw, 2)),
        "dragon20k": (["cgal/ChineseDragon-10kv.off"], lambda: load(raw / "cgal/ChineseDragon-10kv.off")),
        "bunny69k": (["stl-models/bunny.bin.stl"], lambda: scaled(raw / "stl-models/bunny.bin.stl", 500)),
        "knot2": (["cgal/knot2.off"], lambda: knot_parts(raw)),
        "rear_case": (["numpy-stl/rear_case.stl"], lambda: load(raw / "numpy-stl/rear_case.stl")),
    }


def export(mesh, path):
    tmp = path.with_suffix(".tmp")
    mesh.export(tmp, file_type="stl")  # binary STL
    tmp.replace(path)


def describe(path, cache, old):
    """Manifest entry for one file; reuses the old entry while size and mtime are unchanged."""
    rel, stat = str(path.relative_to(cache)), path.stat()
    entry = {"file": rel, "bytes": stat.st_size, "mtime": int(stat.st_mtime)}
    if old.get(rel, {}).get("mtime") == entry["mtime"] and old[rel].get("bytes") == entry["bytes"]:
        return old[rel]
    try:
        mesh = load(path)
        entry.update(triangles=int(len(mesh.faces)), watertight=bool(mesh.is_watertight),
                     bounds=[[round(float(v), 4) for v in row] for row in mesh.bounds])
    except Exception as e:  # broken inputs: record why trimesh could not read them
        entry.update(triangles=None, bounds=None, load_error=f"{type(e).__name__}: {e}"[:200])
    return entry


def main():
    cache = Path(sys.argv[1]).resolve()
    force = "--force" in sys.argv
    raw = cache / "raw"
    missing = []
    for name, (needs, build) in recipes(raw).items():
        out = cache / f"{name}.stl"
        if out.exists() and not force:
            continue
        if not all((raw / n).exists() for n in needs):
            missing.append(name)
            continue
        t0 = time.monotonic()
        result = build()
        meshes = result if isinstance(result, list) else [placed(result)[0]]
        export(meshes[0], out)
        for suffix, part in zip("ab", meshes[1:]):
            export(part, cache / f"{name}_{suffix}.stl")
        print(f"derive.py: {name}.stl ({len(meshes[0].faces)} triangles, {time.monotonic() - t0:.1f} s)")
    (cache / "broken").mkdir(exist_ok=True)
    for name, src in RAW_BROKEN.items():
        if (raw / src).exists() and (force or not (cache / "broken" / name).exists()):
            shutil.copyfile(raw / src, cache / "broken" / name)
        elif not (raw / src).exists():
            missing.append(f"broken/{name}")
    try:
        prev = json.loads((cache / "manifest.json").read_text())
        old = {e["file"]: e for group in ("models", "broken") for e in prev[group].values()}
    except (OSError, ValueError, KeyError):
        old = {}
    manifest = {"models": {p.stem: describe(p, cache, old) for p in sorted(cache.glob("*.stl"))},
                "broken": {p.name: describe(p, cache, old) for p in sorted((cache / "broken").glob("*.stl"))},
                "missing": missing}
    (cache / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    if missing:
        print(f"derive.py: missing sources for: {', '.join(missing)}", file=sys.stderr)
    print(f"derive.py: manifest.json: {len(manifest['models'])} models, {len(manifest['broken'])} broken files")


if __name__ == "__main__":
    main()
