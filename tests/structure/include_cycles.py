#!/usr/bin/env python3
"""Fails when the stage folders of the engine include each other in a cycle.

    python3 tests/structure/include_cycles.py ENGINE_DIR

Every stage is a top-level folder of ENGINE_DIR (common, geometry, settings, ..., pipeline). A subfolder
(settings/formula, settings/profiles, communication/arcus) is part of its top-level stage: it is that
stage's inside, and the pipeline order is an order of stages. A file directly in ENGINE_DIR (main.cpp)
is the node "(top)".

An edge A -> B is a line `#include "B/..."` (or `<B/...>`) in a .h or .cpp file under A, where B is a
top-level folder of ENGINE_DIR; includes of the own stage and of other libraries are not edges. The
folders of a strongly connected component of more than one folder include each other in a cycle
(Tarjan's algorithm). For each such component the script finds an order of its folders, lowest first,
against which the fewest include lines run (an upward include: a folder including one later in the
order; exact, by dynamic programming over subsets), prints that order and those include lines
(file:line: text) — the ones to move — and exits 1. Otherwise it prints a one-line summary and exits
0. Exit 2: ENGINE_DIR is not a directory.

    python3 tests/structure/include_cycles.py --rooms ENGINE_DIR
    python3 tests/structure/include_cycles.py --sizes ENGINE_DIR
    python3 tests/structure/include_cycles.py --clipper ENGINE_DIR

--rooms: the same check one level down. A room is a subfolder of a stage (toolpaths/infill,
mixing/color, settings/formula); the files directly in a stage folder are its room "stage/(top)". An
edge is an include from one room to another room of the same stage (`#include "toolpaths/infill/X.h"`
in toolpaths/walls, or `#include "toolpaths/GroupToolpaths.h"` in toolpaths/support); rooms of a
stage include each other without a cycle, the stages' order being checked above.
--sizes: every folder under ENGINE_DIR (ENGINE_DIR itself included) holds at most 30 C++ files
(.h, .hpp, .cpp, .cc) directly; the ones holding more are printed with their count (exit 1).
--clipper: only engine/geometry/ (the polygon facade, geometry/PolygonOps.h) names Clipper: a line
of a file elsewhere that mentions `ClipperLib` or includes clipper.hpp is printed (exit 1).
"""
import re
import sys
from collections import defaultdict
from pathlib import Path

INCLUDE = re.compile(r'^\s*#\s*include\s*["<]([^">]+)[">]')
SOURCE_SUFFIXES = {".h", ".hpp", ".cpp", ".cc"}
TOP = "(top)"


def stage_of(root, path):
    parts = path.relative_to(root).parts
    return parts[0] if len(parts) > 1 else TOP


def room_of(parts):
    """'stage/room' for the parts of a path below ENGINE_DIR (the file name last), 'stage/(top)' for a
    file directly in the stage folder."""
    return f"{parts[0]}/{parts[1] if len(parts) > 2 else TOP}"


def source_files(root):
    return sorted(p for p in root.rglob("*") if p.is_file() and p.suffix in SOURCE_SUFFIXES)


def include_edges(root, rooms=False):
    """{(from, to): [(file, line number, text)]} for includes between different stages, or (rooms)
    between different rooms of one stage."""
    stages = {p.name for p in root.iterdir() if p.is_dir()}
    edges = defaultdict(list)
    for path in source_files(root):
        source = stage_of(root, path)
        for number, text in enumerate(path.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(text)
            if not match or "/" not in match.group(1):
                continue
            target = match.group(1).split("/", 1)[0]
            if target not in stages:
                continue
            if rooms:
                if target != source:
                    continue
                target = room_of(match.group(1).split("/"))
                source_room = room_of(path.relative_to(root).parts)
                if target != source_room:
                    edges[(source_room, target)].append((path.relative_to(root), number, text.strip()))
            elif target != source:
                edges[(source, target)].append((path.relative_to(root), number, text.strip()))
    return edges


def strongly_connected(nodes, successors):
    """Tarjan's algorithm (iterative): the components, each a sorted list of nodes."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    for start in sorted(nodes):
        if start in index:
            continue
        work = [(start, iter(sorted(successors[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(successors[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                components.append(sorted(component))
    return components


def cheapest_order(component, weight):
    """The order of `component` (lowest first) with the fewest include lines from a folder to a later one.

    weight[(a, b)]: include lines a -> b. Dynamic programming over the subsets placed first; adding
    folder v above the set S costs the includes from S up to v. Ties go to the alphabetically first."""
    nodes = sorted(component)
    best = {0: (0, [])}
    for mask in range(1 << len(nodes)):
        if mask not in best:
            continue
        cost, order = best[mask]
        for bit, node in enumerate(nodes):
            if mask & (1 << bit):
                continue
            added = cost + sum(weight.get((lower, node), 0) for lower in order)
            key = mask | (1 << bit)
            if key not in best or added < best[key][0]:
                best[key] = (added, order + [node])
    return best[(1 << len(nodes)) - 1][1]


def cycles(root, rooms=False):
    """[(order, [(from, to, file, line, text)])] for every cycle of stage folders (or of rooms inside a
    stage) under root: the folders in the cheapest order and the include lines that run upward against
    it."""
    edges = include_edges(root, rooms)
    successors = defaultdict(set)
    nodes = set()
    for source, target in edges:
        successors[source].add(target)
        nodes.update((source, target))
    found = []
    for component in strongly_connected(nodes, successors):
        if len(component) < 2:
            continue
        weight = {key: len(places) for key, places in edges.items()}
        order = cheapest_order(component, weight)
        rank = {node: i for i, node in enumerate(order)}
        lines = [(s, t, *where) for (s, t), places in sorted(edges.items())
                 if s in rank and t in rank and rank[s] < rank[t] for where in places]
        found.append((order, lines))
    return found, len(nodes), sum(len(v) for v in edges.values())


MAX_FILES_PER_FOLDER = 30
CLIPPER = re.compile(r"ClipperLib|^\s*#\s*include\s*[\"<][^\">]*clipper")


def crowded_folders(root):
    """[(folder relative to root, C++ file count)] for the folders holding more than 30 directly."""
    crowded = []
    for folder in sorted([root, *(p for p in root.rglob("*") if p.is_dir())]):
        count = sum(1 for p in folder.iterdir() if p.is_file() and p.suffix in SOURCE_SUFFIXES)
        if count > MAX_FILES_PER_FOLDER:
            crowded.append((folder.relative_to(root), count))
    return crowded


def clipper_lines(root):
    """[(file, line number, text)]: the lines outside geometry/ that name ClipperLib or include clipper."""
    found = []
    for path in source_files(root):
        if path.relative_to(root).parts[0] == "geometry":
            continue
        for number, text in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if CLIPPER.search(text):
                found.append((path.relative_to(root), number, text.strip()))
    return found


def check_sizes(root):
    crowded = crowded_folders(root)
    if not crowded:
        print(f"every folder of {root} holds at most {MAX_FILES_PER_FOLDER} C++ files directly")
        return 0
    for folder, count in crowded:
        print(f"{folder}: {count} C++ files directly (at most {MAX_FILES_PER_FOLDER}: split it into rooms)")
    return 1


def check_clipper(root):
    found = clipper_lines(root)
    if not found:
        print(f"only geometry/ names Clipper under {root}")
        return 0
    print(f"{len(found)} line(s) outside geometry/ name Clipper (use geometry/PolygonOps.h instead):")
    for path, number, text in found:
        print(f"  {path}:{number}: {text}")
    return 1


def main(argv):
    modes = {"--rooms": "rooms", "--sizes": "sizes", "--clipper": "clipper"}
    mode = modes.get(argv[1]) if len(argv) == 3 else "stages"
    if len(argv) not in (2, 3) or mode is None or not Path(argv[-1]).is_dir():
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    root = Path(argv[-1]).resolve()
    if mode == "sizes":
        return check_sizes(root)
    if mode == "clipper":
        return check_clipper(root)
    rooms = mode == "rooms"
    found, folder_count, include_count = cycles(root, rooms)
    if not found:
        what = "rooms inside the stage folders" if rooms else "stage folders"
        print(f"no include cycle between the {folder_count} {what} of {root} "
              f"({include_count} includes between them)")
        return 0
    for order, lines in found:
        print(f"include cycle between {len(order)} folders: {', '.join(sorted(order))}")
        print(f"  the order against which the fewest includes run (lowest first): {' < '.join(order)}")
        print(f"  the {len(lines)} include line(s) against it (move the type or feed the stage instead):")
        for source, target, path, number, text in lines:
            print(f"  {source} -> {target}: {path}:{number}: {text}")
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
