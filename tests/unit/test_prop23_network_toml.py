"""Property tests, round 5: a thermal network survives the scene's TOML round trip.

Invariant: a network is data (nodes, capacities, boundary temperatures, conductance models
with their parameters, streams), so ``ThermalNetwork.from_dict`` of the TOML text written by
:func:`thermobearing.toml_writer.dumps_toml` from ``to_dict`` rebuilds the same system: the
same state nodes in the same order and, at any temperatures, the same C, K and s of
``C dT/dt = -K T + s`` (bit for bit: every float is written with ``repr``, which reads back
exactly, IEEE 754 / Python float repr round trip). Node names may be any Unicode text
("Gehäuse", "Außenring") since the session-23 writer fix.
"""

from __future__ import annotations

import tomllib

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing import load_bearing, load_lubricant
from thermobearing.network import ThermalNetwork, assemble
from thermobearing.network.conductances import CylindricalShell, PlaneWall
from thermobearing.network.templates import TEMPLATES
from thermobearing.toml_writer import dumps_toml

_names = st.text(min_size=1, max_size=8).filter(lambda s: s.strip() == s and "." not in s)


def _dense(K):
    return K.toarray() if hasattr(K, "toarray") else np.asarray(K)


@st.composite
def networks(draw):
    """A template network of a catalogue bearing, plus a random chain of extra nodes with
    Unicode names hung on its ambient through fixed, plane-wall and shell conductances."""
    name = draw(st.sampled_from(("SKF6304", "QJ1044", "NU214", "CRB_50x75x16")))
    b = load_bearing(name)
    net = TEMPLATES.get(draw(st.sampled_from(TEMPLATES.names())))(
        b, load_lubricant("ISO_VG46"), housing_outer_diameter=1.6 * b.outer_diameter,
        housing_length=2.0 * b.width, oil_flow=draw(st.floats(0.0, 1e-4)),
        oil_inlet_temperature=draw(st.floats(290.0, 330.0)),
        ambient_temperature=draw(st.floats(280.0, 320.0)),
        contact_model=draw(st.sampled_from(("hertz_constriction", "hertz_contact_paper002"))))
    extra = draw(st.lists(_names, max_size=3, unique=True))
    extra = [n for n in extra if n not in set(net.state_nodes) | set(net.boundary_nodes)]
    previous = net.state_nodes[0]
    for n in extra:
        net.add_node(n, draw(st.floats(0.0, 1e4)))
        model = draw(st.sampled_from(("fixed", "wall", "shell")))
        if model == "fixed":
            g = draw(st.floats(0.01, 100.0))
        elif model == "wall":
            g = PlaneWall(draw(st.floats(0.1, 400.0)), draw(st.floats(1e-4, 1.0)),
                          draw(st.floats(1e-3, 0.1)))
        else:
            r_i = draw(st.floats(0.005, 0.1))
            g = CylindricalShell(draw(st.floats(0.1, 400.0)), r_i,
                                 r_i * draw(st.floats(1.1, 3.0)), draw(st.floats(0.01, 0.5)))
        net.add_edge(previous, n, g)
        previous = n
    return net


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(networks(), st.integers(0, 2**32 - 1))
def test_network_reads_back_from_its_toml_with_the_same_system(net, seed):
    """Same node order, and C, K, s identical at three random temperature fields."""
    text = dumps_toml({"network": net.to_dict()})
    back = ThermalNetwork.from_dict(tomllib.loads(text)["network"])
    assert back.state_nodes == net.state_nodes
    assert back.boundary_nodes == net.boundary_nodes
    rng = np.random.default_rng(seed)
    for _ in range(3):
        T = rng.uniform(280.0, 420.0, len(net.state_nodes))
        a, b = assemble(net, T), assemble(back, T)
        np.testing.assert_array_equal(a.C, b.C)
        np.testing.assert_array_equal(_dense(a.K), _dense(b.K))
        np.testing.assert_array_equal(a.s, b.s)
