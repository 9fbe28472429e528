"""User-facing settings that act only through Cura's formulas must change the print
(CuraEngine's command line ignores formulas, so there infill_sparse_density=5 and =40 print alike)."""
import re
import subprocess

import pytest


def _filament_m(engine, tmp_path, model, *settings):
    out = tmp_path / "out.gcode"
    args = [str(engine), "slice", "-j", "creality_ender3", "--profiles"]
    for s in settings:
        args += ["-s", s]
    run = subprocess.run(args + ["-l", str(model), "-o", str(out)], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    header = out.read_text().split(";LAYER_COUNT", 1)[0]
    return float(re.search(r";Filament used: ([0-9.]+)m", header).group(1))


@pytest.mark.parametrize("key,low,high", [("infill_sparse_density", "5", "40"),
                                          ("top_bottom_thickness", "0.4", "2"),
                                          ("wall_thickness", "0.4", "2")])
def test_formula_driven_setting_changes_filament(engine, corpus, tmp_path, report, key, low, high):
    model = corpus("cube20")
    a = _filament_m(engine, tmp_path, model, f"{key}={low}")
    b = _filament_m(engine, tmp_path, model, f"{key}={high}")
    report(f"formula effect {key}: {low} -> {a:.4f} m, {high} -> {b:.4f} m")
    assert b > a * 1.1, f"{key}={high} used {b} m, {key}={low} used {a} m"
