"""Property tests of the sweep parameter language (thermobearing.sweep_params, session 22).

- a range ``start:stop:step`` written in decimals gives the decimal values start + i step,
  i = 0 .. n, in order, stop included: the count is exact, every value is within round-off of
  the decimal one, and the unit written after the range (or the scene's own) is on each;
- a comma list keeps its order, drops a repeated quantity (whatever the unit it is written
  in) and reports it, and the unit after the list is taken by every bare number;
- the text of a swept value carries no float noise (sweep_params._DIGITS: "a double's 15,
  less the float noise of a range's start + i * step"): a range crossing zero writes its
  zero as 0 (it wrote the noise of the cancellation, 5.55e-17, until range values were
  rounded to the range's own scale).
"""

from __future__ import annotations

from decimal import Decimal

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.errors import InputError
from thermobearing.sweep_params import parse_set
from thermobearing.units import to_si

SCENE = {"supply": {"flow": "20 L/min", "inlet_temperature": "40 degC"},
         "environment": {"ambient_temperature": "20 degC"},
         "schedule": {"steps": [{"speed": "3000 rpm", "duration": "10 min"}]}}


@st.composite
def decimal_ranges(draw, non_negative: bool = False):
    """(start, stop, step, n) as Decimals: stop = start + n step exactly."""
    k = draw(st.integers(0, 6))
    lo = 0 if non_negative else -10**6
    a = Decimal(draw(st.integers(lo, 10**6))).scaleb(-k)
    s = Decimal(draw(st.integers(1, 10**4))).scaleb(-k)
    n = draw(st.integers(0, 150))
    return a, a + n * s, s, n


def _numbers(values):
    return [Decimal(v.split()[0]) for v in values]


@settings(max_examples=150, deadline=None)
@given(decimal_ranges(), st.sampled_from(["", " L/min", " L/h", " m**3/s"]))
def test_a_range_gives_its_decimal_values_in_order(rng, unit):
    a, b, s, n = rng
    p = parse_set(f"supply.flow={a}:{b}:{s}{unit}", SCENE)
    assert len(p.values) == n + 1
    assert p.dropped == ()
    assert all(v.endswith(unit or " L/min") for v in p.values)
    got = _numbers(p.values)
    scale = max(abs(a), abs(b), s)
    for i, v in enumerate(got):
        assert abs(v - (a + i * s)) <= Decimal("1e-11") * scale
    assert all(x < y for x, y in zip(got, got[1:], strict=False))


@settings(max_examples=150, deadline=None)
@given(decimal_ranges(non_negative=True))
def test_a_non_negative_range_is_written_without_float_noise(rng):
    a, b, s, n = rng
    p = parse_set(f"supply.flow={a}:{b}:{s}", SCENE)
    assert _numbers(p.values) == [a + i * s for i in range(n + 1)]


@pytest.mark.parametrize(("spec", "zero_at"), [("-0.3:0.3:0.1", 3), ("-2.1:2.1:0.7", 3)])
def test_a_range_crossing_zero_writes_its_zero(spec, zero_at):
    p = parse_set(f"environment.ambient_temperature={spec}", SCENE)
    assert p.values[zero_at] == "0 degC"


@settings(max_examples=100, deadline=None)
@given(st.lists(st.integers(1, 200), min_size=1, max_size=8),
       st.sampled_from(["L/min", "L/h"]))
def test_a_comma_list_keeps_its_order_and_drops_repeats(numbers, unit):
    p = parse_set("supply.flow=" + ",".join(map(str, numbers)) + f" {unit}", SCENE)
    first = list(dict.fromkeys(numbers))
    assert p.values == tuple(f"{x} {unit}" for x in first)
    assert len(p.dropped) == len(numbers) - len(first)


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 600), st.booleans())
def test_one_quantity_in_two_units_is_one_value(litres_per_minute, hours_first):
    """x L/min and 60 x L/h are one flow: the second written is dropped and reported (as
    the same quantity, whatever its spelling)."""
    a, b = f"{litres_per_minute} L/min", f"{60 * litres_per_minute} L/h"
    if hours_first:
        a, b = b, a
    p = parse_set(f"supply.flow={a},{b}", SCENE)
    assert p.values == (a,)
    assert len(p.dropped) == 1 and b in p.dropped[0]


@settings(max_examples=60, deadline=None)
@given(st.floats(-40.0, 150.0), st.sampled_from(["degC", "degF", "K"]))
def test_a_temperature_list_converts_with_its_unit(t_c, unit):
    """Each value of a list carries the unit written after it; to SI it is that
    temperature (offset units are not read as differences)."""
    t_k = t_c + 273.15
    written = {"degC": t_c, "degF": t_c * 1.8 + 32.0, "K": t_k}[unit]
    p = parse_set(f"supply.inlet_temperature={written!r} {unit}", SCENE)
    assert to_si(p.values[0], "temperature") == pytest.approx(t_k, rel=1e-11)


@pytest.mark.parametrize("spec", ["supply.flow=3:1:1", "supply.flow=1:3:0", "supply.flow=1:3:-1",
                                  "supply.flow=1:3", "supply.flow=1,,3", "supply.flow=",
                                  "supply.flow"])
def test_bad_ranges_and_lists_name_the_option(spec):
    with pytest.raises(InputError, match="--set"):
        parse_set(spec, SCENE)


# --------------------------------------------------------------------------- expansion
@pytest.fixture(scope="module")
def rig_scene():
    from thermobearing.scene import load_scene

    return load_scene("qj1044_rig")


@settings(max_examples=8, deadline=None)
@given(flows=st.lists(st.integers(5, 60), min_size=1, max_size=4, unique=True),
       temps=st.lists(st.integers(20, 60), min_size=1, max_size=3, unique=True))
def test_expansion_is_the_cartesian_product_in_order(rig_scene, flows, temps):
    """expand gives len(a) x len(b) cases in itertools.product order (the first --set
    outermost), each case's scene carries its values (in SI: L/min -> m^3/s, degC -> K),
    and the case ids do not depend on the order of the --set options."""
    import itertools

    from thermobearing.scene import loads_scene
    from thermobearing.sweep_cases import expand

    d = rig_scene.to_dict()
    pf = parse_set("supply.flow=" + ",".join(map(str, flows)), d)
    pt = parse_set("supply.inlet_temperature=" + ",".join(map(str, temps)), d)
    cases = expand(rig_scene, [pf, pt])
    assert len(cases) == len(flows) * len(temps)
    want = list(itertools.product(pf.values, pt.values))
    assert [tuple(v for _, v in c.assignments) for c in cases] == want
    for case, (flow, temp) in zip(cases, want, strict=True):
        sc = loads_scene(case.scene_toml)
        assert sc.supply.flow == pytest.approx(to_si(flow, "volume_flow"), rel=1e-12)
        assert sc.supply.inlet_temperature == pytest.approx(to_si(temp, "temperature"),
                                                            rel=1e-12)
    swapped = expand(rig_scene, [pt, pf])
    assert sorted(c.case_id for c in swapped) == sorted(c.case_id for c in cases)
