"""Fixtures shared by the unit tests: the paper 000 NU214 bearing and its oil."""

from __future__ import annotations

import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant


@pytest.fixture(scope="session")
def nu214():
    """NU214 preset (paper 000 Table 1)."""
    return load_bearing("NU214")


@pytest.fixture(scope="session")
def oil():
    """PAPER000_OIL preset (paper 000 Table 1)."""
    return load_lubricant("PAPER000_OIL")
