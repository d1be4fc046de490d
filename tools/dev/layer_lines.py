#!/usr/bin/env python3
"""Lines of code per layer of the house (README "Design"), at a git revision or in the work tree.

    tools/dev/layer_lines.py [REVISION ...]

One column per revision (the work tree when none is given): the layers core -> kernel ->
analysis -> synthesis -> catalog -> api -> {cli, python}, the picture library, tests. Lines are
all lines of the C++/Python sources (.cpp, .hpp, .h, .py, .pyi) under each layer's folder; the
closing note of the one-front-door issue gives these before and after.
"""
import subprocess
import sys
from pathlib import Path

LAYERS = [
    ("core", "core/"),
    ("kernel", "solver/kernel/"),
    ("analysis", "solver/analysis/"),
    ("synthesis", "solver/synthesis/"),
    ("catalog", "catalog/"),
    ("api", "tools/api/"),
    ("cli", "tools/cli/"),
    ("python", "tools/python/"),
    ("plot+export", ("tools/plot/", "tools/export/")),
    ("tests", "tests/"),
]
SOURCES = (".cpp", ".hpp", ".h", ".py", ".pyi")


def files(revision):
    if revision is None:
        out = subprocess.run(["git", "ls-files"], capture_output=True, text=True, check=True).stdout
    else:
        out = subprocess.run(["git", "ls-tree", "-r", "--name-only", revision], capture_output=True, text=True, check=True).stdout
    return [f for f in out.splitlines() if f.endswith(SOURCES)]


def lines(revision, path):
    if revision is None:
        return Path(path).read_text(errors="replace").count("\n")
    blob = subprocess.run(["git", "show", f"{revision}:{path}"], capture_output=True, check=True).stdout
    return blob.count(b"\n")


def count(revision):
    totals = {name: 0 for name, _ in LAYERS}
    for f in files(revision):
        for name, prefix in LAYERS:
            if f.startswith(prefix):
                totals[name] += lines(revision, f)
                break
    return totals


def main():
    revisions = sys.argv[1:] or [None]
    columns = [count(r) for r in revisions]
    header = ["layer"] + [r or "work tree" for r in revisions]
    print(",".join(header))
    for name, _ in LAYERS:
        print(",".join([name] + [str(c[name]) for c in columns]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
