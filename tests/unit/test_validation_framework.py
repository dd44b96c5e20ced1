"""The validation driver: parallel runs equal serial ones, progress lines, bad input."""

from __future__ import annotations

import pytest

from thermobearing import validation
from thermobearing.errors import InputError, UnknownNameError

FAST = ["paper004_bpfo", "paper002_csr_theoretical", "paper000_cage_speed_theoretical"]


def test_progress_line_per_case_in_order() -> None:
    lines: list[str] = []
    records = validation.run_cases(FAST, progress=lines.append)
    assert [ln.split("]")[0] + "]" for ln in lines] == [f"[{c}]" for c in FAST]
    assert all(" ok (" in ln for ln in lines)
    assert [r.case for r in records][0] == FAST[0] and records[-1].case == FAST[-1]


@pytest.mark.slow  # two spawned workers import the package (~15-30 s on 2 cores)
def test_parallel_equals_serial_in_the_given_order() -> None:
    serial = validation.run_cases(FAST)
    parallel = validation.run_cases(FAST, jobs=2)
    assert [r.case for r in serial] == [r.case for r in parallel]
    assert [(r.quantity, r.computed, r.passed) for r in serial] == \
        [(r.quantity, r.computed, r.passed) for r in parallel]


def test_bad_jobs_and_unknown_case() -> None:
    with pytest.raises(InputError, match="jobs"):
        validation.run_cases(FAST[:1], jobs=0)
    with pytest.raises(UnknownNameError, match="no_such_case"):
        validation.run_cases(["paper004_bpfo", "no_such_case"])


def _copy_case(src: str, dst, slow: bool) -> None:
    import shutil

    shutil.copytree(validation.cases_dir() / src, dst)
    if slow:
        toml = dst / "case.toml"
        toml.write_text("slow = true\n" + toml.read_text(encoding="utf-8"), encoding="utf-8")


def test_slow_cases_run_only_on_request(tmp_path) -> None:
    _copy_case("paper004_bpfo", tmp_path / "fast_case", slow=False)
    _copy_case("paper002_csr_theoretical", tmp_path / "slow_case", slow=True)
    lines: list[str] = []
    records = validation.run_cases(None, tmp_path, progress=lines.append)
    assert {r.case for r in records} == {"fast_case"}
    assert any(ln.startswith("[slow_case] skipped: slow case") for ln in lines)
    both = validation.run_cases(None, tmp_path, include_slow=True)
    assert {r.case for r in both} == {"fast_case", "slow_case"}
    named = validation.run_cases(["slow_case"], tmp_path)
    assert {r.case for r in named} == {"slow_case"} and all(r.passed for r in named)
    (tmp_path / "fast_case" / "case.toml").write_text(
        'slow = "yes"\n' + (tmp_path / "fast_case" / "case.toml").read_text())
    with pytest.raises(InputError, match="slow"):
        validation.run_cases(None, tmp_path)


def test_numerical_drag_runner_books_both_drags(monkeypatch) -> None:
    """The paper 000 numerical-drag runner (minutes; not run here): with a stand-in solver
    it returns every quantity of its reference.csv, the errors against Tables 2-3 and the
    gated difference of the mean absolute errors."""
    import math
    from types import SimpleNamespace

    import thermobearing.skidding.roller as roller
    from thermobearing.validation import runners_paper000_drag as mod

    speeds = {"closed_form": 1.10, "numerical_ehl": 1.04}  # x paper's value

    def fake_solve(bearing, lub, speed, load, axial, temperature, *, viscosity, drag_model,
                   **options):
        assert ("film_pressure" in options) == (drag_model == "closed_form")
        tag = mod.CONDITIONS[(load, viscosity)]
        rpm = mod.PAPER_MEAN_CAGE_SPEED_RPM[tag] * speeds[drag_model]
        return SimpleNamespace(cage_speed=rpm * 2 * math.pi / 60)

    monkeypatch.setattr(roller, "solve_roller", fake_solve)
    case = validation.cases_dir() / "paper000_numerical_drag"
    import tomllib

    spec = tomllib.loads((case / "case.toml").read_text())
    out = mod.paper000_numerical_drag(dict(spec["inputs"]), case)
    wanted = {c.quantity for c in validation.read_checks(case)}
    assert wanted <= set(out)
    assert out["mean_abs_error_closed_form"] == pytest.approx(0.10)
    assert out["mean_abs_error_numerical_ehl"] == pytest.approx(0.04)
    assert out["mean_abs_error_numerical_minus_closed_form"] == pytest.approx(-0.06)
    assert out["cage_speed_change_Fr100_to_Fr200_numerical_ehl"] == pytest.approx(
        (1195.46 - 1292.78) * 1.04 * 2 * math.pi / 60)


def test_numerical_drag_case_runs_the_paper000_case_model() -> None:
    """"At least as close as before" compares against the model of case
    paper000_nu214_cage_speed: both cases must pass the solver the same options."""
    import tomllib

    def inputs(case: str) -> dict:
        text = (validation.cases_dir() / case / "case.toml").read_text(encoding="utf-8")
        return tomllib.loads(text)["inputs"]

    a, b = inputs("paper000_nu214_cage_speed"), inputs("paper000_numerical_drag")
    assert a["model"] == b["model"]
    for key in ("bearing", "lubricant", "inner_speed", "temperature", "paper_eq9_alpha"):
        assert a[key] == b[key], key


def test_paper000_variants_case_is_the_case_model_plus_variants() -> None:
    """The variants case runs the paper000 case model (same inputs) and only adds variants;
    every one of its reference rows is a report row of a named variant."""
    import csv
    import tomllib

    def inputs(case: str) -> dict:
        text = (validation.cases_dir() / case / "case.toml").read_text(encoding="utf-8")
        return tomllib.loads(text)

    a, b = inputs("paper000_nu214_cage_speed"), inputs("paper000_whirl_variants")
    assert b["slow"] is True and a["runner"] == b["runner"]
    variants = b["inputs"].pop("variants")
    assert a["inputs"] == b["inputs"] and set(variants) == {"in_phase", "oil_layer_10um"}
    with open(validation.cases_dir() / "paper000_whirl_variants" / "reference.csv") as f:
        rows = list(csv.DictReader(f))
    assert rows and all(r["gate"] == "report" for r in rows)
    assert all(r["quantity"].endswith(tuple(f"_{v}" for v in variants)) for r in rows)


@pytest.mark.parametrize("variant, field", [({"model": {}, "speed": 1}, "variants.bad"),
                                            ({"whirl": {"not_a_field": 1}}, "variants.bad.whirl")])
def test_paper000_runner_refuses_a_bad_variant_before_solving(variant, field) -> None:
    from thermobearing.errors import InputError
    from thermobearing.validation.runners_roller_skidding import paper000_nu214_cage_speed

    inputs = {"inner_speed": "5000 rpm", "temperature": "40 degC", "whirl_radius": "6e-5 m",
              "variants": {"bad": variant}}
    with pytest.raises(InputError, match=field.replace(".", r"\.")):
        paper000_nu214_cage_speed(inputs, validation.cases_dir())
