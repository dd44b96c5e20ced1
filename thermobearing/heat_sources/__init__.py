"""Modular heat sources: the plug-in contract and the registry.

A heat source is a callable registered in :data:`HEAT_SOURCES`::

    @HEAT_SOURCES.register("my_source", references=[...], summary="...")
    def my_source(ctx: HeatContext) -> HeatResult: ...

It receives a :class:`HeatContext` (bearing, lubricant, oil supply, operating point, node
temperatures by ROLE, kinematic state, traction law, per-source options) and returns a
:class:`HeatResult`: watts per role it heats, watts per component (for the breakdown), the
FVA class of each component, the drag forces/moments the skidding solver needs, and the
force pairs whose power equals its heat (``heat == sum(-F . v)``: every watt is a force
times a relative sliding speed).

Roles (where heat goes; the network template maps roles to nodes): ``inner_ring``,
``outer_ring``, ``elements``, ``cage``, ``oil``.

Third-party sources register through the entry-point group ``thermobearing.heat_sources``
(``name = "package.module:callable"``); the callable should carry ``references`` (citation
keys) and may carry ``summary``. They are loaded by :func:`load_entry_points`, which this
package calls once at import.

Sources in this package: ``raceway_traction``, ``ehl_rolling_resistance`` (raceway.py);
``churning_cage``, ``churning_elements``, ``churning_inner_ring`` (churning.py);
``cage_guide`` (cage_guide.py); ``pocket_friction`` (pocket.py); H's rib source (rib.py).
"""

from __future__ import annotations

import importlib
import importlib.metadata
import math
import pkgutil
import warnings
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import InputError, UnknownNameError
from ..registry import Registry
from ..state import KinematicState, OilSupply, OperatingPoint

ROLES = ("inner_ring", "outer_ring", "elements", "cage", "oil")
LOSS_CLASSES = ("load_dependent", "load_independent")
ENTRY_POINT_GROUP = "thermobearing.heat_sources"


@dataclass(frozen=True)
class ForcePair:
    """A force (or moment) and the relative velocity (or angular velocity) it acts across.

    ``force`` acts on body A; ``velocity`` is the velocity of A relative to B at the point
    of action (same shape, last axis = components if any). Dissipated power =
    ``-sum(force * velocity)`` >= 0.
    """

    name: str
    force: Any
    velocity: Any

    @property
    def power(self) -> float:
        """Dissipated power -sum(F . v) [W]."""
        return float(-np.sum(np.asarray(self.force, float) * np.asarray(self.velocity, float)))


class RoleTemperatures(dict):
    """Role -> temperature [K] that records which roles a heat source read.

    A source that never reads a role's temperature cannot depend on it (everything else it
    sees is fixed by the kinematic state and the options), so the coupled transient
    re-evaluates a source only when a role it read has changed, and differentiates the heat
    only in the nodes of roles that were read. Any bulk access (iteration, ``items``,
    ``values``, ``copy``...) counts as reading every role.
    """

    __slots__ = ("reads",)

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.reads: set[str] = set()

    def __getitem__(self, role: str) -> float:
        self.reads.add(role)
        return super().__getitem__(role)

    def get(self, role: str, default: Any = None) -> Any:
        self.reads.add(role)
        return super().get(role, default)

    def _all(self) -> None:
        self.reads.update(super().keys())

    def __iter__(self):  # type: ignore[override]
        self._all()
        return super().__iter__()

    def keys(self):  # type: ignore[override]
        self._all()
        return super().keys()

    def values(self):  # type: ignore[override]
        self._all()
        return super().values()

    def items(self):  # type: ignore[override]
        self._all()
        return super().items()

    def copy(self) -> dict[str, float]:  # type: ignore[override]
        self._all()
        return dict(super().items())

    def __reduce__(self):  # pickles as a plain dict of its values
        return (RoleTemperatures, (dict(super().items()),))


@dataclass(frozen=True)
class HeatContext:
    """Everything a heat source may read.

    Attributes
    ----------
    bearing : ``geometry.BallBearing`` or ``geometry.RollerBearing``.
    lubricant : ``lubricant.Lubricant``.
    supply : :class:`~thermobearing.state.OilSupply`.
    operating : :class:`~thermobearing.state.OperatingPoint`.
    temperatures : node ROLE -> temperature [K] (all five roles are needed by the built-in
        sources; :meth:`isothermal` fills them with one value).
    kinematics : :class:`~thermobearing.state.KinematicState` (race control or skidding).
    traction : traction law for the raceway contacts (``traction.make_traction_law``) or None.
    options : per-source options, ``{source_name: {option: value}}`` (SI).
    """

    bearing: Any
    lubricant: Any
    supply: OilSupply
    operating: OperatingPoint
    temperatures: Mapping[str, float]
    kinematics: KinematicState
    traction: Any = None
    options: Mapping[str, Mapping[str, Any]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        temps = RoleTemperatures()
        for role, value in dict(self.temperatures).items():
            if role not in ROLES:
                raise UnknownNameError("heat context temperatures role", role, ROLES)
            if not (math.isfinite(float(value)) and float(value) > 0):
                raise InputError(f"temperatures[{role}]", value, "a temperature > 0 K")
            dict.__setitem__(temps, role, float(value))
        object.__setattr__(self, "temperatures", temps)
        if not isinstance(self.supply, OilSupply):
            raise InputError("heat context supply", self.supply, "an OilSupply")
        if not isinstance(self.kinematics, KinematicState):
            raise InputError("heat context kinematics", self.kinematics, "a KinematicState")
        for name in self.options:
            if not isinstance(self.options[name], Mapping):
                raise InputError(f"options[{name}]", self.options[name], "a mapping")

    @classmethod
    def isothermal(cls, temperature: float, **kwargs: Any) -> HeatContext:
        """A context with every role at ``temperature`` [K]."""
        return cls(temperatures=dict.fromkeys(ROLES, float(temperature)), **kwargs)

    def temperature(self, role: str) -> float:
        """Temperature of ``role`` [K]; InputError if the context lacks it."""
        if role not in ROLES:
            raise UnknownNameError("temperature role", role, ROLES)
        try:
            return self.temperatures[role]
        except KeyError:
            raise InputError(f"temperatures[{role}]", None,
                             "a node temperature for this role (heat sources read it)") from None

    def option(self, source: str, name: str, default: Any) -> Any:
        """Option ``name`` of ``source`` (``default`` if not given). A given value is
        checked against the interval the source's registry entry documents for it
        (``limits``), whoever set it (scene or kinematics model)."""
        opts = self.options.get(source)
        if not opts or name not in opts:
            return default
        value = opts[name]
        if source in HEAT_SOURCES:
            HEAT_SOURCES.entry(source).check_parameter(name, value,
                                                       f"options[{source}].{name}")
        return value


@dataclass(frozen=True)
class HeatResult:
    """What a heat source returns.

    Attributes
    ----------
    source : registered name of the source.
    power_by_role : role -> heat rate [W] (>= 0).
    components : component -> heat rate [W] (e.g. "inner contact", "outer contact",
        "cage", "balls", "inner ring", "rib"); sums to the total.
    loss_class : component -> "load_dependent" | "load_independent" (FVA convention).
    forces : drag forces / moments for the skidding solver (name -> array or float, SI).
    force_pairs : forces with the relative velocities they act across; the sum of their
        dissipated powers equals the total heat (checked by tests).
    details : any further diagnostics (regime, Reynolds number, oil fraction...).
    component_roles : optional component -> {role: W}, where a source with several
        components heats different roles per component (e.g. inner vs outer contact); if
        absent, each component is split over the roles in the proportion of
        ``power_by_role``.
    """

    source: str
    power_by_role: Mapping[str, float]
    components: Mapping[str, float]
    loss_class: Mapping[str, str] = field(default_factory=dict)
    forces: Mapping[str, Any] = field(default_factory=dict)
    force_pairs: tuple[ForcePair, ...] = ()
    details: Mapping[str, Any] = field(default_factory=dict)
    component_roles: Mapping[str, Mapping[str, float]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        by_role = {}
        for role, power in self.power_by_role.items():
            if role not in ROLES:
                raise UnknownNameError(f"heat source {self.source!r} role", role, ROLES)
            p = float(power)
            if not math.isfinite(p) or p < -1e-9 * max(1.0, abs(p)):
                raise InputError(f"heat source {self.source!r} power_by_role[{role}]", power,
                                 "a finite heat rate >= 0 W")
            by_role[role] = max(p, 0.0)
        object.__setattr__(self, "power_by_role", by_role)
        comps = {k: float(v) for k, v in self.components.items()}
        for name, p in comps.items():
            if not math.isfinite(p):
                raise InputError(f"heat source {self.source!r} components[{name}]", p,
                                 "a finite heat rate [W]")
        object.__setattr__(self, "components", comps)
        for comp, cls_ in self.loss_class.items():
            if cls_ not in LOSS_CLASSES:
                raise UnknownNameError(f"heat source {self.source!r} loss_class[{comp}]", cls_,
                                       LOSS_CLASSES)
        total_roles = sum(by_role.values())
        total_comp = sum(comps.values())
        if abs(total_roles - total_comp) > 1e-9 * max(1.0, abs(total_comp)):
            raise InputError(f"heat source {self.source!r}", (total_roles, total_comp),
                             "power by role and by component must have the same total")
        object.__setattr__(self, "force_pairs", tuple(self.force_pairs))
        for comp, split in self.component_roles.items():
            if comp not in comps:
                raise UnknownNameError(f"heat source {self.source!r} component_roles", comp,
                                       comps)
            for role in split:
                if role not in ROLES:
                    raise UnknownNameError(f"heat source {self.source!r} role", role, ROLES)
            if abs(sum(split.values()) - comps[comp]) > 1e-9 * max(1.0, abs(comps[comp])):
                raise InputError(f"heat source {self.source!r} component_roles[{comp}]", split,
                                 "role powers adding up to the component's power")

    def split(self) -> list[tuple[str, str, float]]:
        """(component, role, W) rows: ``component_roles`` where given, else proportional."""
        total = self.total
        rows = []
        for comp, power in self.components.items():
            if comp in self.component_roles:
                rows.extend((comp, role, float(w)) for role, w in
                            self.component_roles[comp].items())
            elif total > 0:
                rows.extend((comp, role, power * w / total) for role, w in
                            self.power_by_role.items())
            else:
                rows.append((comp, next(iter(self.power_by_role), "oil"), power))
        return rows

    @property
    def total(self) -> float:
        """Total heat rate of the source [W]."""
        return float(sum(self.power_by_role.values()))


HeatSource = Callable[[HeatContext], HeatResult]

HEAT_SOURCES: Registry[HeatSource] = Registry(
    "heat_source", "modular heat sources: watts per node role from an operating state")


def evaluate(names: Iterable[str], ctx: HeatContext,
             node_roles: Iterable[str] | None = None) -> list[HeatResult]:
    """Run the named sources on ``ctx``.

    ``node_roles``: the roles the thermal network maps to nodes; a source that heats a
    role the network lacks raises :class:`~thermobearing.errors.InputError` naming the
    source and the role.
    """
    return [r for r, _ in evaluate_recorded(names, ctx, node_roles)]


def evaluate_recorded(names: Iterable[str], ctx: HeatContext,
                      node_roles: Iterable[str] | None = None
                      ) -> list[tuple[HeatResult, frozenset[str]]]:
    """As :func:`evaluate`, with the set of temperature roles each source read."""
    roles = None if node_roles is None else set(node_roles)
    if roles is not None:
        unknown = roles - set(ROLES)
        if unknown:
            raise UnknownNameError("network node role", sorted(unknown)[0], ROLES)
    if ctx.kinematics.origin == "standstill":
        # both rings at rest (kinematic_models.standstill): no relative motion anywhere,
        # so no source dissipates; each books 0 W (a row per source keeps the loss tables
        # complete) and reads no temperature
        return [(HeatResult(name, {"oil": 0.0}, {"at rest": 0.0}), frozenset())
                for name in names]
    results = []
    temps = ctx.temperatures
    for name in names:
        temps.reads.clear()
        result = HEAT_SOURCES.get(name)(ctx)
        if roles is not None:
            for role, power in result.power_by_role.items():
                if role not in roles and power != 0.0:
                    raise InputError(f"heat source {name!r} role", role,
                                     "a role the thermal network has: " + ", ".join(sorted(roles)))
        results.append((result, frozenset(temps.reads)))
    temps.reads.clear()
    return results


def power_by_role(results: Iterable[HeatResult]) -> dict[str, float]:
    """Sum of the sources' heat per role [W] (all five roles, zeros included)."""
    out = dict.fromkeys(ROLES, 0.0)
    for r in results:
        for role, p in r.power_by_role.items():
            out[role] += p
    return out


def load_entry_points(group: str = ENTRY_POINT_GROUP) -> list[str]:
    """Register third-party heat sources declared under the entry-point ``group``.

    Each entry point names a callable ``source(ctx) -> HeatResult``; it is registered under
    the entry point's name with its ``references`` attribute (required) and ``summary``.
    A module that registers itself on import may also be named; it is then only imported.
    Returns the names added. A broken plug-in warns and is skipped (it must not break the
    built-in sources).
    """
    added = []
    for ep in importlib.metadata.entry_points(group=group):
        if ep.name in HEAT_SOURCES:
            continue
        try:
            obj = ep.load()
        except Exception as exc:  # noqa: BLE001 - any plug-in failure is reported, not fatal
            warnings.warn(f"heat-source plug-in {ep.name!r} failed to load: {exc}", stacklevel=2)
            continue
        if ep.name in HEAT_SOURCES or not callable(obj):
            continue
        refs = getattr(obj, "references", None)
        if not refs:
            warnings.warn(f"heat-source plug-in {ep.name!r} has no 'references'; skipped",
                          stacklevel=2)
            continue
        HEAT_SOURCES.register(ep.name, references=list(refs),
                              summary=getattr(obj, "summary", ""))(obj)
        added.append(ep.name)
    return added


def _import_submodules() -> None:
    for info in pkgutil.iter_modules(__path__):
        importlib.import_module(f"{__name__}.{info.name}")


_import_submodules()
load_entry_points()
