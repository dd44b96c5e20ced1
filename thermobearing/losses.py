"""Power-loss breakdown: a tidy pandas table per operating point.

One row per (operating point, source, component, role) with the power [W], the node the
role maps to (if a role -> node map is given) and the FVA loss class:

- ``load_dependent``: friction caused by the load in the rolling contacts (raceway sliding
  and spinning, rib/roller-end friction) -- Palmgren's M1 part;
- ``load_independent``: hydrodynamic and fluid losses (EHL rolling resistance, churning and
  drag, cage-land shear, pocket friction) -- Palmgren's M0 part.

(FVA/Schaeffler convention of splitting the frictional moment into M0 and M1; Harris &
Kotzalas 2007 ch. on friction; the SKF model's M_rr is load-dependent through G_rr, but its
EHL (Poiseuille) part does not depend on load in paper 000 eq. 35, so we class it with M0.)

Functions
---------
:func:`loss_breakdown`  results of the heat sources -> tidy DataFrame
:func:`compute_losses`  run named sources on a context -> tidy DataFrame
:func:`loss_totals`     per point: load-dependent, load-independent, total [W]
:func:`by_source`       per point and source: power and share of the total
:func:`role_map`        role -> node names of a thermal network
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import pandas as pd

from .errors import InputError
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
