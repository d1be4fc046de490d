"""Every CSV koppel writes, for tests/data/hostile-names.yaml, read back with Python's csv module
(an independent RFC 4180 reader).

    python3 hostile_names_test.py KOPPEL_EXECUTABLE TEST_DATA_DIR

The names hold quotes, commas, markup, spreadsheet formulas (= + - @ first) and letters beyond
ASCII. References: RFC 4180 (every record has the header's number of fields; a quoted field
holds commas and doubled quotes), OWASP "CSV Injection" (a cell a spreadsheet would evaluate
starts with a ' instead), and the names exactly as the fixture gives them.
"""
import csv
import io
import json
import os
import subprocess
import sys
import unittest

KOPPEL, DATA = sys.argv[1], sys.argv[2]
FIXTURE = os.path.join(DATA, "hostile-names.yaml")

# the names of tests/data/hostile-names.yaml
IMG = "<img src=x onerror=\"document.title+='[X]'\">"
DRIVE = "phi, deg " + IMG
S = "s, mm " + IMG
MU = "mu <!--<script>"
K = "+K <svg onload=\"document.title+='[X]'\">"
FRAME, CRANK, COUPLER, SLIDER = 'Gestell, "frame"', '=HYPERLINK("http://x","crank")', "coupler <img src=x onerror=alert(1)>", "Schieber σ ✓"


def run_koppel(*args):
    r = subprocess.run([KOPPEL, *args], capture_output=True)
    if r.returncode != 0:
        raise AssertionError(f"koppel {args}: exit {r.returncode}\n{r.stderr.decode(errors='replace')}")
    return r.stdout.decode("utf-8")  # strict: the output is UTF-8


def guarded(cell):
    """The cell as koppel's CSV must show it: a leading ' before = + - @ unless it is a number."""
    if cell[:1] in ("=", "+", "-", "@"):
        try:
            float(cell)
        except ValueError:
            return "'" + cell
    return cell


class Csv(unittest.TestCase):
    def read(self, *args):
        text = run_koppel(*args)
        # no control character reaches a terminal: only the line ends
        self.assertFalse([c for c in text if (ord(c) < 0x20 and c != "\n") or 0x7F <= ord(c) <= 0x9F], args)
        rows = list(csv.reader(io.StringIO(text, newline="")))
        self.assertGreater(len(rows), 1, args)
        for i, row in enumerate(rows):
            self.assertEqual(len(row), len(rows[0]), f"{args}: record {i} has {len(row)} fields, the header {len(rows[0])}")
        for row in rows:
            for cell in row:  # nothing a spreadsheet would evaluate: a guarded cell starts with '
                self.assertEqual(cell, guarded(cell), args)
                if cell.startswith("'"):  # and a number is never guarded
                    self.assertRaises(ValueError, float, cell[1:])
        return rows

    def test_analyze(self):
        rows = self.read("analyze", FIXTURE, "--step", "90")
        components = [S, S + "_d1", S + "_d2", MU, MU + "_d1", MU + "_d2"]
        for axis in ("_x", "_y"):
            components += [K + axis, K + axis + "_d1", K + axis + "_d2"]
        self.assertEqual(rows[0], [guarded(c) for c in [DRIVE] + components + ["singular"]])
        self.assertEqual(len(rows), 1 + 5)  # 0, 90, 180, 270, 360
        # the JSON keeps the names as they are, unguarded
        table = json.loads(run_koppel("analyze", FIXTURE, "--step", "90", "--format", "json"))
        self.assertEqual(table["columns"], [DRIVE] + components + ["singular"])

    def test_deadcentres(self):
        rows = self.read("deadcentres", FIXTURE, "--output", S)
        self.assertEqual(rows[0], ["kind", DRIVE, S, S + "_d2"])
        self.assertEqual(len(rows), 1 + 2)  # the two dead centres of a slider-crank

    def test_curve(self):
        rows = self.read("curve", FIXTURE, "--point", K, "--step", "90")
        self.assertEqual(rows[0][0], DRIVE)

    def test_curvature(self):
        self.read("curvature", FIXTURE, "--point", K, "--at", "30")

    def test_poles(self):
        rows = self.read("poles", FIXTURE, "--at", "30")
        links = {cell for row in rows[1:] for cell in row[:2]}
        self.assertEqual(links, {guarded(name) for name in (FRAME, CRANK, COUPLER, SLIDER)})

    def test_tolerance(self):
        rows = self.read("tolerance", FIXTURE, "--output", S, "--at", "30", "--tol", "l1=0.01")
        self.assertEqual(len(rows), 2)

    def test_range_and_classify(self):
        self.read("range", FIXTURE)
        self.read("classify", FIXTURE)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
