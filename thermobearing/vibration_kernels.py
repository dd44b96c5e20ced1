"""Compiled kernels (numba, ``cache=True``) of the lumped vibration model.

One job: the right-hand side of paper 004's equations of motion (:func:`_rhs`, contact
loads :func:`_loads`, signed traction :func:`_mu_signed`), the exact spin sub-flow of the
Strang splitting (:func:`_torque`, :func:`_spin_flow`, :func:`_spin_sub`) and the fixed-step
integrator loop (:func:`_integrate`, RK4 or split). The parameter vector ``P`` has the
layout of the ``_Z ... _FYS`` indices below; :func:`thermobearing.vibration.simulate` fills
it and calls :func:`_integrate`.

Sources: Luo et al. 2022 (seed paper 004) eqs. 4-22 (the consistent sign of eq. 20 and the
per-contact switch of eq. 15 as discussed in :mod:`thermobearing.vibration`); Strang 1968,
SIAM J. Numer. Anal. 5: 506 (splitting); classical RK4. The kernels call only each other
(all in this file), so numba's per-file cache check is sufficient. Split out of
``vibration.py`` (names re-exported there). Units: SI.
"""

from __future__ import annotations

import math

import numba
import numpy as np

# ---------------------------------------------------------------------------
# compiled kernel
# ---------------------------------------------------------------------------
# P layout
_Z, _D, _DM, _COSA, _PD, _KI, _KO, _MI, _MR, _J, _C, _CB, _WS, _WC, _W, _UNB, _CF, _FYS = range(18)


@numba.njit(cache=True)
def _mu_signed(v, tv, tmu):
    a = abs(v)
    n = tv.size
    if a >= tv[n - 1]:
        m = tmu[n - 1]
    else:
        lo = 0
        hi = n - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if tv[mid] <= a:
                lo = mid
            else:
                hi = mid
        m = tmu[lo] + (tmu[hi] - tmu[lo]) * (a - tv[lo]) / (tv[hi] - tv[lo])
    if v > 0.0:
        return m
    if v < 0.0:
        return -m
    return 0.0


@numba.njit(cache=True)
def _loads(t, y, P, dev, qi, qo, cth, sth):
    """Contact loads (eqs. 11-16) and cos/sin of the ball angles (eq. 12, by recurrence)."""
    z = int(P[_Z])
    half = 0.5 * P[_PD]
    c = math.cos(P[_WC] * t)
    s = math.sin(P[_WC] * t)
    dc = math.cos(2.0 * math.pi / z)
    ds = math.sin(2.0 * math.pi / z)
    for j in range(z):
        cth[j] = c
        sth[j] = s
        dr = y[0] * c + y[1] * s
        d = y[4 + j]
        din = dr - d - half + 0.5 * dev[j]
        dout = d - half + 0.5 * dev[j]
        qi[j] = P[_KI] * din * math.sqrt(din) if din > 0.0 else 0.0
        qo[j] = P[_KO] * dout * math.sqrt(dout) if dout > 0.0 else 0.0
        c, s = c * dc - s * ds, s * dc + c * ds


@numba.njit(cache=True)
def _race_speeds(P):
    """(omega_s, omega_ca, r, a_i, a_o): shaft and cage speeds [rad/s], the ball's rolling
    radius D cos(alpha) / 2 [m] and the race surface speeds relative to the cage at the
    inner and outer contacts [m/s], paper 004 eqs. 4-8 without the ball's own spin (the
    sliding speeds are a_i - r w and a_o - r w)."""
    ws = P[_WS]
    wc = P[_WC]
    gam = P[_D] * P[_COSA] / P[_DM]
    r = 0.5 * P[_D] * P[_COSA]
    ai = 0.5 * (ws - wc) * P[_DM] * (1.0 - gam)
    ao = 0.5 * wc * P[_DM] * (1.0 + gam)
    return ws, wc, r, ai, ao


@numba.njit(cache=True)
def _rhs(t, y, P, dev, tv, tmu, qi, qo, cth, sth, dy):
    """Full right-hand side; also leaves the contact loads in qi, qo."""
    z = int(P[_Z])
    ws, wc, r, ai, ao = _race_speeds(P)
    _loads(t, y, P, dev, qi, qo, cth, sth)
    fx = P[_W] - P[_C] * y[2]
    fy = -P[_C] * y[3]
    if P[_UNB] != 0.0:
        fx += P[_UNB] * ws * ws * math.cos(ws * t)
        fy += P[_UNB] * ws * ws * math.sin(ws * t)
    cf = P[_CF] * P[_MR] * wc * wc * 0.5 * P[_DM]
    for j in range(z):
        c = cth[j]
        s = sth[j]
        w = y[4 + 2 * z + j]
        fin = qi[j] * _mu_signed(ai - r * w, tv, tmu) if qi[j] > 0.0 else 0.0
        fout = qo[j] * _mu_signed(ao - r * w, tv, tmu) if qo[j] > 0.0 else 0.0
        fx += -qi[j] * c + fin * s
        fy += -qi[j] * s - P[_FYS] * fin * c  # P[_FYS] = 1 (consistent) or -1 (eq20_as_text)
        dy[4 + j] = y[4 + z + j]
        dy[4 + z + j] = (qi[j] - qo[j] + cf - P[_CB] * y[4 + z + j]) / P[_MR]
        dy[4 + 2 * z + j] = 0.5 * P[_D] * (fin + fout) / P[_J]
    dy[0] = y[2]
    dy[1] = y[3]
    dy[2] = fx / P[_MI]
    dy[3] = fy / P[_MI]


@numba.njit(cache=True)
def _torque(w, a_i, a_o, q_i, q_o, r, half_d, tv, tmu):
    return half_d * (q_i * _mu_signed(a_i - r * w, tv, tmu)
                     + q_o * _mu_signed(a_o - r * w, tv, tmu))


@numba.njit(cache=True)
def _spin_flow(w0, tau, a_i, a_o, q_i, q_o, r, half_d, jr, tv, tmu):
    """Exact solution of J w' = T(w) over tau with frozen loads (T piecewise linear)."""
    if q_i <= 0.0 and q_o <= 0.0:
        return w0
    w = w0
    rem = tau
    for _ in range(4 * tv.size + 16):
        t0 = _torque(w, a_i, a_o, q_i, q_o, r, half_d, tv, tmu)
        if t0 == 0.0 or rem <= 0.0:
            return w
        direction = 1.0 if t0 > 0.0 else -1.0
        # nearest kink of T ahead: w where a contact's sliding speed a - r w = +-tv[k]
        bp = math.inf
        dist = math.inf
        eps = 1e-12 * (abs(w) + 1.0)
        for k in range(tv.size):
            for m in range(4):
                if m < 2:
                    if q_i <= 0.0:
                        continue
                    wb = (a_i - tv[k]) / r if m == 0 else (a_i + tv[k]) / r
                else:
                    if q_o <= 0.0:
                        continue
                    wb = (a_o - tv[k]) / r if m == 2 else (a_o + tv[k]) / r
                dd = (wb - w) * direction
                if eps < dd < dist:
                    dist = dd
                    bp = wb
        probe = w + direction * (0.5 * dist if dist < math.inf else 1.0)
        b = (_torque(probe, a_i, a_o, q_i, q_o, r, half_d, tv, tmu) - t0) / (probe - w)
        if b == 0.0:
            t_bp = jr * dist / abs(t0) if dist < math.inf else math.inf
            if t_bp >= rem:
                return w + t0 * rem / jr
            w = bp
            rem -= t_bp
            continue
        wstar = w - t0 / b  # root of the segment's line
        if b < 0.0 and (wstar - w) * direction <= dist:
            return wstar + (w - wstar) * math.exp(b * rem / jr)
        ratio = (bp - wstar) / (w - wstar) if dist < math.inf else math.inf
        t_bp = jr / b * math.log(ratio) if ratio > 0.0 and ratio < math.inf else math.inf
        if t_bp >= rem or t_bp <= 0.0:
            return wstar + (w - wstar) * math.exp(b * rem / jr)
        w = bp
        rem -= t_bp
    return w


@numba.njit(cache=True)
def _spin_sub(t, y, tau, P, dev, tv, tmu, qi, qo, cth, sth):
    """Spin sub-flow over tau with the loads of (t, y) frozen."""
    z = int(P[_Z])
    _, _, r, ai, ao = _race_speeds(P)
    _loads(t, y, P, dev, qi, qo, cth, sth)
    for j in range(z):
        k = 4 + 2 * z + j
        y[k] = _spin_flow(y[k], tau, ai, ao, qi[j], qo[j], r, 0.5 * P[_D], P[_J], tv, tmu)


@numba.njit(cache=True)
def _integrate(method, y, t0, h, sub, n_out, P, dev, tv, tmu, ax, ay, xs, ys, q0, f0):
    """Advance y in place; record n_out samples every `sub` steps of size h.

    method 0: RK4 on all equations. method 1: Strang splitting, spin(h/2) - mechanics RK4(h)
    - spin(h/2); the two spin half-flows that meet between steps inside an output interval
    use the same frozen loads and are merged into one flow over h (exactly equivalent).
    """
    n = y.size
    z = int(P[_Z])
    nmech = 4 + 2 * z
    m = nmech if method == 1 else n
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    tmp = np.empty(n)
    dy = np.empty(n)
    qi = np.empty(z)
    qo = np.empty(z)
    cth = np.empty(z)
    sth = np.empty(z)
    t = t0
    evals = 0
    gam = P[_D] * P[_COSA] / P[_DM]
    r = 0.5 * P[_D] * P[_COSA]
    ai = 0.5 * (P[_WS] - P[_WC]) * P[_DM] * (1.0 - gam)
    for i in range(n_out):
        _rhs(t, y, P, dev, tv, tmu, qi, qo, cth, sth, dy)
        evals += 1
        ax[i] = dy[2]
        ay[i] = dy[3]
        xs[i] = y[0]
        ys[i] = y[1]
        q0[i] = qi[0]
        f0[i] = qi[0] * _mu_signed(ai - r * y[4 + 2 * z], tv, tmu)
        for step in range(sub):
            if method == 1:
                _spin_sub(t, y, 0.5 * h if step == 0 else h, P, dev, tv, tmu, qi, qo, cth,
                          sth)
            _rhs(t, y, P, dev, tv, tmu, qi, qo, cth, sth, k1)
            for q in range(m):
                tmp[q] = y[q] + 0.5 * h * k1[q]
            for q in range(m, n):
                tmp[q] = y[q]
            _rhs(t + 0.5 * h, tmp, P, dev, tv, tmu, qi, qo, cth, sth, k2)
            for q in range(m):
                tmp[q] = y[q] + 0.5 * h * k2[q]
            _rhs(t + 0.5 * h, tmp, P, dev, tv, tmu, qi, qo, cth, sth, k3)
            for q in range(m):
                tmp[q] = y[q] + h * k3[q]
            _rhs(t + h, tmp, P, dev, tv, tmu, qi, qo, cth, sth, k4)
            for q in range(m):
                y[q] += h / 6.0 * (k1[q] + 2.0 * k2[q] + 2.0 * k3[q] + k4[q])
            evals += 4
            t += h
        if method == 1:
            _spin_sub(t, y, 0.5 * h, P, dev, tv, tmu, qi, qo, cth, sth)
    return evals
