"""The Python module (tools/python): its numbers against closed forms and against the CLI's own
output for the same request, its errors with file and line. Run by ctest (python_module) with
PYTHONPATH set to the package in the build tree and KOPPEL_EXECUTABLE to the CLI."""
import ast
import csv
import io
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import koppel

CATALOG = os.environ["KOPPEL_CATALOG_DIR"]
SLIDER_CRANK = os.path.join(CATALOG, "slider-crank-offset.yaml")
DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data"))
L1, L2 = 1.0, 2.6


def closed_form_s(phi, e):
    """Seed 000: s/l1 = sin phi + cos psi/lambda, sin psi = -lambda cos phi - eps."""
    lam, eps = L1 / L2, e / L2
    cos_psi = math.sqrt(1 - (lam * math.cos(phi) + eps) ** 2)
    return L1 * (math.sin(phi) + cos_psi / lam)


class ImportTest(unittest.TestCase):
    def test_import_without_numpy_says_so(self):
        # issue 22 item 13: NumPy made unimportable (None in sys.modules), `import koppel` itself
        # fails and names NumPy, instead of loading and failing at the first sweep
        code = ("import sys\nsys.modules['numpy'] = None\ntry:\n    import koppel\nexcept ImportError as e:\n"
                "    print('ImportError:', e)\nelse:\n    print('imported')\n")
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
        self.assertIn("ImportError: koppel needs NumPy", out.stdout)
        self.assertIn("python3-numpy", out.stdout)


class MechanismTest(unittest.TestCase):
    def test_a_catalog_id_loads_the_entry(self):
        # issue 22 item 9: a catalog id where a file is expected names the catalog's entry
        by_id = koppel.Mechanism.load("slider-crank-offset", set={"e": 0.8})
        by_file = koppel.Mechanism.load(SLIDER_CRANK, set={"e": 0.8})
        np.testing.assert_array_equal(by_id.sweep(0, 360, 30).values, by_file.sweep(0, 360, 30).values)
        with self.assertRaises(koppel.InputError) as raised:
            koppel.Mechanism.load("slider-crank-ofset")
        self.assertIn("did you mean 'slider-crank-offset'?", str(raised.exception))

    def test_a_mechanism_of_mobility_2_is_refused_as_by_the_cli(self):
        # issue 24: the admission rule is the library's (koppel/api/admission.hpp), not the CLI's
        five_bar = os.path.join(DATA, "five-bar.yaml")
        with self.assertRaises(koppel.InputError) as raised:
            koppel.Mechanism.load(five_bar)
        self.assertIn("mobility 2", str(raised.exception))
        cli = subprocess.run([os.environ["KOPPEL_EXECUTABLE"], "analyze", five_bar], capture_output=True, text=True)
        self.assertEqual(cli.returncode, 2)
        self.assertIn("mobility 2", cli.stderr)
        redundant = koppel.Mechanism.load(os.path.join(DATA, "redundant-parallelogram.yaml"))
        self.assertEqual(len(redundant.notes), 1)
        self.assertIn("overconstrained but consistent", redundant.notes[0])

    def test_version_is_the_cli_version(self):
        out = subprocess.run([os.environ["KOPPEL_EXECUTABLE"], "--version"], capture_output=True, text=True, check=True)
        self.assertEqual(out.stdout.strip(), "koppel " + koppel.__version__)

    def test_sweep_equals_koppel_analyze(self):
        # the same request through the CLI: every number of its CSV (12 digits) equals the module's
        m = koppel.Mechanism.load(SLIDER_CRANK, set={"e": 0.8})
        t = m.sweep(0, 360, 5, order=3)
        cli = subprocess.run([os.environ["KOPPEL_EXECUTABLE"], "analyze", SLIDER_CRANK, "--set", "e=0.8", "--step", "5",
                              "--order", "3"], capture_output=True, text=True, check=True)
        rows = list(csv.reader(io.StringIO(cli.stdout)))
        self.assertEqual(rows[0], t.columns)
        self.assertEqual(len(rows) - 1, len(t))
        expected = np.array([[float(x) for x in row] for row in rows[1:]])
        np.testing.assert_allclose(t.values, expected, rtol=1e-11, atol=1e-11)

    def test_sweep_against_closed_form_and_dict(self):
        m = koppel.Mechanism.load(SLIDER_CRANK, set={"e": "l1/2"})
        t = m.sweep(0, 360, 1, order=2)
        self.assertEqual(t.status, "complete")
        self.assertEqual(t.values.shape, (361, len(t.columns)))
        for phi, s in zip(t["phi"], t["s"]):
            self.assertAlmostEqual(s, closed_form_s(math.radians(phi), 0.5), delta=1e-9)
        d = t.to_dict()
        self.assertEqual(list(d), t.columns)
        np.testing.assert_array_equal(d["s_d1"], t.values[:, t.columns.index("s_d1")])

    def test_dead_centres_stroke(self):
        for e in (0.0, 0.8):
            d = koppel.Mechanism.load(SLIDER_CRANK, set={"e": e}).dead_centres("s")
            stroke = math.sqrt((L1 + L2) ** 2 - e ** 2) - math.sqrt((L2 - L1) ** 2 - e ** 2)
            self.assertEqual(d.status, "complete")
            self.assertAlmostEqual(d.stroke, stroke, delta=1e-9)
            self.assertEqual([p["kind"] for p in d.points], ["extended", "folded"])

    def test_transmission_extremes(self):
        # seed 000, e = 0.8: mu_min = 90 deg - asin((l1 + e)/l2) at phi = 0; mu folds at 90 deg
        # where cos phi = -e/l1
        d = koppel.Mechanism.load(SLIDER_CRANK).dead_centres("mu")
        self.assertTrue(d.has_extremes)
        self.assertEqual(d.minimum["at"], "stationary")
        self.assertAlmostEqual(d.minimum["input"], 0, delta=1e-9)
        self.assertAlmostEqual(d.minimum["value"], 90 - math.degrees(math.asin((L1 + 0.8) / L2)), delta=1e-9)
        self.assertEqual(d.maximum["at"], "fold")
        self.assertAlmostEqual(d.maximum["input"], math.degrees(math.acos(-0.8 / L1)), delta=1e-9)
        self.assertAlmostEqual(d.maximum["value"], 90, delta=1e-9)

    def test_range_and_pose(self):
        m = koppel.Mechanism.load(SLIDER_CRANK)
        r = m.range()
        self.assertEqual(r.branches[0]["to_kind"], "full-turn")
        pose = m.move_to(30, order=4)
        self.assertTrue(pose.ok)
        self.assertAlmostEqual(pose["s"], closed_form_s(math.radians(30), 0.8), delta=1e-9)
        self.assertEqual(pose.valid_order, 4)
        m.set("e", 0)
        self.assertFalse(m.assembled)
        self.assertAlmostEqual(m.move_to(30)["s"], closed_form_s(math.radians(30), 0.0), delta=1e-9)

    def test_input_error_names_file_and_line(self):
        with open(SLIDER_CRANK) as f:
            text = f.read()
        bad = text.replace("links: [coupler, slider]", "links: [coupler, slidr]")
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "bad.yaml")
            with open(path, "w") as f:
                f.write(bad)
            with self.assertRaises(koppel.InputError) as caught:
                koppel.Mechanism.load(path)
        error = caught.exception
        self.assertIsInstance(error, ValueError)
        self.assertEqual(error.file, path)
        self.assertEqual(error.line, bad[:bad.index("slidr")].count("\n") + 1)
        self.assertIn("slidr", str(error))
        with self.assertRaises(koppel.InputError):
            koppel.Mechanism.load(SLIDER_CRANK, set={"no_such": 1})
        with self.assertRaises(koppel.InputError):
            koppel.Mechanism.load(SLIDER_CRANK).sweep(0, 360, 0)

    def test_set_of_an_unread_parameter_raises(self):
        # watt-six-bar's psi1_a is read only by its catalog card, never by the mechanism
        m = koppel.Mechanism.load(os.path.join(CATALOG, "watt-six-bar.yaml"))
        with self.assertRaises(koppel.InputError) as caught:
            m.set("psi1_a", 1)
        self.assertIn("psi1_a", str(caught.exception))
        self.assertIn("the parameters read:", str(caught.exception))
        m.set("a1", 1.01)  # a parameter that is read

    def test_catalog_find(self):
        hits = koppel.catalog.find(links=4, prismatic=1, directory=CATALOG)
        self.assertIn("slider-crank-offset", [h.id for h in hits])
        for h in hits:
            self.assertEqual((h.links, h.prismatic), (4, 1))
            self.assertEqual(h.load().path, h.path)
        with self.assertRaises(koppel.InputError):
            koppel.catalog.find(links="four", directory=CATALOG)

    def test_synthesis_reanalysed(self):
        d = koppel.synth.crank_rocker(phi0=164, psi0=60)
        self.assertEqual(d.status, "ok")
        swing = d.mechanism.dead_centres("psi")
        self.assertAlmostEqual(swing.stroke, 60, delta=1e-7)
        self.assertEqual(koppel.synth.crank_rocker(phi0=180, psi0=60).status, "optimum on the boundary")
        with self.assertRaises(koppel.InputError):
            koppel.synth.crank_rocker(phi0=400, psi0=60)
        s = koppel.synth.slider_crank(phi0=160, stroke=2.5)
        self.assertAlmostEqual(s.mechanism.dead_centres("s").stroke, 2.5, delta=1e-7)
        # the classic log10 four-bar (tests/data/function-log10.yaml): exact at the middle
        # Chebyshev point x = 5.5, where the crank stands at 45 deg
        f = koppel.synth.function(math.log10, x=(1, 10), input=(15, 75), output=(105, 195))
        self.assertTrue(f.ok)
        self.assertLess(f.figures["error_at_precision"], 1e-7)
        psi = f.mechanism.move_to(45)["psi"]
        self.assertAlmostEqual(math.remainder(psi - (105 + 90 * math.log10(5.5)), 360), 0, delta=1e-6)

    def test_fit_reanalysed(self):
        # tests/data/fit-direction-three-points.yaml: exactly solvable, l1 = 1.674809355059234 from
        # an independent Newton solve on closed-form four-bar geometry; the fitted mechanism,
        # driven to each target's input, shows the target's direction
        d = koppel.synth.fit(os.path.join(DATA, "fit-direction-three-points.yaml"))
        self.assertTrue(d.ok, d.message)
        self.assertAlmostEqual(d.figures["l1"], 1.674809355059234, delta=1e-9)
        for phi, direction in ((100, 153), (225, 202), (270, 223)):
            self.assertAlmostEqual(math.remainder(d.mechanism.move_to(phi)["dir"] - direction, 360), 0, delta=1e-6)
        missed = koppel.synth.fit(os.path.join(DATA, "fit-direction-unmeetable.yaml"), threads=1)
        self.assertEqual(missed.status, "no design")
        self.assertIn("impossible", missed.message)
        self.assertIsNone(missed.mechanism)
        with self.assertRaises(koppel.InputError):
            koppel.synth.fit(os.path.join(DATA, "no-such-problem.yaml"))

    def test_motion_reanalysed(self):
        # poses 1, 3 and 5 of tests/data/motion-five-poses.yaml with the circle points of the crank-rocker
        # A0 (0, 0), A (1, 0.2), B (3.1, 2.4), B0 (4, 0.3) whose coupler made them: its pivots come back,
        # and the model, driven to each pose's crank angle, puts P and theta on the pose
        poses = [(2.2, 3.3, 15), (2.4665273929408, 3.50994854354389, -3.90644221239416),
                 (1.42227564999058, 2.23224622167394, -11.1093603534674)]
        r = koppel.synth.motion(poses, circle_points=[(1, 0.2), (3.1, 2.4)])
        self.assertTrue(r["ok"], r["message"])
        pivots = sorted((round(d.figures["A0_x"], 6), round(d.figures["A0_y"], 6)) for d in r["designs"])
        self.assertEqual(pivots, [(0.0, 0.0), (4.0, 0.3)])
        for d in r["designs"]:
            if d.figures["branch_defect"]:
                continue
            for i, (x, y, angle) in enumerate(poses):
                p = d.mechanism.move_to(d.figures[f"pose{i + 1}_input"])
                self.assertAlmostEqual(p["P_x"], x, delta=1e-7)
                self.assertAlmostEqual(p["P_y"], y, delta=1e-7)
                self.assertAlmostEqual(math.remainder(p["theta"] - angle, 360), 0, delta=1e-6)
        with self.assertRaises(koppel.InputError):
            koppel.synth.motion(poses)  # three poses need circle points

    def test_cognates_trace_the_same_curve(self):
        # seed 003's straight-line four-bar: cognate 2, driven with the original's input, puts K
        # where the original does (the reference is the original's own sweep)
        original = koppel.Mechanism.load(os.path.join(CATALOG, "mzc-crank-rocker.yaml"))
        r = koppel.synth.cognates(original, "K")
        self.assertTrue(r["ok"], r["message"])
        self.assertAlmostEqual(r["designs"][0].figures["A0C0"], 40 / 9 * math.sqrt(3), delta=1e-9)
        a = original.sweep(0, 330, 30, order=0)
        b = r["designs"][1].mechanism.sweep(0, 330, 30, order=0)
        np.testing.assert_allclose(b["K_x"], a["K_x"], atol=1e-9)
        np.testing.assert_allclose(b["K_y"], a["K_y"], atol=1e-9)
        with self.assertRaises(koppel.InputError):
            koppel.synth.cognates(original, "nowhere")

    def test_curvature_equals_koppel_curvature(self):
        # issue 27: seed 003's K at 180 deg on the inflection circle (rho infinite), and the same
        # numbers as the CLI's JSON
        mzc = os.path.join(CATALOG, "mzc-crank-rocker.yaml")
        c = koppel.Mechanism.load(mzc).curvature("K", at=180)
        self.assertEqual(c["status"], "complete")
        self.assertIsNone(c["rho"])
        self.assertTrue(c["rho_infinite"])
        radius = math.hypot(c["K_x"] - c["inflection_x"], c["K_y"] - c["inflection_y"])
        self.assertAlmostEqual(radius, c["inflection_diameter"] / 2, delta=1e-9)
        out = subprocess.run([os.environ["KOPPEL_EXECUTABLE"], "curvature", mzc, "--point", "K", "--at", "180", "--format", "json"],
                             capture_output=True, text=True, check=True)
        import json
        cli = json.loads(out.stdout)
        for key in ("pole_x", "pole_y", "inflection_x", "inflection_y", "inflection_diameter", "ball_x", "ball_y", "K_x", "K_y"):
            self.assertAlmostEqual(c[key], cli[key], delta=1e-9 * (1 + abs(cli[key])), msg=key)
        poles = koppel.Mechanism.load(mzc).poles(at=180)
        self.assertEqual(len(poles["poles"]), 6)
        centrodes = koppel.Mechanism.load(mzc).centrodes("coupler", start=0, stop=360, step=10, at=180)
        self.assertEqual(centrodes["fixed"].shape, (37, 2))

    def test_tolerance_against_closed_form(self):
        # issue 27: the crank pin's clearance c / cos psi (seed 000), and a seeded Monte Carlo run
        # that the same seed repeats
        m = koppel.Mechanism.load(SLIDER_CRANK)
        r = m.tolerance("s", inputs=[60], tol={"l1": 0.01, "l2": 0.02, "e": 0.005}, clearance={"A": 0.003}, samples=2000, seed=1)
        self.assertEqual(r["status"], "complete")
        row = r["rows"][0]
        phi = math.radians(60)
        sin_psi = -L1 / L2 * math.cos(phi) - 0.8 / L2
        self.assertAlmostEqual(row["clearance_worst_case"], 0.003 / math.sqrt(1 - sin_psi ** 2), delta=1e-12)
        self.assertAlmostEqual(row["nominal"], closed_form_s(phi, 0.8), delta=1e-12)
        h = 1e-5
        self.assertAlmostEqual(row["sens_e"], (closed_form_s(phi, 0.8 + h) - closed_form_s(phi, 0.8 - h)) / (2 * h), delta=1e-8)
        again = m.tolerance("s", inputs=[60], tol={"l1": 0.01, "l2": 0.02, "e": 0.005}, clearance={"A": 0.003}, samples=2000, seed=1,
                            threads=1)
        self.assertEqual(again["rows"][0]["mc_std"], row["mc_std"])
        with self.assertRaises(koppel.InputError):
            m.tolerance("s", inputs=[60], tol={"nope": 0.01})

    def test_stubs_name_what_the_module_has(self):
        # every class, function and member of the compiled module is in _koppel.pyi and back
        from koppel import _koppel
        with open(os.path.join(os.path.dirname(koppel.__file__), "_koppel.pyi")) as f:
            tree = ast.parse(f.read())
        stubbed = {}
        for node in tree.body:
            if isinstance(node, ast.ClassDef):
                members = set()
                for item in node.body:
                    if isinstance(item, ast.FunctionDef):
                        members.add(item.name)
                    elif isinstance(item, ast.AnnAssign):
                        members.add(item.target.id)
                stubbed[node.name] = members
            elif isinstance(node, ast.FunctionDef):
                stubbed[node.name] = None
        compiled = {name for name in dir(_koppel) if not name.startswith("__")}
        self.assertEqual(set(stubbed), compiled)
        for name, members in stubbed.items():
            if members is None or name == "InputError":
                continue
            public = {m for m in dir(getattr(_koppel, name)) if not m.startswith("_")} | (
                {"__getitem__", "__len__"} & set(dir(getattr(_koppel, name))))
            self.assertEqual(members - {"__getitem__", "__len__"}, public - {"__getitem__", "__len__"}, name)
        for name in ("catalog", "synth"):
            for function in getattr(koppel, name).__dict__.values():
                if callable(function) and getattr(function, "__module__", "").startswith("koppel."):
                    self.assertTrue(function.__doc__, f"{name}.{function.__name__} has no docstring")


if __name__ == "__main__":
    unittest.main()
