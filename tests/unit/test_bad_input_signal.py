"""Bad-input audit, issue 8 (cage speed from vibration): a sampling rate too low, a file with
NaN or a constant signal, a band outside Nyquist, no detectable cage line -- each a clear
error or a result flagged as not detected, never a made-up frequency. Through
:func:`thermobearing.signal.estimate_cage_speed` and ``thermobearing cage-speed``.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from thermobearing import cli
from thermobearing import signal as S
from thermobearing.errors import InputError

FS = 25600.0
SHAFT = 30.0  # 1800 r/min
Z = 17  # any comb size; the tests do not need a real bearing
CSR_TH = 0.45


@pytest.fixture(scope="module", autouse=True)
def _warm_imports():
    """Import every sub-command module (~3 s once) outside the timed tests."""
    cli.build_parser()


def noise(seconds=1.0, fs=FS, seed=0):
    return np.random.default_rng(seed).normal(size=int(seconds * fs))


def estimate(x, fs=FS, **kw):
    return S.estimate_cage_speed(x, fs, SHAFT, Z, CSR_TH, **kw)


def test_sampling_rate_too_low_for_the_lines():
    with pytest.raises(InputError) as info:
        estimate(noise(5.0, fs=200.0), fs=200.0)
    assert info.value.field == "sampling_rate" and info.value.value == 200.0
    assert "a rate above" in info.value.allowed and "Hz" in info.value.allowed


def test_nan_samples_named_with_index():
    x = noise()
    x[100] = np.nan
    with pytest.raises(InputError) as info:
        estimate(x)
    assert "first at index 100" in str(info.value.value)
    assert "finite samples" in info.value.allowed


def test_constant_signal():
    with pytest.raises(InputError) as info:
        estimate(np.full(int(FS), 0.3))
    assert info.value.value == "a constant signal"
    assert "varies in time" in info.value.allowed


@pytest.mark.parametrize(("band", "allowed"), [
    ((10000.0, 20000.0), "Nyquist"), ((-100.0, 3000.0), "Nyquist"),
    ((3000.0, 1000.0), "low < high"),
])
def test_band_outside_nyquist_or_reversed(band, allowed):
    # a reversed band was reported as "a band at least ... Hz wide" before
    with pytest.raises(InputError) as info:
        estimate(noise(), band=band)
    assert info.value.field == "band" and info.value.value == band
    assert allowed in info.value.allowed


def test_no_cage_line_is_flagged_not_detected_without_a_frequency():
    est = estimate(noise(2.0))
    assert not est.detected
    assert est.cage_frequency is None and est.csr is None and est.slip is None
    assert est.reason


def test_bad_bearing_numbers():
    with pytest.raises(InputError) as info:
        S.estimate_cage_speed(noise(), FS, -30.0, Z, CSR_TH)
    assert info.value.field == "shaft_frequency"
    with pytest.raises(InputError) as info:
        S.estimate_cage_speed(noise(), FS, SHAFT, 2.5, CSR_TH)
    assert info.value.field == "n_balls"


# --- through the command line ---------------------------------------------------------
def write_csv(path, t, x):
    np.savetxt(path, np.c_[t, x], delimiter=",", header="time [s],accel [m/s2]", comments="")
    return path


def cage_speed(capsys, *argv):
    code = cli.main(["cage-speed", *map(str, argv), "--rpm", "1800", "--bearing", "QJ1044",
                     "--no-plot"])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_cli_no_cage_line_exits_3_and_prints_no_frequency(tmp_path, capsys):
    t = np.arange(int(FS)) / FS
    path = write_csv(tmp_path / "noise.csv", t, noise())
    code, out, err = cage_speed(capsys, path, "--json")
    assert code == 3 and "Traceback" not in err
    record = json.loads(out)
    assert record["detected"] is False and record["csr"] is None
    assert record["cage_frequency_hz"] is None and record["slip"] is None and record["reason"]


def test_cli_nan_file_exits_1_one_line(tmp_path, capsys):
    t = np.arange(int(FS)) / FS
    x = noise()
    x[7] = np.nan
    code, _, err = cage_speed(capsys, write_csv(tmp_path / "nan.csv", t, x))
    assert code == 1 and "Traceback" not in err
    assert "nan.csv" in err and "first at index 7" in err and "finite samples" in err


def test_cli_time_column_going_backwards_is_explained(tmp_path, capsys):
    # before: "sampling_rate = None ... (the file carries no time column)" although it has one
    t = np.arange(int(FS)) / FS
    t[500:] -= 0.01
    code, _, err = cage_speed(capsys, write_csv(tmp_path / "back.csv", t, noise()))
    assert code == 1 and "Traceback" not in err
    assert "does not increase at data row 501" in err


def test_cli_sampling_rate_not_a_rate(tmp_path, capsys):
    np.save(tmp_path / "x.npy", noise())
    code, _, err = cage_speed(capsys, tmp_path / "x.npy", "--fs", "fast")
    assert code == 1 and "--fs" in err and "'fast'" in err and "Hz" in err
    code, _, err = cage_speed(capsys, tmp_path / "x.npy")
    assert code == 1 and "--fs is missing" in err and "no time column" in err


def test_cli_missing_file(tmp_path, capsys):
    code, _, err = cage_speed(capsys, tmp_path / "nope.csv")
    assert code == 1 and "nope.csv" in err and "an existing .npy, .npz or .csv file" in err


# --- the vibration model of issue 8 (paper 004) --------------------------------------------
@pytest.fixture(scope="module")
def p004():
    from thermobearing.traction import make_traction_law
    from thermobearing.vibration import paper004_parameters

    return paper004_parameters(), make_traction_law("linear_saturating", mu_max=0.01,
                                                    slip_speed_max=0.1)


W_2000 = 2000 * np.pi / 30  # 2000 r/min


@pytest.mark.parametrize(("kwargs", "field"), [
    ({"cage_slip": 1.5}, "cage_slip"), ({"cage_slip": np.nan}, "cage_slip"),
    ({"duration": 0.0}, "duration"), ({"settle_time": -1.0}, "settle_time"),
    ({"sampling_rate": 0.0}, "sampling_rate"), ({"max_step": 0.0}, "max_step"),
    ({"cage_speed": -5.0}, "cage_speed"), ({"method": "euler"}, "method"),
])
def test_vibration_model_bad_settings(p004, kwargs, field):
    from thermobearing.vibration import simulate

    params, law = p004
    with pytest.raises(InputError) as info:
        simulate(params, W_2000, 2000.0, traction=law, **{"duration": 0.01, **kwargs})
    assert info.value.field == field


def test_vibration_sampling_rate_too_low_for_the_record(p004):
    from thermobearing.vibration import simulate

    params, law = p004
    with pytest.raises(InputError) as info:
        simulate(params, W_2000, 2000.0, traction=law, duration=0.01, settle_time=0.0,
                 sampling_rate=100.0)
    assert info.value.field == "duration" and "at least 4 samples at 100 Hz" in info.value.allowed


def test_vibration_step_above_stability_diverges_with_an_error_not_nan(p004):
    from thermobearing.errors import ConvergenceError
    from thermobearing.vibration import simulate

    params, law = p004
    with pytest.raises(ConvergenceError) as info:
        simulate(params, W_2000, 2000.0, traction=law, duration=0.01, settle_time=0.0,
                 method="rk4", max_step=1e-3)
    assert "diverged" in str(info.value) and "stability" in info.value.state


def test_vibration_parameter_overrides_unknown_or_fixed_by_geometry():
    # before: TypeError "got an unexpected keyword argument" / "multiple values for n_balls"
    from thermobearing.errors import UnknownNameError
    from thermobearing.vibration import paper004_parameters

    with pytest.raises(UnknownNameError) as info:
        paper004_parameters(colour=2)
    assert info.value.field == "vibration.colour" and "support_damping" in info.value.known
    with pytest.raises(InputError) as info:
        paper004_parameters(n_balls=2)
    assert info.value.field == "vibration.n_balls" and "bearing geometry" in info.value.allowed


@pytest.mark.parametrize(("kwargs", "field"), [
    ({"alpha": 0.0}, "alpha"),                  # before: ZeroDivisionError
    ({"alpha": 2.0}, "alpha"),                  # before: accepted
    ({"padding": 0}, "padding"),                # before: ValueError from numpy's FFT
    ({"search": (0.3,)}, "search"),             # before: IndexError
    ({"cage_harmonics": 2.5}, "cage_harmonics"),  # before: TypeError
    ({"cage_harmonics": 0}, "cage_harmonics"),  # before: "not detected" with no cage line
    ({"n_bands": 0}, "n_bands"),
    ({"shaft_sidebands": -1}, "shaft_sidebands"),
])
def test_analyser_settings_out_of_range(kwargs, field):
    with pytest.raises(InputError) as info:
        estimate(noise(), **kwargs)
    assert info.value.field == field and info.value.value == next(iter(kwargs.values()))


@pytest.mark.parametrize(("call", "field"), [
    (lambda x: S.envelope_spectrum(x, FS, (1000.0, 3000.0), padding=0), "padding"),
    (lambda x: S.spectral_peak(x, FS, 1000.0, 3000.0, padding=0), "padding"),
    (lambda x: S.kurtogram_bands(x, FS, n_bands=0), "n_bands"),       # before: accepted
    (lambda x: S.kurtogram_band(x, FS, min_frequency=-5.0), "min_frequency"),
    (lambda x: S.envelope_spectrum(x, FS, (np.nan, 3000.0)), "band"),
])
def test_spectrum_helpers_settings_out_of_range(call, field):
    # padding 0 was a ValueError from numpy's FFT
    with pytest.raises(InputError) as info:
        call(noise())
    assert info.value.field == field
