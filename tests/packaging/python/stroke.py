"""The slider-crank's stroke through the installed Python module, from the installed catalog,
checked against the closed form sqrt((l1 + l2)^2 - e^2) - sqrt((l2 - l1)^2 - e^2) (seed 000).
KOPPEL_PREFIX: the install prefix; the module and the catalog must be the ones installed there."""
import math
import os
import sys

import koppel

m = koppel.catalog.load("slider-crank-offset", set={"e": 0.8})
d = m.dead_centres("s")
p = m.parameters
l1, l2, e = p["l1"], p["l2"], p["e"]
expected = math.sqrt((l1 + l2) ** 2 - e ** 2) - math.sqrt((l2 - l1) ** 2 - e ** 2)
print(f"koppel {koppel.__version__} from {os.path.dirname(koppel.__file__)}, catalog {koppel.catalog.directory()}")
print(f"stroke {d.stroke:.12f}, closed form {expected:.12f}")
t = m.sweep(0, 360, 1, order=2)
s = t["s"]
print(f"sweep: {len(t)} rows, max s - min s = {s.max() - s.min():.12f}")
ok = (d.status == "complete" and abs(d.stroke - expected) < 1e-9 and t.complete
      and s.max() - s.min() <= d.stroke + 1e-12 and abs(s.max() - s.min() - expected) < 1e-3
      and koppel.__file__.startswith(os.environ["KOPPEL_PREFIX"] + os.sep)
      and koppel.catalog.directory() == os.path.join(os.environ["KOPPEL_PREFIX"], "share", "koppel", "catalog"))
sys.exit(0 if ok else 1)
