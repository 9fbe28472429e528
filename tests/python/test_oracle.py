"""CuraEngine 4.13 (/usr/bin/CuraEngine) as the oracle: the same arguments give the same exit code and
the same ;LAYER_COUNT:.

CuraEngine needs up to ~45 s per large model at fdmprinter's 0.1 mm layers, so its results are cached in
CORPUS/oracle-cache.json, keyed by CuraEngine's size and mtime, the arguments, and each model's name, size and
mtime. MixEngine itself is always run.
"""
import hashlib
import json
import os

import pytest

import helpers

FDM = ["-j", helpers.FDMPRINTER]
MODELS = [("cube20",), ("bunny_lowpoly",), ("cylinder1000",), ("knot2",), ("knot2_a", "knot2_b"),
          ("dragon20k",), ("armadillo52k",), ("bunny69k",)]
SETTINGS = {  # extra arguments placed before -l (mesh_rotation_matrix is read when -l loads a file)
    "layers_0.2": ["-s", "layer_height=0.2", "-s", "layer_height_0=0.2"],
    "layers_0.15_first_0.27": ["-s", "layer_height=0.15", "-s", "layer_height_0=0.27"],
    "scaled_1.5": ["-s", "mesh_rotation_matrix=[[1.5,0,0],[0,1.5,0],[0,0,1.5]]"],
    "x_to_z": ["-s", "mesh_rotation_matrix=[[0,0,1],[0,1,0],[-1,0,0]]"],
}
# The broken files whose outcome is well defined (test_cli.py): compared one to one.
# HalfDonut (z_max exactly 3.0 mm): its plane at 2.95 mm cuts only a sliver too thin for a wall, and both engines
# leave that empty layer out (27 layers; issue 28 found the cause, it was MixEngine's 28th).
BROKEN = ["empty.stl", "faceless.ascii.stl", "HalfDonut.stl", "wrongHeader.bin.stl",
          "incorrectFaceCounter.bin.stl", "Spider_binary.stl", "sphereWithHole.stl", "triamid.stl",
          "issue1580-zero-area-triangle.stl", "issue1580-back-to-back.stl", "singleFace.ascii.stl",
          "missingFace.ascii.stl", "solidNameMismatch.ascii.stl"]


def outcome(run, args, out):
    proc = run("slice", *args, "-o", out)
    count = helpers.gcode_layer_count(out) if proc.returncode == 0 and out.exists() else None
    return {"rc": proc.returncode, "layer_count": count}, proc


def cura_outcome(args, tmp_path):
    cache_file = helpers.CORPUS / "oracle-cache.json"
    stat = os.stat(helpers.CURA_BIN)
    key_parts = [stat.st_size, int(stat.st_mtime)]
    for a in map(str, args):
        if a.endswith(".stl") and os.path.exists(a):  # by name, size and mtime: the corpus may move
            key_parts += [os.path.basename(a), os.path.getsize(a), int(os.path.getmtime(a))]
        else:
            key_parts.append(a)
    key = hashlib.sha256(json.dumps(key_parts).encode()).hexdigest()[:24]
    try:
        cache = json.loads(cache_file.read_text())
    except (OSError, ValueError):
        cache = {}
    if key not in cache:
        cache[key], _ = outcome(helpers.cura, args, tmp_path / "cura.gcode")
        if cache_file.parent.is_dir():
            tmp = cache_file.with_suffix(f".{os.getpid()}.tmp")
            tmp.write_text(json.dumps(cache, indent=1))
            tmp.replace(cache_file)
    return cache[key]


def compare(args, tmp_path):
    expected = cura_outcome(args, tmp_path)
    got, proc = outcome(helpers.mixengine, args, tmp_path / "mixengine.gcode")
    assert got == expected, (f"CuraEngine {expected}, mixengine {got} for {' '.join(map(str, args))}; "
                             f"mixengine stderr: {proc.stderr.strip()[-500:]}")


@pytest.mark.parametrize("names", MODELS, ids=["+".join(m) for m in MODELS])
def test_same_layer_count_as_cura(engine, corpus, tmp_path, names):
    args = list(FDM)
    for name in names:
        args += ["-l", corpus(name)]
    compare(args, tmp_path)


@pytest.mark.parametrize("model", ["cube20", "bunny_lowpoly"])
@pytest.mark.parametrize("setting", sorted(SETTINGS))
def test_settings_change_layer_count_like_cura(engine, corpus, tmp_path, model, setting):
    compare(FDM + SETTINGS[setting] + ["-l", corpus(model)], tmp_path)


@pytest.mark.parametrize("name", BROKEN)
def test_broken_file_like_cura(engine, corpus, tmp_path, name):
    compare(FDM + ["-l", corpus(f"broken/{name}")], tmp_path)
