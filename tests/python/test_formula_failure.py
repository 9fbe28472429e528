"""A definition formula that fails during a slice (issue 28): the slice goes on with the setting's
default_value and says so in one warning line naming the setting and the formula — once, though the formula
is evaluated for every scope and for every setting that reads it. `mixengine settings` says the same."""
import json
import re

import helpers
from mixing_gcode import box_stl


def broken_printer(tmp_path):
    """A printer inheriting fdmprinter whose speed_travel formula names a setting that does not exist."""
    path = tmp_path / "broken_printer.def.json"
    path.write_text(json.dumps({"version": 2, "name": "Broken formula printer", "inherits": "fdmprinter",
                                "metadata": {},
                                "overrides": {"speed_travel": {"value": "speed_print * no_such_setting"}}}))
    return path


def fdmprinter_default(key):
    """The default_value of `key` in Cura's installed fdmprinter.def.json, found by walking its tree."""
    def walk(node):
        for name, child in node.items():
            if name == key:
                return child["default_value"]
            found = walk(child.get("children", {}))
            if found is not None:
                return found
        return None
    return walk(json.loads(helpers.FDMPRINTER.read_text())["settings"])


def test_a_failing_formula_is_one_warning_and_the_default(tmp_path):
    printer = broken_printer(tmp_path)
    cube = box_stl(tmp_path / "cube.stl", 20, 20, 5)
    out = tmp_path / "out.gcode"
    proc = helpers.mixengine("slice", "-j", printer, "-l", cube, "-o", out)
    assert proc.returncode == 0, proc.stderr
    warnings = [line for line in helpers.stderr_lines(proc) if "formula" in line]
    assert warnings == ["[warning] formula fell back to default_value: setting 'speed_travel': formula "
                        "'speed_print * no_such_setting': unknown name 'no_such_setting'"], proc.stderr
    # past the slowed first layers (speed_slowdown_layers) every travel runs at speed_travel
    after = out.read_text().split(";LAYER:3\n", 1)[1]
    travel_f = {float(m.group(1)) for m in re.finditer(r"^G0 F([\d.]+) X", after, re.M)}
    assert travel_f == {60.0 * fdmprinter_default("speed_travel")}
    settings = helpers.mixengine("settings", "-j", printer)
    assert [line for line in helpers.stderr_lines(settings) if "formula" in line] == warnings


def test_a_formula_failing_only_for_a_mesh_is_one_warning_too(tmp_path):
    """A formula that fails only with a mesh's own value (its scope is resolved apart from the
    trains') is reported once as well, however many meshes have that value."""
    path = tmp_path / "mesh_broken_printer.def.json"
    path.write_text(json.dumps({"version": 2, "name": "Mesh broken formula printer", "inherits": "fdmprinter",
                                "metadata": {}, "overrides": {"infill_line_distance": {
                                    "value": "line_width * 100 / (infill_sparse_density - 50)"}}}))
    cube = box_stl(tmp_path / "cube.stl", 20, 20, 5)
    proc = helpers.mixengine("slice", "-j", path, "-l", cube, "-s", "infill_sparse_density=50",
                             "-l", cube, "-s", "infill_sparse_density=50", "-o", tmp_path / "out.gcode")
    assert proc.returncode == 0, proc.stderr
    warnings = [line for line in helpers.stderr_lines(proc) if "formula" in line]
    assert warnings == ["[warning] formula fell back to default_value: setting 'infill_line_distance': formula "
                        "'line_width * 100 / (infill_sparse_density - 50)': division by zero"], proc.stderr
