"""Reading bearing configs (TOML with unit strings) into :mod:`thermobearing.geometry` objects.

Public entry points are re-exported by :mod:`thermobearing.geometry` (``load_bearing``,
``bearing_from_dict``, ``preset_names``, ``configs_dir``). Unknown keys are errors naming the
key; unit strings are converted with :func:`thermobearing.units.to_si`.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Mapping
from dataclasses import MISSING, fields, replace
from pathlib import Path
from typing import Any

from .bearing_estimates import complete_from_catalogue
from .errors import InputError, UnknownNameError
from .geometry import (
    BALL_KINDS,
    ROLLER_KINDS,
    BallBearing,
    Bearing,
    CageGeometry,
    RollerBearing,
)
from .geometry_ball import _diagonal_free_angle
from .materials import Material, get_material
from .toml_files import read_toml
from .units import to_si

#: field -> unit kind of the scalar fields of a bearing TOML (None: not a quantity).
_LENGTH_FIELDS = (
    "bore", "outer_diameter", "width", "ball_diameter", "pitch_diameter", "diametral_clearance",
    "gothic_arch_offset", "inner_shoulder_diameter", "outer_shoulder_diameter",
    "roller_diameter", "roller_length", "roller_effective_length", "crown_radius",
    "end_face_crown_radius", "axial_clearance", "rib_height", "raceway_roughness",
    "element_roughness",
)
_ANGLE_FIELDS = ("contact_angle", "rib_angle")
_PLAIN_FIELDS = ("inner_conformity", "outer_conformity")
_INT_FIELDS = ("n_balls", "n_rollers")
_TEXT_FIELDS = ("name", "kind", "source", "ribbed_ring")
_TABLE_FIELDS = ("cage", "estimated", "ball_material", "roller_material", "ring_material",
                 "notes")
_CAGE_LENGTHS = ("guide_land_diameter", "guide_clearance", "land_width", "pocket_clearance",
                 "width", "inner_diameter", "outer_diameter")
_MATERIAL_KEYS = ("base", "name", "youngs_modulus", "poisson_ratio", "density", "specific_heat",
                  "thermal_conductivity", "source", "estimated")
_MATERIAL_UNITS = {"youngs_modulus": "pressure", "poisson_ratio": "dimensionless",
                   "density": "density", "specific_heat": "specific_heat",
                   "thermal_conductivity": "thermal_conductivity"}


def configs_dir() -> Path:
    """The repository's ``configs`` folder."""
    import thermobearing

    return Path(thermobearing.__file__).resolve().parents[1] / "configs"


def preset_names() -> list[str]:
    """Names of the bearing presets in ``configs/bearings`` (companion files such as
    ``QJ1044.calibration.toml`` are not presets)."""
    folder = configs_dir() / "bearings"
    if not folder.is_dir():
        return []
    return sorted(p.stem for p in folder.glob("*.toml") if "." not in p.stem)


def _material(value: Any, field_name: str) -> Material:
    if isinstance(value, Material):
        return value
    if isinstance(value, str):
        return get_material(value)
    if not isinstance(value, Mapping):
        raise InputError(field_name, value, "a material name or a table of properties")
    unknown = sorted(set(value) - set(_MATERIAL_KEYS))
    if unknown:
        raise InputError(f"{field_name}.{unknown[0]}", value[unknown[0]],
                         "one of the keys " + ", ".join(_MATERIAL_KEYS))
    base_name = value.get("base")
    changes: dict[str, Any] = {}
    for key, kind in _MATERIAL_UNITS.items():
        if key in value:
            changes[key] = to_si(value[key], kind, field=f"{field_name}.{key}")
    if "source" in value:
        changes["source"] = str(value["source"])
    if "name" in value:
        changes["name"] = str(value["name"])
    if "estimated" in value:
        changes["estimated"] = {str(k): str(v) for k, v in dict(value["estimated"]).items()}
    if base_name is not None:
        return replace(get_material(str(base_name)), **changes)
    missing = [k for k in ("name", *_MATERIAL_UNITS, "source") if k not in changes]
    if missing:
        raise InputError(f"{field_name}.{missing[0]}", None,
                         "a value (or give 'base' = a known material to inherit from)")
    return Material(**changes)


def _cage(data: Any) -> CageGeometry:
    if not isinstance(data, Mapping):
        raise InputError("cage", data, "a table")
    allowed = ("guidance", *_CAGE_LENGTHS, "mass", "material", "source")
    unknown = sorted(set(data) - set(allowed))
    if unknown:
        raise InputError(f"cage.{unknown[0]}", data[unknown[0]],
                         "one of the keys " + ", ".join(allowed))
    kwargs: dict[str, Any] = {"guidance": data.get("guidance", "rolling_element"),
                              "source": str(data.get("source", ""))}
    for key in _CAGE_LENGTHS:
        if key in data:
            kwargs[key] = to_si(data[key], "length", field=f"cage.{key}")
    for key in ("width", "inner_diameter", "outer_diameter", "pocket_clearance"):
        if key not in kwargs:
            raise InputError(f"cage.{key}", None, "a value (required)")
    if "mass" in data:
        kwargs["mass"] = to_si(data["mass"], "mass", field="cage.mass")
    if "material" in data:
        kwargs["material"] = _material(data["material"], "cage.material")
    return CageGeometry(**kwargs)


#: angle field -> its allowed interval [deg] (the geometry's own check, in radians)
_ANGLE_RANGES = {"contact_angle": (0.0, 90.0, "[0, 90) deg"), "rib_angle": (0.0, 45.0,
                                                                          "[0, 45] deg")}


def _is_bare(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


_SI_WORDS = {"m": "metres", "rad": "radians"}


def _bare_hint(value: Any, si_unit: str, unit: str) -> str:
    """The hint for a bare number a unit field read in SI: what it was read as and the
    spelling that was probably meant."""
    return (f"; a bare number is read in {_SI_WORDS[si_unit]} ({value:g} {si_unit}): "
            f"write \"{value:g} {unit}\" if {unit} was meant")


def _check_bare_angles(data: Mapping[str, Any], origin: str) -> None:
    """Refuse a bare-number angle outside its range, saying that a bare number is read in
    radians (``contact_angle = 40`` is 40 rad) and suggesting ``"40 deg"``."""
    for key, (low, high, allowed) in _ANGLE_RANGES.items():
        value = data.get(key)
        if not _is_bare(value) or not math.isfinite(value):
            continue
        if not low <= math.degrees(value) < high + (1e-12 if allowed.endswith("]") else 0.0):
            raise InputError(f"{origin}.{key}", value,
                             f"an angle in {allowed}" + _bare_hint(value, "rad", "deg"))


def _check_given_dimensions(data: Mapping[str, Any], origin: str) -> None:
    """Check the envelope and element dimensions a config gives against each other before
    anything is estimated from them (an estimate built on a wrong one was refused under
    its own name: ``ball_diameter = 12.7``, read as 12.7 m, stopped as
    ``cage.inner_diameter = -5.645``). Bore d < outer diameter D, the element diameter
    below the ring section (D - d) / 2 and the pitch diameter between d and D; a bare
    number among the offending values is said to be read in metres, with the mm spelling.
    Checked here when the config estimates (``estimate_missing``) or the value is a bare
    number; otherwise the geometry's own checks refuse it as before.
    """
    given = {k: to_si(data[k], "length", field=f"{origin}.{k}")
             for k in ("bore", "outer_diameter", "pitch_diameter", "ball_diameter",
                       "roller_diameter") if k in data}

    estimating = "estimate_missing" in data

    def refuse(key: str, allowed: str) -> None:
        value = data[key]
        if not (estimating or _is_bare(value)):
            return  # nothing is estimated from it: the geometry's own check names it
        hint = _bare_hint(value, "m", "mm") if _is_bare(value) else ""
        raise InputError(f"{origin}.{key}", value, allowed + hint)

    d, D = given.get("bore"), given.get("outer_diameter")
    if d is not None and D is not None and not d < D:
        blame = "bore" if _is_bare(data["bore"]) and not _is_bare(data["outer_diameter"]) \
            else "outer_diameter"
        other = D if blame == "bore" else d
        refuse(blame, (f"a bore below the outer diameter {1e3 * D:g} mm" if blame == "bore"
                       else f"an outer diameter above the bore {1e3 * other:g} mm"))
    for key in ("ball_diameter", "roller_diameter"):
        if key in given and d is not None and D is not None and not given[key] < 0.5 * (D - d):
            refuse(key, f"a diameter below the ring section (D - d)/2 = "
                        f"{0.5e3 * (D - d):g} mm (bore {1e3 * d:g} mm, outer diameter "
                        f"{1e3 * D:g} mm)")
    dm = given.get("pitch_diameter")
    if dm is not None and d is not None and D is not None and not d < dm < D:
        refuse("pitch_diameter", f"a diameter between the bore {1e3 * d:g} mm and the outer "
                                 f"diameter {1e3 * D:g} mm")


def bearing_from_dict(data: Mapping[str, Any], *, origin: str = "bearing") -> Bearing:
    """Build a bearing from a config mapping (unit strings allowed); unknown keys are errors.

    ``estimate_missing = true`` fills the internal geometry a catalogue does not give, each
    value marked in ``estimated`` with its rule (:mod:`thermobearing.bearing_estimates`).
    """
    allowed = set(_LENGTH_FIELDS + _ANGLE_FIELDS + _PLAIN_FIELDS + _INT_FIELDS + _TEXT_FIELDS
                  + _TABLE_FIELDS + ("estimate_missing",))
    for key in data:
        if key not in allowed:
            raise InputError(f"{origin}.{key}", data[key],
                             "a known bearing key: " + ", ".join(sorted(allowed)))
    kind = data.get("kind")
    if kind is None:
        raise InputError(f"{origin}.kind", None, "one of " + ", ".join(BALL_KINDS + ROLLER_KINDS))
    if kind not in BALL_KINDS + ROLLER_KINDS:
        raise UnknownNameError(f"{origin}.kind", kind, BALL_KINDS + ROLLER_KINDS)
    if not str(data.get("source", "")).strip():
        raise InputError(f"{origin}.source", data.get("source"), "a non-empty source")
    _check_bare_angles(data, origin)
    _check_given_dimensions(data, origin)
    if "estimate_missing" in data:
        data = complete_from_catalogue(data, origin=origin)
    kw: dict[str, Any] = {}
    for key in _LENGTH_FIELDS:
        if key in data:
            kw[key] = to_si(data[key], "length", field=f"{origin}.{key}")
    for key in _ANGLE_FIELDS:
        if key in data:
            kw[key] = to_si(data[key], "angle", field=f"{origin}.{key}")
    for key in _PLAIN_FIELDS:
        if key in data:
            kw[key] = to_si(data[key], "dimensionless", field=f"{origin}.{key}")
    for key in _INT_FIELDS:
        if key in data:
            value = data[key]
            if isinstance(value, bool) or not isinstance(value, int):
                raise InputError(f"{origin}.{key}", value, "an integer >= 3")
            kw[key] = value
    for key in ("name", "kind", "source", "ribbed_ring"):
        if key in data:
            kw[key] = str(data[key])
    kw.setdefault("name", "unnamed")
    estimated = data.get("estimated", {})
    if not isinstance(estimated, Mapping):
        raise InputError(f"{origin}.estimated", estimated, "a table field -> reasoning")
    kw["estimated"] = {str(k): str(v) for k, v in estimated.items()}
    if "cage" not in data:
        raise InputError(f"{origin}.cage", None, "a [cage] table")
    kw["cage"] = _cage(data["cage"])
    ball = kind in BALL_KINDS
    elem_mat = "ball_material" if ball else "roller_material"
    for key in (elem_mat, "ring_material"):
        if key not in data:
            raise InputError(f"{origin}.{key}", None, "a material name or table")
        kw[key] = _material(data[key], f"{origin}.{key}")
    if kind == "four_point" and "contact_angle" not in kw and "gothic_arch_offset" in kw:
        needed = ("ball_diameter", "inner_conformity", "outer_conformity")
        if all(k in kw for k in needed):
            kw["contact_angle"] = _diagonal_free_angle(
                kw["ball_diameter"], kw["inner_conformity"], kw["outer_conformity"],
                kw["gothic_arch_offset"], kw.get("diametral_clearance", 0.0),
                field=f"{origin}.diametral_clearance")
    if kind == "deep_groove" and "diametral_clearance" in kw and all(
            k in kw for k in ("ball_diameter", "inner_conformity", "outer_conformity")):
        # the balls must stay in their grooves at this clearance, checked before the rings
        # are built: an override of 15 mm on the SKF 6304 was refused as
        # 'bearing.pitch_diameter ... raceway diameter <= bore', 1.5 mm only at the first
        # load distribution as 'diametral_clearance' (neither the scene's key)
        # cos(alpha_f) = 1 - P_d / (2 A) > 0, A = (f_i + f_o - 1) D (Harris & Kotzalas 2007,
        # vol. 1 ch. 2): P_d < 2 A
        limit = 2.0 * (kw["inner_conformity"] + kw["outer_conformity"] - 1.0) * kw[
            "ball_diameter"]
        if limit > 0.0 and not kw["diametral_clearance"] < limit:
            raise InputError(f"{origin}.diametral_clearance", kw["diametral_clearance"],
                             f"a clearance below 2 (f_i + f_o - 1) D = {limit * 1e3:.4g} mm, "
                             "at which the balls leave their grooves (a free contact angle "
                             "of 90 deg); the ISO 5753-1 groups give micrometres to a few "
                             "tenths of a mm")
    if not ball and all(k in kw for k in ("diametral_clearance", "roller_diameter",
                                          "pitch_diameter", "bore", "outer_diameter")):
        # d_i = d_m - D_w - P_d/2 > d and d_o = d_m + D_w + P_d/2 < D: checked here so that
        # the refusal names the clearance (3e28 mm on the NU214 was refused as
        # 'bearing.pitch_diameter ... leaving an inner ring', no key of the scene)
        room = 2.0 * min(kw["pitch_diameter"] - kw["roller_diameter"] - kw["bore"],
                         kw["outer_diameter"] - kw["pitch_diameter"] - kw["roller_diameter"])
        if room > 0.0 and not kw["diametral_clearance"] < room:
            raise InputError(f"{origin}.diametral_clearance", kw["diametral_clearance"],
                             f"a clearance below {room * 1e3:.4g} mm, which keeps both "
                             "raceways inside their rings (d_i = d_m - D_w - P_d/2 > bore, "
                             "d_o = d_m + D_w + P_d/2 < outer diameter)")
    cls = BallBearing if ball else RollerBearing
    names = {f.name for f in fields(cls)}
    wrong = sorted(set(kw) - names)
    if wrong:
        raise InputError(f"{origin}.{wrong[0]}", data.get(wrong[0]),
                         f"a key of a {kind} bearing (not {wrong[0]})")
    required = [f.name for f in fields(cls)
                if f.default is MISSING and f.default_factory is MISSING]
    for key in required:
        if key not in kw:
            raise InputError(f"{origin}.{key}", None, "a value (required)")
    return cls(**kw)


def load_bearing(name_or_path: str | Path,
                 overrides: Mapping[str, Any] | None = None) -> Bearing:
    """Load a bearing from a preset name (``"QJ1044"``) or a TOML path.

    ``overrides`` replaces top-level keys (unit strings allowed, e.g.
    ``{"diametral_clearance": "0.1 mm"}``) before the bearing is built; a table given for a
    table (``{"cage": {"guide_clearance": "0.4 mm"}}``) is merged into it key by key. For a
    four-point preset with a gothic-arch offset, overriding only the clearance keeps the
    offset and lets the contact angle follow (as :meth:`BallBearing.with_clearance`).
    Unknown keys, unknown presets and bad values raise
    :class:`~thermobearing.errors.InputError`.
    """
    text = str(name_or_path)
    path = Path(text)
    if not (text.endswith(".toml") or path.is_file()):
        path = configs_dir() / "bearings" / f"{text}.toml"
        if not path.is_file():
            raise UnknownNameError("bearing preset", text, preset_names())
    elif not path.is_file():
        raise InputError("bearing path", text, "an existing TOML file")
    try:
        data = read_toml(path)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("bearing file", str(path), f"valid TOML ({exc})") from None
    data.pop("notes", None)
    if overrides:
        overrides = dict(overrides)
        if (data.get("kind") == "four_point" and "gothic_arch_offset" in data
                and "diametral_clearance" in overrides and "contact_angle" not in overrides
                and "gothic_arch_offset" not in overrides):
            # the ground gothic arch stays; the free contact angle follows the new clearance
            data = {k: v for k, v in data.items() if k != "contact_angle"}
        # a table overridden by a table is merged key by key (``cage = { guide_clearance =
        # "0.4 mm" }`` changes that one key; replacing the whole [cage] table left the
        # other cage keys reported missing); anything else replaces
        data = {**data, **{k: ({**data[k], **v} if isinstance(v, Mapping)
                               and isinstance(data.get(k), Mapping) else v)
                           for k, v in overrides.items()}}
    data.setdefault("name", path.stem)
    return bearing_from_dict(data, origin=f"bearing[{path.stem}]")

