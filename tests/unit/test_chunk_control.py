"""Coupling-chunk control: a chunk in which the contact viscosity leaves the held kinematic
state's by more than ``[solver] chunk_viscosity_limit`` is repeated at half the length
(:func:`thermobearing.coupled._run_transient`)."""

from __future__ import annotations

import warnings

import pytest

from tests.unit.test_contact_temperature import NU214_RUN_UP
from thermobearing.errors import ConvergenceError, InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

START_AT_SPEED = '{ duration = "1 min", speed = "10000 rpm" }'


def _run(chunk: str, extra: str = ""):
    text = NU214_RUN_UP.format(steps=START_AT_SPEED, chunk=chunk).replace(
        f'chunk = "{chunk}"\n', f'chunk = "{chunk}"\n{extra}')
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Simulation(loads_scene(text), progress=False).run()


def test_cold_start_at_speed_runs_on_default_chunks_and_meets_short_chunks():
    """NU 214 from 22 degC straight to 10000 r/min (8 kN, 2 L/min jet): the rollers heat by
    tens of kelvin per second. On 90-s chunks without the control the first chunk ran on the
    cold kinematic state and the rollers passed 300 degC (701 degC at 90 s, a runaway);
    with it the chunks are halved where the viscosity moves more than 25 % and the run
    ends within 5 K of 0.5-s chunks (measured: 155.0 against 151.6 degC after 60 s)."""
    res = _run("90 s")
    fine = _run("0.5 s")
    assert res.stats["rejected_chunks"] > 0
    a = res.tables["temperatures"]
    b = fine.tables["temperatures"]
    assert a["time [s]"].iloc[-1] == pytest.approx(60.0)
    for col in ("de.rollers [degC]", "de.shaft [degC]", "de.housing [degC]", "de.oil [degC]"):
        assert abs(a[col].iloc[-1] - b[col].iloc[-1]) < 5.0, col


#: the isothermal rolling force (eq. 35 without inlet heating)
ISOTHERMAL_ROLLING = ('\n[models.heat_source_options.ehl_rolling_resistance]\n'
                      'thermal_reduction = "none"\n')


def test_without_the_control_the_cold_start_runs_away():
    """The same start with the limit lifted (1e9): the 90-s chunk holds the cold state. With
    the isothermal rolling force the rollers run away (701 degC at 90 s); with the default
    Gupta inlet-heating reduction (since 2026-11-24) the cold chunk's rolling heat is lower
    and they reach 240.8 degC at 90 s (measured), below the 300 degC runaway limit: the
    runaway is shown on the isothermal force."""
    with pytest.raises(ConvergenceError, match="thermal runaway"):
        _run("90 s", "chunk_viscosity_limit = 1e9\n" + ISOTHERMAL_ROLLING)


@pytest.mark.parametrize("value", ["0", "-0.1", '"abc"', "true"])
def test_bad_limit_names_the_field(value):
    text = NU214_RUN_UP.format(steps=START_AT_SPEED, chunk="90 s").replace(
        'chunk = "90 s"\n', f'chunk = "90 s"\nchunk_viscosity_limit = {value}\n')
    with pytest.raises(InputError, match=r"solver\.chunk_viscosity_limit"):
        loads_scene(text)
