"""Shared pytest configuration."""

from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")
os.environ.setdefault("MPLBACKEND", "Agg")

from hypothesis import settings  # noqa: E402

# Property tests draw the same examples on every run by default (profile "ci"), so that a
# clean-clone test run is reproducible; HYPOTHESIS_PROFILE=explore draws fresh random
# examples (and keeps hypothesis' example database) to look for new failures.
settings.register_profile("ci", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
