#!/usr/bin/env python3
"""List the library sources that have no mirrored test (the house rule of tests/CMakeLists.txt).

Rule: every library source <dir>/src/<name>.cpp, for <dir> one of the library folders below, has
its test tests/<dir>/<name>_test.cpp (solver/kernel/src/point_schedule.cpp ->
tests/solver/kernel/point_schedule_test.cpp). Only the .cpp files directly in <dir>/src count;
private headers (<dir>/src/*.hpp) are tested through the sources that include them.

Usage: tools/dev/mirrored_tests.py [--check] [ROOT]   (ROOT: the repository, default the current directory)
Prints one line per source without its test, `<source>  (expected <test>)`, then the count on
stderr. With --check: exit 1 when any is missing, else 0 with a one-line count of the sources checked.
"""
import argparse
import pathlib
import sys

LIBRARY_DIRS = [
    "core",
    "solver/kernel",
    "solver/analysis",
    "solver/synthesis",
    "catalog",
    "tools/api",
    "tools/plot",
    "tools/export",
]


def mirrored(root):
    """(source, expected test, exists) for every library source under `root`, sorted by source."""
    for d in LIBRARY_DIRS:
        src = root / d / "src"
        if not src.is_dir():
            raise FileNotFoundError(f"{src} is no folder: is {root} the repository's root?")
        for source in sorted(src.glob("*.cpp")):
            test = root / "tests" / d / f"{source.stem}_test.cpp"
            yield source.relative_to(root), test.relative_to(root), test.is_file()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("root", nargs="?", default=".", help="the repository's root (default: the current directory)")
    parser.add_argument("--check", action="store_true", help="exit 1 when a library source has no mirrored test")
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    try:
        found = list(mirrored(root))
    except FileNotFoundError as e:
        print(e, file=sys.stderr)
        return 2
    missing = [(source, test) for source, test, exists in found if not exists]
    for source, test in missing:
        print(f"{source}  (expected {test})")
    if args.check:
        if missing:
            print(f"{len(missing)} of {len(found)} library sources have no mirrored test", file=sys.stderr)
            return 1
        print(f"all {len(found)} library sources have their mirrored test")
        return 0
    print(f"{len(missing)} of {len(found)} library sources without a mirrored test", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
