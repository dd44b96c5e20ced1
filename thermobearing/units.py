"""Unit strings at the edges: configs and the command line.

Inside the package everything is SI (m, kg, s, K, N, Pa, W, rad). This module is the
only place that knows about pint: a config value such as ``"1800 rpm"``, ``"33 L/min"``,
``"35 degC"``, ``"2 kN"`` or ``"0.08 Pa*s"`` is converted once, at load time, to a float in
the SI unit declared for that field. A bare number is taken to be SI already. Spellings of
data sheets that pint does not read are accepted too: ``"16000 r/min"`` (``rev/min``),
a bare exponent digit after a length unit (``"30 mm3/h"``, ``"32 mm2/s"``), the
one-character degree signs ``"35 \u2103"`` / ``"95 \u2109"``; a decimal
comma (``"0,5 kN"``) is an error that shows the value with a point. A frequency written
as a rotation speed counts revolutions (``"1812 rpm"`` is 30.2 Hz, ``"6.283 rad/s"`` 1 Hz),
and a frequency without an angle is refused for an angular speed (``"30 Hz"``).
"""

from __future__ import annotations

import functools
import math
import re
from typing import Any

import pint

from .errors import InputError

#: SI target unit of each kind of quantity used in configs (pint spelling).
SI_UNITS: dict[str, str] = {
    "length": "m",
    "area": "m**2",
    "volume": "m**3",
    "mass": "kg",
    "time": "s",
    "temperature": "K",
    "temperature_difference": "delta_degC",  # "10 K" or "10 degC" both mean 10 K
    "angle": "rad",
    "angular_speed": "rad/s",
    "speed": "m/s",
    "force": "N",
    "moment": "N*m",
    "pressure": "Pa",
    "stress": "Pa",
    "dynamic_viscosity": "Pa*s",
    "kinematic_viscosity": "m**2/s",
    "density": "kg/m**3",
    "volume_flow": "m**3/s",
    "mass_flow": "kg/s",
    "power": "W",
    "energy": "J",
    "heat_capacity": "J/K",
    "specific_heat": "J/(kg*K)",
    "thermal_conductivity": "W/(m*K)",
    "heat_transfer_coefficient": "W/(m**2*K)",
    "conductance": "W/K",
    "frequency": "Hz",
    "inverse_pressure": "1/Pa",
    "inverse_temperature": "1/K",
    "stiffness": "N/m",
    "dimensionless": "dimensionless",
}

_NUMBER_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
#: a number written with a decimal comma ("0,5 kN")
_DECIMAL_COMMA = re.compile(r"^\s*[-+]?\d+,\d+")
#: a number written in digit groups ("16 000 rpm", "16,000 rpm"; also with a thin space,
#: an apostrophe as in Switzerland or an underscore as in Python and TOML numbers)
_DIGIT_GROUPS = re.compile(r"^\s*([-+]?)([1-9]\d{0,2})"
                           r"((?:([ ,_'\u00a0\u2009\u202f\u2019])\d{3})+)(?![\d,])"
                           r"(?:\.\d+)?\s*(.*?)\s*$")
#: revolutions per minute / second as ISO 80000 and catalogues write them ("r/min",
#: "rev/min"), which pint does not read
_REV_PER = re.compile(r"(?<![A-Za-z_])(?:r|rev)\s*/\s*(min|s)(?![A-Za-z_])")
#: a length unit with its exponent written as a bare digit ("mm3/h", "mm2/s", "kg/m3")
#: the megametre as a unit or a factor of one ("Mm", "Mm**2/s", "kg/Mm**3")
_MEGAMETRE = re.compile(r"(?<![A-Za-z_\u00b5\u03bc])Mm(?![A-Za-z_])")
_BARE_EXPONENT = re.compile(r"(?<![A-Za-z_\u00b5\u03bc])(km|dm|cm|mm|um|\u00b5m|\u03bcm|m|in|ft)"
                            r"([23])(?![\d.])")


#: an offset temperature unit and the unit of its differences: a temperature difference
#: written in degrees ("10 degC", "18 degF") is that many degrees of difference (10 K and
#: 10 K); "18 degF" was refused as not convertible to delta_degC while "10 degC" was read
_DIFFERENCE_OF = {
    "degC": "delta_degC", "\u00b0C": "delta_degC", "celsius": "delta_degC",
    "degree_Celsius": "delta_degC",
    "degF": "delta_degF", "\u00b0F": "delta_degF", "fahrenheit": "delta_degF",
    "degree_Fahrenheit": "delta_degF",
}


@functools.lru_cache(maxsize=1)
def unit_registry() -> pint.UnitRegistry:
    """The one pint registry of the package (created lazily, never mutated after).

    pint's parsed definitions are cached on disk (``cache_folder=":auto:"``, pint's
    own cache in the user cache folder): building the registry costs ~0.03 s instead of
    ~0.4 s of every run's start. A cache that cannot be read or written (read-only home,
    a file half-written by a concurrent first run) falls back to parsing.
    """
    try:
        ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except Exception:  # noqa: BLE001 - any cache failure: parse the definitions instead
        ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.define("rpm_rev = revolution / minute = r_per_min")
    return ureg


def si_unit(kind: str) -> str:
    """SI unit string of a quantity kind; raises for an unknown kind."""
    try:
        return SI_UNITS[kind]
    except KeyError:
        raise InputError("unit kind", kind, "one of " + ", ".join(sorted(SI_UNITS))) from None


def to_si(value: Any, unit: str, *, field: str = "value") -> float:
    """Convert a config value to a float in ``unit``.

    Parameters
    ----------
    value : str, int or float
        ``"1800 rpm"``, ``"35 degC"``, ``"0.08 Pa*s"``...; a bare number is returned as is
        (it is taken to be in ``unit`` already, which must be the SI unit of the field).
    unit : str
        Target unit in pint spelling (``"rad/s"``, ``"K"``, ``"m**3/s"``) or a quantity kind
        from :data:`SI_UNITS` (``"angular_speed"``).
    field : str
        Dotted field name, used in error messages.

    Returns
    -------
    float
        The magnitude in the target unit.

    Raises
    ------
    InputError
        If the string does not parse, or its unit does not convert to ``unit``
        (``"1800 kg"`` for a speed).
    """
    target = SI_UNITS.get(unit, unit)
    if isinstance(value, bool):
        raise InputError(field, value, f"a number or a quantity string convertible to {target}")
    if isinstance(value, int | float):
        if not math.isfinite(value):
            raise InputError(field, value, f"a finite number (in {target})")
        return float(value)
    if not isinstance(value, str):
        raise InputError(field, value, f"a number or a quantity string convertible to {target}")
    # the minus sign of word processors and spreadsheets (U+2212), which no unit contains:
    # "\u22125 degC" was refused as "'<number> <unit>' convertible to K"
    text = value.replace("\u2212", "-")
    match = _NUMBER_UNIT.match(text)
    if match is None:
        raise InputError(field, value, f"'<number> <unit>' convertible to {target}")
    number, unit_text = match.groups()
    _refuse_separators(text, field, target)
    unit_text = _usual_spellings(unit_text)
    _refuse_megametre(value, number, unit_text, field, target)
    if target == "delta_degC" and unit_text in _DIFFERENCE_OF:
        unit_text = _DIFFERENCE_OF[unit_text]
    if target == "delta_degC" and unit_text in ("K", "kelvin"):
        return float(number)
    if target == "rad/s" and unit_text and cycles_per_time(unit_text):
        rev_s = _convert(float(number), unit_text, "1/s")
        raise InputError(field, value, f"a speed whose unit names its angle: "
                         f"'{60 * rev_s:.6g} rpm', '{rev_s:.6g} rev/s' or "
                         f"'{2 * math.pi * rev_s:.6g} rad/s' for {rev_s:.6g} revolutions per "
                         f"second ({value!r} would read as {rev_s:.6g} rad/s, 2 pi low)")
    if target in ("Hz", "1/s") and unit_text and _names_an_angle(unit_text):
        # a rotation speed given for a frequency ("1812 rpm", "189.8 rad/s" for a shaft or
        # cage frequency) is that many revolutions per second: pint takes the radian as 1,
        # and "60 rpm" read as 6.283 Hz (2 pi high)
        target = "revolution/second"
    try:
        out = _convert(float(number), unit_text or "dimensionless", target)
    except pint.errors.DimensionalityError:
        hint = _spelling_hint(number, unit_text, target)
        if not hint and target in ("K", "delta_degC") and unit_text in ("C", "F"):
            # coulomb, farad
            hint = f" (degrees Celsius / Fahrenheit are deg{unit_text} or \u00b0{unit_text})"
        if not unit_text:  # a number in a text without its unit ("-1" for a pressure)
            hint = _bare_text_hint(number, target)
        raise InputError(
            field, value, f"a quantity with units convertible to {target}{hint}"
        ) from None
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError, AttributeError,
            TypeError, ValueError, AssertionError):
        hint = _case_hint(unit_text, target) or _spelling_hint(number, unit_text, target)
        raise InputError(field, value, f"a known unit convertible to {target}{hint}") from None
    if not math.isfinite(out):
        raise InputError(field, value, f"a finite quantity convertible to {target}")
    if target == "K" and out <= 0.0:
        raise InputError(field, value, "a temperature above absolute zero (> 0 K, > -273.15 degC)")
    return float(out)


#: a number written as text for a temperature [K] is read as meant in degC where it is a
#: usual temperature of a bearing, its oil or its surroundings (cold start to the limit of
#: mineral and synthetic oils), and as meant in K from the lowest plausible absolute one
#: (200 K, -73 degC); both are suggested where the ranges meet (200-300)
BARE_DEGC_RANGE = (-50.0, 300.0)
BARE_KELVIN_MIN = 200.0


def _bare_text_hint(number: str, target: str) -> str:
    """`` (a number written as text needs its unit: '38 degC')`` for a number in a text
    without its unit: for a temperature (``K``) the unit(s) it is plausibly meant in
    (:data:`BARE_DEGC_RANGE`, :data:`BARE_KELVIN_MIN`: ``"38"`` -> ``'38 degC'``, ``"250"``
    -> ``'250 degC' or '250 K'``, ``"310"`` -> ``'310 K'``; ``'38 K'`` was suggested for an
    oil inlet meant at 38 degC), for a temperature difference ``K``, else ``target``."""
    if target == "delta_degC":
        return f" (a number written as text needs its unit: '{number} K')"
    if target != "K":
        return f" (a number written as text needs its unit: '{number} {target}')"
    x = float(number)
    lo, hi = BARE_DEGC_RANGE
    units = [u for u, plausible in (("degC", lo <= x <= hi), ("K", x >= BARE_KELVIN_MIN))
             if plausible]
    if not units:  # below -50: no absolute temperature; degC down to absolute zero
        if x <= -273.15:
            return f" ({number} is below absolute zero in degC and in K)"
        units = ["degC"]
    said = " or ".join(f"'{number} {u}'" for u in units)
    return f" (a number written as text needs its unit: {said})"


def _refuse_separators(value: str, field: str, target: str) -> None:
    """A number in digit groups or with a decimal comma, refused with the reading(s) it
    may have meant: ``"16 000 rpm"`` -> ``'16000 rpm'``; ``"16,000 rpm"`` -> ``'16000 rpm'``
    or ``'16.000 rpm'``; ``"0,5 kN"`` -> ``'0.5 kN'``."""
    groups = _DIGIT_GROUPS.match(value)
    if groups is not None:
        sign, head, rest, sep, unit = groups.groups()
        joined = f"{sign}{head}{re.sub(r'[^0-9]', '', rest)}"
        whole = value.strip()
        if sep != "," or rest.count(",") > 1:
            raise InputError(field, value, f"a number without digit-group separators "
                             f"('{joined} {unit}'), in a unit convertible to {target}")
        raise InputError(field, value, f"an unambiguous number: '{joined} {unit}' (a "
                         f"thousands separator) or '{whole.replace(',', '.', 1)}' (a "
                         f"decimal comma), in a unit convertible to {target}")
    if _DECIMAL_COMMA.match(value):
        raise InputError(field, value, f"a number with a decimal point, not a comma "
                         f"('{value.strip().replace(',', '.', 1)}'), in a unit convertible "
                         f"to {target}")


def _refuse_megametre(value: str, number: str, unit_text: str, field: str,
                      target: str) -> None:
    """A unit with ``Mm`` in it (pint: the megametre, 1000 km) is refused with the ``mm``
    reading: no length of a bearing, its oil or its housing is in megametres, and a capital
    M for mm is a usual slip ("3 Mm" read as 3000 km; "68 Mm2/s" as 6.8e13 m^2/s for a
    viscosity meant in cSt). Refused rather than read as mm: the value may be a slip of
    another kind, and a silent reinterpretation would hide it."""
    if _MEGAMETRE.search(unit_text) is None:
        return
    meant = _MEGAMETRE.sub("mm", unit_text)
    raise InputError(field, value, f"a unit convertible to {target} without 'Mm' (the "
                     f"megametre, 1000 km; units are case-sensitive): did you mean "
                     f"'{number} {meant}'?")


def _usual_spellings(unit_text: str) -> str:
    """Unit spellings of data sheets in pint's: ``r/min`` and ``rev/min`` -> ``rpm``
    (``r/s`` -> ``rps``), ``\u2103`` / ``\u2109`` -> ``degC`` / ``degF``, a bare exponent digit
    after a length unit -> ``**``
    (``mm3/h`` -> ``mm**3/h``, ``mm2/s`` -> ``mm**2/s``, ``kg/m3`` -> ``kg/m**3``)."""
    unit_text = _REV_PER.sub(lambda m: "rpm" if m.group(1) == "min" else "rps", unit_text)
    # the one-character degree signs (U+2103, U+2109) that keyboards and data sheets give
    unit_text = unit_text.replace("\u2103", "degC").replace("\u2109", "degF")
    return _BARE_EXPONENT.sub(r"\1**\2", unit_text)


#: spellings of data sheets and other languages that pint does not read (or reads as
#: something else: "deg C" is degree x coulomb, "grad" the gradian), compared in lower case
#: without spaces and dots, "\u00b0" as "deg" -> the unit suggested; never accepted
#: silently (a "U/min" may be meant per minute of something else), only suggested
_SPELLINGS = {
    **dict.fromkeys(("degc", "degreec", "degreesc", "gradc", "oc", "degcelsius",
                     "gradcelsius", "centigrade", "degcentigrade"), "degC"),
    **dict.fromkeys(("degf", "degreef", "degreesf", "of", "degfahrenheit"), "degF"),
    **dict.fromkeys(("u/min", "umin", "u/mn", "tr/min", "trmin", "t/min", "obr/min",
                     "revs/min", "rev/mn", "rpm", "min-1", "min^-1", "min**-1", "1/min",
                     "revmin-1", "rmin-1", "umin-1"), "rpm"),
    **dict.fromkeys(("u/s", "u/sec", "rev/sec", "revs/s", "r/sec", "tr/s", "rps"), "rps"),
}


def _spelling_hint(number: str, unit_text: str, target: str) -> str:
    """`` (did you mean '40 degC'?)`` for a usual spelling pint does not read as meant
    (:data:`_SPELLINGS`: "40 deg C", "3000 U/min"), when the suggestion converts to
    ``target``; empty otherwise."""
    key = (unit_text.lower().replace("\u00b0", "deg").replace("\u00ba", "deg")
           .replace(" ", "").replace(".", ""))
    meant = _SPELLINGS.get(key)
    if meant is None or meant == unit_text:
        return ""
    try:
        to_si(f"{number} {meant}", target)
    except InputError:
        return ""
    return f" (did you mean '{number} {meant}'?)"


def _case_hint(unit_text: str, target: str) -> str:
    """`` (units are case-sensitive: 'rpm')`` when ``unit_text`` in lower case is a unit
    convertible to ``target`` ("RPM", "Rpm"), else empty."""
    lower = unit_text.lower()
    if not unit_text or lower == unit_text:
        return ""
    try:
        _convert(1.0, lower, target)
    except Exception:  # noqa: BLE001 -- no such unit in lower case either: no hint
        return ""
    return f" (units are case-sensitive: '{lower}')"


def quantity_unit(value: Any) -> str | None:
    """The unit of a quantity string in pint's spelling (``"30 mm3/h"`` -> ``"mm**3/h"``,
    ``"16000 r/min"`` -> ``"rpm"``); None for a bare number or a string without a unit.
    The unit is not checked here (:func:`to_si` does that)."""
    if not isinstance(value, str):
        return None
    match = _NUMBER_UNIT.match(value)
    if match is None or not match.group(2):
        return None
    return _usual_spellings(match.group(2))


@functools.lru_cache(maxsize=64)
def cycles_per_time(unit_text: str) -> bool:
    """True for a frequency without an angle in it (``Hz``, ``kHz``, ``1/s``, ``1/min``).
    pint converts ``30 Hz`` to 30 rad/s (it takes the radian as 1), where a shaft turning
    at 30 Hz makes 30 rev/s = 188.5 rad/s; ``rpm``, ``rps``, ``rad/s``, ``deg/s`` and
    ``turn/s`` carry their angle and convert right."""
    ureg = unit_registry()
    try:
        names = [name for name, _ in ureg.Quantity(1.0, unit_text).unit_items()]
    except Exception:  # noqa: BLE001 - an unparsable unit is refused by the conversion
        return False
    return bool(names) and all(
        name.endswith("hertz") or ureg.Quantity(1.0, name).dimensionality == {"[time]": 1}
        for name in names)


@functools.lru_cache(maxsize=64)
def _names_an_angle(unit_text: str) -> bool:
    """True for a unit with one angle in it (``rpm``, ``rad/s``, ``deg/s``, ``turn/s``,
    ``rps``: radian / second in pint's root units), False for a plain frequency (``Hz``,
    ``1/s``, ``1/min``) or an unparsable unit."""
    try:
        root = unit_registry().Quantity(1.0, unit_text).to_root_units().units
    except Exception:  # noqa: BLE001 - an unparsable unit is refused by the conversion
        return False
    return dict(root._units).get("radian") == 1


@functools.lru_cache(maxsize=4096)
def _convert(number: float, unit_text: str, target: str) -> float:
    """``number unit_text`` in ``target`` (pint; memoised: configs repeat the same few
    quantities -- two bearings of one preset, a sweep's scenes -- and a conversion is a pure
    function of its three arguments; failures raise and are not cached)."""
    return float(unit_registry().Quantity(number, unit_text).to(target).magnitude)


@functools.lru_cache(maxsize=256)
def _from_si_affine(unit: str) -> tuple[float, float]:
    """(a, b) with value_in_unit = a * value_SI + b (every pint unit conversion is affine)."""
    ureg = unit_registry()
    base = ureg.Quantity(1.0, unit).to_base_units().units
    y0 = float(ureg.Quantity(0.0, base).to(unit).magnitude)
    y1 = float(ureg.Quantity(1.0, base).to(unit).magnitude)
    return y1 - y0, y0


def from_si(value: float, unit: str, kind: str | None = None) -> float:
    """Convert an SI float to ``unit`` (for report labels and printed tables).

    ``kind="temperature_difference"``: ``value`` is a difference [K] and an offset unit
    means its degrees (0.5 K in ``"degC"`` is 0.5, in ``"degF"`` 0.9), the inverse of
    :func:`to_si` for that kind; without it ``"degC"`` is read as a temperature (0.5 K is
    -272.65 degC). ``kind="frequency"``: a unit with an angle (``rpm``, ``rad/s``) counts
    revolutions, as :func:`to_si` reads it (1 Hz is 60 rpm, 6.283 rad/s). The unit is read
    with :func:`to_si`'s usual spellings (``"mm3/h"``, ``"r/min"``)."""
    unit = _usual_spellings(unit)
    if kind == "temperature_difference":
        unit = _DIFFERENCE_OF.get(unit, unit)
    if kind == "frequency" and _names_an_angle(unit):  # 1 Hz in rpm is 60 (not 9.55)
        return _convert(float(value), "revolution/second", unit)
    a, b = _from_si_affine(unit)
    return float(a * value + b)


def format_quantity(value: float, unit: str, digits: int = 4, kind: str | None = None) -> str:
    """SI float -> ``"<value> <unit>"`` string in ``unit`` (used by ``Scene.to_toml``);
    ``kind`` as in :func:`from_si` (a temperature difference in ``"degC"``)."""
    if unit in ("", "dimensionless"):
        return f"{value:.{digits}g}"
    return f"{from_si(value, unit, kind):.{digits}g} {unit}"
