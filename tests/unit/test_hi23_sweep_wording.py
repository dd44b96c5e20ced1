"""Session 23 (HI): the sweep's messages count their cases in words ("1 case", "6 cases"),
not "1 case(s)"; one swept quantity reads in one unit throughout a sweep folder; a report
table groups the thousands of every number by one rule."""

from __future__ import annotations

from pathlib import Path

from thermobearing.commands.sweep import interrupt_message
from thermobearing.sweep_store import counted, kept_text


def test_counted_agrees_with_the_number():
    assert counted(1, "case") == "1 case"
    assert counted(0, "case") == "0 cases"
    assert counted(6, "planned case") == "6 planned cases"


def test_kept_text_agrees_verb_and_noun():
    # before: "1 finished case(s) of 6 planned are kept"
    assert kept_text(1, 6) == "1 finished case of 6 planned is kept"
    assert kept_text(2) == "2 finished cases are kept"


def test_interrupt_message_reads_singular_and_plural(tmp_path: Path):
    assert interrupt_message(tmp_path, 1, 6).startswith(
        "interrupted: 1 finished case of 6 planned is kept in")
    assert interrupt_message(tmp_path, 3, 6).startswith(
        "interrupted: 3 finished cases of 6 planned are kept in")
    one = interrupt_message(tmp_path, 0, 1)
    assert "0 of 1 planned case finished" in one and "case(s)" not in one
