"""Command-line behaviour: help, errors (exit 1, one stderr line, no output left behind), the broken and
odd inputs of test-corpus.md §4, and a G-code check of cube20 with fdmprinter's defaults."""
import pytest

import helpers

# Broken inputs and their defined outcomes (CuraEngine 4.13 gives the same exit codes).
ERROR = ["empty.stl", "faceless.ascii.stl"]  # nothing to slice: exit 1
SLICED = [  # sliced; ;LAYER_COUNT: at most the formula for the file's highest vertex, and at least 1
    "HalfDonut.stl", "wrongHeader.bin.stl", "incorrectFaceCounter.bin.stl", "Spider_binary.stl",
    "sphereWithHole.stl", "triamid.stl", "issue1580-zero-area-triangle.stl", "missingEndsolid.ascii.stl",
    "missingFace.ascii.stl", "missingNormal.ascii.stl", "notANumberNormal.ascii.stl",
    "solidNameMismatch.ascii.stl", "wrongNormal.ascii.stl", "wrongNormals.ascii.stl",
]
WARNED = {"HalfDonut.stl"}  # sliced, and stderr mentions a warning (binary STL with one trailing byte)
EXACT = {"wrongHeader.bin.stl": 498, "incorrectFaceCounter.bin.stl": 8}  # flat-topped: formula exactly
ZERO_HEIGHT = ["issue1580-back-to-back.stl", "issue1580-back-to-back2.stl", "singleFace.ascii.stl"]  # rc 0, 0 layers
MALFORMED = ["quad.ascii.stl", "fourVertices.ascii.stl", "twoVertices.ascii.stl"]  # facets of 4 or 2 vertices


def assert_one_line_error(proc, *needles):
    lines = helpers.stderr_lines(proc)
    assert proc.returncode == 1, f"exit code {proc.returncode}, expected 1; stderr: {proc.stderr[-1000:]}"
    assert len(lines) == 1, f"expected one stderr line, got {len(lines)}: {lines[:5]}"
    for needle in needles:
        assert str(needle) in lines[0], f"stderr line does not name {needle!r}: {lines[0]}"


def slice_file(model, tmp_path, *extra):
    out = tmp_path / "out.gcode"
    return helpers.mixengine("slice", *extra, "-l", model, "-o", out), out


def test_help_mentions_slice(engine):
    proc = helpers.mixengine("help")
    assert proc.returncode == 0
    assert "slice" in proc.stdout + proc.stderr


def test_unknown_command_is_one_line_error(engine):
    proc = helpers.mixengine("frobnicate")
    assert_one_line_error(proc, "frobnicate")


def test_missing_model_file(engine, tmp_path):
    missing = tmp_path / "no_such_model.stl"
    proc, out = slice_file(missing, tmp_path)
    assert_one_line_error(proc, missing)
    assert not out.exists(), "an output file was left behind after an error"


def test_missing_definition_file(engine, corpus, tmp_path):
    missing = tmp_path / "no_such.def.json"
    proc, out = slice_file(corpus("cube20"), tmp_path, "-j", missing)
    assert_one_line_error(proc, missing)
    assert not out.exists()


@pytest.mark.parametrize("setting", ["layer_height=abc", "layer_height=", "layer_height=0", "layer_height=-0.1"])
def test_bad_setting_value(engine, corpus, tmp_path, setting):
    proc, out = slice_file(corpus("cube20"), tmp_path, "-s", setting)
    assert_one_line_error(proc, "layer_height")
    assert not out.exists()


def test_cube20_gcode(engine, corpus, tmp_path):
    """fdmprinter defaults, no -j: layer count, one ;LAYER:n per layer, walls 20 - 0.4 mm wide at the
    bed centre (50, 50) on every layer above the first, and each layer printed at its own height."""
    proc, out = slice_file(corpus("cube20"), tmp_path)
    assert proc.returncode == 0, proc.stderr[-2000:]
    n = helpers.expected_layer_count(20.0)
    assert helpers.gcode_layer_count(out) == n
    text = out.read_text()
    assert [int(line[7:]) for line in text.splitlines() if line.startswith(";LAYER:")] == list(range(n))
    layers = helpers.extrusion_by_layer(out)
    assert sorted(layers) == list(range(n)), "every layer must extrude"
    for k in range(1, n):
        xmin, xmax, ymin, ymax, zs = layers[k]
        assert zs == {round(0.3 + 0.1 * k, 4)}, f"layer {k} extrudes at z {sorted(zs)}"
        assert xmax - xmin == pytest.approx(19.6, abs=0.01), f"layer {k}: x span {xmax - xmin}"
        assert ymax - ymin == pytest.approx(19.6, abs=0.01), f"layer {k}: y span {ymax - ymin}"
        assert (xmin + xmax) / 2 == pytest.approx(50, abs=0.01) and (ymin + ymax) / 2 == pytest.approx(50, abs=0.01)


@pytest.mark.parametrize("name", ERROR)
def test_broken_file_is_an_error(engine, corpus, tmp_path, name):
    proc, out = slice_file(corpus(f"broken/{name}"), tmp_path)
    assert_one_line_error(proc, name)
    assert not out.exists()


@pytest.mark.parametrize("name", SLICED)
def test_broken_file_is_sliced(engine, corpus, tmp_path, name):
    model = corpus(f"broken/{name}")
    proc, out = slice_file(model, tmp_path)
    assert proc.returncode == 0, f"rc {proc.returncode}: {proc.stderr[-1000:]}"
    count = helpers.gcode_layer_count(out)
    limit = helpers.expected_layer_count(helpers.stl_z_max(model))
    assert count is not None, "no ;LAYER_COUNT: line in the G-code"
    if name in EXACT:
        assert count == EXACT[name]
    else:
        assert 1 <= count <= limit, f";LAYER_COUNT:{count}, formula for the highest vertex: {limit}"
    if name in WARNED:
        assert "warn" in proc.stderr.lower(), f"no warning on stderr: {proc.stderr[-500:]!r}"


@pytest.mark.parametrize("name", ZERO_HEIGHT)
def test_zero_height_file_gives_no_layers(engine, corpus, tmp_path, name):
    proc, out = slice_file(corpus(f"broken/{name}"), tmp_path)
    assert proc.returncode == 0, proc.stderr[-1000:]
    assert helpers.gcode_layer_count(out) == 0


@pytest.mark.parametrize("name", MALFORMED)
def test_malformed_facets_are_handled(engine, corpus, tmp_path, name):
    """Either a one-line error naming the file (and no output), or a slice of at most the formula's layers."""
    model = corpus(f"broken/{name}")
    proc, out = slice_file(model, tmp_path)
    if proc.returncode == 1:
        assert_one_line_error(proc, name)
        assert not out.exists()
    else:
        assert proc.returncode == 0, f"rc {proc.returncode}: {proc.stderr[-1000:]}"
        assert 0 <= helpers.gcode_layer_count(out) <= helpers.expected_layer_count(helpers.stl_z_max(model))


def test_not_honoured_settings_are_named_once_each(engine, corpus, tmp_path):
    """Issue 19, no silent ignores: a listed setting (settings/mixengine/not_honoured.json) given a value that
    MixEngine does not act on yet gives one warning line; its definitions' own value gives none."""
    cube = corpus("cube20")
    out = tmp_path / "x.gcode"
    proc = helpers.mixengine("slice", "-j", "creality_ender3", "-s", "wireframe_enabled=True", "-l", cube,
                             "-o", out)
    assert proc.returncode == 0, proc.stderr
    lines = [line for line in proc.stderr.splitlines() if "has no effect in MixEngine yet" in line]
    assert lines == ["[warning] setting 'wireframe_enabled' has no effect in MixEngine yet "
                     "(value True: wire printing is not built)"], proc.stderr
    proc = helpers.mixengine("slice", "-j", "creality_ender3", "-s", "wireframe_enabled=False", "-l", cube,
                             "-o", out)
    assert proc.returncode == 0 and "has no effect in MixEngine yet" not in proc.stderr, proc.stderr
    proc = helpers.mixengine("slice", "-j", "creality_ender3", "-l", cube, "-o", out)
    assert proc.returncode == 0 and "has no effect in MixEngine yet" not in proc.stderr, proc.stderr


HELP_COMMANDS = {  # command -> words its usage must show (its own options, nothing of the others)
    "slice": ["mixengine slice", "-j <file|id>", "--preview", "--next"],
    "layers": ["mixengine layers", "layers.json", "predicted_colors"],
    "settings": ["mixengine settings", "--json"],
    "orient": ["mixengine orient", "--offset", "--report"],
    "connect": ["mixengine connect", "<host>[:<port>]"],
    "demo": ["mixengine demo", "[<dir>]"],
}


@pytest.mark.parametrize("command", sorted(HELP_COMMANDS))
@pytest.mark.parametrize("flag", ["--help", "-h"])
def test_command_help_prints_its_usage_and_exits_0(engine, tmp_path, command, flag):
    # run in an empty folder: --help must not slice, connect or write anything (demo used to create ./--help)
    proc = helpers.run([engine, command, flag], cwd=tmp_path, timeout=30)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ""
    usage = proc.stdout
    assert usage.startswith("usage:\n")
    for word in HELP_COMMANDS[command]:
        assert word in usage, (command, word)
    for other in set(HELP_COMMANDS) - {command}:
        assert f"mixengine {other} " not in usage and f"mixengine {other}\n" not in usage, (command, other)
    assert list(tmp_path.iterdir()) == []


def test_help_after_other_options_and_help_command_forms(engine, tmp_path):
    late = helpers.run([engine, "slice", "-j", "creality_ender3", "-s", "layer_height=0.2", "--help"], cwd=tmp_path)
    named = helpers.run([engine, "help", "slice"], cwd=tmp_path)
    assert late.returncode == named.returncode == 0
    assert late.stdout == named.stdout and "mixengine slice" in late.stdout
    assert list(tmp_path.iterdir()) == []
    unknown = helpers.mixengine("help", "frobnicate")
    assert_one_line_error(unknown, "frobnicate")
