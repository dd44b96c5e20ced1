"""NumPy records that ``thermobearing cage-speed`` stopped on with a traceback, found while
fuzzing the command with generated records (session 18): an .npz whose rate is an array of
two numbers (TypeError) or a text (ValueError), an object array (ValueError from np.load),
a file of random bytes or one cut short (ValueError); a complex record ran on its real
part without a word. Each is now an InputError naming the file (or its array)."""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.signal_input import load_acceleration

X = np.random.default_rng(0).normal(size=4096)


@pytest.mark.parametrize(("rate", "shown"), [(np.array([20000.0, 1.0]), "shape \\(2,\\)"),
                                             ("20 kHz", "<U6")])
def test_npz_rate_must_be_one_number(tmp_path, rate, shown):
    path = tmp_path / "rec.npz"
    np.savez(path, data=X, fs=rate)
    with pytest.raises(InputError, match=rf"rec.npz\['fs'\] = .*{shown}.*one number: the "
                                         "sampling rate in Hz"):
        load_acceleration(path)


def test_object_arrays_are_refused(tmp_path):
    npy = tmp_path / "obj.npy"
    np.save(npy, np.array(["a"] * 300, dtype=object), allow_pickle=True)
    with pytest.raises(InputError, match=r"file = .*obj.npy.*NumPy .npy file of numbers"):
        load_acceleration(npy, sampling_rate=1000.0)
    npz = tmp_path / "obj.npz"
    np.savez(npz, data=np.array(["a"] * 300, dtype=object), fs=1000.0)
    with pytest.raises(InputError, match=r"obj.npz\['data'\] = 'an object array'"):
        load_acceleration(npz)


def test_random_bytes_and_a_cut_file(tmp_path):
    junk = tmp_path / "junk.npz"
    junk.write_bytes(bytes(range(256)))
    with pytest.raises(InputError, match=r"junk.npz.*NumPy .npz file"):
        load_acceleration(junk)
    full = tmp_path / "full.npy"
    np.save(full, X)
    cut = tmp_path / "cut.npy"
    cut.write_bytes(full.read_bytes()[:2000])
    with pytest.raises(InputError, match=r"cut.npy.*NumPy .npy file of numbers"):
        load_acceleration(cut, sampling_rate=1000.0)


def test_complex_samples_are_refused(tmp_path):
    path = tmp_path / "c.npz"
    np.savez(path, data=X.astype(complex), fs=1000.0)
    with pytest.raises(InputError, match=r"real samples \(the array is complex128"):
        load_acceleration(path)


def test_a_good_npz_still_reads(tmp_path):
    path = tmp_path / "ok.npz"
    np.savez(path, data=X, sampling_rate=np.float64(2048.0))
    rec = load_acceleration(path)
    assert rec.sampling_rate == 2048.0
    assert rec.data == pytest.approx(X)
