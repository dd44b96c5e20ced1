"""Compiled kernels get one type per argument from their callers.

Every distinct argument type tuple is a full numba compilation (seconds for the large
kernels, on every fresh clone and CI run): compiled callers must not pass literal ints or
bools (typed ``Literal[int](2)``, one compilation per value) and Python callers must not pass
read-only broadcast views where the compiled callers pass writable arrays.
"""

from __future__ import annotations

import sys

import numpy as np
from numba.core import types
from numba.core.registry import CPUDispatcher

from thermobearing import contact_traction
from thermobearing.contact_traction import integrate
from thermobearing.traction import make_traction_law

# argument positions of _integrate_contacts: q, a, b, vy, vx, wz, wx, wy, curv, h
_CONTACT_INPUTS = range(7, 17)
# specialised on purpose: the rib contact per face (side -1 / 1 literal: 2-4 % faster in
# the roller dynamics' right-hand side than a run-time side, measured)
_SPECIALISED = {"thermobearing.rib.face_values", "thermobearing.rib.face_contact",
                "thermobearing.rib._support", "thermobearing.rib._contact_radii"}


def _thermobearing_dispatchers() -> list[tuple[str, CPUDispatcher]]:
    found = []
    for name, module in list(sys.modules.items()):
        if not name.startswith("thermobearing") or module is None:
            continue
        for attr, value in vars(module).items():
            if isinstance(value, CPUDispatcher) and value.py_func.__module__ == name:
                found.append((f"{name}.{attr}", value))
    return found


def test_read_only_inputs_reach_the_contact_kernel_as_writable_arrays():
    # a read-only input (e.g. a frozen state array) and scalars broadcast against it
    q = np.array([800.0, 1200.0])
    q.flags.writeable = False
    a = np.full(2, 2e-3)
    a.flags.writeable = False
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=1.0)
    r = integrate(law, normal_load=q, semi_major=a, semi_minor=0.4e-3, sliding_speed=0.3)
    assert np.all(r.heat > 0.0)
    sigs = contact_traction._integrate_contacts.signatures
    assert sigs
    for sig in sigs:
        for i in _CONTACT_INPUTS:
            assert isinstance(sig[i], types.Array) and sig[i].mutable, (i, sig[i])
            assert sig[i].layout == "C" and sig[i].dtype == types.float64, (i, sig[i])


def test_no_kernel_is_compiled_for_a_literal_argument():
    # the kernels this process has compiled or loaded so far (at least the contact
    # integration's, from the call below)
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=1.0)
    integrate(law, normal_load=1000.0, semi_major=2e-3, semi_minor=0.4e-3, sliding_speed=0.2)
    checked = 0
    for name, disp in _thermobearing_dispatchers():
        if name in _SPECIALISED:
            continue
        for sig in disp.signatures:
            checked += 1
            literal = [str(t) for t in sig if isinstance(t, types.Literal)]
            assert not literal, f"{name} compiled for literal arguments {literal}"
    assert checked > 0
