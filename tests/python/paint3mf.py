"""Painted 3MF boxes for the colour-mode tests, written with zipfile (no slicer involved): a box
20 × 20 × 10 mm (or size × size × height) centred on x = y = 0 whose triangles are split at x = 0, the left
half (x < 0) painted one way and the right half another, as

  colorgroup      core 3MF material extension: m:colorgroup, triangles with pid/p1
  basematerials   core 3MF: basematerials displaycolor, triangles with pid/p1
  prusa           PrusaSlicer: slic3rpe:mmu_segmentation="4" (extruder 1) / "8" (extruder 2)
  orca            OrcaSlicer: paint_color with the same encoding
"""
import zipfile

CONTENT_TYPES = """<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
 <Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
 <Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
</Types>"""
RELS = """<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
 <Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>"""


def box_halves(size=20.0, height=10.0):
    """(vertices, [(a, b, c, half)]) with half 0 for x < 0 and 1 for x > 0, outward winding."""
    h = size / 2
    xs, ys, zs = (-h, 0.0, h), (-h, h), (0.0, height)
    index = {}
    vertices = []

    def v(x, y, z):
        if (x, y, z) not in index:
            index[(x, y, z)] = len(vertices)
            vertices.append((x, y, z))
        return index[(x, y, z)]

    faces = []

    def quad(p, q, r, s, half):  # p q r s counter-clockwise seen from outside
        faces.append((v(*p), v(*q), v(*r), half))
        faces.append((v(*p), v(*r), v(*s), half))

    for half, (x0, x1) in enumerate(((xs[0], xs[1]), (xs[1], xs[2]))):
        quad((x0, ys[0], 0), (x0, ys[1], 0), (x1, ys[1], 0), (x1, ys[0], 0), half)  # bottom, -z
        quad((x0, ys[0], height), (x1, ys[0], height), (x1, ys[1], height), (x0, ys[1], height), half)  # top
        quad((x0, ys[0], 0), (x1, ys[0], 0), (x1, ys[0], height), (x0, ys[0], height), half)  # front, -y
        quad((x0, ys[1], 0), (x0, ys[1], height), (x1, ys[1], height), (x1, ys[1], 0), half)  # back, +y
    quad((xs[0], ys[0], 0), (xs[0], ys[0], height), (xs[0], ys[1], height), (xs[0], ys[1], 0), 0)  # left
    quad((xs[2], ys[0], 0), (xs[2], ys[1], 0), (xs[2], ys[1], height), (xs[2], ys[0], height), 1)  # right
    return vertices, faces


def write_painted_box(path, style, left="#FFFF00", right="#0000FF", size=20.0, height=10.0):
    vertices, faces = box_halves(size, height)
    resources, attrs, default = "", None, ""
    ns = ""
    if style == "colorgroup":
        ns = ' xmlns:m="http://schemas.microsoft.com/3dmanufacturing/material/2015/02"'
        resources = f'<m:colorgroup id="2"><m:color color="{left}FF"/><m:color color="{right}FF"/></m:colorgroup>'
        attrs = lambda half: f'pid="2" p1="{half}"'  # noqa: E731
        default = ' pid="2" pindex="0"'
    elif style == "basematerials":
        resources = (f'<basematerials id="2"><base name="left" displaycolor="{left}"/>'
                     f'<base name="right" displaycolor="{right}"/></basematerials>')
        attrs = lambda half: f'pid="2" p1="{half}"'  # noqa: E731
        default = ' pid="2" pindex="0"'
    elif style == "prusa":
        ns = ' xmlns:slic3rpe="http://schemas.slic3r.org/3mf/2017/06"'
        attrs = lambda half: f'slic3rpe:mmu_segmentation="{"48"[half]}"'  # noqa: E731
    elif style == "orca":
        attrs = lambda half: f'paint_color="{"48"[half]}"'  # noqa: E731
    else:
        raise ValueError(style)
    vertex_xml = "".join(f'<vertex x="{x}" y="{y}" z="{z}"/>' for x, y, z in vertices)
    triangle_xml = "".join(f'<triangle v1="{a}" v2="{b}" v3="{c}" {attrs(half)}/>' for a, b, c, half in faces)
    model = (f'<?xml version="1.0" encoding="UTF-8"?>\n'
             f'<model unit="millimeter" xml:lang="en-US" '
             f'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"{ns}>'
             f'<resources>{resources}<object id="1" type="model" name="halves"{default}><mesh>'
             f'<vertices>{vertex_xml}</vertices><triangles>{triangle_xml}</triangles></mesh></object>'
             f'</resources><build><item objectid="1"/></build></model>')
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("[Content_Types].xml", CONTENT_TYPES)
        z.writestr("_rels/.rels", RELS)
        z.writestr("3D/3dmodel.model", model)
    return path
