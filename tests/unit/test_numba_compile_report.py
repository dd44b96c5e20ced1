"""scripts/numba_compile_report.py: compile events paired into per-kernel CPU seconds."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numba
import pytest
from numba.core import event

_SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "numba_compile_report.py"


@pytest.fixture(scope="module")
def report():
    spec = importlib.util.spec_from_file_location("numba_compile_report", _SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module          # its dataclass looks the module up
    try:
        spec.loader.exec_module(module)
        yield module
    finally:
        del sys.modules[spec.name]


def test_nested_compilations_are_split_into_self_and_inclusive_time(report):
    @numba.njit(cache=False)
    def inner(x):
        return 2.0 * x

    @numba.njit(cache=False)
    def outer(x):
        return inner(x) + 1.0

    recorder = report._recording_listener()
    with event.install_listener("numba:compile", recorder):
        assert outer(1.5) == 4.0
        assert inner(2) == 4       # a second signature of inner, from Python
    kernels = report.collect(recorder.buffer)
    (k_out,) = [k for n, k in kernels.items() if n.endswith("outer")]
    (k_in,) = [k for n, k in kernels.items() if n.endswith("inner")]
    assert k_out.signatures == ["float64"]
    assert sorted(k_in.signatures) == ["float64", "int64"]
    assert k_out.callers == ["<python>"]
    assert set(k_in.callers) == {k_out.name, "<python>"}
    # outer's span contains inner's float64 compilation: self = inclusive - that child
    assert 0.0 < k_out.self_s < k_out.incl_s
    assert k_in.self_s == pytest.approx(k_in.incl_s)
    assert k_out.wall_s > 0.0


def test_unbalanced_events_are_refused(report):
    @numba.njit(cache=False)
    def lone(x):
        return x

    recorder = report._recording_listener()
    with event.install_listener("numba:compile", recorder):
        lone(1.0)
    with pytest.raises(RuntimeError, match="did not end"):
        report.collect(recorder.buffer[:1])
