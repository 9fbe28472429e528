#!/usr/bin/env python3
"""Writes a closed, dense heightfield model as binary STL (for the memory benchmark and test).

    dense_model.py OUT.stl [--cells 1000]

An 80 x 80 mm block whose top is the surface z = 12 + 4 sin(x / 5) cos(y / 7) mm over a grid of
cells x cells squares (2 triangles each), closed by four side walls and a bottom fan: with the default
1000 cells it has 2,012,000 triangles (100.6 MB). Deterministic; written to OUT.stl.tmp, then renamed.
"""
import argparse
from pathlib import Path

import numpy as np

SIZE_MM = 80.0


def height(x, y):
    return 12.0 + 4.0 * np.sin(x / 5.0) * np.cos(y / 7.0)


def triangles(cells):
    g = np.linspace(0.0, SIZE_MM, cells + 1)
    x, y = np.meshgrid(g, g, indexing="ij")
    top = np.stack([x, y, height(x, y)], axis=-1)              # (cells+1, cells+1, 3)
    a, b = top[:-1, :-1], top[1:, :-1]                         # quad corners a b c d, counter-clockwise
    c, d = top[1:, 1:], top[:-1, 1:]
    quads = [np.stack([a, b, c], axis=-2), np.stack([a, c, d], axis=-2)]
    parts = [q.reshape(-1, 3, 3) for q in quads]
    # the boundary of the top, walked counter-clockwise seen from above
    ring = np.concatenate([top[:, 0], top[-1, 1:], top[-2::-1, -1], top[0, -2:0:-1]])
    nxt = np.roll(ring, -1, axis=0)
    low, low_next = ring.copy(), nxt.copy()
    low[:, 2] = 0.0
    low_next[:, 2] = 0.0
    parts.append(np.stack([low, low_next, nxt], axis=1))       # side walls, outward
    parts.append(np.stack([low, nxt, ring], axis=1))
    centre = np.broadcast_to([SIZE_MM / 2, SIZE_MM / 2, 0.0], low.shape)
    parts.append(np.stack([centre, low_next, low], axis=1))    # bottom fan, facing down
    return np.concatenate(parts).astype("<f4")


def write_stl(tris, path):
    record = np.dtype([("normal", "<f4", 3), ("vertices", "<f4", (3, 3)), ("attribute", "<u2")])
    data = np.zeros(len(tris), dtype=record)
    data["vertices"] = tris
    tmp = Path(str(path) + ".tmp")
    with open(tmp, "wb") as f:
        f.write(b"MixEngine dense heightfield benchmark model".ljust(80, b" "))
        f.write(np.uint32(len(tris)).tobytes())
        data.tofile(f)
    tmp.replace(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", type=Path)
    ap.add_argument("--cells", type=int, default=1000)
    args = ap.parse_args()
    tris = triangles(args.cells)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    write_stl(tris, args.out)
    print(f"dense_model.py: {args.out} ({len(tris)} triangles, {args.out.stat().st_size / 1e6:.1f} MB)")


if __name__ == "__main__":
    main()
