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


def include_edges(root):
    """{(from stage, to stage): [(file, line number, text)]} for includes between different stages."""
    stages = {p.name for p in root.iterdir() if p.is_dir()}
    edges = defaultdict(list)
    for path in sorted(p for p in root.rglob("*") if p.is_file() and p.suffix in SOURCE_SUFFIXES):
        source = stage_of(root, path)
        for number, text in enumerate(path.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(text)
            if not match or "/" not in match.group(1):
                continue
            target = match.group(1).split("/", 1)[0]
            if target in stages and target != source:
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


def cycles(root):
    """[(order, [(from, to, file, line, text)])] for every cycle of stage folders under root: the folders
    in the cheapest order and the include lines that run upward against it."""
    edges = include_edges(root)
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


def main(argv):
    if len(argv) != 2 or not Path(argv[1]).is_dir():
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    root = Path(argv[1]).resolve()
    found, folder_count, include_count = cycles(root)
    if not found:
        print(f"no include cycle between the {folder_count} stage folders of {root} "
              f"({include_count} includes between folders)")
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
