"""Conductance models (hand-checked values) and the bearing templates."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate as sint
from scipy.special import ellipk

from thermobearing.errors import InputError
from thermobearing.network import ThermalNetwork, assemble, integrate, solve_steady
from thermobearing.network.conductances import (
    CONDUCTANCE,
    Convection,
    CylindricalShell,
    HertzConstriction,
    HertzContactPaper002,
    NaturalConvectionCylinder,
    PlaneWall,
    elliptic_constriction_resistance,
    whitaker_sphere_nusselt,
)


def test_simple_conduction_and_convection_by_hand():
    assert PlaneWall(40.0, 0.01, 0.02).conductance(0, 0) == pytest.approx(20.0)
    # 2 pi k L / ln(ro/ri) = 2 pi 40 0.05 / ln(1.2) = 68.92 W/K
    assert CylindricalShell(40.0, 0.1, 0.12, 0.05).conductance(0, 0) == pytest.approx(
        2 * math.pi * 40 * 0.05 / math.log(1.2))
    # paper 002 eq. 27 corrected: G = h A, not h A / L
    assert Convection(270.0, 0.5).conductance(0, 0) == pytest.approx(135.0)
    with pytest.raises(InputError):
        CylindricalShell(40.0, 0.12, 0.1, 0.05)


def test_elliptic_constriction_circle_limit_and_numeric_check():
    # circle: 1/(4 k a) (Carslaw & Jaeger; Yovanovich 1976)
    assert elliptic_constriction_resistance(1e-3, 1e-3, 40.0) == pytest.approx(
        1.0 / (4 * 40.0 * 1e-3))
    # ellipse: centre temperature of the flux q = Q/(2 pi a b sqrt(1 - rho^2)) through the
    # half-space Green's function 1/(2 pi k r), integrated numerically (unit Q)
    a, b, k = 0.5e-3, 0.075e-3, 40.0

    def integrand(rho, phi):
        r = rho * math.sqrt(a**2 * math.cos(phi) ** 2 + b**2 * math.sin(phi) ** 2)
        q = 1.0 / (2 * math.pi * a * b * math.sqrt(1 - rho**2))
        return q / (2 * math.pi * k * r) * a * b * rho

    val, _ = sint.dblquad(integrand, 0, 2 * math.pi, 0, 1)
    assert elliptic_constriction_resistance(a, b, k) == pytest.approx(val, rel=1e-6)
    # the primer's magnitude: a = 0.5 mm, b/a = 0.15, k = 40 -> K(e) = 3.30, R = 52 K/W
    assert ellipk(1 - 0.15**2) == pytest.approx(3.296, abs=1e-3)
    assert elliptic_constriction_resistance(a, b, k) * 2 == pytest.approx(52.46, rel=1e-3)


def test_hertz_models_per_element_times_count():
    g1 = HertzConstriction(0.5e-3, 0.075e-3, 40.0, 40.0, 1).conductance(0, 0)
    g20 = HertzConstriction(0.5e-3, 0.075e-3, 40.0, 40.0, 20).conductance(0, 0)
    assert g20 == pytest.approx(20 * g1)
    assert 1 / g1 == pytest.approx(52.46, rel=1e-3)
    # paper 002 eq. 26 in consistent form: G = Z K pi b / 2
    gp = HertzContactPaper002(0.5e-3, 0.075e-3, 40.0, 20).conductance(0, 0)
    assert gp == pytest.approx(20 * 40.0 * math.pi * 0.075e-3 / 2)
    assert g20 / gp == pytest.approx(2 * 0.5 / (0.075 * ellipk(1 - 0.15**2)), rel=1e-9)


def test_natural_convection_matches_hand_calculation():
    """D = 0.15 m, surface 330 K, air 300 K (film 315 K): Churchill-Chu by hand."""
    from CoolProp.CoolProp import PropsSI

    Tf = 315.0
    rho, mu, k, cp = (PropsSI(x, "T", Tf, "P", 101325.0, "Air") for x in "DVLC")
    nu = mu / rho
    pr = mu * cp / k
    ra = 9.80665 * (1 / Tf) * 30.0 * 0.15**3 / nu**2 * pr
    nu_d = (0.60 + 0.387 * ra ** (1 / 6) / (1 + (0.559 / pr) ** (9 / 16)) ** (8 / 27)) ** 2
    h_hand = nu_d * k / 0.15
    m = NaturalConvectionCylinder(0.15, 1.0)
    h = m.heat_transfer_coefficient(330.0, 300.0)
    assert h == pytest.approx(h_hand, rel=1e-3)  # air props may come from lubricant.py
    assert 4.0 < h < 5.5  # primer sec. 4.2 worked example: about 4.7 W/(m^2 K)
    assert m.temperature_dependent


def test_whitaker_sphere():
    # Incropera Example 7.7-like magnitude: Re = 1e4, Pr = 0.7 -> Nu = 2 + (40 + 27.8) 0.867
    nu = whitaker_sphere_nusselt(1e4, 0.7)
    assert nu == pytest.approx(2 + (0.4 * 100 + 0.06 * 1e4 ** (2 / 3)) * 0.7**0.4)


def test_registry_round_trip_of_every_model():
    params = {
        "fixed": {"value": 3.0},
        "plane_wall": {"thermal_conductivity": 40.0, "area": 0.01, "thickness": 0.02},
        "cylindrical_shell": {"thermal_conductivity": 40.0, "inner_radius": 0.1,
                              "outer_radius": 0.12, "length": 0.05},
        "convection": {"h": 100.0, "area": 0.1},
        "contact_fit": {"contact_conductance": 5000.0, "area": 0.01},
        "hertz_constriction": {"semi_major": 1e-3, "semi_minor": 2e-4, "k_element": 40.0,
                               "k_ring": 40.0, "n_contacts": 20},
        "hertz_contact_paper002": {"semi_major": 1e-3, "semi_minor": 2e-4,
                                   "thermal_conductivity": 40.0, "n_contacts": 20},
        "natural_convection_horizontal_cylinder": {"diameter": 0.3, "area": 0.5},
    }
    for name, p in params.items():
        m = CONDUCTANCE.get(name)(**p)
        d = m.to_dict()
        assert d["model"] == name
        again = CONDUCTANCE.get(name)(**{k: v for k, v in d.items() if k != "model"})
        assert again.conductance(320.0, 300.0) == pytest.approx(m.conductance(320.0, 300.0))


def test_temperature_dependent_edge_is_lagged_but_converges():
    net = ThermalNetwork()
    net.add_boundary("air", 300.0)
    net.add_node("housing", 2e4, role="outer_ring")
    net.add_edge("housing", "air", NaturalConvectionCylinder(0.3, 0.5))
    st = solve_steady(net, [60.0], T_guess=320.0)
    g = net.edge_conductance("housing", "air", 0, st.temperatures["housing"], 300.0)
    assert g * (st.temperatures["housing"] - 300.0) == pytest.approx(60.0, rel=1e-8)
    res = integrate(net, [60.0], (0, 2e6), 300.0, rtol=1e-6, atol=1e-5)
    assert res.temperatures[-1, 0] == pytest.approx(st.temperatures["housing"], abs=1e-3)


def test_dense_assembly_of_temperature_dependent_edges_equals_generic_stamping():
    """The dense fast path (edges resolved once per revision) against the generic sparse
    stamping: a state-state and a state-boundary temperature-dependent edge, a constant
    edge and a boundary temperature changed after the first assembly."""
    import scipy.sparse as sp

    from thermobearing.network.assemble import Assembler

    net = ThermalNetwork()
    net.add_boundary("air", 300.0)
    net.add_node("housing", 2e4, role="outer_ring")
    net.add_node("shaft", 1e4, role="inner_ring")
    net.add_edge("housing", "air", NaturalConvectionCylinder(0.3, 0.5))
    net.add_edge("shaft", "housing", NaturalConvectionCylinder(0.1, 0.2))
    net.add_edge("shaft", "air", Convection(10.0, 0.1))
    for t_air in (300.0, 310.0):
        net.set_boundary_temperature("air", t_air)
        dense = Assembler(net)
        generic = Assembler(net)
        generic.dense = False
        generic.K0 = sp.csc_matrix(generic.K0)
        T = np.array([335.0, 321.0])
        a, b = dense.system(T), generic.system(T)
        np.testing.assert_allclose(a.K, b.K.toarray(), rtol=1e-15)
        np.testing.assert_allclose(a.s, b.s, rtol=1e-15)
        order_a, order_b = np.lexsort((a.bnd_G, a.bnd_index)), np.lexsort((b.bnd_G, b.bnd_index))
        np.testing.assert_array_equal(a.bnd_index[order_a], b.bnd_index[order_b])
        np.testing.assert_allclose(a.bnd_G[order_a], b.bnd_G[order_b], rtol=1e-15)
        np.testing.assert_allclose(a.bnd_T[order_a], b.bnd_T[order_b], rtol=1e-15)
        g = net.edge_conductance("housing", "air", 0, 335.0, t_air)
        assert g > 0 and a.s[0] == pytest.approx(g * t_air, rel=1e-12)


def test_drift_and_its_jacobian_from_the_edges_equal_reassembly():
    """Assembler.drift on a dense system works edge by edge from the step's stored
    conductances; it equals the change of s - K T between two full assemblies, sums to
    minus the change of the heat to the boundaries, and drift_jacobian is its derivative
    (central differences of the drift)."""
    import dataclasses

    from thermobearing.network.assemble import Assembler

    net = ThermalNetwork()
    net.add_boundary("air", 300.0)
    net.add_node("housing", 2e4, role="outer_ring")
    net.add_node("shaft", 1e4, role="inner_ring")
    net.add_edge("housing", "air", NaturalConvectionCylinder(0.3, 0.5))
    net.add_edge("shaft", "housing", NaturalConvectionCylinder(0.1, 0.2))
    net.add_edge("shaft", "air", Convection(10.0, 0.1))
    asm = Assembler(net)
    T0, T = np.array([335.0, 321.0]), np.array([341.0, 318.5])
    ref = asm.system(T0)
    d, db = asm.drift(ref, T)
    full = asm.system(T)
    np.testing.assert_allclose(d, (full.s - full.K @ T) - (ref.s - ref.K @ T), atol=1e-10)
    assert db == pytest.approx(full.to_boundaries(T) - ref.to_boundaries(T), rel=1e-10)
    assert d.sum() == pytest.approx(-db, rel=1e-10)
    d_generic, db_generic = asm.drift(dataclasses.replace(ref, var_g=None), T)
    np.testing.assert_allclose(d, d_generic, atol=1e-10)
    D = asm.drift_jacobian(T0)
    h = 1e-4
    for j in range(2):
        e = np.zeros(2)
        e[j] = h
        fd = (asm.drift(ref, T0 + e)[0] - asm.drift(ref, T0 - e)[0]) / (2.0 * h)
        np.testing.assert_allclose(D[:, j], fd, rtol=1e-5, atol=1e-9)


# ---------------------------------------------------------------------- templates
@pytest.fixture(scope="module")
def qj1044():
    geometry = pytest.importorskip("thermobearing.geometry")
    lub = pytest.importorskip("thermobearing.lubricant")
    return geometry.load_bearing("QJ1044"), lub.load_lubricant("ISO_VG46")


def test_four_node_template_paper002(qj1044):
    from thermobearing.network.templates import four_node_paper002

    b, lub = qj1044
    net = four_node_paper002(b, lub, housing_outer_diameter=0.42, housing_length=0.1,
                             oil_flow=33 / 60000, ball_load=5000.0)
    assert net.state_nodes == ("balls", "housing", "shaft", "oil")
    assert net.nodes_for_role("outer_ring") == ["housing"]
    assert net.nodes_for_role("cage") == ["oil"] == net.nodes_for_role("oil")
    # balls: Z m c
    assert net.capacity("balls") == pytest.approx(
        b.n_balls * b.ball_mass * b.ball_material.specific_heat)
    # stream = rho c_p Q at the inlet temperature
    w = net.streams["oil"].capacity_rate
    assert w == pytest.approx(float(lub.density(308.15) * lub.specific_heat(308.15)) * 33 / 60000)
    q = net.distribute({"elements": 1000.0, "outer_ring": 300.0, "inner_ring": 300.0,
                        "oil": 500.0, "cage": 200.0})
    st = solve_steady(net, q, T_guess=320.0)
    assert st.generated == pytest.approx(2300.0)
    assert st.to_boundaries + st.to_streams == pytest.approx(2300.0, rel=1e-8)
    assert st.to_streams > 0.8 * 2300.0  # the oil carries most of the heat (primer 4.4)
    # what-if: halve the oil flow -> hotter oil, still one network
    net.set_stream_flow("oil", w / 2)
    assert solve_steady(net, q, T_guess=320.0).temperatures["oil"] > st.temperatures["oil"]
    # serialization keeps the evaluated network
    back = ThermalNetwork.from_dict(net.to_dict())
    np.testing.assert_allclose(assemble(back, np.full(4, 320.0)).K,
                               assemble(net, np.full(4, 320.0)).K)


def test_two_bearings_one_rig_and_seven_node(qj1044):
    from thermobearing.network.templates import four_node_paper002, seven_node

    b, lub = qj1044
    net = four_node_paper002(b, lub, housing_outer_diameter=0.42, housing_length=0.1,
                             oil_flow=5e-4, group="de", prefix="de_")
    four_node_paper002(b, lub, housing_outer_diameter=0.42, housing_length=0.1,
                       oil_flow=5e-4, group="nde", prefix="nde_", network=net)
    assert net.groups() == ["de", "nde"]
    assert len(net.state_nodes) == 8 and len(net.boundary_nodes) == 2
    assert net.nodes_for_role("elements", group="nde") == ["nde_balls"]
    n7 = seven_node(b, lub, housing_outer_diameter=0.42, housing_length=0.1, oil_flow=5e-4)
    assert set(n7.roles()) == {"outer_ring", "inner_ring", "elements", "cage", "oil"}
    four = four_node_paper002(b, lub, housing_outer_diameter=0.42, housing_length=0.1,
                              oil_flow=5e-4)
    # the seven-node split conserves the total heat capacity
    assert sum(n7.capacity(n) for n in n7.state_nodes) == pytest.approx(
        sum(four.capacity(n) for n in four.state_nodes), rel=1e-12)


def test_oil_forced_convection_models_by_hand():
    lub_mod = pytest.importorskip("thermobearing.lubricant")
    from thermobearing.network.conductances import (
        OilForcedConvectionPlate,
        OilForcedConvectionSphere,
    )

    lub = lub_mod.load_lubricant("ISO_VG46")
    Tb, Ta = 330.0, 340.0  # oil, ball
    rho, mu = float(lub.density(Tb)), float(lub.dynamic_viscosity(Tb))
    k, cp = float(lub.thermal_conductivity(Tb)), float(lub.specific_heat(Tb))
    mu_s = float(lub.dynamic_viscosity(Ta))
    D, v = 0.035, 3.0
    re, pr = rho * v * D / mu, mu * cp / k
    nu = 2 + (0.4 * re**0.5 + 0.06 * re ** (2 / 3)) * pr**0.4 * (mu / mu_s) ** 0.25
    m = OilForcedConvectionSphere("ISO_VG46", D, v, 20)
    assert m.conductance(Ta, Tb) == pytest.approx(20 * math.pi * D**2 * nu * k / D, rel=1e-9)
    # plate, laminar, Pr > 10: Nu = 0.678 Re^0.5 Pr^(1/3) (ht, Baehr) at the film temperature
    Tf = 0.5 * (Ta + Tb)
    rho, mu = float(lub.density(Tf)), float(lub.dynamic_viscosity(Tf))
    k, cp = float(lub.thermal_conductivity(Tf)), float(lub.specific_heat(Tf))
    L = 0.05
    re, pr = rho * v * L / mu, mu * cp / k
    h = 0.678 * re**0.5 * pr ** (1 / 3) * k / L
    p = OilForcedConvectionPlate("ISO_VG46", L, v, 0.02)
    assert p.conductance(Ta, Tb) == pytest.approx(h * 0.02, rel=1e-9)
