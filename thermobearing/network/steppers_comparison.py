"""Fixed-step comparison steppers of the thermal network (BM-3): Crank-Nicolson and
explicit Euler, registered in :data:`.steppers.STEPPERS` to show (BM-3) what the
L-stable steppers avoid: ringing of stiff modes and zero-capacity nodes (Crank-Nicolson)
and blow-up above h = 2 C/K (explicit Euler). Units: times [s], temperatures [K], heat
[W], energies [J].
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .steppers import STEPPERS, _audit, _Method, _NewtonFailure, _Trial


@STEPPERS.register("crank_nicolson", references=["crank_nicolson1947"],
                   parameters={"dt": "s"},
                   validity="A-stable, not L-stable: rings on stiff modes; fixed dt only; "
                            "for comparison (BM-3)")
class CrankNicolson(_Method):
    """Crank-Nicolson (trapezoidal rule), C (y1 - y0) = h/2 (f0 + f1); fixed step only.

    Crank & Nicolson (1947). Second order but not L-stable: the amplification factor tends
    to -1 on stiff modes, so small-capacity nodes oscillate at large steps.
    """

    order = 2
    adaptive = False
    name = "crank_nicolson"

    def step(self, core, t, h, y0, f0, q0):
        core.factor(0.5 * h)
        ydot0 = f0 * core.invC
        y1, f1, q1, _ = core.newton(t + h, y0, y0 + h * ydot0, 0.5 * h, 0.5 * h * f0)
        d1, db1 = core.stage_drift   # temperature-dependent conductances (TRBDF2.step)
        q1 = q1 - d1
        gen, to_b, to_s = _audit(core, h, (0.5, 0.5), (y0, y1), (q0, q1))
        return _Trial(y1, f1, q1, None, gen, to_b + 0.5 * h * db1, to_s)


@STEPPERS.register("explicit_euler", references=["hairer_wanner1996"],
                   parameters={"dt": "s"},
                   validity="stable only for dt < 2 min(C_i / K_ii); no zero-capacity nodes; "
                            "for comparison (BM-3)")
class ExplicitEuler(_Method):
    """Forward (explicit) Euler, y1 = y0 + h f0 / C; fixed step only, for comparison.

    Unstable for h > 2 C_i/K_ii on the smallest node (Hairer & Wanner 1996, sec. IV.2).
    """

    order = 1
    adaptive = False
    name = "explicit_euler"

    def step(self, core, t, h, y0, f0, q0):
        if core.has_alg:
            raise InputError("method", "explicit_euler", "a network without zero-capacity nodes")
        with np.errstate(over="ignore", invalid="ignore"):
            y1 = y0 + h * f0 / core.C
            ok = bool(np.all(np.isfinite(y1)))
            if ok:
                f1, q1 = core.f(t + h, y1)
                ok = bool(np.all(np.isfinite(f1)) and np.all(np.isfinite(f1 * core.invC)))
        if not ok:
            raise _NewtonFailure(math.inf, "explicit Euler blew up (step above 2 C/K)")
        gen, to_b, to_s = _audit(core, h, (1.0,), (y0,), (q0,))
        return _Trial(y1, f1, q1, None, gen, to_b, to_s)
