"""The syntheses of `koppel synth` as functions.

Each returns a Design: a dict-like result with status ("ok", "no design", "optimum on the
boundary", "re-analysis failed"), ok, message, figures ({name: value} as the CLI prints them; angles in
degrees) and mechanism (a koppel.Mechanism, ready to analyse; None unless ok). Every design is
proved by the solver's re-analysis before it is returned. A malformed request raises
koppel.InputError.
"""
from typing import Callable, Optional, Sequence, Tuple

from . import _koppel


class Design(dict):
    """The outcome of a synthesis; keys are also attributes (d.status, d.figures, d.mechanism)."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError as error:
            raise AttributeError(name) from error


def crank_rocker(phi0: float, psi0: float, rocker_sense: str = "same",
                 beta: Optional[float] = None, lambda_: Optional[float] = None,
                 frame: float = 1.0, sense: str = "ccw") -> Design:
    """Dead-centre synthesis of a crank-rocker (seed 002; koppel synth deadcentre crank-rocker).

    phi0: the crank's turn from the folded to the extended dead centre [deg]; psi0: the rocker's
    swing meanwhile [deg]; rocker_sense "same" (the document's) or "opposite"; beta [deg] or
    lambda_ = l1/l2 picks the design (neither: the largest smallest transmission angle); frame:
    A0B0; sense "ccw" or "cw" (the mirror image). Mechanism: input phi, outputs psi and mu.
    """
    return Design(_koppel._crank_rocker(phi0, psi0, rocker_sense, beta, lambda_, frame, sense))


def slider_crank(phi0: float, stroke: float, offset: Optional[float] = None,
                 beta: Optional[float] = None) -> Design:
    """Dead-centre synthesis of a slider-crank (seed 000's conventions): phi0 [deg], the stroke,
    and the offset |e| or beta [deg] (neither: the largest smallest transmission angle)."""
    return Design(_koppel._slider_crank(phi0, stroke, offset, beta))


def mzc(lambda_: Optional[float] = None, kappa: Optional[float] = None, D: float = 1.0) -> Design:
    """Meyer zur Capellen straight-line linkage (seed 003) from lambda_ or the coupler angle
    kappa [deg], and the inflection-circle diameter D. Mechanism: the double rocker, output K."""
    return Design(_koppel._mzc(lambda_, kappa, D))


def function(f: Callable[[float], float], x: Tuple[float, float] = (0.0, 1.0),
             input: Tuple[float, float] = (0.0, 90.0), output: Tuple[float, float] = (0.0, 90.0),
             type: str = "four-bar", points: int = 3, at: Sequence[float] = (),
             frame: float = 1.0) -> Design:
    """Function generation (koppel synth function): a "four-bar" (rocker angle) or
    "slider-crank" (slider displacement) whose output follows y = f(x) while the crank follows x,
    x mapped onto input [deg] and f onto output [deg or length]; `points` Chebyshev precision
    points or the x values `at`. Figures: link lengths, error_max, error_at_precision."""
    return Design(_koppel._function(f, type, x[0], x[1], input[0], input[1], output[0], output[1],
                                    points, list(at), frame))


def fit(problem: str, threads: int = 0) -> Design:
    """Least-squares fitting of any mechanism file to targets (koppel synth fit): `problem` is a
    fit problem file naming the mechanism, the free parameters (bounds, starts) and the targets.
    Figures: each free parameter, target<i>_<name>_residual [deg or length], target<i>_input for
    a free input, cost, starts_at_best. "ok" only when every target is within its tolerance and
    the design assembles over `require`; otherwise "no design", the message naming the targets
    missed. The mechanism is the problem's mechanism file read with the fitted values. threads:
    for the starts (0: the file's, or one per core)."""
    return Design(_koppel._fit(problem, threads))


def motion(poses: Sequence[Tuple[float, float, float]],
           circle_points: Sequence[Tuple[float, float]] = (), crank_turn: float = 90.0,
           curve_samples: int = 18, require_crank: bool = False, threads: int = 0) -> dict:
    """Motion generation (koppel synth motion, Burmester): four-bars whose coupler carries a plane
    through 2 to 5 poses (x, y, angle [deg]). Five poses fix the dyads (give no circle points);
    four give the centre-point curve (curve_samples lines) unless circle points are given; three
    and two need circle points (global, in the first pose), two also the crank's turn [deg].

    Returns {"status", "ok", "message", "designs"}: the designs by mu_min (largest first), each a
    Design with figures A0_x .. B0_y, mu_min [deg], branch_defect, order_defect,
    crank_turns_fully, pose_error, pose<i>_input [deg], the Grashof type as its message, and its
    mechanism (outputs P, theta, psi, mu). Every four-bar is re-analysed through every pose."""
    r = _koppel._motion([tuple(p) for p in poses], [tuple(c) for c in circle_points], crank_turn,
                        curve_samples, require_crank, threads)
    r["designs"] = [Design(d) for d in r["designs"]]
    return r


def cognates(mechanism: "_koppel.Mechanism", point: str) -> dict:
    """The two Roberts-Chebyshev cognates (koppel cognates) of a four-bar of revolute joints:
    four-bars whose coupler point traces the curve of `point` (a point output, "link.point" or a
    point name). Returns {"status", "ok", "message", "designs"}: designs[0] (pivots A0, C0; its
    crank turns with the original coupler; figures A0C0, A0A1, A1C1, C0C1, A1K, C1K, input_min,
    input_max [deg]) and designs[1] (pivots C0, B0, driven with the original's input; C0B0, C0C2,
    C2B2, B0B2, B2K, C2K), each with its mechanism. Cognate 2 is proved against the original
    sample by sample over a turn. Raises koppel.InputError for a point that is not there or a
    mechanism that is not such a four-bar."""
    r = mechanism._cognates(point)
    r["designs"] = [Design(d) for d in r["designs"]]
    return r
