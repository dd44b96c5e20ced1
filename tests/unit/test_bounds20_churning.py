"""Churning options beyond physical sense (session 20 fuzzer): the inner-ring source's
``raceway_arc_length`` and ``shoulder_length`` are bounded by the ring width (5e300 mm
gave 'total loss per bearing: inf W' with no error), the ``gap`` options have a 1 um floor,
refused when the scene is built (and by the source itself), naming the option (1e-300 mm was refused
only as 'power_by_role[oil] = inf', which named no option; 1e-30 mm ended in a transient as
a stepper non-convergence), and a churning power that overflows is refused naming the
options given."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest
from probe_scene import probe_scene

from thermobearing.errors import InputError
from thermobearing.heat_sources import churning
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation


def _run(source: str, options: str, mode: str = "steady"):
    models = (f'kinematics = "race_control"\nheat_sources = ["{source}"]\n'
              f'heat_source_options = {{ {source} = {{ {options} }} }}')
    return Simulation(loads_scene(probe_scene(title="bounds 20 churning probe",
                                              models=models, mode=mode)),
                      progress=False).run()


def _total(res) -> float:
    return float(res.tables["losses"]["power [W]"].sum())


@pytest.mark.parametrize("key, value, bound_mm", [
    ("raceway_arc_length", "5e300 mm", 0.5 * math.pi * 15.0),  # SKF6304: w = 15 mm
    ("raceway_arc_length", "24 mm", 0.5 * math.pi * 15.0),
    ("shoulder_length", "5e300 mm", 7.5),
    ("shoulder_length", "7.6 mm", 7.5),
])
def test_inner_ring_lengths_beyond_the_ring_width_are_refused(key, value, bound_mm) -> None:
    with pytest.raises(InputError) as info:
        _run("churning_inner_ring", f'{key} = "{value}"')
    assert info.value.field == f"options[churning_inner_ring].{key}"
    assert f"[0, {bound_mm:.6g} mm]" in str(info.value)
    assert "w = 15 mm" in str(info.value)


def test_inner_ring_lengths_within_the_width_run_and_scale_the_power() -> None:
    """At the bounds the source runs; eq. 17 is linear in B_arc + 2 B_Li, so the power at
    B_arc = pi w / 2, B_Li = w / 2 over that at B_arc = B_Li = 1 mm is their ratio."""
    top = _run("churning_inner_ring",
               f'raceway_arc_length = "{0.5 * math.pi * 15.0} mm", shoulder_length = "7.5 mm"')
    one = _run("churning_inner_ring", 'raceway_arc_length = "1 mm", shoulder_length = "1 mm"')
    q_top, q_one = _total(top), _total(one)
    assert math.isfinite(q_top) and q_top > 0.0
    # the temperatures differ (more heat), so the viscosity does: a loose band
    assert 0.3 * (0.5 * math.pi * 15.0 + 15.0) / 3.0 < q_top / q_one \
        < 1.5 * (0.5 * math.pi * 15.0 + 15.0) / 3.0


@pytest.mark.parametrize("source", ["churning_cage", "churning_inner_ring",
                                    "churning_elements"])
@pytest.mark.parametrize("value, mode", [("1e-300 mm", "steady"), ("1e-30 mm", "transient"),
                                         ("0.5 um", "steady")])
def test_gaps_below_one_micrometre_are_refused_naming_the_option(source, value, mode) -> None:
    # refused when the scene is built (the source's declared interval [1e-06, inf)), before
    # any step; the source's own check (roughness reason) stays behind it for the Python API
    with pytest.raises(InputError) as info:
        _run(source, f'gap = "{value}"', mode)
    assert info.value.field == f"models.heat_source_options.{source}.gap"
    assert "[1e-06, inf)" in str(info.value)


def test_the_source_itself_refuses_a_gap_below_one_micrometre() -> None:
    ctx = SimpleNamespace(option=lambda source, key, default: 5e-7)
    with pytest.raises(InputError) as info:
        churning._gap(ctx, "churning_cage", 1e-3)
    assert info.value.field == "options[churning_cage].gap"
    assert "a gap >= 1 um" in str(info.value) and "roughness" in str(info.value)


def test_a_one_micrometre_cage_gap_runs_to_a_finite_loss() -> None:
    q = _total(_run("churning_cage", 'gap = "1 um"'))
    assert math.isfinite(q) and q > 0.0


def test_an_overflowing_power_is_refused_naming_the_options() -> None:
    ctx = SimpleNamespace(options={"churning_cage": {"gap": 1e-6}})
    with pytest.raises(InputError) as info:
        churning._finite_power(ctx, "churning_cage", math.inf)
    assert info.value.field == "options[churning_cage]"
    assert "gap = 1e-06" in str(info.value)
    assert churning._finite_power(ctx, "churning_cage", 12.5) == 12.5
