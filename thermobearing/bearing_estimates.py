"""Catalogue bearings: the internal geometry a catalogue does not give, estimated and marked.

A bearing config with ``estimate_missing = true`` needs only what a catalogue page or a sample
bearing on the bench gives:

* ball bearings: ``kind``, ``bore``, ``outer_diameter``, ``width``, ``ball_diameter``,
  ``n_balls`` (and ``contact_angle`` for an angular-contact bearing; ``contact_angle`` and
  ``diametral_clearance`` for a four-point bearing, whose gothic arch no standard fixes);
* cylindrical roller bearings: ``kind``, ``bore``, ``outer_diameter``, ``width``,
  ``roller_diameter``, ``roller_length``, ``n_rollers``.

Every other required value the config leaves out is filled by the rule below and recorded in
the bearing's ``estimated`` table with that rule and its value (``thermobearing check`` and
the report list them); a value the config gives is never changed. The rules are typical
design proportions, not a maker's data: where a result matters (clearance, conformity), give
the real value.

Rules (field: rule; source):

* ``pitch_diameter``: d_m = (d + D)/2; the mean diameter of the SKF friction model
  (``skf_catalogue_friction``).
* ``inner_conformity``, ``outer_conformity``: 0.52 / 0.53; typical groove radii of radial
  ball bearings (Harris & Kotzalas 2007, vol. 1 ch. 2; the SKF6304 preset uses the same).
* ``contact_angle``: 0 for a deep-groove bearing (the kind).
* ``diametral_clearance``: mid-range of the ISO 5753-1 Normal (CN) group (deep groove
  d <= 100 mm, cylindrical roller d <= 500 mm; ``iso5753_1_2009``, rows checked against
  makers' public reproductions of its tables); 0 for an angular-contact bearing.
* ``ball_material``, ``roller_material``, ``ring_material``: through-hardened bearing
  steel ``STEEL_52100``.
* ``raceway_roughness``, ``element_roughness``: Rq 0.1 um raceways; 0.025 um balls
  (ISO 3290-1 G10), 0.08 um rollers; as the presets (their ``[estimated]`` reasoning).
* ``roller_effective_length``: the roller length (end chamfers neglected, as the presets);
  ``ribbed_ring``: ``"outer"``, the NU type (the geometry's default, now listed as an
  estimate: an N, NJ or NUP bearing must say so).
* ``[cage]``: rolling-element guided; pressed steel (deep groove) or machined brass
  (others); pocket clearance 3 % of D (balls) / 2 % of D_w (rollers); width 0.55 B (balls)
  / 0.75 B (rollers); bore and outside diameter d_m -+ 0.45 D / 0.5 D_w; mass from the
  material and the annulus less the pockets; the presets' estimates (SKF6304, NU214).

The deep-groove Normal group is tabulated only to d = 100 mm (the rows checked against a
public source); a larger deep-groove bearing must give ``diametral_clearance``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .errors import InputError
from .units import to_si

#: ISO 5753-1 Normal (CN) radial internal clearance of single-row deep-groove ball bearings:
#: (bore over [mm], bore incl [mm], min [um], max [um]); checked against a bearing maker's
#: public reproduction of the table (rows to 100 mm).
DEEP_GROOVE_CN = (
    (0.0, 10.0, 2.0, 13.0), (10.0, 18.0, 3.0, 18.0), (18.0, 24.0, 5.0, 20.0),
    (24.0, 30.0, 5.0, 20.0), (30.0, 40.0, 6.0, 20.0), (40.0, 50.0, 6.0, 23.0),
    (50.0, 65.0, 8.0, 28.0), (65.0, 80.0, 10.0, 30.0), (80.0, 100.0, 12.0, 36.0),
)
#: ISO 5753-1 Normal radial internal clearance of cylindrical roller bearings with a
#: cylindrical bore (same layout; checked against SKF's public table, rows to 500 mm).
CYLINDRICAL_ROLLER_CN = (
    (0.0, 24.0, 20.0, 45.0), (24.0, 30.0, 20.0, 45.0), (30.0, 40.0, 25.0, 50.0),
    (40.0, 50.0, 30.0, 60.0), (50.0, 65.0, 40.0, 70.0), (65.0, 80.0, 40.0, 75.0),
    (80.0, 100.0, 50.0, 85.0), (100.0, 120.0, 50.0, 90.0), (120.0, 140.0, 60.0, 105.0),
    (140.0, 160.0, 70.0, 120.0), (160.0, 180.0, 75.0, 125.0), (180.0, 200.0, 90.0, 145.0),
    (200.0, 225.0, 105.0, 165.0), (225.0, 250.0, 110.0, 175.0), (250.0, 280.0, 125.0, 195.0),
    (280.0, 315.0, 130.0, 205.0), (315.0, 355.0, 145.0, 225.0), (355.0, 400.0, 190.0, 280.0),
    (400.0, 450.0, 210.0, 310.0), (450.0, 500.0, 220.0, 330.0),
)

#: what a config with ``estimate_missing = true`` must give, per kind family
CATALOGUE_FIELDS = {
    "ball": ("bore", "outer_diameter", "width", "ball_diameter", "n_balls"),
    "roller": ("bore", "outer_diameter", "width", "roller_diameter", "roller_length",
               "n_rollers"),
}

_MARK = "estimate_missing"


def normal_clearance(kind: str, bore: float) -> tuple[float, float]:
    """ISO 5753-1 Normal-group radial internal clearance [m] (min, max) for a bore [m].

    ``kind``: "deep_groove" (single-row deep-groove ball bearings, bore <= 100 mm) or
    "cylindrical" (cylindrical roller bearings with cylindrical bore, bore <= 500 mm). The
    radial internal clearance of ISO 5753-1 is the total radial play of the unmounted
    bearing, i.e. the diametral clearance P_d of this package. Source: ``iso5753_1_2009``.
    """
    tables = {"deep_groove": DEEP_GROOVE_CN, "cylindrical": CYLINDRICAL_ROLLER_CN}
    if kind not in tables:
        raise InputError("kind", kind, "deep_groove or cylindrical (the tabulated ISO 5753-1 "
                         "Normal groups)")
    d_mm = bore * 1e3
    for over, incl, lo, hi in tables[kind]:
        if over < d_mm <= incl:
            return lo * 1e-6, hi * 1e-6
    top = tables[kind][-1][1]
    raise InputError("diametral_clearance", None,
                     f"a value: the ISO 5753-1 Normal group of a {kind} bearing is tabulated "
                     f"here for bores up to {top:g} mm (bore {d_mm:g} mm)")


def _si(data: Mapping[str, Any], key: str, kind: str, origin: str) -> float:
    return to_si(data[key], kind, field=f"{origin}.{key}")


def complete_from_catalogue(data: Mapping[str, Any], *, origin: str = "bearing"
                            ) -> dict[str, Any]:
    """A bearing config (unit strings allowed) with every missing required value estimated.

    Parameters
    ----------
    data : the config mapping; ``estimate_missing`` must be true (else it is returned as a
        copy without the key). Values are unit strings or SI numbers.
    origin : the config's name in error messages.

    Returns
    -------
    A new mapping without ``estimate_missing``, every filled value in SI (bare numbers) and
    its rule in ``estimated`` (the module docstring lists the rules). A field the config
    gives is kept as given; an ``estimated`` entry the config gives is kept too.

    Raises
    ------
    InputError : ``estimate_missing`` not a boolean; a catalogue field missing (named); a
        four-point bearing without ``contact_angle`` / ``diametral_clearance`` or an
        angular-contact one without ``contact_angle``; a bore outside the clearance tables
        without ``diametral_clearance``.
    """
    flag = data.get(_MARK, False)
    if not isinstance(flag, bool):
        raise InputError(f"{origin}.{_MARK}", flag, "true or false")
    out = {k: v for k, v in data.items() if k != _MARK}
    if not flag:
        return out
    kind = str(data.get("kind", ""))
    family = "roller" if kind == "cylindrical" else "ball"
    for key in CATALOGUE_FIELDS[family]:
        if key not in data:
            raise InputError(f"{origin}.{key}", None,
                             f"a value: estimate_missing fills the internal geometry but needs "
                             f"{', '.join(CATALOGUE_FIELDS[family])} (catalogue data)")
    needed = {"angular_contact": ("contact_angle",),
              "four_point": ("contact_angle", "diametral_clearance")}.get(kind, ())
    for key in needed:
        if key not in data:
            raise InputError(f"{origin}.{key}", None,
                             f"a value for a {kind} bearing (no standard fixes it; "
                             "estimate_missing does not guess it)")
    estimated = dict(data.get("estimated", {}) or {})
    note = "estimate_missing: "

    def fill(key: str, value: Any, why: str) -> None:
        if key not in out:
            out[key] = value
            estimated.setdefault(key, note + why)

    def fill_clearance(table: str, matters: str) -> None:
        """The mid-range of the ISO 5753-1 Normal group of the bore (when not given)."""
        if "diametral_clearance" not in out:
            try:
                lo, hi = normal_clearance(table, d)
            except InputError as exc:
                # named as the config's key (the message named "diametral_clearance" alone,
                # no key of the scene or the file); a bare bore is metres: bore = 30 is 30 m
                bare = isinstance(data["bore"], int | float)
                raise InputError(f"{origin}.diametral_clearance", None, exc.allowed + (
                    f"; bore = {data['bore']!r} is a bare number, read in m: write e.g. "
                    f"\"{data['bore']} mm\"" if bare else "")) from None
            fill("diametral_clearance", 0.5 * (lo + hi),
                 f"mid-range of the ISO 5753-1 Normal (CN) group for a {d * 1e3:g} mm bore, "
                 f"{lo * 1e6:g}-{hi * 1e6:g} um; give the measured or the C3/C4 value where "
                 f"it matters ({matters})")

    d = _si(data, "bore", "length", origin)
    D_out = _si(data, "outer_diameter", "length", origin)
    B = _si(data, "width", "length", origin)
    for key, value in (("bore", d), ("outer_diameter", D_out), ("width", B)):
        if not value > 0.0:
            # width = "0 mm" was refused as "cage.width = 0.0" (the estimated cage's)
            raise InputError(f"{origin}.{key}", data[key], "a length > 0")
    dm = 0.5 * (d + D_out)
    fill("pitch_diameter", dm, f"d_m = (d + D)/2 = {dm * 1e3:.4g} mm, the mean diameter of "
         "the SKF friction model; a series' true pitch diameter differs by a few percent")
    dm = _si(out, "pitch_diameter", "length", origin)
    if family == "ball":
        elem = _si(data, "ball_diameter", "length", origin)
        fill("inner_conformity", 0.52, "f_i = 0.52, typical inner groove of radial ball "
             "bearings (Harris & Kotzalas 2007 vol. 1 ch. 2)")
        fill("outer_conformity", 0.53, "f_o = 0.53, typical outer groove of radial ball "
             "bearings (Harris & Kotzalas 2007 vol. 1 ch. 2)")
        if kind == "deep_groove":
            fill("contact_angle", 0.0, "0 deg: deep groove (the free angle follows from the "
                 "clearance)")
            fill_clearance("deep_groove", "free contact angle, load zone")
        else:
            fill("diametral_clearance", 0.0, "0: an angular-contact bearing mounted without "
                 "play (the design contact angle is taken as the free angle); give the "
                 "operating play of the arrangement where it matters")
        fill("ball_material", "STEEL_52100", "through-hardened bearing steel (52100 / 100Cr6)")
        fill("element_roughness", 0.025e-6, "Rq 0.025 um: ISO 3290-1 grade G10 balls (Ra <= "
             "0.020 um), Rq = 1.25 Ra; enters only the Lambda validity check")
    else:
        elem = _si(data, "roller_diameter", "length", origin)
        fill_clearance("cylindrical", "load zone")
        length = _si(data, "roller_length", "length", origin)
        fill("roller_effective_length", length,
             f"the roller length, {length * 1e3:.4g} mm: end chamfers neglected (as the "
             "presets); the straight length is shorter by the two chamfers")
        fill("ribbed_ring", "outer", "'outer': NU type (two ribs on the outer ring, none on "
             "the inner ring), which carries no axial load; give 'inner' for an N type or "
             "'both' for NJ / NUP types")
        fill("roller_material", "STEEL_52100", "through-hardened bearing steel (52100 / "
             "100Cr6)")
        fill("element_roughness", 0.08e-6, "Rq 0.08 um: superfinished rollers (Ra about "
             "0.05-0.08 um, as the roller presets); enters only the Lambda validity check")
    fill("ring_material", "STEEL_52100", "through-hardened bearing steel (52100 / 100Cr6)")
    fill("raceway_roughness", 0.1e-6, "Rq 0.1 um: superfinished raceways (Ra about 0.05-0.1 "
         "um, as the presets); enters only the Lambda validity check")
    if "cage" not in out:
        out["cage"], reasons = _cage_estimate(kind, family, dm, elem, B)
        for key, why in reasons.items():
            estimated.setdefault(f"cage.{key}", note + why)
    out["estimated"] = estimated
    return out


def _cage_estimate(kind: str, family: str, dm: float, elem: float, width: float
                   ) -> tuple[dict[str, Any], dict[str, str]]:
    """Cage table (SI) and the rule of each value (module docstring)."""
    ball = family == "ball"
    pocket, wfrac, rfrac = (0.03, 0.55, 0.45) if ball else (0.02, 0.75, 0.5)
    material = "STEEL_LOW_CARBON" if kind == "deep_groove" else "BRASS"
    what = "pressed steel" if material == "STEEL_LOW_CARBON" else "machined brass"
    sym = "D" if ball else "D_w"
    cage = {"guidance": "rolling_element", "pocket_clearance": pocket * elem,
            "width": wfrac * width, "inner_diameter": dm - rfrac * elem,
            "outer_diameter": dm + rfrac * elem, "material": material,
            "source": "estimated from the catalogue data (estimate_missing)"}
    reasons = {
        "guidance": "rolling-element guided (no land geometry known)",
        "pocket_clearance": f"{pocket:.0%} of {sym} = {cage['pocket_clearance'] * 1e3:.3g} mm",
        "width": f"{wfrac:g} of the ring width = {cage['width'] * 1e3:.3g} mm",
        "inner_diameter": f"d_m - {rfrac:g} {sym} = {cage['inner_diameter'] * 1e3:.4g} mm",
        "outer_diameter": f"d_m + {rfrac:g} {sym} = {cage['outer_diameter'] * 1e3:.4g} mm",
        "material": f"{what}; the mass follows from its density and the annulus less the "
                    "pockets (overestimates a pressed two-piece cage)",
    }
    return cage, reasons
