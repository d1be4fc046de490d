"""koppel export --dxf read back with an independent DXF reader (ezdxf, Debian python3-ezdxf).

    python3 dxf_readback_test.py KOPPEL_EXECUTABLE CATALOG_DIR TEST_DATA_DIR

References: the four-bar of seed 003 (catalog/entries/mzc-crank-rocker.yaml) by circle
intersection (A0 = 0, B0 = (l4, 0), A = l1 (cos phi, sin phi), B left of A -> B0, K = A +
k R(kappa) (B - A)/|B - A|), its link lengths from the file's parameters, `koppel curve` for the
coupler curve, seed 000's slider-crank (A0 = (0, -e), slide on y = 0) for the slot, its dead
centres s = sqrt((l2 -+ l1)^2 - e^2) (A0, A, B in line: the closed forms of tests/support,
SliderCrankPhiA/PhiI in SliderCrank), and seed 001's proportional linkage for slots on a turning
link (slider 5: s = c sin phi / (1 - lambda cos phi), extreme where cos phi = lambda; the slot
through B0 and A: |B0 A| = l6 -+ l1, |B0 D| = sqrt(h^2 + s^2)).
"""
import csv
import io
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import ezdxf
from ezdxf.lldxf.validator import is_valid_layer_name
from ezdxf.math import bulge_to_arc

KOPPEL, CATALOG, DATA = sys.argv[1], sys.argv[2], sys.argv[3]
MZC = os.path.join(CATALOG, "mzc-crank-rocker.yaml")

# seed 003's dimensions (mzc-crank-rocker.yaml: l1 = 1, l2 = l3 = 5/2 sqrt 3, l4 = 4, k = 25/3)
L1, L2, L3, L4 = 1.0, 2.5 * math.sqrt(3), 2.5 * math.sqrt(3), 4.0
K_LENGTH, KAPPA = 25 / 3, math.acos(5 / 9 * math.sqrt(3))

# The DXF holds 15 significant digits and the solver converges to 1e-12 of the length scale:
# positions agree far inside 1e-9.
POSITION_TOLERANCE = 1e-9
# A slot's end is its travel's extreme refined to 1e-12 in the input (where s' = 0, so its value
# is exact to roundoff), written with 15 digits: the closed form's to 1e-12 of the size (L ~ 1).
# Cut at the 1-degree samples it fell short by up to 1.2e-5.
REFINED_TOLERANCE = 1e-12


def run_koppel(*args, expect=0):
    r = subprocess.run([KOPPEL, *args], capture_output=True, text=True)
    if r.returncode != expect:
        raise AssertionError(f"koppel {' '.join(args)}: exit {r.returncode}, expected {expect}\n{r.stderr}")
    return r


def four_bar(phi):
    """A0, A, B, B0, K of seed 003's crank-rocker at crank angle phi [rad], B left of A -> B0."""
    a0, b0 = (0.0, 0.0), (L4, 0.0)
    a = (L1 * math.cos(phi), L1 * math.sin(phi))
    dx, dy = b0[0] - a[0], b0[1] - a[1]
    d = math.hypot(dx, dy)
    ux, uy = dx / d, dy / d
    along = (L2 * L2 - L3 * L3 + d * d) / (2 * d)
    h = math.sqrt(L2 * L2 - along * along)
    b = (a[0] + along * ux - h * uy, a[1] + along * uy + h * ux)
    theta = math.atan2(b[1] - a[1], b[0] - a[0]) + KAPPA
    k = (a[0] + K_LENGTH * math.cos(theta), a[1] + K_LENGTH * math.sin(theta))
    return {"A0": a0, "A": a, "B": b, "B0": b0, "K": k}


def distance(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1])


def slot_lines(msp, layer, radius):
    """The slots on `layer`: closed polylines of two half circles of `radius` (bulge +-1) joined
    by two lines; each as the lengths of its two lines (its centre line's length)."""
    found = []
    for polyline in msp.query(f'LWPOLYLINE[layer=="{layer}"]'):
        points = list(polyline.get_points("xyb"))
        if len(points) != 4 or not polyline.closed:
            continue
        arcs = [bulge_to_arc((x, y), points[(i + 1) % 4][:2], b) for i, (x, y, b) in enumerate(points) if b != 0]
        if len(arcs) != 2 or any(abs(r - radius) > POSITION_TOLERANCE for _, _, _, r in arcs):
            continue
        found.append([distance(p[:2], points[(i + 1) % 4][:2]) for i, p in enumerate(points) if p[2] == 0])
    return found


def nearest_on_curve(point, phi_guess):
    """Distance from `point` to the closed-form coupler curve near phi_guess (golden section)."""
    low, high = phi_guess - 0.02, phi_guess + 0.02
    g = (math.sqrt(5) - 1) / 2
    for _ in range(80):
        m1, m2 = high - g * (high - low), low + g * (high - low)
        if distance(four_bar(m1)["K"], point) < distance(four_bar(m2)["K"], point):
            high = m2
        else:
            low = m1
    return distance(four_bar((low + high) / 2)["K"], point)


class MzcCrankRocker(unittest.TestCase):
    """The issue's command: koppel export mzc-crank-rocker.yaml --dxf --at 30 --trace K -o m.dxf"""

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.path = os.path.join(cls.dir.name, "m.dxf")
        run_koppel("export", MZC, "--dxf", "--at", "30", "--trace", "K", "-o", cls.path)
        cls.doc = ezdxf.readfile(cls.path)
        cls.msp = cls.doc.modelspace()
        cls.pose = four_bar(math.radians(30))

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def holes(self, layer):
        return [(c.dxf.center[0], c.dxf.center[1], c.dxf.radius) for c in self.msp.query(f'CIRCLE[layer=="{layer}"]')]

    def test_a_valid_drawing(self):
        auditor = self.doc.audit()
        self.assertEqual(len(auditor.errors), 0, [e.message for e in auditor.errors])

    def test_a_layer_per_link_and_curve(self):
        names = {layer.dxf.name for layer in self.doc.layers}
        self.assertTrue({"frame", "crank", "coupler", "rocker", "curve-K"} <= names, names)

    def test_unitless_without_units_in_the_file(self):
        self.assertEqual(self.doc.header.get("$INSUNITS", 0), 0)

    def test_a0_at_the_origin(self):
        # the file puts A0 at (0, 0): the frame's pivot hole and the crank's are there
        for layer in ("frame", "crank"):
            centres = [(x, y) for x, y, _ in self.holes(layer)]
            self.assertTrue(any(math.hypot(x, y) < POSITION_TOLERANCE for x, y in centres), (layer, centres))

    def test_hole_centres_at_the_joints(self):
        expected = {"frame": ["A0", "B0"], "crank": ["A0", "A"], "coupler": ["A", "B"], "rocker": ["B0", "B"]}
        for layer, joints in expected.items():
            centres = [(x, y) for x, y, _ in self.holes(layer)]
            self.assertEqual(len(centres), len(joints), layer)
            for joint in joints:
                gap = min(distance(c, self.pose[joint]) for c in centres)
                self.assertLess(gap, POSITION_TOLERANCE, f"{layer}: no hole at {joint} {self.pose[joint]}: {centres}")

    def test_link_lengths_between_holes(self):
        for layer, length in (("frame", L4), ("crank", L1), ("coupler", L2), ("rocker", L3)):
            (x1, y1, _), (x2, y2, _) = self.holes(layer)
            self.assertAlmostEqual(math.hypot(x2 - x1, y2 - y1), length, delta=POSITION_TOLERANCE, msg=layer)

    def test_coupler_curve_is_a_closed_polyline_of_at_least_90_points_on_the_curve(self):
        curves = list(self.msp.query('LWPOLYLINE[layer=="curve-K"]'))
        self.assertEqual(len(curves), 1)
        curve = curves[0]
        self.assertTrue(curve.closed)
        points = [(p[0], p[1]) for p in curve.get_points("xy")]
        self.assertGreaterEqual(len(points), 90)
        # against `koppel curve` (the analysis command): every vertex is one of its rows
        table = run_koppel("curve", MZC, "--point", "K", "--from", "0", "--to", "360", "--step", "1").stdout
        rows = [(float(r["x"]), float(r["y"]), float(r["phi"])) for r in csv.DictReader(io.StringIO(table))]
        for p in points:
            x, y, phi = min(rows, key=lambda r: distance(p, r))
            self.assertLess(distance(p, (x, y)), POSITION_TOLERANCE, p)
            # and independently on the closed-form curve
            self.assertLess(nearest_on_curve(p, math.radians(phi)), POSITION_TOLERANCE, p)
        # the whole turn: every row of the curve has its vertex (360 distinct points)
        self.assertEqual(len(points), 360)

    def test_plate_outlines_at_half_the_plate_width(self):
        # default W = 1/4 of the shortest joint distance (the crank, 1), D = W/2
        width, pin = 0.25, 0.125
        for layer, joints in (("crank", ["A0", "A"]), ("rocker", ["B0", "B"]), ("coupler", ["A", "B", "K"])):
            outlines = list(self.msp.query(f'LWPOLYLINE[layer=="{layer}"]'))
            self.assertEqual(len(outlines), 1, layer)
            self.assertTrue(outlines[0].closed)
            vertices = list(outlines[0].get_points("xyb"))
            for x, y, bulge in vertices:
                nearest = min(distance((x, y), self.pose[j]) for j in joints)
                self.assertAlmostEqual(nearest, width / 2, delta=POSITION_TOLERANCE, msg=layer)
            # every arc turns counter-clockwise around a joint point at radius W/2
            arcs = 0
            for (x, y, bulge), (nx, ny, _) in zip(vertices, vertices[1:] + vertices[:1]):
                if bulge == 0:
                    continue
                arcs += 1
                self.assertGreater(bulge, 0, layer)
                centre, _, _, radius = bulge_to_arc((x, y), (nx, ny), bulge)
                self.assertAlmostEqual(radius, width / 2, delta=POSITION_TOLERANCE, msg=layer)
                self.assertLess(min(distance(centre, self.pose[j]) for j in joints), POSITION_TOLERANCE, layer)
            self.assertEqual(arcs, len(joints), layer)
        for layer in ("frame", "crank", "coupler", "rocker"):
            for _, _, r in self.holes(layer):
                self.assertAlmostEqual(2 * r, pin, delta=1e-12)

    def test_coupler_point_is_marked(self):
        marks = [p.dxf.location for p in self.msp.query('POINT[layer=="coupler"]')]
        self.assertEqual(len(marks), 1)
        self.assertLess(distance(marks[0], self.pose["K"]), POSITION_TOLERANCE)


class Sizes(unittest.TestCase):
    def test_pin_and_plate(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "m.dxf")
            run_koppel("export", MZC, "--dxf", "--at", "120", "--pin", "0.2", "--plate", "0.5", "-o", path)
            msp = ezdxf.readfile(path).modelspace()
            pose = four_bar(math.radians(120))
            for c in msp.query('CIRCLE[layer=="rocker"]'):
                self.assertAlmostEqual(c.dxf.radius, 0.1, delta=1e-12)
            for x, y, _ in msp.query('LWPOLYLINE[layer=="rocker"]')[0].get_points("xyb"):
                self.assertAlmostEqual(min(distance((x, y), pose[j]) for j in ("B0", "B")), 0.25, delta=POSITION_TOLERANCE)


class SliderCrank(unittest.TestCase):
    """Seed 000's slider-crank (l1 = 1, l2 = 2.6, e = 0.8): the frame's slot covers the slider's
    travel from the folded to the extended dead centre, s = sqrt((l2 -+ l1)^2 - e^2)."""

    def test_slot_on_the_frame(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "s.dxf")
            run_koppel("export", os.path.join(CATALOG, "slider-crank-offset.yaml"), "--dxf", "--pin", "0.1", "--plate", "0.3",
                       "-o", path)
            msp = ezdxf.readfile(path).modelspace()
            slots = list(msp.query('LWPOLYLINE[layer=="frame"]'))
            self.assertEqual(len(slots), 1)
            points = slots[0].get_points("xyb")
            # a slot is two half circles of radius D/2 joined by two lines along the guide (y = 0)
            self.assertEqual(len(points), 4)
            ys = sorted(p[1] for p in points)
            self.assertAlmostEqual(ys[0], -0.05, delta=POSITION_TOLERANCE)
            self.assertAlmostEqual(ys[-1], 0.05, delta=POSITION_TOLERANCE)
            for p in points:
                if p[2] != 0:
                    self.assertAlmostEqual(abs(p[2]), 1.0, delta=1e-12)  # bulge tan(pi/4): a half circle
            l1, l2, e = 1.0, 2.6, 0.8
            s_min, s_max = math.sqrt((l2 - l1) ** 2 - e * e), math.sqrt((l2 + l1) ** 2 - e * e)
            xs = sorted(p[0] for p in points)
            # the slot's centre line runs from dead centre to dead centre, refined, not sampled
            self.assertAlmostEqual(xs[0], s_min, delta=REFINED_TOLERANCE)
            self.assertAlmostEqual(xs[-1], s_max, delta=REFINED_TOLERANCE)
            # its length, the two lines, is the stroke
            self.assertEqual(len(slot_lines(msp, "frame", 0.05)), 1)
            for length in slot_lines(msp, "frame", 0.05)[0]:
                self.assertAlmostEqual(length, s_max - s_min, delta=REFINED_TOLERANCE)


class SlotsOnATurningLink(unittest.TestCase):
    """Seed 001's proportional linkage with lambda = l1/l6 = 0.4 (its slot steepest at
    cos phi = 0.4, 66.4 deg, off the 1-degree samples): blocks 2 and 4 slide in the slot of link 3,
    which turns about B0; slider 5 on the frame."""

    def test_slot_lengths(self):
        l6, l1, h = 1.0, 0.4, 1.83
        c, lam = l1 * h / l6, l1 / l6
        s5 = c / math.sqrt(1 - lam * lam)  # c sin phi / (1 - lambda cos phi) at cos phi = lambda
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "p.dxf")
            run_koppel("export", os.path.join(CATALOG, "proportional-linkage.yaml"), "--set", "l1=0.4", "--dxf", "--pin", "0.05",
                       "--plate", "0.2", "-o", path)
            msp = ezdxf.readfile(path).modelspace()
            turning = sorted(min(lines) for lines in slot_lines(msp, "slot", 0.025))
            self.assertEqual(len(turning), 2)
            # block 2 at A: |B0 A| from l6 - l1 to l6 + l1; block 4 at D: |B0 D| from h to sqrt(h^2 + s5^2)
            expected = sorted([2 * l1, math.hypot(h, s5) - h])
            for length, reference in zip(turning, expected):
                self.assertAlmostEqual(length, reference, delta=REFINED_TOLERANCE)
            frame = slot_lines(msp, "frame", 0.025)
            self.assertEqual(len(frame), 1)
            for length in frame[0]:
                self.assertAlmostEqual(length, 2 * s5, delta=REFINED_TOLERANCE)


def renamed_slider_crank(crank, coupler, slider):
    """slider-crank-offset.yaml with its crank, coupler and slider named as given (YAML escapes
    allowed: the names go between double quotes)."""
    with open(os.path.join(CATALOG, "slider-crank-offset.yaml"), encoding="utf-8") as f:
        text = f.read()
    for old, new in (("crank", crank), ("coupler", coupler), ("slider", slider)):
        quoted = f'"{new}"'
        text = text.replace(f"  {old}:\n    points:", f"  {quoted}:\n    points:")
        other = r'(\w+|"[^"]*")'  # a link named in a joint's list, plain or renamed before
        text = re.sub(rf"\[{other}, {old}\]", lambda m: f"[{m.group(1)}, {quoted}]", text)
        text = re.sub(rf"\[{old}, {other}\]", lambda m: f"[{quoted}, {m.group(1)}]", text)
        text = text.replace(f"coupler: {old},", f"coupler: {quoted},")
    return text


def export_text(text, directory, name):
    """koppel export of a mechanism given as text: (the CompletedProcess, the DXF's path)."""
    source, out = os.path.join(directory, name + ".yaml"), os.path.join(directory, name + ".dxf")
    with open(source, "w", encoding="utf-8") as f:
        f.write(text)
    r = subprocess.run([KOPPEL, "export", source, "--dxf", "-o", out], capture_output=True, text=True)
    return r, out


def entities(path):
    """What a DXF draws: each modelspace entity's type, layer and points, in order."""
    found = []
    for e in ezdxf.readfile(path).modelspace():
        if e.dxftype() == "LWPOLYLINE":
            where = [tuple(p) for p in e.get_points("xyb")]
        elif e.dxftype() == "CIRCLE":
            where = [tuple(e.dxf.center)[:2], e.dxf.radius]
        else:
            where = [tuple(e.dxf.get("location", (0, 0, 0)))[:2]]
        found.append((e.dxftype(), e.dxf.layer, where))
    return found


class LayerNames(unittest.TestCase):
    """Names the user gives become legal, distinct layers; none can write a group of its own."""

    INJECTED = "crank\\n0\\nLINE\\n8\\n0\\n10\\n0\\n20\\n0\\n11\\n99\\n21\\n99"  # YAML escapes

    def test_a_name_holding_dxf_groups_draws_what_a_plain_name_draws(self):
        # the repro: exit 0, and the crank's plate and both holes each followed by a LINE to
        # (99, 99) on layer 0. The YAML reader may refuse control characters in a name (exit 2,
        # no file); a file written holds exactly the entities of the plain file.
        with tempfile.TemporaryDirectory() as d:
            plain, plain_path = export_text(renamed_slider_crank("crank", "coupler", "slider"), d, "plain")
            self.assertEqual(plain.returncode, 0, plain.stderr)
            odd, odd_path = export_text(renamed_slider_crank(self.INJECTED, "coupler", "slider"), d, "odd")
            if odd.returncode == 2:
                self.assertFalse(os.path.exists(odd_path))
                return
            self.assertEqual(odd.returncode, 0, odd.stderr)
            doc = ezdxf.readfile(odd_path)
            self.assertEqual(len(doc.modelspace().query("LINE")), 0)
            crank_layer = [layer.dxf.name for layer in doc.layers if layer.dxf.name.startswith("crank")]
            self.assertEqual(len(crank_layer), 1)
            self.assertNotIn("\n", crank_layer[0])
            same = [(kind, crank_layer[0] if layer == "crank" else layer, where) for kind, layer, where in entities(plain_path)]
            self.assertEqual(entities(odd_path), same)

    def test_names_apart_stay_apart(self):
        # names are at most 128 bytes in a mechanism file (longer ones are refused on reading;
        # dxf_layers_test.cpp cuts names beyond DXF's 255 characters through the library)
        long_a = "x" * 128
        with tempfile.TemporaryDirectory() as d:
            r, path = export_text(renamed_slider_crank("a<b", "a>b", long_a), d, "names")
            self.assertEqual(r.returncode, 0, r.stderr)
            doc = ezdxf.readfile(path)
            self.assertEqual(len(doc.audit().errors), 0)
            layers = [layer.dxf.name for layer in doc.layers]
            for name in layers:
                self.assertTrue(is_valid_layer_name(name) and len(name) <= 255, name)
            self.assertEqual(len({name.lower() for name in layers}), len(layers))
            msp = doc.modelspace()
            # the crank "a<b" and the coupler "a>b" each on a layer of its own: two holes each
            for layer in ("a_b", "a_b~2"):
                self.assertEqual(len(msp.query(f'CIRCLE[layer=="{layer}"]')), 2, layer)
            self.assertEqual(len(msp.query(f'LWPOLYLINE[layer=="{long_a}"]')), 1)
            r, _ = export_text(renamed_slider_crank("x" * 129, "b", "slider"), d, "long")
            self.assertEqual(r.returncode, 2, r.stderr)  # refused on reading, with its place


class Reproducible(unittest.TestCase):
    def test_the_same_bytes_from_two_runs(self):
        # the dimension style's group 340 (the text style's handle) came from memory never set
        with tempfile.TemporaryDirectory() as d:
            paths = [os.path.join(d, f"{i}.dxf") for i in range(2)]
            for path in paths:
                run_koppel("export", MZC, "--dxf", "--at", "30", "-o", path)
            with open(paths[0], "rb") as a, open(paths[1], "rb") as b:
                self.assertEqual(a.read(), b.read())


class Units(unittest.TestCase):
    def test_millimetres(self):
        # tests/data/slider-crank-loads.yaml says units: {length: mm}: $INSUNITS 4
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "u.dxf")
            run_koppel("export", os.path.join(DATA, "slider-crank-loads.yaml"), "--dxf", "-o", path)
            self.assertEqual(ezdxf.readfile(path).header["$INSUNITS"], 4)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
