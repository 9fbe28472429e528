"""Lightning infill (infill_pattern lightning; engine/toolpaths/infill/lightning/) side by side with Debian's
CuraEngine 4.13 on the armadillo (side_by_side.py: the Ender-3's resolved values handed to both engines).

Lightning prints trees that hold up only the top skins, so it uses much less material than lines at the
same density; the trees grow by CuraEngine's rules but not point for point as CuraEngine's (its order of the
overhang points is a hash of theirs, its branch order rand()), so the filament is compared within +-10 %.
CuraEngine's G-code is cached (~/.cache/mixengine-compare)."""
import pytest

import parity
import side_by_side as sbs

MODEL = "armadillo52k"
LIGHTNING = {"infill_pattern": "lightning"}
LINES = {"infill_pattern": "lines"}
FILAMENT_TOLERANCE = 0.10


@pytest.fixture(scope="module")
def runs(engine, corpus):
    corpus(MODEL)  # skips when the corpus lacks the model
    out = {"mix": sbs.run_mixengine(MODEL, LIGHTNING), "cura": sbs.run_cura(MODEL, LIGHTNING),
           "mix_lines": sbs.run_mixengine(MODEL, LINES)}
    for name, run in out.items():
        assert run.rc == 0, f"{name} failed (rc {run.rc}): {run.stderr[-500:]}"
    return out


def test_filament_within_10_percent_of_cura(runs, report):
    got, want = runs["mix"].filament_mm(), runs["cura"].filament_mm()
    report(f"lightning {MODEL}: filament mixengine {got:.0f} mm / CuraEngine {want:.0f} mm; "
           f"slice {runs['mix'].seconds:.1f} s / {runs['cura'].seconds:.1f} s (CuraEngine's may be cached)")
    assert abs(got - want) <= FILAMENT_TOLERANCE * want, \
        f"filament mixengine {got:.0f} mm vs CuraEngine {want:.0f} mm ({100 * (got - want) / want:+.1f} %)"


def test_lightning_is_not_lines(runs):
    lightning = parity.signature(runs["mix"].gcode)
    lines = parity.signature(runs["mix_lines"].gcode)
    assert lightning["digest"] != lines["digest"]
    # Trees under the top skins only: clearly less infill than lines at the same density (CuraEngine: -32 %).
    assert lightning["figures"]["filament"] < 0.85 * lines["figures"]["filament"]
