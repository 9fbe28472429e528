"""`mixengine connect`: Cura's socket protocol, checked with a frontend built on the real libArcus
(python3-arcus) and Cura's own Cura.proto (tests/python/cura_frontend.py).

Shows: our Cura.proto is wire-compatible with Cura's; the message sequence Cura expects (start
chunk, one GCodeLayer per layer starting with ;LAYER:n, LayerOptimized for every layer, the real
header as GCodePrefix, the end chunk, the estimates in mm³, SlicingFinished, exit 0); and the same
G-code from `slice` on the command line and from `connect` for the same settings and model."""
import re
import socket
import subprocess
import time

import pytest

import helpers
from cura_socket import one_object, resolved_settings, slice_over_socket
from mixing_gcode import box_stl

CURA_PROTO = "/usr/lib/cura/plugins/CuraEngineBackend/Cura.proto"
OUR_PROTO = helpers.REPO / "engine" / "communication" / "arcus" / "Cura.proto"


@pytest.fixture(scope="module")
def cube(tmp_path_factory):
    return box_stl(tmp_path_factory.mktemp("connect") / "cube.stl", 20.0, 20.0, 10.0)


def descriptor_table(proto, tmp_path):
    """(message, field number) -> (type, label, type name) of a .proto file, via protoc."""
    from google.protobuf import descriptor_pb2
    out = tmp_path / (proto.name + ".pb")
    subprocess.run(["protoc", f"-I{proto.parent}", f"--descriptor_set_out={out}", proto.name], check=True)
    files = descriptor_pb2.FileDescriptorSet.FromString(out.read_bytes())
    table = {}

    def walk(prefix, messages):
        for m in messages:
            name = f"{prefix}.{m.name}"
            for f in m.field:
                table[(name, f.number)] = (f.type, f.label, f.type_name)
            walk(name, m.nested_type)

    for f in files.file:
        walk(f.package, f.message_type)
    return table


def test_our_proto_is_wire_compatible_with_curas(tmp_path):
    from pathlib import Path
    cura_dir = tmp_path / "cura"
    cura_dir.mkdir()
    ours_dir = tmp_path / "ours"
    ours_dir.mkdir()
    theirs = descriptor_table(Path(CURA_PROTO), cura_dir)
    ours = descriptor_table(OUR_PROTO, ours_dir)
    assert len(theirs) > 40
    assert ours == theirs


@pytest.fixture(scope="module")
def ender3_slice(engine, cube, tmp_path_factory):
    global_settings, extruders = resolved_settings("creality_ender3")
    return slice_over_socket(engine, tmp_path_factory.mktemp("ender3"), global_settings, extruders,
                             [one_object(cube)])


def test_connect_sends_what_cura_expects_in_order(ender3_slice):
    r = ender3_slice
    assert r["exit_code"] == 0, r["stderr"]
    assert r["finished"]
    layers = r["counts"]["cura.proto.LayerOptimized"]
    assert layers == len(r["layers"]) > 50
    assert r["counts"]["cura.proto.GCodeLayer"] == layers + 2  # start chunk, layers, end chunk
    assert r["counts"]["cura.proto.GCodePrefix"] == 1
    assert r["counts"]["cura.proto.PrintTimeMaterialEstimates"] == 1
    assert r["counts"]["cura.proto.SlicingFinished"] == 1
    prefix, start, *chunks, end = r["gcode_list"]
    assert prefix.startswith(";FLAVOR:Marlin\n;TIME:")
    assert start.endswith(f";LAYER_COUNT:{layers}\n")
    for n, chunk in enumerate(chunks):
        assert chunk.startswith(f";LAYER:{n}\n")
    assert end.rstrip().endswith(";End of Gcode")
    progress = r["progress"]
    assert progress == sorted(progress) and progress[-1] == pytest.approx(1.0)


def test_header_and_estimates_carry_the_real_values(ender3_slice):
    r = ender3_slice
    prefix = r["gcode_list"][0]
    time_s = int(re.search(r";TIME:(\d+)", prefix).group(1))
    filament_m = float(re.search(r";Filament used: ([\d.]+)m", prefix).group(1))
    assert time_s > 60 and filament_m > 0.1
    est = r["estimates"]
    assert sum(v for k, v in est.items() if k.startswith("time_")) == pytest.approx(time_s, abs=1)
    area_mm2 = 3.141592653589793 * (1.75 / 2) ** 2
    assert est["materials"] == [pytest.approx(filament_m * 1000 * area_mm2, rel=1e-4)]


def test_layer_preview_heights_are_microns_and_lines_are_typed(ender3_slice):
    layers = sorted(ender3_slice["layers"], key=lambda layer: layer["id"])
    assert [layer["id"] for layer in layers] == list(range(len(layers)))
    # the Ender-3's definitions alone: layer_height_0 0.3 mm, layer_height 0.1 mm
    assert layers[0]["height"] == 300.0 and layers[0]["thickness"] == 300.0
    assert layers[1]["height"] == 400.0 and layers[1]["thickness"] == 100.0
    types = set()
    for layer in layers:
        for seg in layer["segments"]:
            assert seg["points"] == seg["lines"] + 1 == seg["widths"] + 1 == seg["feedrates"] + 1
            types.update(seg["types"])
    assert {1, 2, 3, 6, 8} <= types  # outer wall, inner wall, skin, infill, travel
    assert 5 in {t for seg in layers[0]["segments"] for t in seg["types"]}  # skirt on layer 0


# libArcus reports its own state changes through the error callback with ErrorCode::Debug; these are not errors.
LIBARCUS_DEBUG_MESSAGES = {"Closing socket because other side requested close.", "We got a request to close the socket."}


def libarcus_errors(result):
    return [e for e in result["errors"] if e not in LIBARCUS_DEBUG_MESSAGES]


def without_volatile_lines(text):
    """Date/time lines are the only allowed difference between the two paths."""
    return [line for line in text.splitlines() if not re.match(r";\s*(Date|Time|TIME_ELAPSED_AT)\b", line)]


SAME_GCODE_CASES = {
    "ender3": ("creality_ender3", ()),
    "gradient_eb_absolute": ("fdmprinter", ("mixing_mode=gradient", "mixing_dialect=eb_axes",
                                            "mixing_gradient_start=20", "mixing_gradient_end=80")),
    "gradient_eb_relative": ("fdmprinter", ("mixing_mode=gradient", "mixing_dialect=eb_axes",
                                            "mixing_gradient_start=0", "mixing_gradient_end=100",
                                            "relative_extrusion=True")),
    "gradient_m163": ("fdmprinter", ("mixing_mode=gradient", "mixing_dialect=marlin_m163",
                                     "mixing_gradient_start=50", "mixing_gradient_end=50")),
    "gradient_rrf_colon": ("fdmprinter", ("mixing_mode=gradient", "mixing_dialect=rrf_colon",
                                          "mixing_gradient_start=80", "mixing_gradient_end=100")),
}


@pytest.mark.parametrize("case", sorted(SAME_GCODE_CASES))
def test_same_gcode_from_the_command_line_and_from_the_socket(engine, cube, tmp_path, case):
    definition, settings = SAME_GCODE_CASES[case]
    cli_out = tmp_path / "cli.gcode"
    args = ["slice", "-j", definition]
    for s in settings:
        args += ["-s", s]
    proc = helpers.mixengine(*args, "-l", cube, "-o", cli_out)
    assert proc.returncode == 0, proc.stderr
    global_settings, extruders = resolved_settings(definition, *settings)
    r = slice_over_socket(engine, tmp_path, global_settings, extruders, [one_object(cube)])
    assert r["exit_code"] == 0, r["stderr"]
    socket_text = "".join(r["gcode_list"])
    assert without_volatile_lines(socket_text) == without_volatile_lines(cli_out.read_text())
    if "mixing_mode=gradient" in settings:
        assert re.search(r"^(G1 .*B[\d.]|M163 |G1 .*E[\d.]+:[\d.]+)", socket_text, re.M)


def test_seed_aliases_over_the_socket_give_the_command_line_gradient(engine, cube, tmp_path):
    """A frontend that knows only the seed's keys (colorMode, colorA, colorB) and none of ours."""
    cli_out = tmp_path / "cli.gcode"
    proc = helpers.mixengine("slice", "-s", "mixing_mode=gradient", "-s", "mixing_dialect=eb_axes",
                             "-s", "mixing_gradient_start=20", "-s", "mixing_gradient_end=80",
                             "-l", cube, "-o", cli_out)
    assert proc.returncode == 0, proc.stderr
    global_settings, extruders = resolved_settings("fdmprinter", "mixing_dialect=eb_axes")
    seed_frontend = {k: v for k, v in global_settings.items() if not k.startswith("mixing_")}
    seed_frontend.update(colorMode="2", colorA="20", colorB="80", mixing_dialect="eb_axes")
    r = slice_over_socket(engine, tmp_path, seed_frontend, extruders, [one_object(cube)])
    assert r["exit_code"] == 0, r["stderr"]
    assert without_volatile_lines("".join(r["gcode_list"])) == without_volatile_lines(cli_out.read_text())


def test_two_extruders_two_objects_same_as_command_line(engine, cube, tmp_path):
    definition = "ultimaker_original_dual"
    base = ("extruders_enabled_count=2", "adhesion_type=skirt")
    cli_out = tmp_path / "cli.gcode"
    args = ["slice", "-j", definition]
    for s in base:
        args += ["-s", s]
    args += ["-l", cube, "-s", "mesh_position_x=-15", "-e1", "-l", cube, "-s", "mesh_position_x=15",
             "-o", cli_out]
    proc = helpers.mixengine(*args)
    assert proc.returncode == 0, proc.stderr
    global_settings, extruders = resolved_settings(definition, *base)
    group = {"settings": {}, "objects": [
        {"name": str(cube), "stl": str(cube), "settings": {"extruder_nr": "0", "mesh_position_x": "-15"}},
        {"name": str(cube), "stl": str(cube), "settings": {"extruder_nr": "1", "mesh_position_x": "15"}}]}
    r = slice_over_socket(engine, tmp_path, global_settings, extruders, [group])
    assert r["exit_code"] == 0, r["stderr"]
    text = "".join(r["gcode_list"])
    assert without_volatile_lines(text) == without_volatile_lines(cli_out.read_text())
    assert re.search(r"^T1$", text, re.M)
    assert len(r["estimates"]["materials"]) == 2 and min(r["estimates"]["materials"]) > 0
    extruders_in_preview = {seg["extruder"] for layer in r["layers"] for seg in layer["segments"]}
    assert extruders_in_preview == {0, 1}


def test_connect_refuses_a_bad_address_in_one_line(engine):
    proc = helpers.mixengine("connect", "127.0.0.1:99999", "")
    assert proc.returncode == 1
    assert proc.stderr.strip().splitlines() == [
        "mixengine: error: connect: '127.0.0.1:99999' is not <host>:<port> with a port from 1 to 65535"]


def test_connect_without_a_frontend_fails_promptly_naming_the_address(engine):
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    start = time.monotonic()
    proc = helpers.mixengine("connect", f"127.0.0.1:{port}", "", "-vvv", "-j", timeout=30)
    assert time.monotonic() - start < 15
    assert proc.returncode == 1
    assert f"cannot connect to Cura at 127.0.0.1:{port}" in proc.stderr.strip().splitlines()[-1]
    assert "ignoring unknown option '-j'" in proc.stderr


def test_a_setting_mixengine_does_not_honour_is_named_in_the_engine_log(engine, cube, tmp_path):
    """Issue 19, no silent ignores over the socket: Cura writes the engine's stderr into cura.log, so the
    warning for a listed setting (settings/mixengine/not_honoured.json) reaches the user there."""
    global_settings, extruders = resolved_settings("creality_ender3", "wireframe_enabled=True")
    r = slice_over_socket(engine, tmp_path, global_settings, extruders, [one_object(cube)])
    assert r["exit_code"] == 0, r["stderr"]
    warnings = [line for line in r["stderr"].splitlines() if "has no effect in MixEngine yet" in line]
    assert any(line.startswith("[warning] setting 'wireframe_enabled' has no effect in MixEngine yet "
                               "(value True") for line in warnings), r["stderr"]


def test_raft_layers_reach_the_preview_numbered_below_zero(engine, cube, tmp_path):
    """Issue 15: under a raft Cura receives CuraEngine's layer numbers — the raft's base, interface and two
    surface layers from -(4 + F), F filler layers (the air gap in layer heights) that print nothing on a
    cube, the model from 0 — in the G-code chunks and the LayerOptimized preview alike; ;LAYER_COUNT: counts
    the model's layers, as CuraEngine's does; every preview layer carries its own thickness."""
    global_settings, extruders = resolved_settings("creality_ender3", "adhesion_type=raft")
    r = slice_over_socket(engine, tmp_path, global_settings, extruders, [one_object(cube)])
    assert r["exit_code"] == 0, r["stderr"]
    assert not re.search(r"setting '(adhesion_type|raft_\w+|layer_0_z_overlap)' has no effect", r["stderr"])
    layers = sorted(r["layers"], key=lambda layer: layer["id"])
    model_layers = len(layers) - 4
    e = extruders["0"]
    gap_um = round((float(e["raft_airgap"]) + float(global_settings["layer_height_0"])
                    - float(e["layer_0_z_overlap"])) * 1000)
    layer_um = round(float(global_settings["layer_height"]) * 1000)
    base = -(2 + int(e["raft_surface_layers"]) + (gap_um + layer_um // 2) // layer_um)
    assert [layer["id"] for layer in layers] == [base, base + 1, base + 2, base + 3] + list(range(model_layers))
    _, start, *chunks, _ = r["gcode_list"]
    assert start.endswith(f";LAYER_COUNT:{model_layers}\n")
    assert [chunk.split("\n", 1)[0] for chunk in chunks] == [f";LAYER:{layer['id']}" for layer in layers]
    raft_thickness = [float(extruders["0"][k]) * 1000 for k in ("raft_base_thickness", "raft_interface_thickness")]
    assert [layers[0]["thickness"], layers[1]["thickness"]] == pytest.approx(raft_thickness)
    assert layers[4]["thickness"] == pytest.approx(float(global_settings["layer_height_0"]) * 1000)
    assert layers[4]["height"] > layers[3]["height"] + float(extruders["0"]["raft_airgap"]) * 1000 - 1
    raft_types = {t for layer in layers[:4] for seg in layer["segments"] for t in seg["types"]}
    assert {7, 10} <= raft_types and not raft_types & {1, 2, 3, 5, 6}  # support / interface lines only


def test_several_mesh_groups_arrive_whole_and_in_order(engine, cube, tmp_path):
    """Issue 29: layers stream as they are written; with several mesh groups (Cura's one-at-a-time sends one
    object list per object) the start code carries the whole print's ;LAYER_COUNT:, so the first group's
    layers wait for it — the G-code is still the command line's, byte for byte."""
    cli_out = tmp_path / "cli.gcode"
    proc = helpers.mixengine("slice", "-j", "creality_ender3", "-l", cube, "-s", "mesh_position_x=-30",
                             "--next", "-l", cube, "-s", "mesh_position_x=30", "-o", cli_out)
    assert proc.returncode == 0, proc.stderr
    global_settings, extruders = resolved_settings("creality_ender3")
    groups = [one_object(cube, mesh_position_x=-30), one_object(cube, mesh_position_x=30)]
    r = slice_over_socket(engine, tmp_path, global_settings, extruders, groups)
    assert r["exit_code"] == 0, r["stderr"]
    assert libarcus_errors(r) == []
    text = "".join(r["gcode_list"])
    assert without_volatile_lines(text) == without_volatile_lines(cli_out.read_text())
    ids = [layer["id"] for layer in r["layers"]]
    assert ids == list(range(len(ids)))  # each group's layers, numbered on, as the G-code's ;LAYER:
    assert [chunk.split("\n", 1)[0] for chunk in r["gcode_list"][2:-1]] == [f";LAYER:{i}" for i in ids]
