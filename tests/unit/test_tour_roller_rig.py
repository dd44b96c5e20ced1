"""Defects met running a cylindrical roller bearing rig (NU 214 and friends): a protocol
with a stop, jet and oil bath, two bearings on one shaft, the report's loss tables."""

from __future__ import annotations

import pandas as pd

from thermobearing.report_losses import glossary, loss_class_of


def _losses_with_a_stop() -> pd.DataFrame:
    """A losses table as a run writes it: step 0 turning (each component classed), step 1 at
    rest (every source books one 0 W row with an empty class cell)."""
    rows = []
    for src, comp, cls in (("raceway_traction", "outer contact", "load_dependent"),
                           ("churning_elements", "element churning", "load_independent"),
                           ("pocket_friction", "roller pocket", "load_independent")):
        rows.append({"step": 0, "bearing": "test", "speed [rpm]": 3000.0, "source": src,
                     "component": comp, "role": "oil", "power [W]": 10.0,
                     "load dependence": cls})
        rows.append({"step": 1, "bearing": "test", "speed [rpm]": 0.0, "source": src,
                     "component": "at rest", "role": "oil", "power [W]": 0.0,
                     "load dependence": ""})
    return pd.DataFrame(rows)


def test_a_stop_in_the_protocol_does_not_make_every_source_mixed():
    losses = _losses_with_a_stop()
    assert loss_class_of(losses) == {"raceway_traction": "load-dependent",
                                     "churning_elements": "load-independent",
                                     "pocket_friction": "load-independent"}
    # read back from the CSV the empty cells are NaN: same classes
    nan = losses.assign(**{"load dependence": losses["load dependence"].replace("", None)})
    assert loss_class_of(nan) == loss_class_of(losses)
    table = glossary(losses).set_index("in the CSV files")["class"]
    assert table["raceway_traction"] == "load-dependent"


def test_a_source_with_two_classes_is_mixed_and_one_without_any_is_blank():
    losses = _losses_with_a_stop()
    extra = pd.DataFrame([
        {"step": 0, "bearing": "test", "speed [rpm]": 3000.0, "source": "churning_elements",
         "component": "other", "role": "oil", "power [W]": 1.0,
         "load dependence": "load_dependent"},
        {"step": 0, "bearing": "test", "speed [rpm]": 3000.0, "source": "plugin_source",
         "component": "x", "role": "oil", "power [W]": 1.0, "load dependence": ""}])
    classes = loss_class_of(pd.concat([losses, extra], ignore_index=True))
    assert classes["churning_elements"] == "mixed"
    assert classes["plugin_source"] == ""
