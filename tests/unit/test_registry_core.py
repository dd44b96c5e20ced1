import pytest

from thermobearing.citations import cite, reference
from thermobearing.errors import UnknownNameError
from thermobearing.registry import Registry


def test_register_and_lookup():
    reg: Registry = Registry("demo", "a demo family")

    @reg.register("double", references=["johnson1985"], parameters={"x": "m"})
    def double(x):
        """Twice x."""
        return 2 * x

    assert reg.get("double")(2.0) == 4.0
    assert reg["double"] is double
    e = reg.entry("double")
    assert e.summary == "Twice x."
    assert e.parameters == {"x": "m"}
    assert "double" in reg and reg.names() == ["double"]


def test_unknown_name_lists_known():
    reg: Registry = Registry("demo")
    reg.register("a", references=["johnson1985"])(lambda: 1)
    with pytest.raises(UnknownNameError) as info:
        reg.get("b")
    assert "known names are: a" in str(info.value)


def test_register_twice_and_without_reference():
    reg: Registry = Registry("demo")
    reg.register("a", references=["johnson1985"])(lambda: 1)
    with pytest.raises(ValueError):
        reg.register("a", references=["johnson1985"])(lambda: 2)
    with pytest.raises(ValueError):
        reg.register("b", references=[])


def test_citations():
    assert "Contact Mechanics" in reference("johnson1985").format()
    assert len(cite(["johnson1985", "johnson1985"])) == 1
    with pytest.raises(UnknownNameError):
        reference("no_such_key")
