"""Repeated validity warnings merged into one line (thermobearing.warning_groups)."""

from __future__ import annotations

from thermobearing.warning_groups import WarningGroups

MSG = ("hamrock_dowson_1977_central: U in [{u0}, {u1}] outside [1e-12, 1e-10]; "
       "W in [{w0}, {w1}] outside [3.69e-07, 7.37e-06]")


def test_repeats_become_one_line_with_the_envelope_steps_and_count():
    lines = ["a note before"]
    g = WarningGroups(lines)
    g.add(MSG.format(u0="5.5e-10", u1="5.5e-10", w0="1.2e-05", w1="1.9e-05"), "front", 0)
    g.add(MSG.format(u0="4.3e-10", u1="9e-10", w0="8e-06", w1="2.5e-05"), "front", 3)
    g.add(MSG.format(u0="1e-09", u1="1.4e-09", w0="1e-05", w1="1e-05"), "front", 1)
    assert len(lines) == 2 and lines[0] == "a note before"
    assert lines[1] == ("front, steps 0-3: hamrock_dowson_1977_central: "
                        "U in [4.3e-10, 1.4e-09] outside [1e-12, 1e-10]; "
                        "W in [8e-06, 2.5e-05] outside [3.69e-07, 7.37e-06] "
                        "[raised 3 times at 3 steps; intervals are the envelope of all]")


def test_different_shapes_and_bearings_stay_apart_and_a_single_warning_is_unchanged():
    lines: list[str] = []
    g = WarningGroups(lines)
    g.add("pan_hamrock_central: U in [1e-09, 2e-09] outside [1e-12, 1e-09]", "de", 2)
    g.add("pan_hamrock_central: U in [1e-09, 2e-09] outside [1e-12, 1e-09]", "nde", 2)
    g.add("hamrock_dowson_1977_central: G in [9000, 9000] outside [1000, 8000]", "de", 2)
    g.add("cage guide: Reynolds number 2.3e4 beyond laminar", "de")
    assert lines == [
        "de, step 2: pan_hamrock_central: U in [1e-09, 2e-09] outside [1e-12, 1e-09]",
        "nde, step 2: pan_hamrock_central: U in [1e-09, 2e-09] outside [1e-12, 1e-09]",
        "de, step 2: hamrock_dowson_1977_central: G in [9000, 9000] outside [1000, 8000]",
        "de: cage guide: Reynolds number 2.3e4 beyond laminar"]
    g.add("cage guide: Reynolds number 4.1e4 beyond laminar", "de")
    assert lines[3] == "de: cage guide: Reynolds number 2.3e4 beyond laminar [raised 2 times]"


def test_a_models_range_warnings_are_one_line_whichever_variables_left_the_range():
    # the default rig listed three film-formula lines per bearing: U and W, W alone, U alone
    lines: list[str] = []
    g = WarningGroups(lines)
    g.add(MSG.format(u0="1.1e-10", u1="1.8e-10", w0="8.8e-10", w1="5.8e-05"), "de", 0)
    g.add("hamrock_dowson_1977_central: W in [3.4e-08, 6.7e-06] outside [3.69e-07, 7.37e-06]",
          "de", 1)
    g.add("hamrock_dowson_1977_central: U in [9.8e-11, 1.35e-10] outside [1e-12, 1e-10]",
          "de", 2)
    g.add("hamrock_dowson_1977_central: G in [9000, 9000] outside [1000, 8000]", "de", 4)
    assert lines == ["de, steps 0-4: hamrock_dowson_1977_central: "
                     "U in [9.8e-11, 1.8e-10] outside [1e-12, 1e-10]; "
                     "W in [8.8e-10, 5.8e-05] outside [3.69e-07, 7.37e-06]; "
                     "G in [9000, 9000] outside [1000, 8000] "
                     "[raised 4 times at 4 steps; intervals are the envelope of all]"]
    # another model, or a message that only looks like one, keeps its own line
    g.add("pan_hamrock_central: U in [1e-09, 2e-09] outside [1e-12, 1e-09]", "de", 2)
    g.add("hamrock_dowson_1977_central: U in [1e-09, 2e-09] beyond the fit", "de", 2)
    assert len(lines) == 3


def test_the_cap_limits_new_lines_only():
    lines: list[str] = []
    g = WarningGroups(lines, cap=2)
    for text in ("one", "two", "three"):
        g.add(f"model {text}", "b")
    g.add("model one", "b", 5)
    assert lines == ["b, step 5: model one [raised 2 times]", "b: model two"]
