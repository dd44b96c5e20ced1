"""Closed-form film thickness formulas against hand-computed values, thermal factors, Lambda."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing import film
from thermobearing.errors import InputError, ValidityWarning

# One point-contact case, computed by hand (calculator) from the formulas as printed in the
# original papers:
#   u = 10 m/s, eta0 = 0.04 Pa s, alpha = 2e-8 1/Pa, w = 1000 N, R_x = 6 mm, R_y = 100 mm,
#   E' = 2.28e11 Pa
#   U = eta0 u / (E' R_x) = 0.4 / 1.368e9            = 2.92398e-10
#   G = alpha E'                                      = 4560
#   W = w / (E' R_x^2) = 1000 / 8.208e6               = 1.21832e-4
#   k = 1.03 (100/6)^0.64 = 1.03 * 6.05317           = 6.23477
POINT = dict(entrainment_speed=10.0, dynamic_viscosity=0.04, pressure_viscosity_coefficient=2e-8,
             load=1000.0, reduced_radius_x=6e-3, reduced_radius_y=0.1, effective_modulus=2.28e11)
# Line case: same U, G; w = 5000 N on l = 10 mm: W' = w / (l E' R_x) = 5000 / 1.368e7 = 3.65497e-4
LINE = dict(entrainment_speed=10.0, dynamic_viscosity=0.04, pressure_viscosity_coefficient=2e-8,
            load=5000.0, length=0.01, reduced_radius_x=6e-3, effective_modulus=2.28e11)


@pytest.fixture(autouse=True)
def _quiet_validity():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        yield


def test_hamrock_dowson_central_by_hand() -> None:
    # Hamrock & Dowson 1977 (Part III): H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^-0.73k)
    # U^0.67 = 4.09452e-7 ; G^0.53 = 86.9464 ; W^-0.067 = 1.82917 ; 1 - 0.61 e^-4.55138 = 0.993563
    # H_c = 2.69 * 4.09452e-7 * 86.9464 * 1.82917 * 0.993563 = 1.74043e-4 -> h_c = 1.0443 um
    h = film.hamrock_dowson_1977_central(**POINT)
    assert h == pytest.approx(1.0443e-6, rel=5e-4)


def test_hamrock_dowson_minimum_by_hand() -> None:
    # H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^-0.68k)
    # U^0.68 = 3.28747e-7 ; G^0.49 = 62.0716 ; W^-0.073 = 1.93081 ; 1 - e^-4.23964 = 0.985587
    # H_min = 3.63 * 3.28747e-7 * 62.0716 * 1.93081 * 0.985587 = 1.40960e-4 -> 0.84576 um
    h = film.hamrock_dowson_1977_minimum(**POINT)
    assert h == pytest.approx(0.84576e-6, rel=5e-4)


def test_ellipticity_argument_equivalent() -> None:
    k = film.hamrock_dowson_ellipticity(6e-3, 0.1)
    assert k == pytest.approx(6.23477, rel=1e-5)
    args = {**POINT, "reduced_radius_y": None, "ellipticity": k}
    assert film.hamrock_dowson_1977_minimum(**args) == pytest.approx(
        film.hamrock_dowson_1977_minimum(**POINT), rel=1e-14)
    with pytest.raises(InputError, match="ellipticity"):
        film.hamrock_dowson_1977_minimum(**{**POINT, "ellipticity": 3.0})


def test_dowson_higginson_by_hand() -> None:
    # H_min = 2.65 U^0.70 G^0.54 W'^-0.13
    # ln U = -21.95291, ln W' = -7.91425, ln G = 8.42508
    # U^0.70 = 2.11925e-7 ; G^0.54 = 94.5891 ; W'^-0.13 = 2.79785
    # H = 2.65 * 2.11925e-7 * 94.5891 * 2.79785 = 1.48626e-4 -> h = 0.89175 um
    assert film.dowson_higginson_minimum(**LINE) == pytest.approx(0.89175e-6, rel=5e-4)


def test_pan_hamrock_by_hand() -> None:
    # Pan & Hamrock 1989: H_min = 1.714 W'^-0.128 U^0.694 G^0.568
    # W'^-0.128 = 2.75392 ; U^0.694 = 2.41761e-7 ; G^0.568 = 119.755
    # H_min = 1.714 * 2.75392 * 2.41761e-7 * 119.755 = 1.36659e-4 -> 0.81996 um
    assert film.pan_hamrock_minimum(**LINE) == pytest.approx(0.81996e-6, rel=5e-4)
    # H_c = 2.922 W'^-0.166 U^0.692 G^0.470
    #     = 2.922 * 3.72016 * 2.52612e-7 * 52.4461 = 1.44015e-4 -> 0.86409 um
    assert film.pan_hamrock_central(**LINE) == pytest.approx(0.86409e-6, rel=5e-4)


def test_moes_asymptotes() -> None:
    # rigid-isoviscous limit (alpha = 0, light load): Moes' H_RI = 3/M dominates, i.e. the
    # central film h_c = 6 U R / W' (Moes 1992): W' = 1e-3/(0.01 * 2.28e11 * 6e-3) = 7.30994e-8,
    # h_c = 6 * 2.92398e-10 * 6e-3 / 7.30994e-8 = 0.144 m (a test of the formula's limit only)
    light = {**LINE, "pressure_viscosity_coefficient": 0.0, "load": 1e-3}
    assert film.moes_line_central(**light) == pytest.approx(0.144, rel=1e-6)
    # elasto-piezoviscous limit at heavy load and high L: H -> H_EP = 1.311 M^-1/8 L^3/4
    heavy = {**LINE, "load": 5e5, "pressure_viscosity_coefficient": 3e-8}
    two_u = 2 * 2.92398e-10
    m = 5e5 / (0.01 * 2.28e11 * 6e-3) / math.sqrt(two_u)
    lam = 3e-8 * 2.28e11 * two_u**0.25
    h_ep = 1.311 * m**-0.125 * lam**0.75 * math.sqrt(two_u) * 6e-3
    assert film.moes_line_central(**heavy) == pytest.approx(h_ep, rel=0.05)


def test_moes_close_to_dowson_toyoda_central_in_ehl_regime() -> None:
    # Dowson & Toyoda's central film 3.06 U^0.69 G^0.56 W'^-0.10 at LINE: 3.06 * 2.63950e-7
    # * 111.949 * 2.20654 R_x = 1.19709 um; Moes's interpolation (1.2424 um) agrees within 5 %
    assert film.moes_line_central(**LINE) == pytest.approx(1.19709e-6, rel=0.05)


def test_zero_speed_gives_zero_film_and_vectorises() -> None:
    h = film.hamrock_dowson_1977_central(**{**POINT, "entrainment_speed": np.array([0.0, 10.0])})
    assert h[0] == 0.0 and h[1] > 0
    h = film.dowson_higginson_minimum(**{**LINE, "load": np.array([1000.0, 2000.0, 4000.0])})
    assert np.all(np.diff(h) < 0)  # film falls (weakly) with load


def test_validity_warning_out_of_range() -> None:
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        film.hamrock_dowson_1977_minimum(**POINT)  # U = 2.9e-10 > 1e-10, W = 1.2e-4 > 7.4e-6
    assert any(issubclass(w.category, ValidityWarning) for w in rec)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        film.hamrock_dowson_1977_minimum(
            entrainment_speed=0.5, dynamic_viscosity=0.02, pressure_viscosity_coefficient=1.6e-8,
            load=20.0, reduced_radius_x=6e-3, ellipticity=4.0, effective_modulus=2.28e11)
    assert not any(issubclass(w.category, ValidityWarning) for w in rec)


def test_thermal_factors_tend_to_one_at_low_speed() -> None:
    speeds = np.array([1e-4, 1e-2, 1.0, 10.0, 50.0])
    args = dict(dynamic_viscosity=0.04, temperature_viscosity_coefficient=0.03,
                thermal_conductivity=0.13)
    ws = film.wilson_sheu_1983(speeds, slide_to_roll=0.0, **args)
    gu = film.gupta_1992(speeds, slide_to_roll=0.0, max_pressure=1e9, effective_modulus=2.28e11,
                         **args)
    assert ws[0] == pytest.approx(1.0, abs=1e-4) and gu[0] == pytest.approx(1.0, abs=1e-3)
    assert np.all(np.diff(ws) < 0) and np.all(np.diff(gu) < 0)
    # by hand at u = 10 m/s: L = 0.03 * 0.04 * 100 / 0.13 = 0.92308; L^0.64 = 0.95005
    # Wilson-Sheu: 1 / (1 + 0.241 * 0.95005) = 0.81370
    assert ws[3] == pytest.approx(0.81370, rel=1e-4)
    # Gupta: (1 - 13.2 * (1e9/2.28e11) * L^0.42) / (1 + 0.213 * L^0.64), L^0.42 = 0.96693
    #      = (1 - 0.057895 * 0.966941) / 1.20236 = (1 - 0.055981) / 1.20236 = 0.78514
    assert gu[3] == pytest.approx(0.78514, rel=1e-4)
    # sliding reduces the film further
    assert film.wilson_sheu_1983(10.0, slide_to_roll=0.5, **args) < ws[3]
    assert film.THERMAL_FILM.get("none")() == 1.0


def test_film_parameter() -> None:
    # Lambda = 0.5 um / sqrt(0.1^2 + 0.2^2) um = 2.23607
    assert film.film_parameter(0.5e-6, 0.1e-6, 0.2e-6) == pytest.approx(2.236068, rel=1e-6)
    with pytest.raises(InputError):
        film.film_parameter(0.5e-6, 0.0, 0.0)
    with pytest.raises(InputError, match="h"):
        film.film_parameter(-1e-6, 0.1e-6, 0.1e-6)


def test_registry_lookup() -> None:
    assert "hamrock_dowson_1977_minimum" in film.FILM
    assert film.FILM.get("dowson_higginson_minimum") is film.dowson_higginson_minimum
    assert set(film.THERMAL_FILM.names()) >= {"gupta_1992", "wilson_sheu_1983", "none"}


def test_bad_input() -> None:
    with pytest.raises(InputError, match="dynamic_viscosity"):
        film.hamrock_dowson_1977_central(**{**POINT, "dynamic_viscosity": 0.0})
    with pytest.raises(InputError, match="load"):
        film.dowson_higginson_minimum(**{**LINE, "load": -5.0})


def test_zero_load_is_inf_not_nan() -> None:
    loads = np.array([0.0, 1000.0])
    for fn, args in ((film.hamrock_dowson_1977_minimum, POINT),
                     (film.hamrock_dowson_1977_central, POINT),
                     (film.dowson_higginson_minimum, LINE), (film.pan_hamrock_minimum, LINE),
                     (film.pan_hamrock_central, LINE), (film.moes_line_central, LINE)):
        h = fn(**{**args, "load": loads})
        assert np.isinf(h[0]) and np.isfinite(h[1]) and h[1] > 0
