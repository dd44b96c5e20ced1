"""Fitted scene fields of :mod:`thermobearing.calibrate`: what can be fitted and how.

One job: turn a dotted scene path (``network.parameters.h_oil``, ``supply.flow``,
``bearings.0.overrides.diametral_clearance``, ...) into a :class:`FitParameter` -- its SI
unit and display unit, start value, bounds, finite-difference step and the fitted
coordinate z (``ln(value / start)`` for positive quantities, ``T - T_start`` in K for
temperatures, ``(value - start) / |start|`` otherwise) -- and write fitted values back into
a scene (:func:`_apply`). The transforms are the ones described in the docstring of
:mod:`thermobearing.calibrate` (parameters kept positive by a log transform: Bates and Watts
1988, ch. 2). Split out of ``calibrate.py`` (names re-exported there). Units: SI inside.
"""

from __future__ import annotations

import inspect
import json
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .errors import InputError
from .scene import Scene
from .sweep_params import DISPLAY_UNITS, assign_path, check_path, get_path
from .units import from_si, to_si, unit_registry

__all__ = ["FitParameter"]


#: kinds of the scene's own numeric fields that can be fitted (path -> unit kind)
_SCENE_KINDS = {
    "supply.flow": "volume_flow",
    "supply.inlet_temperature": "temperature",
    "supply.level": "length",
    "environment.ambient_temperature": "temperature",
    "environment.initial_temperature": "temperature",
    "schedule.speed": "angular_speed",
    "schedule.radial_load": "force",
    "schedule.axial_load": "force",
}
#: template parameters that the scene sets elsewhere (coupled.build_network refuses them)
_SET_ELSEWHERE = {"ambient_temperature": "environment.ambient_temperature",
                  "oil_inlet_temperature": "supply.inlet_temperature",
                  "oil_flow": "supply.flow"}
_DIMENSIONLESS = ("", "-", "dimensionless")


# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class FitParameter:
    """One fitted scene field.

    Attributes
    ----------
    path : dotted scene path (``network.parameters.h_oil``).
    unit : SI unit of the value (pint spelling; ``""`` when dimensionless or unknown).
    display_unit : unit used in tables and in the calibrated scene (``"W/(m**2*K)"``).
    transform : ``"log"`` (z = ln(value / initial)) or ``"linear"``
        (z = (value - initial) / scale).
    initial : starting value [SI]; z = 0 there.
    lower, upper : bounds [SI] (``-inf``/``inf`` when free; ``0`` for log parameters).
    fd_step : finite-difference step in z.
    scale : unit of z for linear parameters (1 K for temperatures, else |initial| or 1).
    """

    path: str
    unit: str
    display_unit: str
    transform: str
    initial: float
    lower: float
    upper: float
    fd_step: float
    scale: float = 1.0

    def to_z(self, value: float) -> float:
        """Fitted coordinate: ln(value / initial) (log) or (value - initial) / scale."""
        if self.transform == "log":
            return math.log(value / self.initial)
        return (float(value) - self.initial) / self.scale

    def from_z(self, z: float) -> float:
        if self.transform == "log":
            try:
                return self.initial * math.exp(z)
            except OverflowError:
                return math.inf
        return self.initial + self.scale * float(z)

    def z_bounds(self) -> tuple[float, float]:
        if self.transform == "log":
            lo = self.to_z(self.lower) if self.lower > 0 else -np.inf
            hi = self.to_z(self.upper) if math.isfinite(self.upper) else np.inf
            return lo, hi
        lo = self.to_z(self.lower) if math.isfinite(self.lower) else -np.inf
        hi = self.to_z(self.upper) if math.isfinite(self.upper) else np.inf
        return lo, hi

    def show(self, value: float) -> float:
        """SI value in the display unit."""
        if self.display_unit in _DIMENSIONLESS or not self.unit:
            return float(value)
        return from_si(value, self.display_unit)

    def scene_value(self, value: float) -> Any:
        """What to write into the scene dict: a unit string when the field has a unit."""
        if self.display_unit in _DIMENSIONLESS or not self.unit:
            return float(value)
        return f"{self.show(value):.10g} {self.display_unit}"


def _template_entry(scene: Scene) -> tuple[str, Any]:
    from .network.templates import TEMPLATES

    name = scene.network.get("template", "four_node_paper002")
    return name, TEMPLATES.entry(name)


def _did_you_mean_parameter(name: str, known: Sequence[str]) -> str:
    """``"; did you mean network.parameters.h_oil?"`` for a misspelt template parameter
    (``h_oill``), else ``""``."""
    import difflib

    close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.75)
    return f"; did you mean network.parameters.{close[0]}?" if close else ""


def _parse_existing(raw: Any, field_name: str) -> tuple[float, str, str]:
    """(SI value, SI unit, unit as written) of a scene value: a unit string or a number."""
    if isinstance(raw, bool) or not isinstance(raw, int | float | str):
        raise InputError(field_name, raw, "a numeric quantity to fit")
    if isinstance(raw, int | float):
        return float(raw), "", ""
    parts = raw.strip().split(maxsplit=1)
    unit_text = parts[1] if len(parts) == 2 else ""
    ureg = unit_registry()
    try:
        q = ureg.Quantity(float(parts[0]), unit_text or "dimensionless")
        base = q.to_base_units()
    except Exception:  # noqa: BLE001 - pint raises many kinds; report the field
        raise InputError(field_name, raw, "a numeric quantity '<number> <unit>' to fit") from None
    unit = "" if base.dimensionless else f"{base.units:~}"
    return float(base.magnitude), unit, unit_text


def _make_parameter(scene: Scene, scene_dict: Mapping[str, Any], path: str,
                    x0: Mapping[str, Any], bounds: Mapping[str, Sequence[Any]],
                    fd_step: Mapping[str, float]) -> FitParameter:
    parts = path.split(".")
    if parts[0] == "network":
        tname, entry = _template_entry(scene)
        fittable = sorted(k for k in entry.parameters if k not in _SET_ELSEWHERE)
        if len(parts) != 3 or parts[1] != "parameters":
            raise InputError("fit", path, "network.parameters.<name>, a parameter of template "
                             f"{tname!r}: " + ", ".join(fittable)
                             + _did_you_mean_parameter(parts[-1], fittable))
        name = parts[2]
        if name in _SET_ELSEWHERE:
            raise InputError("fit", path, f"{_SET_ELSEWHERE[name]} (set there, not in the "
                             "network)")
        unit = entry.parameters.get(name)
        if unit is None:
            raise InputError("fit", path, f"a parameter of template {tname!r}: "
                             + ", ".join(fittable) + _did_you_mean_parameter(name, fittable))
        unit = "" if unit in _DIMENSIONLESS else unit
        raw = scene.network.get("parameters", {}).get(name)
        display = unit
        if raw is None:
            default = inspect.signature(entry.obj).parameters[name].default
            raw = None if default is inspect.Parameter.empty else default
        if isinstance(raw, str):
            _, _, written = _parse_existing(raw, path)
            display = written or unit
            value = to_si(raw, unit or "dimensionless", field=path)
        elif raw is not None:
            value = float(raw)
        else:
            value = None
    else:
        check_path(scene_dict, path, "fit")
        try:
            raw = get_path(scene_dict, path)
        except (KeyError, IndexError, ValueError, TypeError):
            raw = None
        if raw is None and len(parts) >= 4 and parts[0] == "bearings" \
                and parts[2] == "overrides":
            # a bearing value the scene does not override: start from the preset's value
            from .sweep_params import bearing_file_value

            raw = bearing_file_value(scene_dict, parts[1], parts[3:])
        kind = _SCENE_KINDS.get(path)
        if kind is not None:
            from .units import si_unit

            unit = si_unit(kind)
            display = DISPLAY_UNITS.get(parts[-1], unit)
            value = None if raw is None else to_si(raw, unit, field=path)
        elif raw is None:
            value, unit, display = None, "", ""
        else:
            value, unit, written = _parse_existing(raw, path)
            display = written or unit
    def given(v: Any, field_name: str) -> float:
        """A user's x0 / bound: a bare-number STRING ("40", from the command line) is in the
        parameter's display unit (the scene's unit, as ``sweep --set`` reads bare numbers);
        a Python number is SI; a unit string is converted."""
        if (isinstance(v, str) and unit and display not in _DIMENSIONLESS
                and re.fullmatch(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*", v)):
            v = f"{v.strip()} {display}"
        return to_si(v, unit or "dimensionless", field=field_name)

    if path in x0:
        value = given(x0[path], f"x0[{path}]")
    if value is None:
        shown = display if display not in _DIMENSIONLESS else ""
        syntax = (f"--x0 {path}=VALUE, a bare VALUE in {shown}" if shown
                  else f"--x0 {path}=VALUE")
        replaces = (f" (the fitted constant then replaces what template {tname!r} computes "
                    "there)" if parts[0] == "network" else "")
        raise InputError(f"x0[{path}]", None, f"a starting value ({syntax}): the scene "
                         "does not set this field and its default is not a number (a "
                         "correlation, or a value the models choose)" + replaces)
    is_temp = unit == "K"
    lo, hi = (0.0, math.inf) if (not is_temp and value > 0) else (-math.inf, math.inf)
    if path in bounds:
        b = bounds[path]
        if len(b) != 2:
            raise InputError(f"bounds[{path}]", b, "a pair (low, high)")
        lo, hi = (given(v, f"bounds[{path}]") for v in b)
        if not lo < hi:
            raise InputError(f"bounds[{path}]", b, "low < high")
        if not lo <= value <= hi:
            shown = display if display not in _DIMENSIONLESS else ""

            def fmt(v: float) -> str:
                if not shown or not unit:
                    return f"{v:g}"
                return f"{from_si(v, shown):g} {shown}"

            where = "given by --x0" if path in x0 else "the scene's value; --x0 PATH=VALUE " \
                "sets another"
            raise InputError(f"x0[{path}]", fmt(value), f"a start inside the bounds "
                             f"{fmt(lo)} .. {fmt(hi)} (the start is {where})")
    transform = "linear" if (is_temp or value <= 0 or lo < 0) else "log"
    scale = 1.0 if (is_temp or value == 0) else abs(value)
    step = fd_step.get(path, 0.1 if is_temp else 0.01)
    if not step > 0:
        raise InputError(f"fd_step[{path}]", step, "a step > 0")
    return FitParameter(path, unit, display, transform, float(value), float(lo), float(hi),
                        float(step), float(scale))


def _apply(scene_dict: Mapping[str, Any], params: Sequence[FitParameter],
           values: Sequence[float], base_dir: Path | None) -> Scene:
    d = json.loads(json.dumps(scene_dict))
    for p, v in zip(params, values, strict=True):
        assign_path(d, p.path, p.scene_value(v))
    return Scene.from_dict(d, base_dir)
