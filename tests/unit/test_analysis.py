"""Analysis: graph checked before running, only the needed steps run, variants, effects."""

import numpy as np
import pandas as pd
import pytest

import camcontact as cc
from camcontact.errors import InputError, StepFailureWarning
from camcontact.models.base import FilmModel
from camcontact.models.film_line import LINE_INPUTS, moes_line_film


class SpyFilm(FilmModel):
    """Counts its calls; returns a fixed film."""

    name = "spy"
    reference = "test double"
    geometry = "line"
    requires = LINE_INPUTS
    provides = ("h_c",)
    calls = 0

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        type(self).calls += 1
        return {"h_c": 1e-6}


@pytest.fixture
def contact(steel):
    oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
    return cc.LineContact(
        body1=cc.Body(material=steel, radius="33.46 mm", speed="3.5 m/s", roughness="0.2 um"),
        body2=cc.Body(material=steel, radius="10 mm", speed="3.5 m/s", roughness="0.2 um"),
        load="3 kN", length="15 mm", lubricant=oil,
    )


def test_hertz_outputs_never_call_a_film_model(contact):
    SpyFilm.calls = 0
    analysis = cc.Analysis(contact, outputs=["b", "p_h"], models={"film": SpyFilm()})
    assert analysis.steps() == ["geometry", "hertz"]
    result = analysis.run()
    assert SpyFilm.calls == 0
    assert [r.step for r in result.records] == ["geometry", "hertz"]
    film = cc.Analysis(contact, outputs=["h_c"], models={"film": SpyFilm()}).run()
    assert SpyFilm.calls == 1 and film["h_c"] == 1e-6
    assert "lubricant" in [r.step for r in film.records]


def test_hertz_needs_no_lubricant(steel):
    dry = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm"),
                         body2=cc.Body(material=steel, radius="10 mm"), load="1 kN", length="10 mm")
    result = cc.Analysis(dry).run()
    assert "h_c" not in result.outputs and "p_h" in result.outputs
    with pytest.raises(InputError, match=r"output 'h_min' .* \(lubricant: set LineContact.lubricant\)"):
        cc.Analysis(dry, outputs=["h_min"])


def test_missing_roughness_and_temperature_are_reported_up_front(steel):
    oil = cc.Lubricant(nu40="100 cSt", nu100="10 cSt", density="900 kg/m^3", alpha="2e-8 1/Pa")
    c = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm", speed="1 m/s"),
                       body2=cc.Body(material=steel, radius="10 mm", speed="1 m/s"),
                       load="1 kN", length="10 mm", lubricant=oil)
    with pytest.raises(InputError, match=r"temperature: set LineContact.temperature"):
        cc.Analysis(c, outputs=["h_c"])
    with pytest.raises(InputError, match=r"sigma1: set the roughness of body1"):
        cc.Analysis(c, outputs=["Lambda_min"])


def test_unknown_output_and_effect(contact):
    with pytest.raises(InputError, match="cannot give 'torque' with these models; it gives: .*b, .*p_h"):
        cc.Analysis(contact, outputs=["torque"])
    with pytest.raises(InputError, match="no variant of this analysis can give 'torque'"):
        cc.Analysis(contact, outputs=["torque"], models={"film": ["moes", "grubin"]})
    with pytest.raises(InputError, match="cannot give 'h_min' with these models"):
        cc.Analysis(contact, outputs=["h_min"], models={"film": "moes"})
    with pytest.raises(InputError, match="unknown effects"):
        cc.Analysis(contact, effects=["magic"])
    with pytest.raises(InputError, match=r"effects \['dynamics'\] do not apply to a line_contact scene"):
        cc.Analysis(contact, effects=["elasticity", "dynamics"])
    with pytest.raises(InputError, match="unknown model slots"):
        cc.Analysis(contact, models={"friction": "coulomb"})


def test_variants_share_steps_and_differ_downstream(contact):
    result = cc.Analysis(contact, models={"film": ["dowson_higginson", "moes"]}).run()
    steps = [(r.step, r.variant) for r in result.records]
    assert steps.count(("hertz", "dowson_higginson")) == 1 and ("hertz", "moes") not in steps
    assert ("film", "moes") in steps and ("lambda", "moes") in steps
    frame = result.to_frame()
    assert list(frame["variant"]) == ["dowson_higginson", "moes"]
    assert np.isnan(frame.loc[0, "h_c [µm]"]) and np.isnan(frame.loc[1, "h_min [µm]"])
    assert frame.loc[0, "b [µm]"] == frame.loc[1, "b [µm]"]


def test_explicit_outputs_with_variants_that_lack_one(contact):
    result = cc.Analysis(contact, outputs=["h_min", "h_c"], models={"film": ["grubin", "dowson_higginson"]}).run()
    frame = result.to_frame()
    assert list(frame.columns) == ["variant", "h_min [µm]", "h_c [µm]", "not_given"]
    assert np.isnan(frame.loc[0, "h_min [µm]"]) and np.isnan(frame.loc[1, "h_c [µm]"])
    # the NaN cells have their reason beside them: what this row's film model does not give
    assert list(frame["not_given"]) == ["h_min", "h_c"]


def test_two_models_of_the_same_name_are_not_confused(contact):
    class Fixed(SpyFilm):
        def __init__(self, value):
            self.value = value

        def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
            return {"h_c": self.value}

    result = cc.Analysis(contact, outputs=["h_c"], models={"film": [Fixed(1e-6), Fixed(2e-6)]}).run()
    assert result["h_c"] == [1e-6, 2e-6]
    assert result.variants == ("spy", "spy #2")


def test_frame_units_and_columns(contact):
    result = cc.Analysis(contact, outputs=["h_c", "p_h", "regime"], models={"film": "moes"}).run()
    frame = result.to_frame(units={"h_c": "nm", "p_h": "GPa"})
    assert list(frame.columns) == ["h_c [nm]", "p_h [GPa]", "regime"]
    assert frame["h_c [nm]"][0] == pytest.approx(result["h_c"] * 1e9)
    assert isinstance(frame, pd.DataFrame)
    with pytest.raises(InputError, match="not outputs"):
        result.to_frame(units={"h_min": "nm"})
    with pytest.raises(InputError, match="cannot report h_c"):
        result.to_frame(units={"h_c": "Pa"})


def test_step_record_has_model_version_and_time(contact):
    result = cc.Analysis(contact, outputs=["h_c"], models={"film": "moes"}).run()
    film = [r for r in result.records if r.step == "film"][0]
    assert film.model == "moes" and film.version == "1" and film.wall_time > 0
    steps = result.steps_frame()
    assert list(steps.columns) == ["step", "model", "version", "variant", "wall time [ms]"]
    assert result.wall_time == pytest.approx(sum(r.wall_time for r in result.records))


def test_effect_piezoviscosity_off_needs_a_capable_model(contact):
    with pytest.raises(InputError, match="cannot represent a scene without piezoviscosity; line models that can: .*moes"):
        cc.Analysis(contact, outputs=["h_c"], effects=["elasticity"], models={"film": "grubin"})
    iso = cc.Analysis(contact, outputs=["h_c", "L", "M"], effects=["elasticity"], models={"film": "moes"}).run()
    assert iso["L"] == 0.0 and iso.effects == {"elasticity"}
    from camcontact.models.film_line import Moes

    instance = cc.Analysis(contact, outputs=["h_c"], effects=["elasticity"], models={"film": Moes()}).run()
    assert instance["h_c"] == pytest.approx(iso["h_c"], rel=1e-14)
    assert cc.Analysis(contact, outputs=["b"]).run().effects == {"elasticity", "piezoviscosity", "compressibility"}
    # independent: Moes isoviscous-elastic limit, L = 0, evaluated from the formula parts
    M = iso["M"]
    h_ri, h_ei = 3.0 / M, 2.621 * M ** -0.2
    s = (7 + 8 * np.exp(-2 * h_ei / h_ri)) / 5
    H = ((h_ri ** (7 / 3) + h_ei ** (7 / 3)) ** (3 * s / 7)) ** (1 / s)
    assert moes_line_film(M, 0.0) == pytest.approx(H, rel=1e-12)


def test_effect_elasticity_off_gives_rigid_asymptotes(contact):
    rigid = cc.Analysis(contact, outputs=["h_c", "M"], effects=[], models={"film": "moes"}).run()
    # rigid-isoviscous asymptote of Moes: H = H_RI = 3/M, h = H R (2U)^1/2
    assert moes_line_film(rigid["M"], 0.0, elasticity=False) == pytest.approx(3.0 / rigid["M"], rel=1e-12)


def test_thermal_effect_needs_conductivity(contact):
    with pytest.raises(InputError, match="'thermal' effect needs Lubricant"):
        cc.Analysis(contact, outputs=["h_c"], effects=["elasticity", "piezoviscosity", "thermal"])


def test_point_model_rejected_for_line_contact(contact):
    with pytest.raises(InputError, match="is for point contacts"):
        cc.Analysis(contact, outputs=["h_c"], models={"film": "hamrock_dowson"})


def test_zero_entrainment_speed_is_an_error_not_silent_nan(steel):
    oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
    c = cc.LineContact(body1=cc.Body(material=steel, radius="20 mm", speed="1 m/s"),
                       body2=cc.Body(material=steel, radius="10 mm", speed="-1 m/s"),
                       load="1 kN", length="10 mm", lubricant=oil)
    with pytest.raises(InputError, match="entrainment speed"):
        cc.Analysis(c, outputs=["h_c"], strict=True).run()
    with pytest.warns(StepFailureWarning, match="entrainment speed"):
        result = cc.Analysis(c, outputs=["p_h", "h_c"]).run()
    frame = result.to_frame()
    assert frame.loc[0, "p_h [MPa]"] > 0 and np.isnan(frame.loc[0, "h_c [µm]"])
    assert bool(frame.loc[0, "failed"]) and "step 'ehl_groups'" in frame.loc[0, "error"]


def test_not_a_scene():
    with pytest.raises(InputError, match="is not a scene"):
        cc.Analysis(object())


def test_plot_returns_a_figure(contact):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    result = cc.Analysis(contact, models={"film": ["moes", "pan_hamrock"]}).run()
    figure = result.plot()
    assert len(figure.axes) == 3


SPY_PLUGIN = '''
from camcontact.models.base import FilmModel

class CountingFilm(FilmModel):
    """A film plugin that counts its calls."""
    name = "counting_spy"
    reference = "test double"
    geometry = "line"
    requires = ("R", "w", "E_reduced", "u_m", "eta0", "alpha")
    provides = ("h_c", "h_min")
    calls = 0
    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        type(self).calls += 1
        return {"h_c": 2e-7, "h_min": 1e-7}
'''


def test_spy_plugin_found_by_name_is_not_called_for_hertz_outputs(contact, tmp_path, monkeypatch, clean_registry):
    import importlib
    import importlib.metadata as metadata

    from camcontact import registry

    (tmp_path / "spy_plugin_module.py").write_text(SPY_PLUGIN)
    monkeypatch.syspath_prepend(str(tmp_path))
    point = metadata.EntryPoint("counting_spy", "spy_plugin_module:CountingFilm", "camcontact.film_models")
    monkeypatch.setattr(registry, "_entry_points", lambda group: [point] if group == point.group else [])
    for outputs in (["b", "p_h"], ["tau_max", "z_tau_max", "approach"]):
        cc.Analysis(contact, outputs=outputs, models={"film": "counting_spy"}).run()
    spy = importlib.import_module("spy_plugin_module").CountingFilm
    assert spy.calls == 0
    result = cc.Analysis(contact, outputs=["h_min", "Lambda_min"], models={"film": "counting_spy"}).run()
    assert spy.calls == 1 and result["h_min"] == 1e-7 and result["Lambda_min"] == pytest.approx(1e-7 / (0.2e-6 * 2**0.5))
