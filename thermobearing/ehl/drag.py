"""Numerical-EHL fluid forces of roller-raceway contacts for the roller skidding solver.

Registers ``"numerical_ehl"`` in :data:`thermobearing.skidding.roller_fluid.ROLLER_DRAG` (the
drag-model family; selected by ``solve_roller(..., drag_model="numerical_ehl")``).
Paper 000 (seed ``000_3b5ca6eed61dd596.txt``, section 2.2) replaces the Dowson-Higginson
closed-form drag by forces from the numerical EHL pressure and film: its eq. 5,

    T = -int (h/2) dp/dx dx + (u2 - u1) int eta/h dx,

the Poiseuille (rolling) and Couette (sliding) parts. Here the film pressure p(x) and thickness
h(x) come from the isothermal numerical solution (:func:`thermobearing.ehl.solve_line_contact`,
Barus alpha of the drag model's arguments, Dowson-Higginson density), and the Couette stress at
every node from the skidding solver's own traction law ``traction_law.shear_stress(V, p, h, T)``
(Newtonian with a limiting shear stress by default), so that the numerical and closed-form drag
models differ only in the pressure and film they integrate over.

Cost control: the isothermal Newtonian pressure and film do not depend on sliding, so solutions
are memoised on a grid in (ln w', ln u_e) (ratio ``step`` between grid values); the forces of a
query are the bilinear interpolation, in (ln w', ln u_e), of the forces computed on the four
corner solutions with the query's own sliding speed and traction law.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from ..errors import InputError

#: finest grid the drag model refines to when the Richardson error estimate is too large
MAX_NODES = 4096


def _solve_refined(w: float, radius: float, e_prime: float, u: float, eta0: float,
                   alpha: float, n: int) -> Any:
    """:func:`~thermobearing.ehl.line.solve_line_contact` on ``n`` nodes, doubled (up to
    :data:`MAX_NODES`) while the solver reports its central-film error estimate above 5 %
    (heavily loaded contacts, M >~ 150, need more than 512 nodes for their pressure spike)."""
    from .line import GridResolutionError, solve_line_contact

    while True:
        try:
            return solve_line_contact(w, radius, e_prime, u, eta0, alpha=alpha, n=n)
        except GridResolutionError:
            if 2 * n > MAX_NODES:
                raise
            n *= 2


class NumericalRollerDrag:
    """Callable with the signature of
    :func:`thermobearing.skidding.roller_fluid.closed_form_contact_forces`.

    Parameters
    ----------
    n : minimum number of grid nodes (raised for light loads, see
        :func:`thermobearing.ehl.line.nodes_for`).
    step : ratio between neighbouring grid values of load per length and entrainment speed.
    """

    def __init__(self, n: int = 512, step: float = 1.05) -> None:
        if not step > 1.0:
            raise InputError("step", step, "a ratio > 1")
        self.n = int(n)
        self.lstep = math.log(step)
        self._memo: dict[tuple, Any] = {}
        self.solves = 0

    def _solution(self, key: tuple, radius, e_prime, eta0, alpha):
        sol = self._memo.get(key)
        if sol is None:
            from .line import line_contact_case, nodes_for

            w, u = math.exp(key[-2] * self.lstep), math.exp(key[-1] * self.lstep)
            case = line_contact_case(w, radius, e_prime, u, eta0, alpha=alpha)
            sol = _solve_refined(w, radius, e_prime, u, eta0, alpha,
                                 nodes_for(case.M, self.n, case.L))
            self._memo[key] = sol
            self.solves += 1
        return sol

    @staticmethod
    def _forces(sol, slide: float, law, temperature: float) -> np.ndarray:
        """(traction, dtraction, poiseuille, rolling, hertz_traction) per unit length."""
        x, p, h = sol.x, sol.pressure, sol.film
        pos = np.nonzero(p > 0)[0]
        fill = np.ones_like(h)
        if pos.size and pos[-1] + 1 < h.size:
            k = pos[-1] + 1
            fill[k:] = np.minimum(1.0, h[k] / h[k:])
        # traction laws take the sliding-speed magnitude; the stress has the sign of V
        st = law.shear_stress(np.full_like(p, abs(slide)), p, h, np.full_like(p, temperature))
        tau = np.asarray(st[0], float) * np.sign(slide)
        dtau = np.asarray(st[1], float)
        dpdx = np.gradient(p, x)
        dhdx = np.gradient(h, x)
        hertz = np.abs(x) <= sol.hertz_half_width
        return np.array([
            np.trapezoid(tau * fill, x),
            np.trapezoid(dtau * fill, x),
            abs(np.trapezoid(0.5 * h * dpdx, x)),
            abs(np.trapezoid(p * dhdx, x)),  # G2's Q_x >= 0 along the entrainment
            np.trapezoid(np.where(hertz, tau, 0.0), x),
        ])

    @staticmethod
    def _w_min(radius: float, e_prime: float, eta0: float, ue: float) -> float:
        """Load per length at 1.2x the solver's smallest Moes M [N/m]."""
        from .line import M_RANGE

        two_u = 2.0 * eta0 * ue / (e_prime * radius)
        return 1.2 * M_RANGE[0] * math.sqrt(two_u) * e_prime * radius

    def _rigid_scaled(self, w, w_min, ue, slide, radius, e_prime, eta0, alpha, law,
                      temperature):
        from dataclasses import replace

        cu = round(math.log(ue) / self.lstep)
        u_node = math.exp(cu * self.lstep)
        key = (radius, e_prime, eta0, alpha, "rigid", cu)
        sol = self._memo.get(key)
        if sol is None:
            from .line import line_contact_case, nodes_for

            wm = self._w_min(radius, e_prime, eta0, u_node)
            case = line_contact_case(wm, radius, e_prime, u_node, eta0, alpha=alpha)
            sol = _solve_refined(wm, radius, e_prime, u_node, eta0, alpha,
                                 nodes_for(case.M, self.n, case.L))
            self._memo[key] = sol
            self.solves += 1
        wm = self._w_min(radius, e_prime, eta0, u_node)
        # Martin: h0 ~ eta u R / w' -> scale h by (u/u_node)(wm/w); lengths by sqrt of that
        s_h = (ue / u_node) * (wm / w)
        s_x = math.sqrt(s_h)
        s_p = (w / wm) / s_x
        scaled = replace(sol, x=sol.x * s_x, film=sol.film * s_h, pressure=sol.pressure * s_p,
                         hertz_half_width=sol.hertz_half_width * math.sqrt(w / wm))
        return self._forces(scaled, slide, law, temperature), sol.central_film * s_h

    def __call__(self, load: Any, length: float, radius: float, effective_modulus: float,
                 u_race: Any, u_roller: Any, *, eta0: float, alpha: float,
                 film: Callable | None = None, traction_law: Any, temperature: float,
                 rolling_force: str = "regime_min", oil_layer: float | None = None):
        """Fluid forces of the (Z,) contacts (see the module docstring); SI."""
        from ..skidding.roller_fluid import LineContactForces

        if oil_layer is not None:
            raise InputError("oil_layer", oil_layer,
                             "None (the numerical EHL drag model assumes a flooded inlet)")
        q, ur, uro = np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, dtype=float))
                                           for v in (load, u_race, u_roller)))
        z = q.shape
        out = {k: np.zeros(z) for k in ("tr", "dtr", "poi", "roll", "htr")}
        film_c = np.full(z, np.inf)
        half = np.zeros(z)
        pmax = np.zeros(z)
        sign = np.where(ur + uro >= 0.0, 1.0, -1.0)
        for j in np.ndindex(z):
            if q[j] <= 0.0:
                continue
            w = q[j] / length
            ue = 0.5 * abs(ur[j] + uro[j])
            if ue <= 0.0:
                raise InputError("entrainment speed", ue,
                                 "> 0 at a loaded contact (numerical EHL drag)")
            slide = float(ur[j] - uro[j])
            w_min = self._w_min(radius, effective_modulus, eta0, ue)
            if w < w_min:
                # below the solver's load range the contact is rigid and isoviscous: Martin's
                # self-similar solution (verified to 0.3 % by the solver at M = 0.1 and 0.006)
                # is rescaled from w_min: h ~ 1/w', lengths ~ sqrt(h), p ~ w'/length
                f, hc = self._rigid_scaled(w, w_min, ue, slide, radius, effective_modulus,
                                           eta0, alpha, traction_law, temperature)
                out["tr"][j], out["dtr"][j], out["poi"][j], out["roll"][j], out["htr"][j] = (
                    f * length)
                film_c[j] = hc
                half[j] = math.sqrt(8 * w * radius / (math.pi * effective_modulus))
                pmax[j] = math.sqrt(w * effective_modulus / (2 * math.pi * radius))
                continue
            cw, cu = math.log(w) / self.lstep, math.log(ue) / self.lstep
            iw, iu = math.floor(cw), math.floor(cu)
            fw, fu = cw - iw, cu - iu
            acc = np.zeros(5)
            hc = 0.0
            for dw, du in ((0, 0), (1, 0), (0, 1), (1, 1)):
                wgt = (fw if dw else 1 - fw) * (fu if du else 1 - fu)
                if wgt == 0.0:
                    continue
                key = (radius, effective_modulus, eta0, alpha, iw + dw, iu + du)
                sol = self._solution(key, radius, effective_modulus, eta0, alpha)
                acc += wgt * self._forces(sol, slide, traction_law, temperature)
                hc += wgt * math.log(sol.central_film)
            out["tr"][j], out["dtr"][j], out["poi"][j], out["roll"][j], out["htr"][j] = (
                acc * length)
            film_c[j] = math.exp(hc)
            half[j] = math.sqrt(8 * w * radius / (math.pi * effective_modulus))
            pmax[j] = math.sqrt(w * effective_modulus / (2 * math.pi * radius))
        return LineContactForces(
            traction=out["tr"], dtraction_dslide=out["dtr"], poiseuille=out["poi"],
            rolling_force=out["roll"], entrainment_sign=sign, film_thickness=film_c,
            half_width=half, max_pressure=pmax, hertz_traction=out["htr"])


def _register() -> None:
    """Register the model in G2's ROLLER_DRAG family (if the skidding package is present)."""
    try:
        from ..skidding.roller_fluid import ROLLER_DRAG
    except ImportError:  # pragma: no cover - the skidding package is part of the product
        return
    if "numerical_ehl" in ROLLER_DRAG:
        return

    @ROLLER_DRAG.register(
        "numerical_ehl",
        references=["li2018_nu214_skidding", "venner_lubrecht2000", "liu_wang_liu2000_dcfft",
                    "fischer1992"],
        parameters={},
        validity="isothermal Newtonian numerical line-contact EHL, 0.002 <= M <= 3000, "
                 "0 <= L <= 40, flooded inlet; Couette stress by the given traction law",
    )
    def numerical_drag_model() -> NumericalRollerDrag:
        """Roller-raceway fluid forces from the numerical EHL pressure and film (paper 000 eq 5)."""
        return NumericalRollerDrag()


_register()
