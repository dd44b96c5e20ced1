"""Scene fuzzing (scripts/fuzz_scenes.py), the session-17 draws: oil files with Barus, a
given alpha or a given Roelands z, ``[models] film``, ``[solver] chunk_viscosity_limit``,
``[checks]`` per bearing family, heat-source options inside (and now and then outside) their
documented intervals, the sweep check that lists a swept setting whose cases gave identical
results without a note, and the bounds of films, pressures and cage speed ratios in the
result check. No model is solved."""

from __future__ import annotations

import collections
import tomllib
import warnings

import numpy as np
import pandas as pd
import pytest

from thermobearing.lubricant import load_lubricant
from thermobearing.scene import dumps_toml, loads_scene


def test_new_draws_appear_and_load(fuzz, tmp_path):
    catalogue, lubricants = fuzz.bearing_catalogue(), fuzz.lubricant_names()
    seen: collections.Counter[str] = collections.Counter()
    films = set()
    for i in range(300):
        rng = np.random.default_rng([17, i])
        doc, desc = fuzz.make_scene(rng, catalogue, lubricants, tmp_path / f"case_{i:04d}")
        extras = desc["extras"].split(",")
        if set(extras) & fuzz.EDGE_REFUSED:
            continue  # a boundary step the scene refuses (test_fuzz_generator_session18)
        seen.update(extras)
        seen.update("oil:" + x.lstrip("VG0123456789") for x in extras if x.startswith("VG"))
        if "film" in extras:
            films.add(doc["models"]["film"])
        if "checks" in extras and isinstance(doc["checks"].get("contact_stress_limit"), dict):
            seen["checks_family"] += 1
        scene = loads_scene(dumps_toml(doc), base_dir=tmp_path)
        if "cvl" in extras:
            assert scene.solver.chunk_viscosity_limit == pytest.approx(
                doc["solver"]["chunk_viscosity_limit"])
    for tag in ("film", "cvl", "srcopt", "oil:barus", "oil:alpha", "oil:z", "checks_family"):
        assert seen[tag] > 0, (tag, seen)
    assert films <= set(fuzz.POINT_FILMS) | set(fuzz.LINE_FILMS)
    assert films & set(fuzz.POINT_FILMS) and films & set(fuzz.LINE_FILMS)


def test_oil_files_of_every_pressure_law_load(fuzz, tmp_path):
    laws = set()
    for i in range(60):
        rng = np.random.default_rng([18, i])
        path = tmp_path / f"oil_{i}.toml"
        fuzz._oil_file(rng, path)
        laws.add(tomllib.loads(path.read_text())["pressure_viscosity"]["law"])
        lub = load_lubricant(path)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            eta = [lub.dynamic_viscosity(t, 1e9) for t in (333.15, 373.15, 413.15)]
        assert eta[0] > eta[1] > eta[2] > 0.0
    assert laws == {"barus", "roelands"}


def test_unchanged_sweep_is_listed_unless_noted(fuzz):
    path = "supply.inlet_temperature"
    same = pd.DataFrame({"case": ["a", "b"], path: ["20 degC", "30 degC"],
                         "mean total loss [W]": [12.5, 12.5], "max over-skidding [%]": [1.0, 1.0]})
    assert fuzz._unchanged_by_sweep(same, path, "").startswith("identical")
    noted = f"sweep: {path} is swept but not used by the runs ..."
    assert fuzz._unchanged_by_sweep(same, path, noted) is None
    moved = same.assign(**{"mean total loss [W]": [12.5, 13.0]})
    assert fuzz._unchanged_by_sweep(moved, path, "") is None
    # a threshold (flags only) and steps at rest (no loss to change) are not listed
    assert fuzz._unchanged_by_sweep(same.rename(columns={path: "checks.skid_limit"}),
                                    "checks.skid_limit", "") is None
    rest = same.assign(**{"mean total loss [W]": [0.0, 0.0]})
    assert fuzz._unchanged_by_sweep(rest, path, "") is None


def test_option_draws_stay_in_the_documented_interval(fuzz):
    from thermobearing.heat_sources import HEAT_SOURCES
    from thermobearing.units import to_si

    inside = outside = 0
    for i in range(300):
        models: dict = {}
        assert fuzz._source_option(np.random.default_rng([19, i]), models)
        ((src, opts),) = models["heat_source_options"].items()
        ((key, text),) = opts.items()
        entry = HEAT_SOURCES.entry(src)
        unit = entry.parameters[key]
        value = to_si(text, "" if unit == "-" else unit)
        if entry.limits[key].contains(value):
            inside += 1
        else:
            outside += 1
    assert inside > 250 and outside > 5


class _Results:
    def __init__(self, tables):
        self.tables, self.warnings = tables, []


def test_result_check_flags_negative_films_and_a_cage_faster_than_the_shaft(fuzz):
    good = pd.DataFrame({"speed [rpm]": [1000.0], "cage speed ratio [-]": [0.45],
                         "min film parameter [-]": [2.0], "max contact pressure [MPa]": [900.0],
                         "radial load [kN]": [1.0], "axial load [kN]": [0.0], "bearing": ["a"]})
    assert fuzz.check_results(_Results({"kinematics": good})) == []
    fast = good.assign(**{"cage speed ratio [-]": [1.2]})
    assert any("above 1" in p for p in fuzz.check_results(_Results({"kinematics": fast})))
    film = pd.DataFrame({"speed [rpm]": [1000.0], "central film [um]": [-0.01]})
    assert any("negative" in p for p in fuzz.check_results(_Results({"film": film})))


def test_missing_wanted_tables_need_a_word(fuzz):
    from types import SimpleNamespace

    def scene(mode, *want):
        return SimpleNamespace(outputs=SimpleNamespace(mode=mode, want=want))

    got = _Results({"losses": pd.DataFrame(), "steady_temperatures": pd.DataFrame()})
    assert fuzz.missing_tables(scene("steady", "temperatures", "losses", "report"), got) == []
    (problem,) = fuzz.missing_tables(scene("steady", "energy", "losses"), got)
    assert "energy" in problem
    got.warnings = ["outputs.want 'energy' gives no table in a steady run: ..."]
    assert fuzz.missing_tables(scene("steady", "energy", "losses"), got) == []
    assert fuzz.missing_tables(scene("transient", "temperatures"), got) == [
        "outputs.want holds temperatures: no temperatures table and no word why"]
