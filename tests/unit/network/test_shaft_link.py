"""Bearings on one shaft: ``[network] shaft_link`` (thermobearing/network/shaft.py).

The conductance by hand, the capacity of overlapping shaft pieces, the heat through the link
in a solved asymmetric network, the energy audit, the default rig unchanged by the link,
the notes ``thermobearing check`` prints, and the schema's errors.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_parts import (
    PAPER002_AMBIENT,
    PAPER002_OIL,
    QJ1044_DE,
    QJ1044_NDE,
    RACE_CONTROL,
    scene_title,
)

from thermobearing import cli
from thermobearing.coupled import build_network
from thermobearing.errors import InputError, UnknownNameError
from thermobearing.materials import get_material
from thermobearing.network import ThermalNetwork, TransientStepper, solve_steady
from thermobearing.network.shaft import (
    axial_shaft_conductance,
    fin_span_conductances,
    kept_lengths,
    link_shafts,
    parse_shaft_links,
)
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

TWO = (scene_title("two bearings on one shaft") + QJ1044_DE + QJ1044_NDE + PAPER002_OIL
       + PAPER002_AMBIENT + RACE_CONTROL + """[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "10 kN"
duration = "{duration}"
[outputs]
want = ["temperatures", "energy"]
[network]
template = "{template}"
parameters = {{ housing_outer_diameter = "510 mm", housing_length = "140 mm", \
shaft_diameter = "220 mm", shaft_length = "{shaft_length}", h_air = "10 W/(m**2*K)" }}
""")


def plain_text() -> str:
    """The two-bearing scene without a link, four-node template, one 3 min step."""
    return TWO.format(template="four_node_paper002", shaft_length="500 mm", duration="3 min")


def scene(link: str = "", template: str = "four_node_paper002", shaft_length: str = "500 mm",
          duration: str = "3 min"):
    text = TWO.format(template=template, shaft_length=shaft_length, duration=duration)
    return loads_scene(text + (f"shaft_link = {link}\n" if link else ""))


def link_edge(net: ThermalNetwork):
    found = [(a, b, m) for a, b, _, m in net.edges() if {a, b} == {"de.shaft", "nde.shaft"}]
    assert len(found) == 1
    return found[0][2]


def test_conductance_by_hand_and_the_note_check_prints():
    # G = k pi d^2 / 4 / L = 47 * pi * 0.22^2 / 4 / 0.5 = 3.5732 W/K (STEEL_52100, k = 47)
    k = get_material("STEEL_52100").thermal_conductivity
    assert k == 47.0
    G = 47.0 * math.pi * 0.22**2 / 4.0 / 0.5
    assert axial_shaft_conductance(47.0, 0.22, 0.5) == pytest.approx(G, rel=1e-15)
    assert G == pytest.approx(3.5732, abs=1e-4)
    sim = Simulation(scene('{ spacing = "500 mm" }'), progress=False)
    net = build_network(sim)
    assert link_edge(net).conductance(300.0, 350.0) == pytest.approx(G, rel=1e-14)
    line = [n for n in sim.notes if n.startswith("shaft link")]
    assert line == ["shaft link de.shaft -- nde.shaft: axial conduction along 500 mm of a "
                    "220 mm solid STEEL_52100 shaft (k = 47 W/(m K)), G = 3.573 W/K "
                    "(span adiabatic)"]
    assert not any("thermally independent" in n for n in sim.notes)
    # a given diameter and material replace the template's: 100 mm of low-carbon steel
    sim = Simulation(scene('{ spacing = "0.4 m", diameter = "100 mm", '
                           'material = "STEEL_LOW_CARBON" }'), progress=False)
    k = get_material("STEEL_LOW_CARBON").thermal_conductivity
    assert k != 47.0
    assert link_edge(build_network(sim)).conductance(300.0, 300.0) == pytest.approx(
        k * math.pi * 0.1**2 / 4.0 / 0.4, rel=1e-14)


def test_default_diameter_is_the_smaller_bore_without_a_shaft_diameter():
    text = plain_text().replace(
        'shaft_diameter = "220 mm", ', "")
    sim = Simulation(loads_scene(text + 'shaft_link = { spacing = "1 m" }\n'), progress=False)
    bore = sim.bearings[0].bearing.bore
    assert bore == pytest.approx(0.22)
    assert link_edge(build_network(sim)).conductance(300.0, 300.0) == pytest.approx(
        47.0 * math.pi * bore**2 / 4.0, rel=1e-14)


def test_two_bearings_without_a_link_are_noted_as_independent_in_check(tmp_path, capsys):
    path = tmp_path / "two.toml"
    path.write_text(plain_text(),
                    encoding="utf-8")
    assert cli.main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert ("note: bearings de, nde are thermally independent: their networks share only "
            "the ambient and the oil inlet") in out
    path.write_text(path.read_text(encoding="utf-8") + 'shaft_link = { spacing = "0.5 m" }\n',
                    encoding="utf-8")
    assert cli.main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert "note: shaft link de.shaft -- nde.shaft:" in out and "G = 3.573 W/K" in out
    assert "thermally independent" not in out


def test_kept_lengths_share_overlapping_pieces_once():
    # no overlap (pieces meet at 0.25 m): every node keeps its piece
    assert kept_lengths([0.0, 0.5], [0.5, 0.5]) == pytest.approx([0.5, 0.5])
    # 0.5 m pieces 0.3 m apart overlap over 0.2 m: 0.1 m of it goes to each
    assert kept_lengths([0.0, 0.3], [0.5, 0.5]) == pytest.approx([0.4, 0.4])
    # three pieces: [-0.3, 0.3], [-0.1, 0.5], [0.1, 0.7]; what is kept adds up to the
    # union, 1.0 m
    kept = kept_lengths([0.0, 0.2, 0.4], [0.6, 0.6, 0.6])
    assert sum(kept) == pytest.approx(1.0)
    # [-0.3,-0.1] alone, [-0.1,0.1] with the second, [0.1,0.3] with both
    assert kept[0] == pytest.approx(0.2 + 0.1 + 0.2 / 3)


def test_overlapping_shaft_pieces_move_capacity_explicitly():
    base = build_network(Simulation(scene(), progress=False))
    sim = Simulation(scene('{ spacing = "300 mm" }'), progress=False)
    net = build_network(sim)
    m = get_material("STEEL_52100")
    # half the 0.2 m overlap of the two 0.5 m pieces leaves each shaft node
    per_length = m.density * m.specific_heat * math.pi / 4.0 * 0.22**2
    for node in ("de.shaft", "nde.shaft"):
        assert net.capacity(node) == pytest.approx(base.capacity(node) - 0.1 * per_length,
                                                   rel=1e-12)
    assert any("overlap" in n and "de.shaft -" in n for n in sim.notes)
    # spacing = shaft_length: the pieces meet, nothing moves
    net = build_network(Simulation(scene('{ spacing = "500 mm" }'), progress=False))
    for node in ("de.shaft", "nde.shaft"):
        assert net.capacity(node) == base.capacity(node)


def _asymmetric_heat(net: ThermalNetwork) -> np.ndarray:
    """800 W in the drive end (a much hotter bearing), 100 W in the non-drive end, split
    over the roles as the contact losses are (most to the elements)."""
    q = net.distribute({"elements": 480.0, "inner_ring": 160.0, "outer_ring": 160.0},
                       group="de")
    return net.distribute({"elements": 60.0, "inner_ring": 20.0, "outer_ring": 20.0},
                          group="nde", out=q)


def _outflow(net: ThermalNetwork, T: dict[str, float], group_nodes: set[str]) -> float:
    """Heat [W] leaving a set of nodes through every edge to the boundaries and every
    stream leaving them (not the shaft link)."""
    out = 0.0
    for a, b, k, _ in net.edges():
        inside = (a in group_nodes, b in group_nodes)
        if inside == (True, True) or inside == (False, False):
            continue
        if {a, b} == {"de.shaft", "nde.shaft"}:
            continue
        src, dst = (a, b) if inside[0] else (b, a)
        Ts = T[src]
        Td = T[dst] if dst in T else net.boundary_temperature(dst)
        out += net.edge_conductance(a, b, k, T[a] if a in T else net.boundary_temperature(a),
                                    T[b] if b in T else net.boundary_temperature(b)) * (Ts - Td)
    for st in net.streams.values():
        last = st.path[-1]
        if last in group_nodes:
            out += st.capacity_rate * (T[last] - net.boundary_temperature(st.path[0]))
    return out


def test_link_cools_the_hot_bearing_and_carries_g_times_dt():
    free = build_network(Simulation(scene(), progress=False))
    net = build_network(Simulation(scene('{ spacing = "500 mm" }'), progress=False))
    T0 = solve_steady(free, _asymmetric_heat(free)).temperatures
    T1 = solve_steady(net, _asymmetric_heat(net)).temperatures
    assert T1["de.shaft"] < T0["de.shaft"] - 0.1
    assert T1["nde.shaft"] > T0["nde.shaft"] + 0.1
    G = link_edge(net).conductance(0.0, 0.0)
    through = G * (T1["de.shaft"] - T1["nde.shaft"])
    assert through > 0.0
    # the hot bearing's books: 800 W in, what its boundaries and oil stream take out, the
    # rest leaves through the link; the cold bearing receives it
    de = {n for n in net.state_nodes if n.startswith("de.")}
    nde = {n for n in net.state_nodes if n.startswith("nde.")}
    assert 800.0 - _outflow(net, T1, de) == pytest.approx(through, rel=1e-8)
    assert _outflow(net, T1, nde) - 100.0 == pytest.approx(through, rel=1e-8)


def test_energy_audit_closes_with_the_link():
    net = build_network(Simulation(scene('{ spacing = "500 mm" }'), progress=False))
    stepper = TransientStepper(net, method="exprb43", rtol=1e-8, atol=1e-6)
    out = stepper.advance(0.0, np.full(len(net.state_nodes), 308.15), 1800.0,
                          _asymmetric_heat(net))
    T = dict(zip(net.state_nodes, out.temperatures, strict=True))
    assert T["de.shaft"] > T["nde.shaft"] + 0.1  # heat flows through the link
    a = out.audit
    books = float(np.sum(a.generated))
    assert books == pytest.approx(900.0 * 1800.0, rel=1e-12)
    assert abs(float(np.sum(a.imbalance))) <= 1e-9 * books


@pytest.mark.parametrize("template", ["four_node_paper002", "seven_node"])
def test_identical_bearings_run_the_same_with_and_without_the_link(template):
    runs = []
    for link in ("", '{ spacing = "500 mm" }'):
        res = Simulation(scene(link, template=template, duration="20 min"),
                         progress=False).run()
        runs.append(res.tables["temperatures"])
    free, linked = runs
    cols = [c for c in free.columns if c.endswith("[degC]")]
    assert list(linked.columns) == list(free.columns)
    assert np.max(np.abs(linked[cols].to_numpy() - free[cols].to_numpy())) <= 1e-9
    # the 20 min run heated every node (the shafts least); the link joins nodes at equal
    # temperatures
    assert np.all(linked[cols].to_numpy()[-1] > 35.2)


def test_shaft_link_round_trips_through_to_toml():
    for link in ('{ spacing = "500 mm" }',
                 '[{ bearings = ["nde", "de"], spacing = ["0.3 m"], diameter = "80 mm", '
                 'material = "STEEL_52100" }]'):
        sc = scene(link)
        again = loads_scene(sc.to_toml())
        assert again.network == sc.network
        assert again.to_toml() == sc.to_toml()


@pytest.mark.parametrize("link, field, text", [
    ('{ spacing = "0 mm" }', "network.shaft_link.spacing", "a length > 0"),
    ('{ spacing = "-300 mm" }', "network.shaft_link.spacing", "a length > 0"),
    ('{ spacing = "300 kg" }', "network.shaft_link.spacing", "m"),
    ("{ diameter = \"0.2 m\" }", "network.shaft_link.spacing", "this key is required"),
    ('{ spacing = "0.3 m", bearings = ["de"] }', "network.shaft_link.bearings",
     "two or more bearings"),
    ('{ spacing = "0.3 m", bearings = ["de", "de"] }', "network.shaft_link.bearings",
     "different bearings"),
    ('{ spacing = "0.3 m", lenght = "1 m" }', "network.shaft_link.lenght", "a known key"),
    ('{ spacing = "0.3 m", diameter = "-1 mm" }', "network.shaft_link.diameter", "> 0"),
    ('{ spacing = ["0.3 m", "0.2 m"], bearings = ["de", "nde"] }',
     "network.shaft_link.spacing", "one length or 1"),
    ('{ spacing = ["0.3 m", "0.2 m"] }', "network.shaft_link.spacing",
     "one length or 1 (one per gap between 2 bearings)"),
    ('"0.3 m"', "network.shaft_link", "a table"),
])
def test_bad_shaft_links_are_refused_when_the_scene_loads(link, field, text):
    with pytest.raises(InputError) as err:
        scene(link)
    assert err.value.field == field
    assert text in str(err.value)


def test_unknown_material_lists_the_presets():
    with pytest.raises(UnknownNameError) as err:
        scene('{ spacing = "0.3 m", material = "unobtainium" }')
    assert err.value.field == "network.shaft_link.material"
    assert "STEEL_52100" in str(err.value)


@pytest.mark.parametrize("link, field, text", [
    ('{ spacing = "0.3 m", bearings = ["de", "tail"] }', "network.shaft_link.bearings[1]",
     "known names are: de, nde"),
    ('[{ spacing = "0.3 m", bearings = ["de", "nde"] }, '
     '{ spacing = "0.3 m", bearings = ["nde", "de"] }]', "network.shaft_link[1].bearings[0]",
     "on no other shaft"),
])
def test_bad_bearing_names_are_refused(link, field, text):
    # when the scene loads (its [[bearings]] names are known there) ...
    with pytest.raises(InputError) as err:
        scene(link)
    assert err.value.field == field and text in str(err.value)
    # ... and by the network build, for a scene changed after loading
    sc = scene().with_changes(network={**scene().network,
                                       "shaft_link": _toml_value(link)})
    with pytest.raises(InputError) as err:
        build_network(Simulation(sc, progress=False))
    assert err.value.field == field and text in str(err.value)


def _toml_value(text: str):
    import tomllib

    return tomllib.loads(f"v = {text}")["v"]


def test_a_link_on_a_one_bearing_scene_is_refused():
    one = plain_text().replace('[[bearings]]\nname = "nde"\npreset = "QJ1044"\n', "")
    with pytest.raises(InputError) as err:
        loads_scene(one + 'shaft_link = { spacing = "0.3 m" }\n')
    assert err.value.field == "network.shaft_link.bearings"
    assert "two or more bearings on the shaft (the scene has 1: de)" in str(err.value)
    # and one bearing alone gets no independence note
    sim = Simulation(loads_scene(one), progress=False)
    build_network(sim)
    assert not any("independent" in n for n in sim.notes)


def test_a_network_without_shaft_nodes_is_refused():
    net = ThermalNetwork("no shafts")
    net.add_boundary("ambient", 300.0)
    for b in ("de", "nde"):
        net.add_node(f"{b}.housing", 1000.0, group=b)
        net.add_edge(f"{b}.housing", "ambient", 1.0)
    with pytest.raises(InputError) as err:
        link_shafts(net, parse_shaft_links({"spacing": 0.3}), ["de", "nde"], {}, "custom")
    assert err.value.field == "network.shaft_link"
    assert "a network template with a 'shaft' node per bearing" in str(err.value)
    assert "'custom'" in str(err.value)


def test_coupled_run_of_an_unequal_pair_closes_its_books_and_evens_the_shafts():
    # the non-drive end with a larger clearance (0.4 mm, preset 0.1 mm) runs slightly
    # hotter at the shaft; the link narrows the difference, the run's audit closes
    text = TWO.format(template="four_node_paper002", shaft_length="500 mm",
                      duration="30 min").replace(
        'name = "nde"\npreset = "QJ1044"\n',
        'name = "nde"\npreset = "QJ1044"\noverrides = { diametral_clearance = "0.4 mm" }\n')
    gaps = []
    for link in ("", 'shaft_link = { spacing = "500 mm" }\n'):
        res = Simulation(loads_scene(text + link), progress=False).run()
        last = res.tables["temperatures"].iloc[-1]
        gaps.append(last["nde.shaft [degC]"] - last["de.shaft [degC]"])
        assert res.stats["relative_energy_imbalance"] < 1e-12
    free, linked = gaps
    assert free > 0.01
    assert 0.0 < linked < free


def test_fin_span_two_port_by_hand_and_its_adiabatic_limit():
    """k = 47 W/(m K), d = 0.22 m, L = 0.5 m, h = 10 W/(m^2 K): m = sqrt(4 h / (k d)),
    G_ab = k A m / sinh(m L), G_end = k A m tanh(m L / 2); h -> 0 gives k A / L and 0."""
    import math

    k, d, L, h = 47.0, 0.22, 0.5, 10.0
    m = math.sqrt(4 * h / (k * d))
    assert m * L == pytest.approx(0.9834, rel=1e-3)
    kam = k * math.pi * d**2 / 4 * m
    g_ab, g_end = fin_span_conductances(k, d, L, h)
    assert g_ab == pytest.approx(kam / math.sinh(m * L), rel=1e-14)
    assert g_end == pytest.approx(kam * math.tanh(m * L / 2), rel=1e-14)
    g0 = axial_shaft_conductance(k, d, L)
    assert g_ab / g0 == pytest.approx(m * L / math.sinh(m * L), rel=1e-12)  # 0.85 here
    assert fin_span_conductances(k, d, L, 0.0) == (g0, 0.0)
    small = fin_span_conductances(k, d, L, 1e-9)
    assert small[0] == pytest.approx(g0, rel=1e-9) and small[1] < 1e-9


def test_fin_two_port_matches_the_fin_equation_solved_numerically():
    """The two-port gives the end heats of the fin ODE theta'' = m^2 theta with both end
    temperatures prescribed (solved here by scipy's BVP solver)."""
    import math

    import numpy as np
    from scipy.integrate import solve_bvp

    from thermobearing.network.shaft import fin_span_conductances

    k, d, L, h = 47.0, 0.08, 0.4, 40.0
    area = math.pi * d**2 / 4
    m2 = 4 * h / (k * d)
    th_a, th_b = 30.0, 5.0  # end excess temperatures over the ambient [K]
    x = np.linspace(0.0, L, 50)
    sol = solve_bvp(lambda x, y: np.vstack([y[1], m2 * y[0]]),
                    lambda ya, yb: np.array([ya[0] - th_a, yb[0] - th_b]),
                    x, np.vstack([np.linspace(th_a, th_b, x.size), np.zeros(x.size)]),
                    tol=1e-10, max_nodes=100000)
    assert sol.success
    q_a = -k * area * sol.sol(0.0)[1]    # heat entering the rod at a [W]
    q_b = k * area * sol.sol(L)[1]       # heat entering the rod at b [W]
    g_ab, g_end = fin_span_conductances(k, d, L, h)
    assert q_a == pytest.approx(g_ab * (th_a - th_b) + g_end * th_a, rel=1e-6)
    assert q_b == pytest.approx(g_ab * (th_b - th_a) + g_end * th_b, rel=1e-6)


def test_a_link_with_h_adds_the_span_loss_to_the_ambient_and_notes_it(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(plain_text() + 'shaft_link = { spacing = "500 mm", h = "10 W/(m**2*K)" }\n',
                    encoding="utf-8")
    assert cli.main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert "fin: h = 10 W/(m^2 K) on the span" in out
    net = build_network(Simulation(scene('{ spacing = "500 mm", h = "10 W/(m**2*K)" }'),
                                   progress=False))
    g_ab, g_end = fin_span_conductances(47.0, 0.22, 0.5, 10.0)
    assert link_edge(net).conductance(300.0, 300.0) == pytest.approx(g_ab, rel=1e-14)
    span = [m for a, b, _, m in net.edges() if "ambient" in (a, b)
            and {a, b} & {"de.shaft", "nde.shaft"}]
    # each shaft node: its template edge to the ambient plus the span's G_end
    assert sum(m.conductance(300.0, 300.0) == pytest.approx(g_end, rel=1e-14)
               for m in span) == 2


@pytest.mark.parametrize("h", ['"-1 W/(m**2*K)"', '"10 W/m"'])
def test_bad_h_is_refused_naming_the_field(h):
    with pytest.raises(InputError, match=r"network\.shaft_link\.h"):
        scene(f'{{ spacing = "500 mm", h = {h} }}')


def test_link_notes_reach_the_run_report():
    """The notes build_network adds (each link's G) are in the run's Results.warnings, the
    list the report prints with the scene's other notes."""
    res = Simulation(scene('{ spacing = "500 mm" }', duration="1 min"), progress=False).run()
    assert any(w.startswith("shaft link de.shaft -- nde.shaft") for w in res.warnings)
    res = Simulation(scene(duration="1 min"), progress=False).run()
    assert any("thermally independent" in w for w in res.warnings)
