"""Property tests of two kernels of the roller dynamics (session 20).

Cage-bar contact (:mod:`thermobearing.skidding.roller_dynamics_pocket`): the Winkler bars
are conservative, so the force and skew moment of :func:`bar_contact` are minus the
gradient of the stored energy U(z, alpha) = (k_l / 2) int (d_f+^2 + d_b+^2) dx over the
roller length (d_f = z - alpha x - c_p/2, d_b = -(z - alpha x) - c_p/2; M_y does work at
the skew rate, the module's sign convention), computed here by quadrature; mirroring the
roller (z, alpha) -> (-z, -alpha) swaps the bars and flips force and moment; the squeeze
film of :func:`pocket_force_z` only dissipates (its force opposes the circumferential
velocity).

Exponential time differencing (:mod:`thermobearing.skidding.roller_dynamics_etd`): one
ETDRK4 step of dv/dt = lambda v + N with constant N is exact, v(h) = e^z v(0) + h phi_1(z) N
(f1 + 4 f2 + f3 = h phi_1), for any z = lambda h, stiff or not, across the switch from the
Taylor series to the recurrence at |z| = 1; the phi-functions satisfy z phi_{k+1} = phi_k -
1/k! on both sides of it.
"""

from __future__ import annotations

import math

from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from thermobearing.skidding.roller_dynamics_etd import etd_coefficients, phi_functions
from thermobearing.skidding.roller_dynamics_pocket import bar_contact, pocket_force_z


def _energy(z, a, half, clearance, stiffness):
    k_l = stiffness / (2.0 * half)

    def density(x):
        d_f = max(z - a * x - 0.5 * clearance, 0.0)
        d_b = max(-(z - a * x) - 0.5 * clearance, 0.0)
        return 0.5 * k_l * (d_f * d_f + d_b * d_b)

    kinks = [x for x in ((z - 0.5 * clearance) / a, (z + 0.5 * clearance) / a)
             if -half < x < half] if a != 0.0 else []
    return quad(density, -half, half, points=kinks or None, epsabs=0.0, epsrel=1e-13,
                limit=200)[0]


bar = dict(half=st.floats(2e-3, 1e-2), clearance=st.floats(1e-5, 5e-4),
           stiffness=st.floats(1e6, 1e9), zf=st.floats(-1.0, 1.0), af=st.floats(-0.1, 0.1))


@settings(max_examples=80, deadline=None)
@given(**bar)
def test_bar_forces_are_minus_the_energy_gradient(half, clearance, stiffness, zf, af):
    """Central differences of the quadrature energy: within 1e-9 of k c_p (force) and
    k c_p L_r/2 (moment); measured 5e-11."""
    z = zf * clearance
    a = af * clearance / half
    fz, my, front, rear = bar_contact(z, a, half, clearance, stiffness)
    hz, ha = 1e-6 * clearance, 1e-6 * clearance / half
    # a nearly unskewed roller touching a bar within the difference step: U'' jumps there
    # (contact along the whole length at once) and the central difference is off by k h/4
    assume(abs(a) * half > 1e-3 * clearance or min(
        abs(z - 0.5 * clearance), abs(z + 0.5 * clearance)) > 10 * hz + abs(a) * half)
    gz = -(_energy(z + hz, a, half, clearance, stiffness)
           - _energy(z - hz, a, half, clearance, stiffness)) / (2 * hz)
    ga = -(_energy(z, a + ha, half, clearance, stiffness)
           - _energy(z, a - ha, half, clearance, stiffness)) / (2 * ha)
    scale = stiffness * clearance
    assert abs(fz - gz) <= 1e-9 * scale
    assert abs(my - ga) <= 1e-9 * scale * half
    assert front >= 0.0 and rear >= 0.0 and math.isclose(fz, rear - front, rel_tol=1e-12,
                                                         abs_tol=1e-12 * scale)
    m = bar_contact(-z, -a, half, clearance, stiffness)
    assert math.isclose(m[0], -fz, rel_tol=1e-12, abs_tol=1e-300)
    assert math.isclose(m[1], -my, rel_tol=1e-12, abs_tol=1e-300)
    assert math.isclose(m[2], rear, rel_tol=1e-12, abs_tol=1e-300)
    assert math.isclose(m[3], front, rel_tol=1e-12, abs_tol=1e-300)


@settings(max_examples=80, deadline=None)
@given(**bar, speed=st.floats(-1.0, 1.0), eta=st.floats(1e-3, 0.5))
def test_squeeze_film_only_dissipates(half, clearance, stiffness, zf, af, speed, eta):
    z = zf * clearance
    a = af * clearance / half
    dry = bar_contact(z, a, half, clearance, stiffness)[0]
    wet = pocket_force_z(z, speed, a, half, clearance, stiffness, eta, 3e-3, 1e-6)[0]
    assert (wet - dry) * speed <= 0.0


def _phi1(z):
    """(e^z - 1)/z, by its series where expm1(z)/z loses digits (near the smallest normal
    numbers)."""
    return math.expm1(z) / z if abs(z) > 1e-8 else 1.0 + z / 2.0 + z * z / 6.0


@settings(max_examples=200, deadline=None)
@given(z=st.one_of(st.floats(-200.0, 50.0, allow_subnormal=False),
                  st.floats(-1.5, 1.5, allow_subnormal=False)), h=st.floats(1e-8, 1e-3),
       v0=st.floats(-1e3, 1e3), forcing=st.floats(-1e6, 1e6))
def test_etd_step_is_exact_for_constant_forcing(z, h, v0, forcing):
    lam = z / h
    e, e2, q, f1, f2, f3 = etd_coefficients(lam, h)
    z = lam * h     # the module's z
    # with N(.) = forcing every stage's N is the same: v+ = E v + (f1 + 4 f2 + f3) N
    v1 = e * v0 + (f1 + 4.0 * f2 + f3) * forcing
    exact = math.exp(z) * v0 + h * _phi1(z) * forcing
    assert math.isclose(v1, exact, rel_tol=1e-12,
                        abs_tol=1e-12 * (abs(math.exp(z) * v0) + abs(h * forcing * math.exp(
                            max(z, 0.0)))))
    assert math.isclose(e2 * e2, e, rel_tol=1e-14)
    assert math.isclose(q, 0.5 * h * _phi1(0.5 * z),
                        rel_tol=1e-13)


@settings(max_examples=200, deadline=None)
@given(z=st.one_of(st.floats(-50.0, 20.0), st.floats(-1.2, 1.2),
                   st.sampled_from([1.0, -1.0, math.nextafter(1.0, 0.0),
                                    math.nextafter(-1.0, 0.0)])))
def test_phi_recurrence_holds_on_both_sides_of_the_switch(z):
    p1, p2, p3 = phi_functions(z)
    assert math.isclose(z * p1, math.expm1(z), rel_tol=1e-14, abs_tol=1e-300)
    assert math.isclose(z * p2, p1 - 1.0, rel_tol=1e-13, abs_tol=1e-15)
    assert math.isclose(z * p3, p2 - 0.5, rel_tol=1e-12, abs_tol=1e-15)
    assert p1 > 0.0 and p2 > 0.0 and p3 > 0.0
