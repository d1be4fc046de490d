"""koppel: planar linkages (ebene Getriebe) from Python.

    import koppel
    m = koppel.Mechanism.load("catalog/entries/slider-crank-offset.yaml", set={"e": 0.8})
    t = m.sweep(0, 360, 1, order=2)      # t.columns, t.values (NumPy), t["s"], t.to_dict()
    d = m.dead_centres("s")              # d.stroke, d.points
    m.range().branches                   # drivable intervals
    koppel.catalog.find(links=4, prismatic=1)
    koppel.synth.crank_rocker(phi0=164, psi0=60).mechanism

Units as in the mechanism files and the CLI: inputs in degrees (R drive) or length (P drive),
angle outputs in degrees, transfer functions d^k y/dx^k per radian (or per length) of the
input. Bad input raises koppel.InputError (a ValueError) with .file, .line, .column, .field and
.diagnostics; outcomes are values with a .status ("complete", "partial", "failed"; designs "ok",
"no design", ...) and a .message.
"""
# NumPy first: the tables are NumPy arrays, and without it the compiled module would load and
# fail only at the first sweep, with pybind11's less telling message.
try:
    import numpy as _numpy  # noqa: F401
except ImportError as _error:
    raise ImportError(
        "koppel needs NumPy, which this Python cannot import (" + str(_error) + "); install it: "
        "apt-get install python3-numpy (Debian), or pip install numpy") from _error

from ._koppel import (DeadCentres, InputError, Mechanism, Pose, Ranges, SweepTable,
                      __version__)
from . import catalog, synth

__all__ = ["Mechanism", "SweepTable", "Pose", "DeadCentres", "Ranges", "InputError",
           "catalog", "synth", "__version__"]
