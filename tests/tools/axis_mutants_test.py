#!/usr/bin/env python3
"""The slot axis fuzz: catalog/entries/proportional-linkage.yaml with its slot S23 given an axis
that is not along its two points (seeded random directions, from near the slot's own to 1e9
askew). Such a slot runs its blocks off to infinity or ends the branch at limit points; walks
that hung (export --dxf still running after 900 s) must each answer within 5 s, with exit 0 or 1
and a message, never a crash or "internal error".

Usage: axis_mutants_test.py KOPPEL CATALOG_DIR [COUNT]
"""
import pathlib
import random
import subprocess
import sys
import tempfile
import time

SECONDS = 5.0
SLOT = "S23: {type: P, links: [slot, block2], points: [B0, A], axis: [1, 0]}"


def axes(count):
    random.seed(38)
    # the issue's own two, then random ones over many magnitudes
    yield (1, 360)
    yield (1, 1e9)
    for _ in range(count - 2):
        kind = random.random()
        if kind < 0.4:
            yield (random.uniform(-10, 10), random.uniform(-10, 10))
        else:
            yield (random.uniform(-1, 1) * 10 ** random.randint(-9, 9), random.uniform(-1, 1) * 10 ** random.randint(-9, 9))


def main():
    koppel, catalog = sys.argv[1], pathlib.Path(sys.argv[2])
    count = int(sys.argv[3]) if len(sys.argv) > 3 else 24
    source = (catalog / "proportional-linkage.yaml").read_text()
    assert SLOT in source, "the slot line of proportional-linkage.yaml changed"
    failures, slowest = [], 0.0
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        for i, (x, y) in enumerate(axes(count)):
            mutant = folder / f"axis{i:03d}.yaml"
            mutant.write_text(source.replace(SLOT, SLOT.replace("axis: [1, 0]", f"axis: [{x!r}, {y!r}]")))
            for command in (["analyze", str(mutant), "--step", "5"],
                            ["export", str(mutant), "--dxf", "-o", str(folder / "m.dxf")],
                            ["range", str(mutant), "--all-branches"],
                            ["animate", str(mutant), "--frames", "12", "--size", "160x120", "-o", str(folder / "m.gif")]):
                start = time.monotonic()
                try:
                    run = subprocess.run([koppel] + command, capture_output=True, text=True, timeout=60)
                except subprocess.TimeoutExpired:
                    failures.append(f"axis [{x!r}, {y!r}]: koppel {command[0]} still running after 60 s")
                    continue
                seconds = time.monotonic() - start
                slowest = max(slowest, seconds)
                what = f"axis [{x!r}, {y!r}]: koppel {command[0]}"
                if seconds > SECONDS:
                    failures.append(f"{what} took {seconds:.1f} s")
                if run.returncode not in (0, 1):
                    failures.append(f"{what} exit {run.returncode}: {run.stderr.strip()[:300]}")
                if "internal error" in run.stderr:
                    failures.append(f"{what}: {run.stderr.strip()[:300]}")
                if run.returncode == 1 and not run.stderr.strip():
                    failures.append(f"{what}: exit 1 without a message")
    print(f"{count} axes x 4 commands, slowest {slowest:.2f} s")
    for failure in failures:
        print(failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
