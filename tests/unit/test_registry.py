"""Plugin registry: built-ins, lazy entry-point discovery, broken plugins, clashes, switches.

Entry points are faked by replacing ``registry._entry_points`` with a function returning
real :class:`importlib.metadata.EntryPoint` objects that point at a throw-away module.
"""

import importlib.metadata as metadata
import sys
import textwrap

import pytest

from camcontact import registry
from camcontact.errors import PluginLoadWarning, PluginNameClashWarning, UnknownModelError
from camcontact.models.base import FilmModel

PLUGIN_SOURCE = textwrap.dedent(
    '''
    from camcontact.models.base import FilmModel, DensityLaw

    class Good(FilmModel):
        """A fake line film model."""
        name = "fake_good"
        reference = "nobody (2026) test plugin"
        geometry = "line"
        requires = ("R", "w", "E_reduced", "u_m", "eta0", "alpha")
        provides = ("h_c",)
        def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
            return {"h_c": 1e-6}

    class Clash(Good):
        name = "moes"

    class NotAModel:
        name = "not_a_model"

    class WrongFamily(DensityLaw):
        name = "wrong_family"
        def density_ratio(self, p):
            return 1.0
    '''
)


@pytest.fixture
def fake_plugins(tmp_path, monkeypatch, clean_registry):
    (tmp_path / "fake_camcontact_plugins.py").write_text(PLUGIN_SOURCE)
    monkeypatch.syspath_prepend(str(tmp_path))
    group = "camcontact.film_models"
    points = [
        metadata.EntryPoint("fake_good", "fake_camcontact_plugins:Good", group),
        metadata.EntryPoint("broken", "module_that_does_not_exist_xyz:Model", group),
        metadata.EntryPoint("moes", "fake_camcontact_plugins:Clash", group),
        metadata.EntryPoint("not_a_model", "fake_camcontact_plugins:NotAModel", group),
        metadata.EntryPoint("wrong_family", "fake_camcontact_plugins:WrongFamily", group),
    ]
    calls = []

    def fake_entry_points(name):
        calls.append(name)
        return points if name == group else []

    monkeypatch.setattr(registry, "_entry_points", fake_entry_points)
    yield calls
    sys.modules.pop("fake_camcontact_plugins", None)


def _lookup_with_expected_warnings(action):
    with pytest.warns(PluginLoadWarning) as load_warnings:
        with pytest.warns(PluginNameClashWarning):
            value = action()
    return value, [str(w.message) for w in load_warnings if issubclass(w.category, PluginLoadWarning)]


def test_good_plugin_is_found_and_broken_ones_are_listed_as_failed(fake_plugins):
    names, messages = _lookup_with_expected_warnings(lambda: registry.available("film_models"))
    assert "fake_good" in names and "moes" in names
    assert "broken" not in names and "not_a_model" not in names and "wrong_family" not in names
    assert any("broken" in m and "ModuleNotFoundError" in m for m in messages)
    rows = {row.name: row for row in registry.entries("film_models") if row.source != "camcontact (built-in)"}
    assert rows["fake_good"].status == "ok"
    assert rows["broken"].status.startswith("failed: ModuleNotFoundError")
    assert rows["not_a_model"].status.startswith("failed:") and "not a subclass of FilmModel" in rows["not_a_model"].status
    assert "not a subclass of FilmModel" in rows["wrong_family"].status
    assert rows["moes"].status == "shadowed by the built-in"
    assert isinstance(registry.get("film_models", "fake_good"), FilmModel)


def test_builtin_wins_a_name_clash(fake_plugins):
    model, _ = _lookup_with_expected_warnings(lambda: registry.get("film_models", "moes"))
    assert type(model).__module__ == "camcontact.models.film_line"


def test_discovery_is_lazy_per_family_and_happens_once(fake_plugins):
    assert fake_plugins == []  # nothing looked up yet
    registry.available("density_laws")
    assert fake_plugins == ["camcontact.density_laws"]
    _lookup_with_expected_warnings(lambda: registry.available("film_models"))
    registry.available("film_models")
    registry.get("film_models", "fake_good")
    assert fake_plugins == ["camcontact.density_laws", "camcontact.film_models"]


def test_autoload_switch(fake_plugins, monkeypatch):
    monkeypatch.setenv("CAMCONTACT_DISABLE_PLUGIN_AUTOLOAD", "1")
    names = registry.available("film_models")
    assert "fake_good" not in names and "moes" in names
    assert fake_plugins == []


def test_unknown_name_lists_available_and_failed(fake_plugins):
    with pytest.raises(UnknownModelError, match=r"no film_models model named 'nope'; available: .*dowson_higginson.*fake_good.*failed to load: broken"):
        _lookup_with_expected_warnings(lambda: registry.get("film_models", "nope"))


def test_unknown_family():
    with pytest.raises(UnknownModelError, match="families are: motion_laws"):
        registry.available("gearbox_models")


def test_instances_classes_and_functions_are_accepted(clean_registry):
    from camcontact.models.film_line import Moes

    model = Moes(piezoviscosity=False)
    assert registry.get("film_models", model) is model
    assert isinstance(registry.get("film_models", Moes), Moes)

    def my_film(R, w, E_reduced, u_m, eta0, alpha):
        return {"h_c": 2e-7}

    wrapped = registry.get("film_models", my_film, requires=("R", "w", "E_reduced", "u_m", "eta0", "alpha"),
                           provides=("h_c",))
    state = dict(R=0.01, w=1e5, E_reduced=2.3e11, u_m=1.0, eta0=0.01, alpha=2e-8)
    assert wrapped(state) == {"h_c": 2e-7} and wrapped.name == "my_film"
    with pytest.raises(UnknownModelError, match="cannot use"):
        registry.get("density_laws", Moes)


def test_builtin_parameters_pass_through(clean_registry):
    law = registry.get("viscosity_laws", "roelands", p0=2e8)
    assert law.p0 == 2e8


def test_plugins_cli_lists_name_family_source_reference_status(capsys, clean_registry):
    from camcontact.cli import main

    assert main(["plugins", "--family", "film_models"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].split() == ["name", "family", "source", "status", "reference"]
    assert "moes" in out and "camcontact (built-in)" in out and "Moes (1992)" in out


# ----------------------------------------------------------------------------- built-in marks
DUPLICATE_SOURCE = textwrap.dedent(
    '''
    from camcontact.models.base import DensityLaw, builtin

    @builtin
    class Incompressible2(DensityLaw):
        name = "incompressible"
        def density_ratio(self, pressure):
            return 1.0
    '''
)


def test_builtin_marks_only_the_decorated_class():
    from camcontact.models import film_line
    from camcontact.models.base import builtin_classes, is_builtin

    assert [cls.__name__ for cls in builtin_classes(film_line)] == [
        "Grubin", "DowsonHigginson", "DowsonToyoda", "PanHamrock", "Moes"]
    assert not is_builtin(film_line.LinePowerLaw)  # a base class in the module, unmarked

    class Thinner(film_line.Moes):  # a subclass of a built-in is no built-in
        name = "thinner"

    assert is_builtin(film_line.Moes) and not is_builtin(Thinner)
    # classes a module only imports are not its built-ins
    from camcontact.models import film_multigrid

    assert [cls.name for cls in builtin_classes(film_multigrid)] == ["multigrid"]


def test_builtin_checks_family_and_name():
    from camcontact.models.base import FilmModel, Model, builtin

    class Nameless(FilmModel):
        pass

    class Familyless(Model):
        name = "x"

    with pytest.raises(TypeError, match="Nameless has no 'name'"):
        builtin(Nameless)
    with pytest.raises(UnknownModelError, match="unknown model family ''"):
        builtin(Familyless)


def test_two_builtins_of_one_name_are_refused_at_lookup(tmp_path, monkeypatch, clean_registry):
    from camcontact.models.base import FAMILIES

    (tmp_path / "fake_duplicate_builtins.py").write_text(DUPLICATE_SOURCE)
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setenv(registry.DISABLE_ENV, "1")
    monkeypatch.setattr(registry, "_builtins", {family: {} for family in FAMILIES})
    monkeypatch.setattr(registry, "_builtins_imported", set())
    monkeypatch.setitem(registry.BUILTIN_MODULES, "density_laws",
                        registry.BUILTIN_MODULES["density_laws"] + ("fake_duplicate_builtins",))
    try:
        with pytest.raises(TypeError, match="two built-in density_laws models are named 'incompressible'"):
            registry.available("density_laws")
    finally:
        sys.modules.pop("fake_duplicate_builtins", None)
