"""Bearings on one shaft: axial conduction between their shaft nodes (``[network] shaft_link``).

Each bearing of a scene gets its own template instance (:mod:`.templates`); without a link
the instances share only the ambient and the oil inlet, so the bearings are thermally
independent. A shaft link joins the ``shaft`` nodes of consecutive bearings on one shaft by
1-D axial conduction through a solid shaft (:func:`axial_shaft_conductance`).

Scene schema (``[network]``, SI after loading; bare numbers are SI)::

    shaft_link = { spacing = "500 mm" }      # every bearing of the scene, in the order
                                             # given, on one shaft, 500 mm between centres
    shaft_link = { bearings = ["a", "b", "c"], spacing = ["300 mm", "450 mm"],
                   diameter = "80 mm", material = "STEEL_52100", h = "10 W/(m**2*K)" }
    # several shafts: an array of such tables ([[network.shaft_link]]), one per shaft

- ``bearings``: the bearings on the shaft in their order along it (two or more scene bearing
  names; default every bearing of the scene in the order of ``[[bearings]]``); a bearing
  sits on one shaft only;
- ``spacing``: the axial distance between the centres of consecutive bearings, one length
  for every gap or a list with one length per gap (> 0);
- ``diameter``: the shaft diameter d_s (default the template's ``shaft_diameter``, else the
  smaller bore of the two bearings of a gap);
- ``material``: a material preset (default the template's ``housing_material``, which the
  templates also use for the shaft's capacity);
- ``h``: convection coefficient [W/(m^2 K)] on the shaft's surface between the bearings
  (default none: the span is adiabatic). With h the span is a fin between the two shaft
  nodes (:func:`fin_span_conductances`): a coupling edge k A m / sinh(m L) between them and
  an edge k A m tanh(m L / 2) from each to the ambient.

Lumped bodies: each bearing's ``shaft`` node stands for the shaft near its bearing -- the
inner ring and a solid shaft piece of the template's ``shaft_length`` L_s (default the
housing length) centred on the bearing. The link is the conduction between two such node
centres, one spacing apart. Where the pieces of neighbouring bearings overlap (L_s larger
than the spacing), the overlapping shaft would be counted in both nodes' capacities; it is
shared equally instead (:func:`kept_lengths`), each node's capacity lowered by what it gives
up, and the build says so. Pieces that do not overlap leave the capacities as the template
made them (the shaft between them, beyond the pieces, has no capacity in the network).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ..errors import InputError, UnknownNameError
from .conductances import Fixed, PlaneWall
from .graph import ThermalNetwork
from .templates import SHAFT_NODE, ShaftSegment

#: keys of one ``shaft_link`` table
LINK_KEYS = ("bearings", "spacing", "diameter", "material", "h")


@dataclass(frozen=True)
class ShaftSpec:
    """One shaft as the scene gives it, in SI (bearing names not yet checked).

    ``bearings`` None: every bearing of the scene in its order. ``spacings`` [m]: one value
    for every gap or one per gap. ``diameter`` [m] or None, ``material`` a preset name or
    None (the template's). ``field`` names the table in errors.
    """

    field: str
    bearings: tuple[str, ...] | None
    spacings: tuple[float, ...]
    diameter: float | None
    material: str | None
    h: float | None = None


@dataclass(frozen=True)
class ShaftLink:
    """One gap of a shaft: the axial conduction edge between two bearings' shaft nodes.

    ``spacing`` L [m], ``diameter`` d_s [m], ``conductivity`` k [W/(m K)] of ``material``,
    ``conductance`` [W/K] between the two nodes: G = k pi d_s^2 / 4 / L for an adiabatic
    span, k A m / sinh(m L) with convection ``h`` [W/(m^2 K)] on it, which then also loses
    ``end_conductance`` = k A m tanh(m L / 2) [W/K] from each node to the ambient.
    """

    bearing_a: str
    bearing_b: str
    node_a: str
    node_b: str
    spacing: float
    diameter: float
    material: str
    conductivity: float
    conductance: float
    h: float | None = None
    end_conductance: float = 0.0

    def describe(self) -> str:
        """One line for ``thermobearing check``: nodes, geometry and G."""
        text = (f"shaft link {self.node_a} -- {self.node_b}: axial conduction along "
                f"{self.spacing * 1e3:.4g} mm of a {self.diameter * 1e3:.4g} mm solid "
                f"{self.material} shaft (k = {self.conductivity:.3g} W/(m K)), "
                f"G = {self.conductance:.4g} W/K")
        if self.h is None:
            return text + " (span adiabatic)"
        return (text + f" (fin: h = {self.h:.4g} W/(m^2 K) on the span, which takes "
                f"{self.end_conductance:.4g} W/K from each end to the ambient)")


def axial_shaft_conductance(conductivity: float, diameter: float, spacing: float) -> float:
    """Axial conduction between two sections of a solid shaft, G = k A / L [W/K].

    A = pi d_s^2 / 4 [m^2], L the distance between the sections [m], k [W/(m K)]: 1-D
    steady conduction, constant k (Incropera et al. 2007, eq. 3.6 with the rod's cross
    section). The shaft's surface between the sections is taken as adiabatic: with
    convection h over the surface the coupling of the two end temperatures is
    k A m / sinh(m L), m = sqrt(4 h / (k d_s)) (fin with prescribed end temperatures,
    Incropera et al. 2007, sec. 3.6, Table 3.4 case C), i.e. (m L / sinh(m L)) G: 0.85 G at
    m L = 0.98 (k = 47 W/(m K), d_s = 220 mm, L = 0.5 m, h = 10 W/(m^2 K)) and 0.49 G at
    m L = 2.2 (h = 50 W/(m^2 K), a faster-turning shaft). A link given ``h`` uses that fin
    solution, with the span's loss to the ambient (:func:`fin_span_conductances`).
    """
    for name, v in (("conductivity", conductivity), ("diameter", diameter),
                    ("spacing", spacing)):
        if not math.isfinite(float(v)) or float(v) <= 0.0:
            raise InputError(f"shaft link {name}", v, "a finite value > 0 (SI)")
    return conductivity * math.pi * diameter**2 / 4.0 / spacing


def fin_span_conductances(conductivity: float, diameter: float, spacing: float, h: float
                          ) -> tuple[float, float]:
    """Two-port of a shaft span with convection to the ambient: (G_ab, G_end) [W/K].

    A solid rod of diameter d_s [m] and length L [m] between two sections held at T_a and
    T_b, convection h [W/(m^2 K)] on its surface to T_inf: the steady fin equation
    theta'' = m^2 theta, m = sqrt(h P / (k A)) = sqrt(4 h / (k d_s)), with both end
    temperatures prescribed (Incropera et al. 2007, sec. 3.6.2, Table 3.4 case C). The heat
    leaving end a into the rod is q_a = k A m [cosh(mL) theta_a - theta_b] / sinh(mL),
    which is exactly the heat of two conductances: G_ab = k A m / sinh(m L) between the
    ends and G_end = k A m (cosh(m L) - 1) / sinh(m L) = k A m tanh(m L / 2) from each end
    to the ambient. h -> 0 gives G_ab -> k A / L and G_end -> 0 (the adiabatic link);
    h = 0 returns exactly (k A / L, 0).
    """
    g0 = axial_shaft_conductance(conductivity, diameter, spacing)
    if not math.isfinite(float(h)) or float(h) < 0.0:
        raise InputError("shaft link h", h, "a finite value >= 0 W/(m^2 K)")
    if h == 0.0:
        return g0, 0.0
    area = math.pi * diameter**2 / 4.0
    m = math.sqrt(4.0 * h / (conductivity * diameter))
    ml = m * spacing
    kam = conductivity * area * m
    # 1 / sinh(mL) = 2 exp(-mL) / (1 - exp(-2 mL)): math.sinh overflowed (OverflowError)
    # beyond mL ~ 710, where the ends are decoupled (G_ab underflows to 0 here)
    return kam * 2.0 * math.exp(-ml) / -math.expm1(-2.0 * ml), kam * math.tanh(0.5 * ml)


def kept_lengths(positions: Sequence[float], lengths: Sequence[float]) -> list[float]:
    """Length [m] of shaft each node keeps when the pieces overlap.

    Node i holds the piece [x_i - L_i/2, x_i + L_i/2] (``positions`` x [m] along the shaft,
    ``lengths`` L [m]); a stretch covered by k pieces is shared equally, L/k to each, so
    that the shaft is counted once. Without overlap every node keeps its L_i.
    """
    ends = sorted({x + s * 0.5 * L for x, L in zip(positions, lengths, strict=True)
                   for s in (-1.0, 1.0)})
    kept = [0.0] * len(positions)
    for lo, hi in zip(ends, ends[1:], strict=False):
        mid = 0.5 * (lo + hi)
        cover = [i for i, (x, L) in enumerate(zip(positions, lengths, strict=True))
                 if abs(mid - x) < 0.5 * L]
        for i in cover:
            kept[i] += (hi - lo) / len(cover)
    return kept


def _length(raw: Any, field: str) -> float:
    from ..scene_values import _quantity

    value = _quantity(raw, "m", field)
    if value <= 0.0:
        raise InputError(field, raw, "a length > 0 (e.g. \"300 mm\")")
    return value


def parse_shaft_links(raw: Any) -> list[ShaftSpec]:
    """The ``[network] shaft_link`` value (a table or an array of tables) as ShaftSpecs.

    Checks the keys, the units (lengths > 0), the material preset and that a ``bearings``
    list names two or more different bearings with one spacing (or one per gap); the
    names themselves are checked against the scene by :func:`resolve_shafts`.
    """
    from ..materials import get_material

    tables = [raw] if isinstance(raw, Mapping) else raw
    if not isinstance(tables, list) or not tables or not all(
            isinstance(t, Mapping) for t in tables):
        raise InputError("network.shaft_link", raw,
                         "a table such as { spacing = \"300 mm\" } or an array of them "
                         "(one per shaft)")
    specs = []
    for i, t in enumerate(tables):
        field = "network.shaft_link" if isinstance(raw, Mapping) else \
            f"network.shaft_link[{i}]"
        for key in t:
            if key not in LINK_KEYS:
                raise InputError(f"{field}.{key}", t[key], "a known key: " + ", ".join(LINK_KEYS))
        names = t.get("bearings")
        if names is not None:
            if (not isinstance(names, list) or not all(isinstance(n, str) for n in names)):
                raise InputError(f"{field}.bearings", names,
                                 "a list of bearing names in their order along the shaft")
            if len(names) < 2:
                raise InputError(f"{field}.bearings", names,
                                 "two or more bearings (a link joins bearings on one shaft)")
            if len(set(names)) != len(names):
                raise InputError(f"{field}.bearings", names, "different bearings")
        if "spacing" not in t:
            raise InputError(f"{field}.spacing", None,
                             "a value (this key is required): the distance between the "
                             "centres of consecutive bearings, e.g. \"300 mm\"")
        sp = t["spacing"]
        spacings = tuple(_length(v, f"{field}.spacing[{j}]") for j, v in enumerate(sp)) \
            if isinstance(sp, list) else (_length(sp, f"{field}.spacing"),)
        if not spacings:
            raise InputError(f"{field}.spacing", sp, "one length or one length per gap")
        if isinstance(sp, list) and names is not None and len(spacings) not in (
                1, len(names) - 1):
            raise InputError(f"{field}.spacing", sp,
                             f"one length or {len(names) - 1} (one per gap between "
                             f"{len(names)} bearings)")
        diameter = _length(t["diameter"], f"{field}.diameter") if "diameter" in t else None
        h = None
        if "h" in t:
            from ..scene_values import _quantity

            h = _quantity(t["h"], "W/(m**2*K)", f"{field}.h")
            if not math.isfinite(h) or h < 0.0:
                raise InputError(f"{field}.h", t["h"],
                                 "a convection coefficient >= 0 (e.g. \"10 W/(m**2*K)\")")
        material = t.get("material")
        if material is not None:
            if not isinstance(material, str):
                raise InputError(f"{field}.material", material, "a material preset name")
            try:
                get_material(material)
            except UnknownNameError as exc:
                raise UnknownNameError(f"{field}.material", material, exc.known) from None
        specs.append(ShaftSpec(field, None if names is None else tuple(names), spacings,
                               diameter, material, h))
    return specs


def resolve_shafts(specs: Sequence[ShaftSpec], bearing_names: Sequence[str]
                   ) -> list[tuple[ShaftSpec, tuple[str, ...], tuple[float, ...]]]:
    """(spec, bearings in order, one spacing [m] per gap) of each shaft, checked against the
    scene's bearing names: known names, two or more bearings, each on one shaft only."""
    out = []
    seen: dict[str, str] = {}
    for spec in specs:
        names = spec.bearings if spec.bearings is not None else tuple(bearing_names)
        if len(names) < 2:
            raise InputError(f"{spec.field}.bearings", list(names),
                             "two or more bearings on the shaft (the scene has "
                             f"{len(bearing_names)}: {', '.join(bearing_names)})")
        for j, n in enumerate(names):
            if n not in bearing_names:
                raise UnknownNameError(f"{spec.field}.bearings[{j}]", n, list(bearing_names))
            if n in seen:
                raise InputError(f"{spec.field}.bearings[{j}]", n,
                                 f"a bearing on no other shaft (it is on {seen[n]})")
            seen[n] = spec.field
        gaps = len(names) - 1
        if len(spec.spacings) not in (1, gaps):
            raise InputError(f"{spec.field}.spacing", list(spec.spacings),
                             f"one length or {gaps} (one per gap between {len(names)} "
                             "bearings)")
        spacings = spec.spacings * gaps if len(spec.spacings) == 1 else spec.spacings
        out.append((spec, tuple(names), tuple(spacings)))
    return out


def link_shafts(net: ThermalNetwork, specs: Sequence[ShaftSpec], bearing_names: Sequence[str],
                segments: Mapping[str, ShaftSegment], template: str
                ) -> tuple[list[ShaftLink], list[str]]:
    """Add the shaft links to a network built with one template instance per bearing (node
    ``<bearing>.shaft``); returns the links and notes (one line per link, and one per shaft
    whose pieces overlap, with the capacity moved).

    ``segments``: each bearing's template shaft piece (:func:`.templates.shaft_segment`).
    The edges are :class:`~.conductances.PlaneWall` models (k, pi d_s^2 / 4, spacing), the
    conductance of :func:`axial_shaft_conductance`.
    """
    from ..materials import get_material

    links: list[ShaftLink] = []
    notes: list[str] = []
    for spec, names, spacings in resolve_shafts(specs, bearing_names):
        nodes = [f"{n}.{SHAFT_NODE}" for n in names]
        for n, node in zip(names, nodes, strict=True):
            if node not in net.state_nodes:
                raise InputError(spec.field, f"bearing {n!r}",
                                 f"a network template with a {SHAFT_NODE!r} node per bearing "
                                 f"(template {template!r} has none: {node!r} is not among "
                                 f"its nodes)")
        # capacities: share overlapping shaft pieces (see the module docstring)
        positions = [0.0]
        for s in spacings:
            positions.append(positions[-1] + s)
        lengths = [segments[n].length for n in names]
        kept = kept_lengths(positions, lengths)
        moved = []
        for n, node, L, k in zip(names, nodes, lengths, kept, strict=True):
            if L - k > 1e-12 * L:
                dC = segments[n].capacity_per_length * (L - k)
                net.set_capacity(node, max(net.capacity(node) - dC, 0.0))
                moved.append(f"{node} -{dC:.4g} J/K")
        if moved:
            notes.append(f"{spec.field}: the template's shaft pieces (shaft_length, each "
                         "centred on its bearing) overlap at the spacing given; the overlap "
                         "is shared so that the shaft is counted once: " + ", ".join(moved))
        for j, s in enumerate(spacings):
            a, b = names[j], names[j + 1]
            d = spec.diameter or min(segments[a].diameter, segments[b].diameter)
            mat = get_material(spec.material) if spec.material else segments[a].material
            k = float(mat.thermal_conductivity)
            name = f"{nodes[j]}--{nodes[j + 1]} (shaft link)"
            if spec.h is None:
                G, G_end = axial_shaft_conductance(k, d, s), 0.0
                net.add_edge(nodes[j], nodes[j + 1], PlaneWall(k, math.pi * d**2 / 4.0, s),
                             name=name)
            else:
                G, G_end = fin_span_conductances(k, d, s, spec.h)
                net.add_edge(nodes[j], nodes[j + 1], Fixed(G), name=name)
                for node in (nodes[j], nodes[j + 1]):
                    net.add_edge(node, "ambient", Fixed(G_end),
                                 name=f"{node}--ambient (shaft span {a}-{b})")
            links.append(ShaftLink(a, b, nodes[j], nodes[j + 1], s, d, mat.name, k, G,
                                   spec.h, G_end))
    notes = [link.describe() for link in links] + notes
    return links, notes


def independence_note(bearing_names: Sequence[str], links: Sequence[ShaftLink]) -> str | None:
    """A note for two or more bearings of which some are on no shaft link: their networks
    share only the ambient and the oil inlet, so they are thermally independent."""
    if len(bearing_names) < 2:
        return None
    linked = {n for link in links for n in (link.bearing_a, link.bearing_b)}
    alone = [n for n in bearing_names if n not in linked]
    if not alone:
        return None
    if not links:
        return (f"bearings {', '.join(bearing_names)} are thermally independent: their "
                "networks share only the ambient and the oil inlet (no [network] "
                "shaft_link; add shaft_link = { spacing = \"...\" } when they sit on one "
                "shaft)")
    return (f"bearing{'s' if len(alone) > 1 else ''} {', '.join(alone)} on no [network] "
            "shaft_link: thermally independent of the others (only the ambient and the oil "
            "inlet are shared)")
