"""The rib heat source's coupled roller dynamics hand over to the reduced model where they
cannot run: a slow cage (cost ~ 1/speed) or a motion that stops (heat_sources/rib.py); a
mineral oil's stiff spin no longer stops it."""

from __future__ import annotations

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

CRB = """
title = "CRB 50x75x16, race control, rib friction (coupled model by default)"
[[bearings]]
name = "a"
preset = "CRB_50x75x16"
[lubricant]
preset = "{oil}"
[supply]
method = "jet"
flow = "10 L/min"
inlet_temperature = "{temp}"
[environment]
ambient_temperature = "{temp}"
[schedule]
speed = "{speed}"
radial_load = "{load}"
axial_load = "0 N"
duration = "1 min"
[models]
kinematics = "race_control"
[outputs]
mode = "steady"
want = ["losses"]
"""


def _rib_run(**kw):
    sim = Simulation(loads_scene(CRB.format(**kw)), progress=False)
    res = sim.run()
    rib = res.tables["losses"]
    rib = rib[rib["source"] == "rib_friction"]["power [W]"].sum()
    return rib, [w for w in res.warnings if "rib_friction" in w]


def test_a_slow_cage_uses_the_reduced_model_with_a_warning():
    """45 r/min (a fuzzed scene): the coupled model would integrate 14.6 s of motion on
    ~1.5 us steps (265 s CPU per temperature node); the reduced model books the heat."""
    rib, notes = _rib_run(oil="OIL_4109", temp="67 degC", speed="45.4631 rpm", load="225 N")
    assert rib >= 0.0
    assert any("would integrate 14.6 s of motion" in n and "reduced model" in n for n in notes)


def test_a_mineral_oil_runs_on_the_coupled_model():
    """ISO VG46 at 80 degC, 20000 r/min, 3 kN: the loaded rollers' spin under the mineral
    oil's raceway shear was too stiff for the explicit RK4 steps (the cage ran away at
    every temperature node tried and the reduced model booked the heat); with the ETDRK4
    integrator the coupled model runs (no fallback warning)."""
    rib, notes = _rib_run(oil="ISO_VG46", temp="80 degC", speed="20000 rpm", load="3 kN")
    assert rib > 0.0
    assert not any("stopped" in n or "reduced model" in n for n in notes), notes


def test_a_stopped_coupled_motion_uses_the_reduced_model_with_a_warning(monkeypatch):
    """The safety net: a coupled run that stops with a ConvergenceError at the node and its
    neighbours hands over to the reduced model, and the warning quotes the stop."""
    from thermobearing.errors import ConvergenceError
    from thermobearing.heat_sources import rib as rib_source
    from thermobearing.skidding import roller_dynamics_heat as rdh

    def stopped(*args, **kw):
        if kw.get("model") == "coupled":
            raise ConvergenceError("roller_dynamics.coupled", float("inf"),
                                   "unstable coupled motion (test)", {})
        return rdh.rib_dynamics_heat(*args, **kw)

    monkeypatch.setattr(rib_source, "rib_dynamics_heat", stopped)
    rib, notes = _rib_run(oil="MIL_PRF_23699", temp="80 degC", speed="20000 rpm",
                          load="3 kN")
    assert rib > 0.0
    assert any("coupled roller dynamics stopped" in n and "unstable coupled motion (test)"
               in n and "reduced model" in n for n in notes)
