"""Power-loss breakdown: a tidy pandas table per operating point.

One row per (operating point, source, component, role) with the power [W], the node the
role maps to (if a role -> node map is given) and the FVA loss class:

- ``load_dependent``: friction caused by the load in the rolling contacts (raceway sliding
  and spinning, rib/roller-end friction, the share of the EHL rolling resistance that the
  load adds) -- Palmgren's M1 part;
- ``load_independent``: hydrodynamic and fluid losses (churning and drag, cage-land shear,
  pocket friction, the EHL rolling resistance of the contacts the centrifugal force alone
  seats on the outer race) -- Palmgren's M0 part, the loss without external load.

(FVA/Schaeffler convention of splitting the frictional moment into M0 and M1; Harris &
Kotzalas 2007 ch. on friction. The SKF model's M_rr is load-dependent through G_rr
(F_r^0.31 for a cylindrical roller bearing). Per contact the EHL force of paper 000 eq. 35
carries no load, but the set of loaded contacts does: ``ehl_rolling_resistance`` books
each outer race's no-load share load-independent and the rest load-dependent (its
components "<race> rolling resistance, no load" / ", load"; heat_sources/raceway.py).
Measured on the CRB 50x75x16 at 10000 r/min, race control: the source grows 47 % from
0.5 to 3 kN, its no-load share 127.0 W at both.)

The class is otherwise each source's nominal one (``HeatResult.loss_class``), not a
property of a run: a source classed load-independent can still move with the load through
the kinematic state it reads. Measured: the pocket friction (boundary mu = 0.1 times the
pocket normal force the solver gives) of the catalogue 6206 in an oil bath rises 274 %
from 1 to 3 kN radial at 6000 r/min. The report's glossary gives each source's change
with the load in the run and names such sources (``report_losses.class_notes``).

Functions
---------
:func:`loss_breakdown`  results of the heat sources -> tidy DataFrame
:func:`compute_losses`  run named sources on a context -> tidy DataFrame
:func:`loss_totals`     per point: load-dependent, load-independent, total [W]
:func:`by_source`       per point and source: power and share of the total
:func:`role_map`        role -> node names of a thermal network
:func:`paper002_bookkeeping`  the same state booked as paper 002 books it (diagnostic)
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import pandas as pd

from .errors import InputError, check_range
from .heat_sources import HeatContext, HeatResult, evaluate

COLUMNS = ("point", "source", "component", "role", "node", "loss class", "power [W]")


def role_map(network: Any, group: str | None = None) -> dict[str, str]:
    """Role -> node name(s) of a :class:`thermobearing.network.ThermalNetwork` (joined by
    ", " where a role is carried by several nodes, which then share its heat equally)."""
    return {role: ", ".join(nodes) for role, nodes in network.roles(group).items()}


def loss_breakdown(results: Iterable[HeatResult], *, point: Any = 0,
                   role_to_node: Mapping[str, str] | None = None) -> pd.DataFrame:
    """Tidy breakdown of heat-source results at one operating point.

    Parameters
    ----------
    results : HeatResult objects (one per source).
    point : label of the operating point (e.g. axial load, step index).
    role_to_node : the thermal network's role -> node map (e.g. four-node template of paper
        002: outer_ring -> housing, inner_ring -> shaft, elements -> balls, cage/oil -> oil);
        without it the node column repeats the role (:func:`role_map` builds the map from a
        ``ThermalNetwork``). A role missing from the map raises
        :class:`~thermobearing.errors.InputError` (a heat source naming a node the network
        lacks).

    Returns
    -------
    DataFrame with columns ``point, source, component, role, node, loss class, power [W]``.
    """
    rows = []
    for r in results:
        for comp, role, power in r.split():
            if role_to_node is not None and role not in role_to_node:
                raise InputError(f"heat source {r.source!r} role", role,
                                 "a role the network maps to a node: "
                                 + ", ".join(sorted(role_to_node)))
            node = role_to_node[role] if role_to_node is not None else role
            rows.append((point, r.source, comp, role, node,
                         r.loss_class.get(comp, "load_independent"), power))
    return pd.DataFrame(rows, columns=list(COLUMNS))


def compute_losses(ctx: HeatContext, sources: Iterable[str], *, point: Any = 0,
                   role_to_node: Mapping[str, str] | None = None) -> pd.DataFrame:
    """Run ``sources`` on ``ctx`` and return their :func:`loss_breakdown`."""
    roles = None if role_to_node is None else list(role_to_node)
    return loss_breakdown(evaluate(sources, ctx, node_roles=roles), point=point,
                          role_to_node=role_to_node)


def loss_totals(breakdown: pd.DataFrame) -> pd.DataFrame:
    """Per point: load-dependent, load-independent and total power [W] (FVA split).

    Returns a DataFrame indexed by point with columns ``load_dependent [W]``,
    ``load_independent [W]``, ``total [W]``.
    """
    missing = set(COLUMNS) - set(breakdown.columns)
    if missing:
        raise InputError("breakdown columns", sorted(missing), "a table from loss_breakdown")
    pivot = breakdown.pivot_table(index="point", columns="loss class", values="power [W]",
                                  aggfunc="sum", fill_value=0.0)
    out = pd.DataFrame(index=pivot.index)
    for cls in ("load_dependent", "load_independent"):
        out[f"{cls} [W]"] = pivot[cls] if cls in pivot else 0.0
    out["total [W]"] = out["load_dependent [W]"] + out["load_independent [W]"]
    return out


def by_source(breakdown: pd.DataFrame) -> pd.DataFrame:
    """Power per point and source [W] with each source's share of the point's total [-]."""
    g = breakdown.groupby(["point", "source"], as_index=False)["power [W]"].sum()
    totals = g.groupby("point")["power [W]"].transform("sum")
    g["share [-]"] = g["power [W]"] / totals.where(totals > 0, 1.0)
    return g


#: scalar gravity for the cage weight of :func:`paper002_bookkeeping` [m/s^2]
STANDARD_GRAVITY = 9.80665


def paper002_bookkeeping(ctx: HeatContext, *, guide_friction: float,
                         guide_load: float | None = None,
                         sources: Iterable[str] = ("raceway_traction", "churning_elements",
                                                   "churning_cage", "churning_inner_ring",
                                                   "cage_guide", "pocket_friction"),
                         ) -> dict[str, float]:
    """Heat per source [W] of one state booked the way seed paper 002 books it (diagnostic).

    Paper 002 (002_0add79adaca5495c.txt) books two losses with formulas that are not the
    power of the forces its dynamics uses:

    - ball churning by eq. 16 (in SI, ``churning_elements`` form ``"paper002"``), which is
      mu_v / 4 times the power of the eq. 10 drag that enters the ball balance (eq. 9);
    - the cage guide by eq. 18, Q_cg = mu_c |F_cg| D_m (omega_g - omega_c) / 2
      (``cage_guide`` form ``"paper002_eq18"``), a hydrodynamic friction coefficient times the
      film force, while its cage balance (eq. 8) uses the viscous drag torque of eq. 5.

    Every other source is evaluated as in ``ctx``. The result is NOT energy-consistent (the
    difference to the shaft power is dissipated but not booked); it exists to show how the
    paper's loss shares follow from its bookkeeping (validation case paper002_loss_ratios).

    Parameters
    ----------
    ctx : the heat context of the state (kinematics from the skidding solver).
    guide_friction : mu_c of eq. 18 [-] (not given by the paper), in [0, 1].
    guide_load : load the land film carries [N]; default the cage weight m_c g (cage mass
        from ``CageGeometry.effective_mass``).
    sources : the sources to evaluate (paper 002 eq. 20's six by default).
    """
    from dataclasses import replace

    from .heat_sources import evaluate

    check_range("guide_friction", guide_friction, 0.0, 1.0)
    b = ctx.bearing
    if guide_load is None:
        length = getattr(b, "roller_length", None)
        guide_load = STANDARD_GRAVITY * b.cage.effective_mass(b.element_diameter, b.n_elements,
                                                              length)
    opts = {k: dict(v) for k, v in ctx.options.items()}
    opts["churning_elements"] = {**opts.get("churning_elements", {}), "form": "paper002"}
    opts["cage_guide"] = {**opts.get("cage_guide", {}), "form": "paper002_eq18",
                          "friction_coefficient": float(guide_friction),
                          "load": float(guide_load)}
    return {r.source: r.total for r in evaluate(sources, replace(ctx, options=opts))}
