"""Per-vertex colours of Cura's layer view from the colours the engine predicted in the G-code (no Cura
imports).

Cura's layer data (cura/LayerDataBuilder.py, LayerPolygon.py) holds, per layer, polygons of N + 1
points and N typed lines; LayerDataBuilder.build() turns them into a vertex list (layers in ascending
order, polygons in order): each line contributes its end point, and its start point as well when its
type differs from the previous line's. The Material Color scheme draws every line in the colour of
its end vertex ("a_material_color", the "colors" attribute). So giving each vertex the colour of the
line it belongs to colours every line exactly.

A line is matched to the G-code move that printed it by layer and end point: the layer view's
layers are numbered as ProcessSlicedLayersJob numbers them (MixGCode.viewLayerIds: from the lowest id,
model layers right after a raft's), the G-code's by ";LAYER:n"; within a layer both lists are in print order. The points are (x, -y) of the G-code's
(x, y) (LayerPolygon's scene frame). Lines without a match, or whose move has no predicted colour, keep
Cura's colour.
"""
import numpy

JUMP_TYPES = (0, 8, 9)  # LayerPolygon NoneType, MoveCombingType, MoveRetractionType
MATCH_TOLERANCE_MM = 0.01  # the G-code writes 3 decimals; the layer view has float32 points
LOOKAHEAD = 64  # moves searched ahead of the last match when the two lists differ


def _polygonArrays(polygon):
    types = numpy.asarray(polygon.types).reshape(-1).astype(numpy.int64)
    data = numpy.asarray(polygon.data).reshape(-1, 3)
    return types, data


def matchLayer(line_xy, move_xy):
    """Index of the G-code move of each extrusion line (-1: none). Both in print order."""
    count = len(line_xy)
    if count == 0 or len(move_xy) == 0:
        return numpy.full(count, -1, dtype=numpy.int64)
    if count == len(move_xy) and numpy.abs(line_xy - move_xy).max() <= MATCH_TOLERANCE_MM:
        return numpy.arange(count, dtype=numpy.int64)  # the usual case: one move per line
    found = numpy.full(count, -1, dtype=numpy.int64)
    pointer = 0
    for i in range(count):
        window = move_xy[pointer:pointer + LOOKAHEAD]
        if len(window) == 0:
            break
        close = numpy.abs(window - line_xy[i]).max(axis=1) <= MATCH_TOLERANCE_MM
        if close.any():
            found[i] = pointer + int(numpy.argmax(close))
            pointer = found[i] + 1
    return found


class RecolourResult:
    def __init__(self, colours, lines, matched, coloured):
        self.colours = colours  # (vertices, 4) new material colours
        self.lines = lines  # extrusion lines in the layer view
        self.matched = matched  # of which matched to a G-code move
        self.coloured = coloured  # of which given the move's predicted colour


def recolour(layers, material_colours, gcode_moves, move_rgb, layer_ids):
    """New per-vertex colours for `material_colours` (the built "colors" attribute, not changed).

    layers: {abs layer number: Layer with .polygons} as LayerDataBuilder holds them;
    gcode_moves: MixGCode.read() result; move_rgb: {layer id: (k, 3) colour of each extruding move, NaN =
    none} (GCodeMoves.moveColours);
    layer_ids: {abs layer number: G-code layer id} (MixGCode.viewLayerIds).
    Returns None when the vertex count does not follow the builder's rule (nothing is changed then)."""
    colours = numpy.array(material_colours, dtype=numpy.float32, copy=True)
    vertex = 0
    lines = matched = coloured = 0
    for number in sorted(layers):
        layer_id = layer_ids.get(number)
        layer_moves = gcode_moves.layers.get(layer_id)
        polygons = layers[number].polygons
        arrays = [_polygonArrays(p) for p in polygons]
        line_colours, counts = _layerLineColours(arrays, layer_moves, move_rgb.get(layer_id))
        lines += counts[0]
        matched += counts[1]
        coloured += counts[2]
        for (types, _), rgb in zip(arrays, line_colours):
            needed = numpy.ones((len(types), 2), dtype=bool)
            needed[1:, 0] = types[1:] != types[:-1]
            count = int(needed.sum())
            if vertex + count > len(colours):
                return None
            if rgb is not None:
                per_vertex = numpy.repeat(rgb, 2, axis=0)[needed.ravel()]
                keep = numpy.isnan(per_vertex[:, 0])
                block = colours[vertex:vertex + count]
                block[~keep, 0:3] = per_vertex[~keep]
            vertex += count
    if vertex != len(colours):
        return None
    return RecolourResult(colours, lines, matched, coloured)


def _layerLineColours(arrays, layer_moves, rgb):
    """Per polygon: (lines, 3) colours (NaN = keep Cura's), and (extrusion lines, matched, coloured)."""
    if layer_moves is None or rgb is None or not layer_moves.xy:
        extrusions = sum(int((~numpy.isin(types, JUMP_TYPES)).sum()) for types, _ in arrays)
        return [None] * len(arrays), (extrusions, 0, 0)
    move_xy = numpy.asarray(layer_moves.xy, dtype=numpy.float64)
    ends, extruding = [], []
    for types, data in arrays:
        ends.append(numpy.column_stack((data[1:, 0], -data[1:, 2])))
        extruding.append(~numpy.isin(types, JUMP_TYPES))
    all_ends = numpy.concatenate(ends) if ends else numpy.zeros((0, 2))
    all_extruding = numpy.concatenate(extruding) if extruding else numpy.zeros(0, dtype=bool)
    found = matchLayer(all_ends[all_extruding], move_xy)
    line_rgb = numpy.full((len(all_ends), 3), numpy.nan)
    hit = found >= 0
    extrusion_rows = numpy.flatnonzero(all_extruding)
    line_rgb[extrusion_rows[hit]] = rgb[found[hit]]
    result, start = [], 0
    for e in ends:
        result.append(line_rgb[start:start + len(e)])
        start += len(e)
    coloured = int((~numpy.isnan(line_rgb[extrusion_rows[hit], 0])).sum())
    return result, (int(all_extruding.sum()), int(hit.sum()), coloured)
