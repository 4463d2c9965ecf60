"""The step graph: step functions bound as graph nodes (rename, extra inputs, narrowed outputs, labels,
checks), builders found through the registry, and the sharing of steps between variants by input value."""

from __future__ import annotations

import numpy as np
import pytest

import camcontact as cc
from camcontact.analysis import input_token
from camcontact.errors import InputError
from camcontact.step_graph import SceneGraph, Step, builder_for, given, step


def positive_width(width):
    if width is not None and not width > 0:
        raise InputError("width <= 0")


@step("area", provides=("area", "perimeter"), model=lambda shape: f"{shape} model", version="2", check=positive_width)
def rectangle(width, height, shape):
    """A test step: the area and perimeter of a rectangle."""
    return {"area": width * height, "perimeter": 2 * (width + height)}


@step("sum", provides=("total",))
def total(first, **more):
    return {"total": first + sum(more.values())}


def test_a_step_function_stays_a_function_and_declares_its_step():
    assert rectangle(2.0, 3.0, "box") == {"area": 6.0, "perimeter": 10.0}
    assert rectangle.step.name == "area" and rectangle.step.provides == ("area", "perimeter")


def test_step_of_reads_requires_from_the_parameters_and_runs_on_a_state():
    node = Step.of(rectangle)
    assert node.name == "area" and node.requires == ("width", "height", "shape")
    assert node.provides == ("area", "perimeter")
    assert node.run({"width": 2.0, "height": 3.0, "shape": "box", "other": 1}) == {"area": 6.0, "perimeter": 10.0}
    assert node.label({"shape": "box"}) == ("box model", "2")


def test_rename_binds_parameters_and_outputs_to_graph_names():
    node = Step.of(rectangle, name="area_in", rename={"width": "b", "height": "b", "area": "square"})
    assert node.name == "area_in" and node.requires == ("b", "shape")
    assert node.provides == ("square", "perimeter")
    assert node.run({"b": 3.0, "shape": "s"}) == {"square": 9.0, "perimeter": 12.0}


def test_extra_inputs_go_through_the_var_keyword_parameter_without_duplicates():
    node = Step.of(total, extra=("first", "a", "b", "a"))
    assert node.requires == ("first", "a", "b")
    assert node.run({"first": 1.0, "a": 2.0, "b": 3.0, "c": 100.0}) == {"total": 6.0}
    with pytest.raises(TypeError, match="takes no \\*\\*inputs"):
        Step.of(rectangle, extra=("depth",))


def test_provides_narrows_to_declared_outputs_only():
    assert Step.of(rectangle, provides=("area",)).provides == ("area",)
    with pytest.raises(TypeError, match="does not provide"):
        Step.of(rectangle, provides=("volume",))


def test_only_declared_step_functions_are_steps():
    with pytest.raises(TypeError, match="not a step function"):
        Step.of(lambda width: {"area": width})


def test_checks_receive_graph_inputs_and_none_for_those_not_given():
    node = Step.of(rectangle)
    node.check({"width": 1.0})
    node.check({})  # width not given: the check sees None
    with pytest.raises(InputError, match="width <= 0"):
        node.check({"width": -1.0})


def test_given_leaves_out_none():
    assert given(a=1.0, b=None, c=0.0) == {"a": 1.0, "c": 0.0}


def test_builders_are_found_by_type_and_unknown_scenes_are_named():
    assert builder_for(cc.LineContact.__new__(cc.LineContact)).__name__ == "build_line_contact"
    with pytest.raises(InputError, match="Material is not a scene; scenes are: .*LineContact"):
        builder_for(cc.Material(E="210 GPa", nu=0.3))


def test_input_tokens_compare_values_not_objects():
    steel = cc.Material(E="210 GPa", nu=0.3)
    assert input_token(np.arange(3.0)) == input_token(np.arange(3.0))
    assert input_token(np.arange(3.0)) != input_token(np.arange(3.0) + 1e-12)
    assert input_token(steel) == input_token(cc.Material(E="210 GPa", nu=0.3))
    assert input_token(steel) != input_token(cc.Material(E="200 GPa", nu=0.3))
    assert input_token(cc.registry.get("film_models", "moes")) == input_token(cc.registry.get("film_models", "moes"))

    class Plain:
        pass

    a, b = Plain(), Plain()
    assert input_token(a) == input_token(a) and input_token(a) != input_token(b)
    assert input_token({"inner": 1.0, "outer": 2.0}) == input_token({"outer": 2.0, "inner": 1.0})


def test_variants_share_exactly_the_steps_whose_inputs_agree():
    """Two film models: Hertz runs once, the film per variant; a friction-free line contact has the
    same scene inputs in both variants (built twice, compared by value)."""
    steel = cc.Material(E="210 GPa", nu=0.3)
    oil = cc.Lubricant(alpha="2e-8 1/Pa", eta0="0.05 Pa*s")
    contact = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm", speed="2 m/s"),
                             body2=cc.Body(material=steel, radius="10 mm", speed="2 m/s"),
                             load="1 kN", length="10 mm", lubricant=oil)
    result = cc.Analysis(contact, outputs=["p_h", "h_c"], models={"film": ["moes", "grubin"]}).run()
    steps = [(r.step, r.variant) for r in result.records]
    assert steps.count(("hertz", "moes")) == 1 and ("hertz", "grubin") not in steps
    assert ("film", "moes") in steps and ("film", "grubin") in steps
    assert result["h_c"][0] != result["h_c"][1]


def test_a_scene_graph_holds_its_steps():
    graph = SceneGraph(kind="test", inputs={"width": 1.0}, steps=(Step.of(rectangle),), default_outputs=("area",))
    assert graph.steps[0].name == "area" and graph.index is None


def test_optional_inputs_reach_the_step_only_when_the_graph_has_them():
    node = Step.of(total, extra=("a",), optional=("b", "a", "first"))
    assert node.requires == ("first", "a") and node.optional == ("b",)
    assert node.run({"first": 1.0, "a": 2.0}) == {"total": 3.0}
    assert node.run({"first": 1.0, "a": 2.0, "b": 4.0}) == {"total": 7.0}


def test_step_bindings_are_cached():
    assert Step.of(rectangle) is Step.of(rectangle)
    assert Step.of(rectangle, rename={"width": "b"}) is not Step.of(rectangle)
