# %% [markdown]
# # Tutorial 2 — choosing models, passing your own, and plugins
#
# Every model lives in a family of the registry (`viscosity_laws`, `film_models`, ...). A scene picks
# models by name; you may also pass a model instance with its own parameters, a class, or a plain
# function. Third-party distributions add models through entry points (see
# `plugins/camcontact-extras`).

# %%
import camcontact as cc
from camcontact import registry
from camcontact.models.base import FilmModel
from camcontact.models.film_line import LINE_INPUTS

for row in registry.entries("film_models"):
    print(f"{row.name:18s} {row.source:26s} {row.status:8s} {row.reference}")

# %% [markdown]
# ## A contact to play with: the LS-1 roller follower at the cam nose (Tsuha 2015, Table 6.3, 90°)
# Reduced radius 7.70 mm (cam 33.46 mm with the 10 mm roller), 3088 N over 15 mm, rolling at
# 3.503 m/s; the lubricant is given by alpha = 2.2e-8 1/Pa and the Roelands index z = 0.68, so
# eta0 follows from the Roelands consistency relation (0.0358 Pa s).

# %%
steel = cc.Material(E="210 GPa", nu=0.3)
oil = cc.Lubricant(alpha="2.2e-8 1/Pa", roelands_z=0.68)
nose = cc.LineContact(
    body1=cc.Body(name="cam", material=steel, radius="33.46 mm", speed="3.503 m/s"),
    body2=cc.Body(name="roller", material=steel, radius="10 mm", speed="3.503 m/s"),
    load="3087.99 N", length="15 mm", lubricant=oil,
)

# %% [markdown]
# ## A function as a film model
# Any function with the film models' keyword signature (SI units) can stand in; here the
# Dowson–Higginson minimum film written by hand, with the *mean* speed halved as Tsuha's
# convention implies (his tables use u_m where Moes uses the sum, reference erratum 9).

# %%
def dowson_higginson_half_speed(R, w, E_reduced, u_m, eta0, alpha):
    U = eta0 * (u_m / 2) / (E_reduced * R)
    return {"h_min": 2.65 * U**0.70 * (alpha * E_reduced) ** 0.54 * (w / (E_reduced * R)) ** -0.13 * R}


dowson_higginson_half_speed.provides = ("h_min",)
result = cc.Analysis(nose, outputs=["h_min"],
                     models={"film": ["dowson_higginson", dowson_higginson_half_speed]}).run()
print(result.to_frame(units={"h_min": "nm"}))
print("Tsuha's numerical h_min at this angle: 322.35 nm (his Table 6.4)")

# %% [markdown]
# ## A model class of your own
# Subclass the family base, declare `name`, `reference`, `requires`/`provides`, and implement
# `evaluate` on SI floats. Pass an instance directly, or publish it through an entry point in the
# group `camcontact.film_models` of your own distribution.

# %%
class ScaledMoes(FilmModel):
    """Moes central film times a constant factor (a toy calibration model)."""

    name = "scaled_moes"
    reference = "Moes (1992) with a user calibration factor"
    geometry = "line"
    requires = LINE_INPUTS
    provides = ("h_c",)

    def __init__(self, factor: float):
        self.factor = factor

    def evaluate(self, R, w, E_reduced, u_m, eta0, alpha):
        moes = registry.get("film_models", "moes").evaluate(R, w, E_reduced, u_m, eta0, alpha)
        return {"h_c": self.factor * moes["h_c"]}


calibrated = cc.Analysis(nose, outputs=["h_c"], models={"film": ["moes", ScaledMoes(0.9)]}).run()
print(calibrated.to_frame(units={"h_c": "nm"}))

# %% [markdown]
# ## Plugins from another distribution
# `plugins/camcontact-extras` registers `martin`, `blok` and `greenwood_tripp` through entry points
# only. With the rigid effects (no elasticity, no piezoviscosity) Martin's classical solution and
# the Moes rigid-isoviscous asymptote can be compared; they differ by 1 + X_e^2 = 1.226 because
# Moes's film is taken where dp/dx = 0, Martin's at the centre.

# %%
if "martin" in registry.available("film_models"):
    rigid = cc.Analysis(nose, outputs=["h_c"], effects=[], models={"film": ["martin", "moes"]}).run()
    frame = rigid.to_frame(units={"h_c": "nm"})
    print(frame)
    print("ratio moes/martin:", frame["h_c [nm]"][1] / frame["h_c [nm]"][0])
else:
    print("camcontact-extras is not installed: pip install -e plugins/camcontact-extras")
