"""What scenes hand their models and how variants share steps, beyond the golden reports: a model reads
the state names it declares (required ones planned or reported missing up front, optional ones when the
scene has them), a missing temperature is an up-front error, variants share the steps of models that are
not attrs classes and never share a hand-made step that differs between them, point film models that give
only h_c, and model slots that cannot serve a scene."""

from __future__ import annotations

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact.errors import InputError
from camcontact.models.base import FilmModel, FrictionModel
from camcontact.models.film_line import LINE_INPUTS
from camcontact.step_graph import Step, scene_builder

STEEL = cc.Material(E="210 GPa", nu=0.3)


def line_contact(**changes):
    oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
    fields = dict(body1=cc.Body(material=STEEL, radius="20 mm", speed="4 m/s"),
                  body2=cc.Body(material=STEEL, radius="10 mm", speed="2 m/s"), load="1 kN", length="10 mm",
                  lubricant=oil)
    return cc.LineContact(**{**fields, **changes})


class SlidingFilm(FilmModel):
    """A film that reads the slide-roll ratio (required) and the temperature (optional)."""

    name = "sliding_film"
    reference = "test double"
    geometry = "line"
    requires = (*LINE_INPUTS, "slide_roll_ratio")
    optional_requires = ("temperature",)
    provides = ("h_c",)

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha, slide_roll_ratio, temperature=300.0):
        return {"h_c": 1e-7 * (1.0 + slide_roll_ratio) * temperature / 300.0}


def test_a_line_film_model_gets_the_names_it_requires_and_its_optional_ones_when_given():
    """slide_roll_ratio = (4 - 2)/3 = 2/3: h_c = 1e-7 (5/3); with a temperature of 600 K twice that; without
    one the model's own default (300 K) holds."""
    without = cc.Analysis(line_contact(), outputs=["h_c"], models={"film": SlidingFilm()}).run()
    assert without["h_c"] == pytest.approx(1e-7 * 5.0 / 3.0, rel=1e-12)
    hot = line_contact(temperature="600 K")
    assert cc.Analysis(hot, outputs=["h_c"], models={"film": SlidingFilm()}).run()["h_c"] == \
        pytest.approx(2e-7 * 5.0 / 3.0, rel=1e-12)


def test_a_film_model_requiring_what_the_scene_cannot_give_is_refused_up_front():
    class NeedsSigma(SlidingFilm):
        name = "needs_sigma"
        requires = (*LINE_INPUTS, "sigma")

        def evaluate(self, R, w, E_reduced, u_m, eta0, alpha, sigma):
            return {"h_c": sigma}

    with pytest.raises(InputError, match="needs input the scene does not give.*sigma1: set the roughness of body1"):
        cc.Analysis(line_contact(), outputs=["h_c"], models={"film": NeedsSigma()})


class HotFriction(FrictionModel):
    """A friction model that reads the lubricant temperature."""

    name = "hot_friction"
    reference = "test double"
    requires = ("normal_force", "temperature")
    provides = ("friction_force",)

    def evaluate(self, normal_force, temperature):
        return {"friction_force": 1e-4 * normal_force * temperature}


def cam_scene(**changes):
    from camcontact.kinematics.motion_program import MotionProgram

    oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68, viscosity_pressure_law="roelands")
    fields = dict(cam=cc.Cam(program=MotionProgram.thesis_ls1(), base_radius="40 mm", width="15 mm", material=STEEL),
                  follower=cc.Follower.roller(radius="10 mm", offset="5 mm", material=STEEL),
                  valve_train=cc.ValveTrain.ls1(), speed="1000 rpm", angle_step="30 deg", lubricant=oil,
                  friction_coefficient=0.05)
    return cc.CamFollower(**{**fields, **changes})


def test_a_missing_temperature_is_an_up_front_error_even_with_an_isothermal_lubricant():
    with pytest.raises(InputError, match="temperature: set CamFollower.temperature"):
        cc.Analysis(cam_scene(), outputs=["friction_force"], models={"friction": HotFriction()})
    force = cc.Analysis(cam_scene(temperature="350 K"), outputs=["friction_force", "normal_force"],
                        models={"friction": HotFriction()}).run()
    assert np.allclose(force["friction_force"], 1e-4 * force["normal_force"] * 350.0, rtol=1e-12)


def test_variants_share_the_film_of_a_model_that_is_not_an_attrs_class():
    """Two film models x three friction models on the cam scene (six variants): each film (pan_hamrock,
    dowson_higginson: not attrs classes) is solved once, each friction model once (friction reads no film)."""
    friction = ["coulomb", cc.registry.get("friction_models", "ferrarese_uehara", k_L=2.0), HotFriction()]
    result = cc.Analysis(cam_scene(temperature="350 K"), outputs=["h_min", "friction_force"],
                         models={"film": ["pan_hamrock", "dowson_higginson"], "friction": friction}).run()
    steps = [record.step for record in result.records]
    assert steps.count("film") == 2
    assert steps.count("friction") == 3
    assert len(result.variants) == 6


@attrs.frozen(kw_only=True)
class ScaledContact(cc.LineContact):
    """A line contact whose test scene adds a hand-made step capturing a value per variant."""


@scene_builder(ScaledContact)
def build_scaled(contact, *, models, effects):
    scale = models.get("scale", 1.0)
    step = Step("scaled", ("b",), ("b_scaled",), lambda s: {"b_scaled": scale * s["b"]})
    from camcontact.scenes.line_contact import build_line_contact

    graph = build_line_contact(contact, models={}, effects=effects)
    return attrs.evolve(graph, steps=(*graph.steps, step))


def test_a_hand_made_step_that_differs_between_variants_is_not_shared():
    """The scaled half-width of two variants differs by their scale (2x), while the Hertz step they both
    need runs once."""
    contact = ScaledContact(**{f.name: getattr(line_contact(), f.name) for f in attrs.fields(cc.LineContact)})
    result = cc.Analysis(contact, outputs=["b", "b_scaled"], models={"scale": [1.0, 2.0]}).run()
    assert result["b"][0] == result["b"][1]
    assert result["b_scaled"][1] == pytest.approx(2.0 * result["b_scaled"][0], rel=1e-15)
    assert [record.step for record in result.records].count("hertz") == 1


def forti_point():
    from pathlib import Path

    from camcontact.scene_file import load_scene

    return load_scene(Path(__file__).resolve().parents[2] / "tutorials" / "forti_ball_cone_cvt.toml").component


def test_point_film_model_with_only_a_central_film():
    result = cc.Analysis(forti_point(), outputs=["h_c_in", "h_c_out"], models={"film": "nijenbanning"}).run()
    assert result["h_c_in"] > 0 and result["h_c_out"] > 0
    with pytest.raises(InputError, match="cannot give 'h_min_in'"):
        cc.Analysis(forti_point(), outputs=["h_min_in"], models={"film": "nijenbanning"})


def test_model_slots_that_cannot_serve_the_scene_are_input_errors():
    with pytest.raises(InputError, match="traction_models slot needs a EhlTraction or Fastsim model, got 'constant'"):
        cc.Analysis(forti_point(), outputs=["creepage_in"], models={"traction": "constant"})
    bearing = load_bearing()
    with pytest.raises(InputError, match="life model 'lundberg_palmgren' is not an ISO 281 modified rating life"):
        cc.Analysis(bearing, outputs=["L_nm"], models={"life": "lundberg_palmgren"})


def load_bearing():
    from pathlib import Path

    from camcontact.scene_file import load_scene

    return load_scene(Path(__file__).resolve().parents[2] / "tutorials" / "pellet_mill_bearing.toml").component
