"""Scene fuzzing (session 17, ``[models] film``): a closed-form film model other than the
contact kind's ran without a word with the kind's film (race control and the film table
compute hamrock_dowson_1977_central for balls, pan_hamrock_central for rollers), while the
model chain listed the name given: ``film = "pan_hamrock_central"`` on an SKF 6304 gave the
Hamrock-Dowson point-contact films. Such a name is now refused naming models.film and what
the scene's bearings use."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.scene_checks import check_model_names
from thermobearing.simulation import Simulation


def _scene(bearings: list[str], film: str | None, axial: str = "0 N") -> str:
    parts = ["title = \"film model\""]
    for i, preset in enumerate(bearings):
        parts.append(f"[[bearings]]\nname = \"b{i}\"\npreset = \"{preset}\"")
    parts.append('[lubricant]\npreset = "ISO_VG68"')
    parts.append('[supply]\nmethod = "jet"\nflow = "1 L/min"')
    parts.append('[schedule]\nsteps = [{ duration = "1 min", speed = "3000 rpm", '
                 f'radial_load = "2 kN", axial_load = "{axial}" }}]')
    models = '[models]\nkinematics = "race_control"'
    if film is not None:
        models += f'\nfilm = "{film}"'
    parts.append(models)
    parts.append('[outputs]\nmode = "steady"\nwant = ["film"]')
    return "\n\n".join(parts) + "\n"


@pytest.mark.parametrize(("bearings", "film", "named"), [
    (["SKF6304"], "pan_hamrock_central", "hamrock_dowson_1977_central for the ball"),
    (["SKF6304"], "hamrock_dowson_1977_minimum", "hamrock_dowson_1977_central for the ball"),
    (["NU214"], "hamrock_dowson_1977_central", "pan_hamrock_central for the roller"),
    (["NU214"], "moes_line_central", "numerical_ehl, numerical_tehl"),
    (["SKF6304", "NU214"], "hamrock_dowson_1977_central", "no film key in a scene with ball"),
])
def test_a_film_model_the_run_would_not_use_is_refused(bearings, film, named):
    scene = loads_scene(_scene(bearings, film))
    with pytest.raises(InputError, match="models.film") as err:
        check_model_names(scene)
    assert named in str(err.value) and repr(film) in str(err.value)
    with pytest.raises(InputError, match="models.film"):
        Simulation(scene, progress=False)


@pytest.mark.parametrize(("bearings", "film"), [
    (["SKF6304"], "hamrock_dowson_1977_central"), (["NU214"], "pan_hamrock_central"),
    (["SKF6304", "NU214"], None)])
def test_the_kinds_own_film_runs(bearings, film):
    res = Simulation(loads_scene(_scene(bearings, film)), progress=False).run()
    assert len(res.tables["film"]) == 2 * len(bearings)
