import math

import pytest

from thermobearing.errors import InputError
from thermobearing.units import format_quantity, from_si, to_si


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("1800 rpm", "rad/s", 1800 * 2 * math.pi / 60),
        ("33 L/min", "m**3/s", 33e-3 / 60),
        ("35 degC", "K", 308.15),
        ("2 kN", "N", 2000.0),
        ("0.08 Pa*s", "Pa*s", 0.08),
        ("46 cSt", "kinematic_viscosity", 46e-6),
        ("40 deg", "angle", math.radians(40)),
        ("220 mm", "length", 0.22),
        ("10 degC", "temperature_difference", 10.0),
        (12.5, "length", 12.5),
        ("1e-3 m", "length", 1e-3),
    ],
)
def test_to_si(text, unit, expected):
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("bad", ["1800 kg", "fast", "12 furlongs_per_blink", True, [1], None])
def test_to_si_rejects(bad):
    with pytest.raises(InputError) as info:
        to_si(bad, "rad/s", field="schedule.speed")
    assert "schedule.speed" in str(info.value)


def test_round_trip_and_format():
    assert from_si(308.15, "degC") == pytest.approx(35.0)
    assert from_si(to_si("1500 rpm", "rad/s"), "rpm") == pytest.approx(1500.0)
    assert to_si(format_quantity(0.00055, "L/min"), "m**3/s") == pytest.approx(0.00055)


def test_registry_falls_back_to_parsing_when_the_definitions_cache_fails(monkeypatch):
    """pint's on-disk definitions cache is an optimisation only: when it cannot be used
    (read-only home, a half-written file) the registry is built by parsing, same units."""
    import pint

    from thermobearing import units

    real = pint.UnitRegistry
    calls = []

    def flaky(*args, **kwargs):
        calls.append(kwargs.get("cache_folder"))
        if kwargs.get("cache_folder") is not None:
            raise EOFError("truncated cache file")
        return real(*args, **kwargs)

    monkeypatch.setattr(pint, "UnitRegistry", flaky)
    ureg = units.unit_registry.__wrapped__()
    assert calls == [":auto:", None]
    assert ureg.Quantity(1800, "rpm_rev").to("rad/s").magnitude == pytest.approx(60 * math.pi)
