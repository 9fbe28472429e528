"""Print quality of a G-code file against the model it was sliced from, layer by layer.

For every layer of the G-code (index >= 0, i.e. no raft):
  E  = the layer's model extrusions (every ;TYPE: except skirt/brim, support and prime tower, see
       NON_MODEL_FEATURES), each segment drawn as a capsule (the set of points within w/2 of the segment) of
       its real width w = filament volume / (length x layer thickness), filament volume = E x pi (d/2)^2
       (gcode_model.segment_widths_mm);
  S  = the model's cross-section at the layer's mid height (z - thickness / 2: where CuraEngine's default
       slicing_tolerance "middle" cuts), computed by trimesh from the mesh file, moved by the engine's
       machine offset (the bed centre unless machine_center_is_zero); where the mesh is open (a scan with
       holes) the section's open pieces are joined nearest ends first up to 10 mm and closed by straight
       lines, as CuraEngine 4.13 stitches them (ModelSections);
  S+ = S grown by `tolerance_mm` (shapely buffer).
All three are rasterised on the same grid of `grid_mm` squares: a square counts when its centre lies inside
(capsules by exact per-row intervals, polygons by the even-odd rule on the row through the centre).

Metrics, each a sum over layers of square counts times the square's area (mm²):
  section  = |S|,   extruded = |E|,   covered = |E ∩ S|,   outside = |E \\ S+|
  coverage      = covered / section   (the share of the model's cross-sections that received material;
                                       with sparse infill it is well below 1, so compare engines at equal
                                       settings, not against 1)
  outside_ratio = outside / section   (material laid more than tolerance_mm beyond the model's outline,
                                       relative to the model's size)
Defaults: grid 0.05 mm (an eighth of a 0.4 mm line, so a wall's width is resolved to about +-6 %);
tolerance 0.1 mm: a quarter of a 0.4 mm line. An outer wall placed correctly (inset by half its width)
ends on the outline, and simplification/raster error stay below ~0.05 mm; an outer wall not inset at all
overshoots by half a line (0.2 mm) and half of that overshoot is counted, so the tolerance hides rounding but
not a missing inset.
"""
from dataclasses import dataclass, field

import numpy as np

import gcode_model

NON_MODEL_FEATURES = ("SKIRT", "SUPPORT", "SUPPORT-INTERFACE", "SUPPORT-INFILL", "SUPPORT-ROOF",
                      "SUPPORT-BOTTOM", "PRIME-TOWER", "PRIME_TOWER")
GRID_MM = 0.05
TOLERANCE_MM = 0.1
MAX_WIDTH_FACTOR = 4.0  # a segment wider than 4 nozzles is drawn 4 nozzles wide (a blob, not a line)


@dataclass
class Grid:
    """Square centres at (ox + i g, oy + j g) for 0 <= i < nx, 0 <= j < ny."""
    ox: float
    oy: float
    g: float
    nx: int
    ny: int

    # Square centres sit 0.37 g off the multiples of g (18.5 µm for g = 0.05): G-code coordinates are whole
    # microns, so a line's edge (centre line +- half of a 0.4 mm width) never falls exactly on a row of
    # centres, where rounding would decide between a full row too many and a gap between touching lines.
    PHASE = 0.37

    @staticmethod
    def around(xmin, ymin, xmax, ymax, g):
        ox = (np.floor(xmin / g) - 1 + Grid.PHASE) * g
        oy = (np.floor(ymin / g) - 1 + Grid.PHASE) * g
        nx, ny = int(np.ceil((xmax - ox) / g)) + 2, int(np.ceil((ymax - oy) / g)) + 2
        return Grid(float(ox), float(oy), g, nx, ny)


def _fill_intervals(grid, rows, lo, hi, parity=False):
    """Marks, on each row, the squares whose centre x lies in [lo, hi] (parity=False: union of intervals),
    or toggles every square from column ceil(lo) on (parity=True, hi ignored: even-odd crossings)."""
    width = grid.nx + 1
    c0 = np.ceil((lo - grid.ox) / grid.g - 1e-9)
    if parity:
        c0 = np.clip(c0, 0, grid.nx).astype(np.int64)
        counts = np.bincount(rows * width + c0, minlength=grid.ny * width).astype(np.uint8)
        # uint8 sums wrap modulo 256, which keeps their parity
        return (np.cumsum(counts.reshape(grid.ny, width), axis=1, dtype=np.uint8)[:, :grid.nx] & 1).astype(bool)
    c1 = np.floor((hi - grid.ox) / grid.g + 1e-9)
    keep = (c1 >= c0) & (c1 >= 0) & (c0 <= grid.nx - 1)
    c0 = np.clip(c0[keep], 0, grid.nx - 1).astype(np.int64)
    c1 = np.clip(c1[keep], 0, grid.nx - 1).astype(np.int64)
    r = rows[keep]
    counts = (np.bincount(r * width + c0, minlength=grid.ny * width)
              - np.bincount(r * width + c1 + 1, minlength=grid.ny * width)).astype(np.int32)
    return np.cumsum(counts.reshape(grid.ny, width), axis=1, dtype=np.int32)[:, :grid.nx] > 0


def _expand_rows(grid, ylo, yhi, closed_top=True):
    """For items spanning [ylo, yhi], every row whose centre lies in it (closed, or [ylo, yhi) when
    closed_top is False): returns (item index per pair, row per pair, row centre y per pair)."""
    j0 = np.maximum(np.ceil((ylo - grid.oy) / grid.g - 1e-9), 0).astype(np.int64)
    if closed_top:
        j1 = np.floor((yhi - grid.oy) / grid.g + 1e-9).astype(np.int64)
    else:
        j1 = np.ceil((yhi - grid.oy) / grid.g - 1e-9).astype(np.int64) - 1
    j1 = np.minimum(j1, grid.ny - 1)
    n = np.maximum(j1 - j0 + 1, 0)
    item = np.repeat(np.arange(len(n)), n)
    start = np.repeat(np.cumsum(n) - n, n)
    rows = j0[item] + (np.arange(int(n.sum())) - start)
    return item, rows, grid.oy + rows * grid.g


def rasterise_capsules(grid, x0, y0, x1, y1, radius):
    """Squares whose centre is within radius of segment (x0,y0)-(x1,y1), for arrays of segments."""
    if len(x0) == 0:
        return np.zeros((grid.ny, grid.nx), bool)
    item, rows, yc = _expand_rows(grid, np.minimum(y0, y1) - radius, np.maximum(y0, y1) + radius)
    ax, ay, bx, by, r = x0[item], y0[item], x1[item], y1[item], radius[item]
    lo, hi = np.full(len(item), np.inf), np.full(len(item), -np.inf)
    for cx, cy in ((ax, ay), (bx, by)):  # end disks
        dy = yc - cy
        h2 = r * r - dy * dy
        half = np.sqrt(np.maximum(h2, 0))
        ok = h2 >= 0
        lo = np.where(ok, np.minimum(lo, cx - half), lo)
        hi = np.where(ok, np.maximum(hi, cx + half), hi)
    dx, dyv = bx - ax, by - ay
    length = np.hypot(dx, dyv)
    with np.errstate(divide="ignore", invalid="ignore"):
        ux, uy = dx / length, dyv / length
        rlo, rhi = _band(yc - ay, ux, uy, 0.0, length)          # 0 <= along <= length
        slo, shi = _band(yc - ay, -uy, ux, -r, r)              # |across| <= r
    rect_lo, rect_hi = np.maximum(rlo, slo) + ax, np.minimum(rhi, shi) + ax
    ok = (length > 0) & (rect_lo <= rect_hi)
    lo = np.where(ok, np.minimum(lo, rect_lo), lo)
    hi = np.where(ok, np.maximum(hi, rect_hi), hi)
    return _fill_intervals(grid, rows, lo, hi)


def _band(dy, kx, ky, vmin, vmax):
    """x offsets (from the segment start) where vmin <= x kx + dy ky <= vmax on a row at height dy."""
    rest = dy * ky
    steep = np.abs(kx) < 1e-12
    with np.errstate(divide="ignore", invalid="ignore"):
        a, b = (vmin - rest) / kx, (vmax - rest) / kx
    inside = (rest >= vmin - 1e-12) & (rest <= vmax + 1e-12)
    lo = np.where(steep, np.where(inside, -np.inf, np.inf), np.minimum(a, b))
    hi = np.where(steep, np.where(inside, np.inf, -np.inf), np.maximum(a, b))
    return lo, hi


def rasterise_polygons(grid, geometry):
    """Squares whose centre lies inside a shapely (Multi)Polygon (even-odd rule over all its rings)."""
    import shapely
    rings = shapely.get_rings(shapely.get_parts(geometry)) if not geometry.is_empty else []
    xs0, ys0, xs1, ys1 = [], [], [], []
    for ring in rings:
        c = shapely.get_coordinates(ring)
        xs0.append(c[:-1, 0]), ys0.append(c[:-1, 1]), xs1.append(c[1:, 0]), ys1.append(c[1:, 1])
    if not xs0:
        return np.zeros((grid.ny, grid.nx), bool)
    x0, y0, x1, y1 = (np.concatenate(a) for a in (xs0, ys0, xs1, ys1))
    keep = y0 != y1
    x0, y0, x1, y1 = x0[keep], y0[keep], x1[keep], y1[keep]
    item, rows, yc = _expand_rows(grid, np.minimum(y0, y1), np.maximum(y0, y1), closed_top=False)
    t = (yc - y0[item]) / (y1[item] - y0[item])
    xc = x0[item] + t * (x1[item] - x0[item])
    return _fill_intervals(grid, rows, xc, None, parity=True)


STITCH_MM = 10.0  # CuraEngine 4.13 joins open section pieces whose ends are up to 10 mm apart


def _stitched_rings(chains, max_mm=STITCH_MM):
    """Open polylines joined end to end, nearest pair of ends first (reversing a piece where needed), a
    piece whose own two ends are the nearest pair closing into a ring: as CuraEngine 4.13 stitches the open
    cut of a mesh with holes. Returns the rings (pieces left open are dropped)."""
    chains = [np.asarray(c, float) for c in chains if len(c) >= 2]
    rings = []
    while chains:
        best = None
        for i, a in enumerate(chains):
            if len(a) >= 3:
                d = float(np.hypot(*(a[0] - a[-1])))
                if d <= max_mm and (best is None or d < best[0]):
                    best = (d, i, None, None)
            for j in range(i + 1, len(chains)):
                b = chains[j]
                for ea, pa in ((0, a[0]), (1, a[-1])):
                    for eb, pb in ((0, b[0]), (1, b[-1])):
                        d = float(np.hypot(*(pa - pb)))
                        if d <= max_mm and (best is None or d < best[0]):
                            best = (d, i, j, (ea, eb))
        if best is None:
            break
        _, i, j, ends = best
        if j is None:
            rings.append(chains.pop(i))
            continue
        a, b = chains[i], chains[j]
        a = a[::-1] if ends[0] == 0 else a        # a now ends at the joined end
        b = b if ends[1] == 0 else b[::-1]        # b now starts at it
        chains[i] = np.vstack([a, b])
        chains.pop(j)
    return rings


def _section_geometry(section):
    """The section's solid as shapely geometry in its own 2D frame: trimesh's closed polygons, or, when the
    mesh is open there, every closed ring and the open pieces stitched into rings (_stitched_rings), filled
    by the even-odd rule."""
    import shapely
    open_chains = [e.discrete(section.vertices) for e in section.entities if not e.closed]
    if not open_chains:
        polys = list(section.polygons_full)
        return shapely.union_all(polys) if polys else shapely.Polygon()
    rings = [e.discrete(section.vertices) for e in section.entities if e.closed] + _stitched_rings(open_chains)
    geometry = shapely.Polygon()
    for ring in rings:
        if len(ring) >= 3:
            geometry = geometry.symmetric_difference(shapely.make_valid(shapely.Polygon(ring)))
    return geometry


class ModelSections:
    """trimesh cross-sections of a mesh file, as shapely geometry in the mesh's own XY frame. Where the mesh
    is open (a scan with holes), the open pieces of a section are stitched as CuraEngine 4.13 does
    (_stitched_rings), so that the section is what a slicer following CuraEngine prints."""

    def __init__(self, mesh_path):
        import trimesh
        self.mesh = trimesh.load(mesh_path, force="mesh")

    def at(self, zs):
        import shapely
        from shapely import affinity
        zs = list(zs)
        if not zs:
            return []
        sections = self.mesh.section_multiplane([0, 0, 0], [0, 0, 1], zs)
        out = []
        for s in sections:
            if s is None:
                out.append(shapely.Polygon())
                continue
            t = s.metadata.get("to_3D", np.eye(4))  # the 2D frame of the section -> mesh XY
            out.append(affinity.affine_transform(_section_geometry(s),
                                                 [t[0, 0], t[0, 1], t[1, 0], t[1, 1], t[0, 3], t[1, 3]]))
        return out


@dataclass
class LayerQuality:
    index: int
    z_mm: float
    section_mm2: float
    extruded_mm2: float
    covered_mm2: float
    outside_mm2: float


@dataclass
class Quality:
    layers: list = field(default_factory=list)
    grid_mm: float = GRID_MM
    tolerance_mm: float = TOLERANCE_MM

    def total(self, key):
        return sum(getattr(q, key) for q in self.layers)

    @property
    def coverage(self):
        s = self.total("section_mm2")
        return self.total("covered_mm2") / s if s else float("nan")

    @property
    def outside_ratio(self):
        s = self.total("section_mm2")
        return self.total("outside_mm2") / s if s else float("nan")

    def as_dict(self):
        return {"coverage": self.coverage, "outside_ratio": self.outside_ratio, "grid_mm": self.grid_mm,
                "tolerance_mm": self.tolerance_mm, "layers": [vars(q) for q in self.layers]}


def capsules(model, layer, filament_diameter_mm, nozzle_mm, model_features=True):
    """(x0, y0, x1, y1, radius) of the layer's model extrusions (or, model_features=False, of the others:
    skirt/brim, support, prime tower). Widths are capped at MAX_WIDTH_FACTOR nozzles."""
    mask = model.feature_mask(layer, NON_MODEL_FEATURES)
    if model_features:
        mask = ~mask
    if layer.thickness_mm and layer.thickness_mm > 0:
        widths = gcode_model.segment_widths_mm(model, layer, filament_diameter_mm)
    else:
        widths = np.zeros(len(layer.e))
    widths = np.minimum(widths, MAX_WIDTH_FACTOR * nozzle_mm)
    return layer.x0[mask], layer.y0[mask], layer.x1[mask], layer.y1[mask], widths[mask] / 2


def _bounds(x0, y0, x1, y1, r):
    if not len(x0):
        return None
    rmax = float(r.max())
    return (min(x0.min(), x1.min()) - rmax, min(y0.min(), y1.min()) - rmax,
            max(x0.max(), x1.max()) + rmax, max(y0.max(), y1.max()) + rmax)


def layer_rasters(model, layer, section, offset_xy, filament_diameter_mm, nozzle_mm, grid_mm=GRID_MM,
                  tolerance_mm=TOLERANCE_MM, grid=None, others=False):
    """Rasters of one layer as a dict: grid, E (model extrusions), S (section), S+ (section grown by the
    tolerance) and, with others=True, O (the other extrusions). section is in mesh coordinates and is moved
    by offset_xy. Without a grid, one is made around S+ and E; None when both are empty."""
    from shapely import affinity
    section = affinity.translate(section, offset_xy[0], offset_xy[1])
    grown = section.buffer(tolerance_mm, quad_segs=16) if not section.is_empty else section
    caps = capsules(model, layer, filament_diameter_mm, nozzle_mm)
    if grid is None:
        boxes = [b for b in (None if grown.is_empty else grown.bounds, _bounds(*caps)) if b is not None]
        if not boxes:
            return None
        b = np.array(boxes)
        grid = Grid.around(b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max(), grid_mm)
    out = {"grid": grid, "E": rasterise_capsules(grid, *caps), "S": rasterise_polygons(grid, section),
           "S+": rasterise_polygons(grid, grown)}
    if others:
        out["O"] = rasterise_capsules(grid, *capsules(model, layer, filament_diameter_mm, nozzle_mm, False))
    return out


def layer_extent(model, layer, section, offset_xy, filament_diameter_mm, nozzle_mm, margin_mm=1.0):
    """(xmin, ymin, xmax, ymax) of the section (moved by offset_xy) and all extrusions, plus margin_mm."""
    boxes = [_bounds(*capsules(model, layer, filament_diameter_mm, nozzle_mm, flag)) for flag in (True, False)]
    if not section.is_empty:
        x0, y0, x1, y1 = section.bounds
        boxes.append((x0 + offset_xy[0], y0 + offset_xy[1], x1 + offset_xy[0], y1 + offset_xy[1]))
    b = np.array([x for x in boxes if x is not None])
    if b.size == 0:  # nothing printed and no section on this layer (e.g. an open scan's stray top)
        return None
    return (b[:, 0].min() - margin_mm, b[:, 1].min() - margin_mm, b[:, 2].max() + margin_mm,
            b[:, 3].max() + margin_mm)


def layer_mid_heights(model, lift_mm=0.0):
    """{layer index: z of the model section it is compared with} for layers >= 0 with a height. lift_mm: how
    far the print raised the model (a raft: side_by_side.raft_lift_mm), taken off every layer's height."""
    return {i: model.layers[i].z_mm - lift_mm - model.layers[i].thickness_mm / 2 for i in sorted(model.layers)
            if i >= 0 and model.layers[i].z_mm is not None}


def measure(model, mesh_path, offset_xy, filament_diameter_mm, nozzle_mm=0.4, grid_mm=GRID_MM,
            tolerance_mm=TOLERANCE_MM, sections=None, lift_mm=0.0):
    """Quality of a gcode_model.Model against the mesh at mesh_path (or a ModelSections of it); lift_mm as in
    layer_mid_heights."""
    mids = layer_mid_heights(model, lift_mm)
    sections = sections or ModelSections(mesh_path)
    q = Quality(grid_mm=grid_mm, tolerance_mm=tolerance_mm)
    area = grid_mm * grid_mm
    for i, section in zip(mids, sections.at(mids.values())):
        layer = model.layers[i]
        r = layer_rasters(model, layer, section, offset_xy, filament_diameter_mm, nozzle_mm, grid_mm, tolerance_mm)
        if r is None:
            q.layers.append(LayerQuality(i, layer.z_mm, 0.0, 0.0, 0.0, 0.0))
            continue
        e, s = r["E"], r["S"]
        q.layers.append(LayerQuality(i, layer.z_mm, float(s.sum()) * area, float(e.sum()) * area,
                                     float((e & s).sum()) * area, float((e & ~r["S+"]).sum()) * area))
    return q
