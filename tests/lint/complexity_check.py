#!/usr/bin/env python3
"""Fails when a function is more complex than the project allows.

    complexity_check.py [--max-ccn N] PATH...

Measures every function in the source files under each PATH with lizard (cyclomatic complexity, CCN,
as `lizard -C N -w` counts it), prints one line per function above N -- "file:line: name has CCN c
(limit N)" -- and exits 1 when there is any, 0 otherwise. The default limit is the project's, 20.
"""
import argparse
import sys

import lizard

DEFAULT_MAX_CCN = 20


def offenders(paths, max_ccn):
    """(file, line, name, ccn) of every function under `paths` with a CCN above `max_ccn`."""
    found = []
    for file_info in lizard.analyze(paths):
        for f in file_info.function_list:
            if f.cyclomatic_complexity > max_ccn:
                found.append((f.filename, f.start_line, f.name, f.cyclomatic_complexity))
    return sorted(found)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-ccn", type=int, default=DEFAULT_MAX_CCN)
    parser.add_argument("paths", nargs="+")
    args = parser.parse_args(argv)
    found = offenders(args.paths, args.max_ccn)
    for filename, line, name, ccn in found:
        print(f"{filename}:{line}: {name} has CCN {ccn} (limit {args.max_ccn})")
    if found:
        print(f"{len(found)} function(s) above CCN {args.max_ccn}: split them (tables, named rules, helpers)")
        return 1
    print(f"no function above CCN {args.max_ccn} in {' '.join(args.paths)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
