"""Exceptions and warnings shared by the whole package.

Every error a user can provoke names the field, the value given and what is allowed;
every solver failure carries its residual and the state it stopped at.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Iterable
from typing import Any

import numpy as np


class ThermobearingError(Exception):
    """Base class of every error raised by thermobearing."""


class InputError(ThermobearingError, ValueError):
    """Bad input: names the field, the value given and what is allowed.

    Parameters
    ----------
    field : dotted name of the offending input (``"bearing.ball_diameter"``).
    value : the value that was given.
    allowed : human-readable statement of what is allowed.
    """

    def __init__(self, field: str, value: Any, allowed: str) -> None:
        self.field = field
        self.value = value
        self.allowed = allowed
        if value is None:  # nothing was given
            super().__init__(f"{field} is missing: {allowed}")
        else:
            # an array on one line, by its ends (``_short``): its repr broke a 512 x 11
            # viscosity grid over seven lines in the middle of a message
            shown = _short(value) if isinstance(value, np.ndarray) else repr(value)
            super().__init__(f"{field} = {shown} is not allowed: {allowed}")


class UnknownNameError(InputError, KeyError):
    """A preset, model or key name that is not known; lists the known ones."""

    def __init__(self, field: str, value: Any, known: Iterable[str]) -> None:
        self.known = sorted(known)
        super().__init__(field, value, "known names are: " + ", ".join(self.known)
                         + _did_you_mean(value, self.known))

    def __str__(self) -> str:  # KeyError would otherwise quote the message
        return self.args[0]


def _did_you_mean(value: Any, known: list[str]) -> str:
    """``" (did you mean 'oil_air'?)"`` for a name that differs from a known one only in
    case, ``-`` / space for ``_``, or by a close spelling, or that starts or ends one to
    three known names after a ``_`` (``VG46`` -> ``ISO_VG46``); else ``""``."""
    import difflib

    if not isinstance(value, str) or not known:
        return ""
    plain = {k.lower().replace("-", "_").replace(" ", "_"): k for k in known
             if isinstance(k, str)}
    key = value.strip().lower().replace("-", "_").replace(" ", "_")
    squeezed = {k.replace("_", ""): v for k, v in plain.items()}
    # known names the value starts (``qj1044`` -> ``qj1044_rig``, ``qj1044_synthetic_...``)
    prefixed = [v for k, v in plain.items() if len(key) >= 3 and k.startswith(key)]
    hit = plain.get(key) or squeezed.get(key.replace("_", "")) or next(
        (plain[k] for k in difflib.get_close_matches(key, list(plain), n=1, cutoff=0.8)),
        None)
    if hit is None and not prefixed:  # the value is a known name's last part(s)
        prefixed = [v for k, v in plain.items() if len(key) >= 3 and k.endswith("_" + key)]
    if hit is None and 1 <= len(prefixed) <= 3:
        return " (did you mean " + " or ".join(repr(v) for v in sorted(prefixed)) + "?)"
    return f" (did you mean {hit!r}?)" if hit and hit != value else ""


class ConvergenceError(ThermobearingError, RuntimeError):
    """A solver did not converge.

    Parameters
    ----------
    solver : name of the solver.
    residual : residual norm at the last iterate.
    message : what happened.
    state : dict of the state at failure (time, step size, iterate, ...).
    """

    def __init__(
        self, solver: str, residual: float, message: str = "", state: dict | None = None
    ) -> None:
        self.solver = solver
        self.residual = residual
        self.state = dict(state or {})
        details = ", ".join(f"{k}={_short(v)}" for k, v in self.state.items())
        text = f"{solver} did not converge (residual {residual:.3e})"
        if message:
            text += f": {message}"
        if details:
            text += f" [{details}]"
        super().__init__(text)


class ValidityWarning(UserWarning):
    """A correlation or model is used outside the range it was fitted or derived for."""


def _short(v: Any) -> str:
    """A state value of an error message, on one line (an error is one line of the CLI's
    output and of a log): floats to 6 significant digits, arrays with 5 (first and last
    three elements of an array over 8; a small 2-D array's rows one after the other, a
    larger one by its shape and range), dicts, lists and tuples element by element,
    anything else its repr with line breaks turned into spaces. numpy's default width
    broke a 7-node temperature vector over two lines in the middle of a message."""
    if isinstance(v, float):
        return f"{v:.6g}"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k!r}: {_short(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list | tuple) and type(v) in (list, tuple):
        inner = ", ".join(_short(x) for x in v)
        return (f"[{inner}]" if isinstance(v, list)
                else f"({inner}{',' if len(v) == 1 else ''})")
    if isinstance(v, np.ndarray) and v.ndim > 1 and v.size > 8 \
            and np.issubdtype(v.dtype, np.number):
        # a grid: its shape and range, not rows of elided numbers
        finite = v[np.isfinite(v)]
        span = (f" from {_float5(finite.min())} to {_float5(finite.max())}" if finite.size
                else "")
        bad = v.size - finite.size
        return (f"({' x '.join(map(str, v.shape))} values{span}"
                + (f", {bad} not finite" if bad else "") + ")")
    if isinstance(v, np.ndarray):
        text = np.array2string(v, threshold=8, edgeitems=3, max_line_width=sys.maxsize,
                               separator=", ", formatter={"float_kind": _float5})
    else:
        text = repr(v)
    return " ".join(text.split()) if "\n" in text or isinstance(v, np.ndarray) else text


def _float5(x: float) -> str:
    return f"{x:.5g}"


# ---------------------------------------------------------------------------
# small argument checks used by the physics functions and data objects
# ---------------------------------------------------------------------------
_SCALARS = (float, int, np.float64)


def check_finite(field: str, value: Any) -> None:
    """Raise :class:`InputError` if ``value`` (scalar or array) holds NaN or inf."""
    if type(value) in _SCALARS:  # the common scalar case without numpy reductions
        if not math.isfinite(value):
            raise InputError(field, value, "a finite number")
        return
    arr = as_floats(field, value)
    if not np.all(np.isfinite(arr)):
        raise InputError(field, value, "a finite number")


def as_floats(field: str, value: Any) -> np.ndarray:
    """``np.asarray(value, dtype=float)``, or an :class:`InputError` naming ``field`` when
    ``value`` is not numbers at all (a unit string such as ``"3 kN"``, None, an object)."""
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(field, value, "a number in SI units (a unit string converts with "
                         "thermobearing.units.to_si('3 kN', 'force'))") from None


def check_positive(field: str, value: Any, *, allow_zero: bool = False) -> None:
    """Raise :class:`InputError` unless ``value`` is finite and > 0 (or >= 0)."""
    check_finite(field, value)
    if type(value) in _SCALARS:
        if value < 0 or (value == 0 and not allow_zero):
            raise InputError(field, value, "a value >= 0" if allow_zero else "a value > 0")
        return
    arr = np.asarray(value, dtype=float)
    if allow_zero:
        if np.any(arr < 0):
            raise InputError(field, value, "a value >= 0")
    elif np.any(arr <= 0):
        raise InputError(field, value, "a value > 0")


def check_range(
    field: str,
    value: Any,
    low: float = -math.inf,
    high: float = math.inf,
    *,
    low_inclusive: bool = True,
    high_inclusive: bool = True,
    unit: str = "",
) -> None:
    """Raise :class:`InputError` unless ``low <= value <= high`` (bounds as flagged)."""
    check_finite(field, value)
    if type(value) in _SCALARS:
        bad_low = value < low if low_inclusive else value <= low
        bad_high = value > high if high_inclusive else value >= high
    else:
        arr = np.asarray(value, dtype=float)
        bad_low = np.any(arr < low) if low_inclusive else np.any(arr <= low)
        bad_high = np.any(arr > high) if high_inclusive else np.any(arr >= high)
    if bad_low or bad_high:
        lb = "[" if low_inclusive else "("
        hb = "]" if high_inclusive else ")"
        suffix = f" {unit}" if unit else ""
        raise InputError(field, value, f"a value in {lb}{low:g}, {high:g}{hb}{suffix}")


def check_temperature(field: str, value: Any) -> None:
    """Raise :class:`InputError` for a temperature [K] at or below absolute zero."""
    check_finite(field, value)
    bad = value <= 0.0 if type(value) in _SCALARS else np.any(np.asarray(value, float) <= 0.0)
    if bad:
        raise InputError(field, value, "a temperature above absolute zero (in K)")
