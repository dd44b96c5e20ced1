"""Property tests, round 5: the memoised TOML reader (:mod:`thermobearing.toml_files`).

Invariants of a cache (it must be invisible): after any sequence of writes, ``read_toml``
returns what ``tomllib`` reads from the file now, whatever the file's timestamp says; and a
caller's edits to its copy never reach another caller. Before session 23 the cache key was
(path, mtime, size): a rewrite of the same size that kept the mtime (a copy with ``cp -p``
or ``rsync -t``, or two writes within the timestamp granularity of FAT / HFS+ (1-2 s) or of
Linux before multigrain timestamps (a clock tick)) returned the old contents.
"""

from __future__ import annotations

import os
import tomllib

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.toml_files import read_toml

_docs = st.dictionaries(
    st.sampled_from(["a", "b", "speed", "load"]),
    st.one_of(st.integers(0, 9), st.sampled_from(["x", "y", "1800 rpm", "2000 rpm"]),
              st.lists(st.integers(0, 9), max_size=3)),
    min_size=1, max_size=3)


def _text(doc: dict) -> str:
    return "".join(f"{k} = {v!r}\n".replace("'", '"') for k, v in doc.items())


@settings(max_examples=40, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(st.tuples(_docs, st.booleans()), min_size=1, max_size=6))
def test_reads_follow_every_write_even_with_the_same_size_and_mtime(tmp_path, writes):
    """After each write (with ``keep`` the previous mtime restored, as a coarse file system
    or ``cp -p`` does), read_toml equals tomllib.loads of the file, and mutating the result
    leaves the next read alone."""
    path = tmp_path / f"case_{abs(hash(repr(writes))) % 10**9}.toml"
    stamp = None
    for doc, keep in writes:
        path.write_text(_text(doc), encoding="utf-8")
        if keep and stamp is not None:
            os.utime(path, ns=stamp)
        stamp = (path.stat().st_atime_ns, path.stat().st_mtime_ns)
        expected = tomllib.loads(path.read_text(encoding="utf-8"))
        got = read_toml(path)
        assert got == expected
        got.clear()
        assert read_toml(path) == expected


def test_same_size_rewrite_keeping_the_mtime_is_read_again(tmp_path):
    """The defect as one example: x = 1 -> x = 2 (same size), mtime restored."""
    path = tmp_path / "same.toml"
    path.write_text("x = 1\n", encoding="utf-8")
    assert read_toml(path) == {"x": 1}
    st = path.stat()
    path.write_text("x = 2\n", encoding="utf-8")
    os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns))
    assert path.stat().st_size == st.st_size
    assert read_toml(path) == {"x": 2}
