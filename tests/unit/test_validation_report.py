"""The Markdown validation report (``thermobearing validate --report FILE``)."""

from __future__ import annotations

import math

from thermobearing.validation import Record
from thermobearing.validation.report import markdown_report


def _records():
    return [
        Record("case_a", "film", "um", 0.514, 0.52, 0.0117, "±20 %", True, True),
        Record("case_a", "trend", "-", 1.0, -1.0, -2.0, "[0.5, 1.5]", False, True,
               note="sign reversed, see SOURCE.md"),
        Record("case_b", "extra", "W", 10.0, math.nan, math.nan, "report", False, False),
    ]


def test_report_lists_failures_first_with_links_and_every_row(tmp_path):
    cases = tmp_path / "cases"
    (cases / "case_a").mkdir(parents=True)
    (cases / "case_a" / "SOURCE.md").write_text(
        "# case_a\n\n**Source.** Paper X, eq. 3.\nSecond line.\n\n## Why\nbecause of Y\n",
        encoding="utf-8")
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    text = markdown_report(_records(), folder=cases, link_base=out_dir, version="9.9",
                           command="thermobearing validate")
    assert "3 rows: 1 of 2 gated rows pass, 1 fail; 1 `report` rows" in text
    fail_section = text.split("## Rows that miss the asked accuracy")[1].split("## Cases")[0]
    assert "trend" in fail_section and "film" not in fail_section
    assert "[case_a](../cases/case_a/SOURCE.md)" in text
    assert "**Source.** Paper X, eq. 3. Second line." in text  # first paragraph only
    assert "because of Y" not in text
    assert "| film | um | 0.514 | 0.52 | +1.17 % | ±20 % | PASS |" in text
    assert "| trend | - | 1 | -1 | -200.00 % | [0.5, 1.5] | **FAIL** |" in text
    assert "| extra | W | 10 | - | - | report | report |" in text
    assert "Note: sign reversed, see SOURCE.md" in text
    assert "thermobearing 9.9" in text


def test_report_without_failures_has_no_failure_section(tmp_path):
    recs = [r for r in _records() if r.passed or not r.gated]
    text = markdown_report(recs, folder=tmp_path)
    assert "Rows that miss" not in text
    assert "1 of 1 gated rows pass, 0 fail" in text


def test_validate_command_writes_the_report(tmp_path, capsys):
    from thermobearing.cli import main

    out = tmp_path / "REPORT.md"
    code = main(["validate", "paper002_cage_frequency_arithmetic", "--quiet",
                 "--report", str(out)])
    assert code == 0
    text = out.read_text(encoding="utf-8")
    assert "### paper002_cage_frequency_arithmetic" in text
    assert "`thermobearing validate paper002_cage_frequency_arithmetic`" in text
    assert "| PASS |" in text and "**FAIL**" not in text


def test_ensemble_rows_print_their_standard_error_on_one_line(tmp_path):
    """A row ``q`` with a companion ``q_stderr`` of the same case reads ``value ± se``.

    The companion is not listed again; a ``_stderr`` row without its base row (or of another
    case) stays an ordinary row; the verdict is the value's.
    """
    recs = [
        Record("c", "slip_ratio", "-", 1.1, 1.0771, -0.0208, "[1, 1e+09] -", True, True),
        Record("c", "slip_ratio_stderr", "-", math.nan, 0.0231, math.nan, "report", False,
               False),
        Record("c", "pv_ratio", "-", 1.1, 0.9941, -0.0963, "[1, 1e+09] -", False, True),
        Record("c", "pv_ratio_stderr", "-", math.nan, 0.0042, math.nan, "report", False,
               False),
        Record("d", "slip_ratio_stderr", "-", math.nan, 0.5, math.nan, "report", False, False),
        Record("e", "minimum", "mm", 550.0, 800.0, 250.0, "±100 mm", False, True),
        Record("e", "minimum_stderr", "mm", math.nan, math.nan, math.nan, "report", False,
               False),
    ]
    text = markdown_report(recs, folder=tmp_path)
    assert "| slip_ratio | - | 1.1 | 1.0771 ± 0.0231 | -2.08 % | [1, 1e+09] - | PASS |" in text
    assert "| pv_ratio | - | 1.1 | 0.9941 ± 0.0042 | -9.63 % | [1, 1e+09] - | **FAIL** |" in text
    fail_section = text.split("## Rows that miss the asked accuracy")[1].split("## Cases")[0]
    assert "| pv_ratio | 1.1 | 0.9941 ± 0.0042 |" in fail_section
    assert "| slip_ratio_stderr |" not in text.split("### d")[0]
    assert "| slip_ratio_stderr | - | - | 0.5 | - | report | report |" in text  # case d
    assert "| minimum | mm | 550 | 800 | +250 | ±100 mm | **FAIL** |" in text  # no SE: plain
    assert "4 rows: 1 of 3 gated rows pass, 2 fail" in text
    assert "2 rows estimated from ensembles of trajectories carry their standard error" in text
