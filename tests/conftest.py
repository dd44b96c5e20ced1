"""Shared pytest configuration."""

from __future__ import annotations

import os

# One BLAS thread, as the command line sets it (thermobearing/cli.py): the solvers factor many
# small matrices, and a threaded BLAS on a busy 2-core machine made a 129 x 129 dgesv of the
# EHL preconditioner take 240-340 ms instead of 0.4-0.7 ms. Must precede the numpy import.
for _var in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
os.environ.setdefault("MPLBACKEND", "Agg")

from hypothesis import settings  # noqa: E402

# Property tests draw the same examples on every run by default (profile "ci"), so that a
# clean-clone test run is reproducible; HYPOTHESIS_PROFILE=explore draws fresh random
# examples (and keeps hypothesis' example database) to look for new failures.
settings.register_profile("ci", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
