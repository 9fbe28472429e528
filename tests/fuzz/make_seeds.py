#!/usr/bin/env python3
"""Writes the seed inputs of the fuzz targets (small valid and odd inputs) into OUT/<target>/.

    make_seeds.py OUT_DIR

Standard library only (runs with the system python3). Targets: stl, obj, threemf, settings, formula.
The formula seeds are the value / minimum_value / maximum_value / enabled formulas of Cura's
fdmprinter.def.json when it is installed (Debian package cura), plus a few hand-written ones. The
settings and formula targets also get REGRESSIONS, the inputs that once took unbounded memory or time.
"""
import io
import json
import struct
import sys
import zipfile
from pathlib import Path

CUBE_V = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (0, 0, 10), (10, 0, 10), (10, 10, 10), (0, 10, 10)]
CUBE_F = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
          (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
FDMPRINTER = Path("/usr/share/cura/resources/definitions/fdmprinter.def.json")


def binary_stl(faces, count=None, header=b"seed"):
    data = bytearray(header.ljust(80, b" ")) + struct.pack("<I", len(faces) if count is None else count)
    for f in faces:
        data += struct.pack("<3f", 0, 0, 1)
        for i in f:
            data += struct.pack("<3f", *CUBE_V[i])
        data += b"\0\0"
    return bytes(data)


def ascii_stl(faces, solids=1):
    out = []
    for s in range(solids):
        out.append(f"solid part{s}")
        for f in faces:
            out += ["facet normal 0 0 1", " outer loop"]
            out += [" vertex {} {} {}".format(*CUBE_V[i]) for i in f]
            out += [" endloop", "endfacet"]
        out.append(f"endsolid part{s}")
    return ("\n".join(out) + "\n").encode()


def stl_seeds():
    return {
        "cube_binary.stl": binary_stl(CUBE_F),
        "cube_binary_solid_header.stl": binary_stl(CUBE_F, header=b"solid cube"),
        "count_high.stl": binary_stl(CUBE_F[:4], count=66),
        "trailing.stl": binary_stl(CUBE_F[:2]) + b"\0",
        "cube_ascii.stl": ascii_stl(CUBE_F[:4]),
        "two_solids.stl": ascii_stl(CUBE_F[:2], solids=2),
        "no_normal.stl": b"solid x\nfacet\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 1e-3\n"
                         b"endloop\nendfacet\nendsolid x\n",
    }


def obj_seeds():
    verts = "".join(f"v {x} {y} {z}\n" for x, y, z in CUBE_V)
    faces = "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in CUBE_F)
    return {
        "cube.obj": (verts + faces).encode(),
        "groups.obj": ("# two groups\n" + verts + "o first\n" + faces[:40] + "g second\n" + faces[40:]).encode(),
        "forms.obj": (verts + "vt 0 0\nvn 0 0 1\nf 1/1 2/1/1 3//1\nf -1 -2 -3 -4\ns off\nusemtl m\n").encode(),
        "forward.obj": b"f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 1\n",
    }


def three_mf(model_xml):
    types = ('<?xml version="1.0" encoding="UTF-8"?><Types xmlns="http://schemas.openxmlformats.org/package/'
             '2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.'
             'relationships+xml"/><Default Extension="model" ContentType="application/vnd.ms-package.'
             '3dmanufacturing-3dmodel+xml"/></Types>')
    rels = ('<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/'
            'package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://'
            'schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>')
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_STORED) as z:  # stored: mutations reach the XML
        z.writestr("[Content_Types].xml", types)
        z.writestr("_rels/.rels", rels)
        z.writestr("3D/3dmodel.model", model_xml)
    return buffer.getvalue()


def mesh_object(oid, name):
    return (f'<object id="{oid}" type="model" name="{name}"><mesh><vertices>'
            + "".join(f'<vertex x="{x}" y="{y}" z="{z}"/>' for x, y, z in CUBE_V)
            + "</vertices><triangles>"
            + "".join(f'<triangle v1="{a}" v2="{b}" v3="{c}"/>' for a, b, c in CUBE_F)
            + "</triangles></mesh></object>")


def threemf_seeds():
    ns = 'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"'
    plain = f'<model unit="millimeter" {ns}><resources>{mesh_object(1, "cube")}</resources>' \
            '<build><item objectid="1"/></build></model>'
    components = (f'<model unit="inch" {ns}><resources>{mesh_object(1, "")}'
                  '<object id="2" type="model"><components><component objectid="1" transform="1 0 0 0 1 0 0 0 1 5 0 0"/>'
                  '<component objectid="1"/></components></object></resources>'
                  '<build><item objectid="2" transform="0 1 0 -1 0 0 0 0 1 0 0 2"/><item objectid="1"/></build></model>')
    return {"cube.3mf": three_mf(plain), "components.3mf": three_mf(components)}


# Inputs that once took unbounded memory or time (issue 29 item 4; tests/fuzz/README.md), kept as seeds so
# that every run starts from them. Formula values are deep copies: a repeated list repeats its items' items.
REPEATED_LIST = "[[0,0,[0,0,0,]]*120*1*1,0,[0,0,0,]]*120*1555"  # -s machine_disallowed_areas=...: 18 GB
NESTED_REPETITION = "[[-20, 10]*999999, [10, 10], [0, -5]]*999999"  # settings_fuzz: out of memory
STRING_COMPREHENSIONS = "[0 for a in infill_pattern * 5000 for b in infill_pattern * 5000 if a + b == '']"
NESTED_COMPREHENSIONS = "[" * 60 + "0" + "".join(f" for a{i} in [1]]" for i in range(60))  # 2^60 parses
LONG_SEARCH = "('a' * 150000 + 'b') in 'a' * 300000"  # std::string::find: ~2 * 10^10 comparisons
REGRESSIONS = [REPEATED_LIST, NESTED_REPETITION, STRING_COMPREHENSIONS, NESTED_COMPREHENSIONS, LONG_SEARCH]


def settings_seeds():
    texts = {0: ["True", "false", "yes", "0"], 1: ["0.2", "-1e3", "+5"], 2: ["3", "3.0", "-7"],
             3: ["0.4", "1e9"], 4: ["50", "12.5"], 5: ["[1, 2.5, -3]", "[]"], 6: ["[[-20, 10], [10, 10], [0, -5]]"],
             7: ["[[[0, 0], [1, 0], [1, 1]], [[5, 5], [6, 5], [6, 6]]]"], 8: ["[[1,0,0],[0,1,0],[0,0,1]]"],
             9: ["0.1", "[[1,2]]", "[0, 1]", "grid", "True", "1e5"]}
    seeds = {}
    for selector, values in texts.items():
        for i, text in enumerate(values):
            for extra in ((0, 10, 20, 50, 70, 90) if selector == 9 else (0,)):
                seeds[f"s{selector + extra}_{i}"] = bytes([selector + extra]) + text.encode()
    for i, text in enumerate(REGRESSIONS):  # as "polygon" (selector 59) and "polygons" (69) values
        for selector in (59, 69):
            seeds[f"regression{i}_s{selector}"] = bytes([selector]) + text.replace("infill_pattern", "'grid'").encode()
    return seeds


def formula_seeds():
    formulas = ["max(0.1, layer_height * 2) if support_enable else 0", "extruderValue(0, 'layer_height') / 3",
                "sum(extruderValues('wall_line_count'))", "[p for p in machine_disallowed_areas if len(p) > 0]",
                "round(2.5) + math.ceil(1.2) // 2 ** 3 % 7", "'a' + infill_pattern in ('grid', 'lines')",
                "all(x != 'x' for x in ['a', 'b'])", "1 < 2 <= 3 != 4", "int('12') + float('1e2')",
                "resolveOrValue('layer_height') if not support_enable or wall_line_count > 2 else -1"]
    try:
        definitions = json.loads(FDMPRINTER.read_text())
    except (OSError, ValueError):
        definitions = {}
    found = []

    def walk(node):
        for child in node.values():
            for field in ("value", "minimum_value", "maximum_value", "enabled", "resolve"):
                if isinstance(child.get(field), str):
                    found.append(child[field])
            walk(child.get("children", {}))
    walk(definitions.get("settings", {}))
    unique = list(dict.fromkeys(formulas + found))
    seeds = {f"f{i:04d}": text.encode() for i, text in enumerate(unique)}
    seeds.update({f"regression{i}": text.encode() for i, text in enumerate(REGRESSIONS)})
    return seeds


def main():
    out = Path(sys.argv[1])
    groups = {"stl": stl_seeds(), "obj": obj_seeds(), "threemf": threemf_seeds(), "settings": settings_seeds(),
              "formula": formula_seeds()}
    for target, seeds in groups.items():
        folder = out / target
        folder.mkdir(parents=True, exist_ok=True)
        for name, data in seeds.items():
            (folder / name).write_bytes(data)
        print(f"make_seeds.py: {len(seeds)} seeds for {target} in {folder}")


if __name__ == "__main__":
    main()
