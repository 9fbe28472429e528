"""speed_slowdown_layers as CuraEngine 4.13 applies it (issue 28): on layers 0 … n−1 every speed — travel
included — goes linearly from its *_layer_0 value to its own (travel: speed_travel_layer_0 → speed_travel), and
with n = 0 nothing is slowed, layer 0 included. Both engines slice the parity scene (an Ender-3, every setting
resolved the same way, tests/python/parity.py) and the F words are read back from their G-code: per layer, the
set of travel speeds (G0 with X or Y, no Z: the layer change's Z move differs in form between the engines) and
the set of print speeds (G1 with F) on the slowed layers must be equal."""
import collections
import re

import pytest

import helpers
import parity

LAYERS = 6


def speeds(path):
    """{layer: (travel F set, print F set)} for layers 0 … LAYERS−1."""
    out = collections.defaultdict(lambda: (set(), set()))
    layer = None
    with open(path) as f:
        for line in f:
            if line.startswith(";LAYER:"):
                layer = int(line[7:])
                continue
            if layer is None or not 0 <= layer < LAYERS or " F" not in line.split(";")[0]:
                continue
            code = line.split(";")[0]
            f_word = float(re.search(r" F([\d.]+)", code).group(1))
            if code.startswith("G0") and (" X" in code or " Y" in code) and " Z" not in code:
                out[layer][0].add(f_word)
            elif code.startswith("G1") and " E" in code:
                out[layer][1].add(f_word)
    return {k: (sorted(t), sorted(p)) for k, (t, p) in out.items()}


@pytest.mark.parametrize("layers", [0, 2, 4])
def test_first_layers_slow_down_as_in_curaengine(layers, tmp_path, report):
    args = parity.SINGLE.slice_args({"speed_slowdown_layers": layers})
    got = {}
    for name, binary in (("CuraEngine", helpers.CURA_BIN), ("MixEngine", helpers.BIN)):
        out = tmp_path / f"{name}.gcode"
        proc = helpers.run([binary, "slice", *args, "-o", out], env=helpers.CURA_ENV)
        assert proc.returncode == 0, proc.stderr[-500:]
        got[name] = speeds(out)
    report(f"speed_slowdown_layers={layers}: travel F per layer, CuraEngine "
           f"{[got['CuraEngine'][k][0] for k in sorted(got['CuraEngine'])]}, MixEngine "
           f"{[got['MixEngine'][k][0] for k in sorted(got['MixEngine'])]}")
    assert sorted(got["CuraEngine"]) == sorted(got["MixEngine"]) == list(range(LAYERS))
    for layer in range(LAYERS):
        assert got["MixEngine"][layer][0] == got["CuraEngine"][layer][0], f"travel speeds on layer {layer}"
    for layer in range(layers):
        assert got["MixEngine"][layer][1] == got["CuraEngine"][layer][1], f"print speeds on layer {layer}"
