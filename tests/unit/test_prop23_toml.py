"""Property tests, round 5: the TOML writer (:mod:`thermobearing.toml_writer`) round trip.

Invariant (TOML 1.0 spec, https://toml.io/en/v1.0.0, "Keys" and "String"): for every document
the writer accepts, ``tomllib.loads(dumps_toml(d)) == d``. Bare keys are ASCII letters, digits,
``_`` and ``-`` only, and a basic string may not hold the control characters U+0000..U+001F
(except tab) or U+007F raw. Before session 23 the writer wrote keys bare whenever
``str.isalnum`` held ("T_außen", "µ", "²": invalid TOML) and wrote "\\r", "\\x00", "\\x1b",
"\\x7f" raw, so a scene with a German CSV column name or a title with a CR could not be read
back (:meth:`Scene.to_toml` promises :func:`loads_scene` reads it back to an equal scene).
"""

from __future__ import annotations

import dataclasses
import math
import tomllib

from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.scene import load_scene, loads_scene
from thermobearing.toml_writer import dumps_toml

_keys = st.text(max_size=8)
_scalars = st.one_of(
    st.booleans(),
    st.integers(min_value=-(2**63), max_value=2**63 - 1),
    st.floats(allow_nan=False, allow_infinity=False),
    st.text(max_size=12),
)
_values = st.recursive(
    _scalars,
    lambda inner: st.one_of(st.lists(inner, max_size=3),
                            st.dictionaries(_keys, inner, max_size=3)),
    max_leaves=8,
)
_named = st.dictionaries(_keys, _values, max_size=3).flatmap(
    lambda d: st.text(max_size=6).map(lambda n: {**d, "name": n}))
_tables = st.dictionaries(
    _keys,
    st.one_of(_values, st.lists(_values, max_size=3)),
    max_size=4,
).flatmap(lambda t: st.one_of(st.just(t), st.lists(_values, max_size=3).map(
    lambda s: {**t, "steps": s})))
_documents = st.dictionaries(
    _keys,
    st.one_of(_values, _tables, st.lists(_named, min_size=1, max_size=3)),
    max_size=5,
)


@settings(max_examples=150, deadline=None)
@given(_documents)
def test_every_written_document_reads_back_equal(doc):
    """tomllib.loads(dumps_toml(d)) == d for nested tables, arrays of named tables, inline
    tables, a schedule's one-per-line ``steps`` and any Unicode key or string (TOML 1.0)."""
    assert tomllib.loads(dumps_toml(doc)) == doc


@settings(max_examples=60, deadline=None)
@given(st.text(min_size=1, max_size=6), st.characters(max_codepoint=0x7F),
       st.characters(min_codepoint=0x80, exclude_categories=("Cs",)))
def test_keys_and_strings_with_controls_and_non_ascii(key, ascii_char, other_char):
    """A key mixing ASCII with a non-ASCII letter ("T_außen", "µ", "²") is quoted, and every
    ASCII control character survives in a string (TOML 1.0 "Keys", "String")."""
    doc = {key + other_char: ascii_char + other_char,
           "table": {other_char + key: [ascii_char, key]}}
    assert tomllib.loads(dumps_toml(doc)) == doc


def test_non_finite_floats_read_back_as_such():
    """TOML 1.0 "Float": nan, inf and -inf are valid values; the reader returns them."""
    back = tomllib.loads(dumps_toml({"a": math.inf, "b": -math.inf, "c": math.nan}))
    assert back["a"] == math.inf and back["b"] == -math.inf and math.isnan(back["c"])


def test_scene_with_a_non_ascii_column_and_a_cr_in_its_title_reads_back_equal():
    """Scene.to_toml promises text that loads_scene reads back to an equal scene: a measured
    CSV column named "T_außen_µ" and a title carrying CR LF and BEL (legal in a TOML basic
    string as escapes) both raised TOMLDecodeError before the fix."""
    scene = load_scene("qj1044_synthetic_measured")
    node = next(iter(scene.measured.columns.values()))
    changed = scene.with_changes(
        title="rig A\r\nrun 3\x07",
        measured=dataclasses.replace(scene.measured, columns={"T_außen_µ": node}))
    back = loads_scene(changed.to_toml(), base_dir=scene.base_dir)
    assert back.to_dict() == changed.to_dict()
    assert back.measured.columns == {"T_außen_µ": node}
    assert back.title == "rig A\r\nrun 3\x07"
