"""The memo of the theoretical cage speed ratio (ball_result.theoretical_csr).

CSR_th is a pure function of the zero-speed load distribution's inputs; the memo must return
the value of a fresh computation to the last bit, and bearings or loads that differ in any of
those inputs must not share an entry.
"""

from __future__ import annotations

import math

import numpy as np

from tests.unit.skidding.helpers import qj_like
from thermobearing.loads import ball_load_distribution
from thermobearing.skidding import ball_result
from thermobearing.skidding.ball_result import theoretical_csr


def _direct(bearing, fr, fa, z=None):
    # the definition (paper 002 section 4.1): (1 - D cos(alpha)/d_m)/2 at the load-weighted
    # inner contact angle of the zero-speed distribution
    ld = ball_load_distribution(bearing, fr, fa, 0.0, n_balls=z)
    alpha = np.sum(ld.inner_load * ld.inner_contact_angle) / np.sum(ld.inner_load)
    return 0.5 * (1.0 - bearing.ball_diameter * math.cos(alpha) / bearing.pitch_diameter)


def test_memo_returns_the_fresh_value_and_keys_on_every_input():
    ball_result._CSR_TH_MEMO.clear()
    b = qj_like()
    first = theoretical_csr(b, 1000.0, 8000.0)
    assert len(ball_result._CSR_TH_MEMO) == 1
    assert first == _direct(b, 1000.0, 8000.0)
    assert theoretical_csr(b, 1000.0, 8000.0) == first            # hit: same bits
    assert len(ball_result._CSR_TH_MEMO) == 1
    # an equal but distinct bearing object hits the same entry
    assert theoretical_csr(qj_like(), 1000.0, 8000.0) == first
    assert len(ball_result._CSR_TH_MEMO) == 1
    # any changed input is a new entry with its own value
    others = [(qj_like(diametral_clearance=0.25e-3), 1000.0, 8000.0, None),
              (qj_like(inner_conformity=0.54), 1000.0, 8000.0, None),
              (b, 1000.0, 8000.5, None), (b, 1200.0, 8000.0, None), (b, 1000.0, 8000.0, 16)]
    for bb, fr, fa, z in others:
        v = theoretical_csr(bb, fr, fa, z)
        assert v == _direct(bb, fr, fa, z)
        assert v != first
    assert len(ball_result._CSR_TH_MEMO) == 1 + len(others)


def test_memo_is_bounded():
    ball_result._CSR_TH_MEMO.clear()
    b = qj_like()
    n = ball_result._CSR_TH_MEMO_SIZE
    for k in range(n):
        ball_result._CSR_TH_MEMO[("fake", k)] = 0.4
    theoretical_csr(b, 1000.0, 5000.0)
    assert len(ball_result._CSR_TH_MEMO) == n
    assert ("fake", 0) not in ball_result._CSR_TH_MEMO       # the oldest entry went
    assert ("fake", 1) in ball_result._CSR_TH_MEMO
    ball_result._CSR_TH_MEMO.clear()
