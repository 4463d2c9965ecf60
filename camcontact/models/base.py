"""Base classes of the plugin families.

Every model, built-in or third-party, is a subclass of one family base below. A
model declares, as class attributes:

``name``
    short id used in scenes and by :func:`camcontact.registry.get` (``"moes"``).
``reference``
    citation of the source with equation numbers.
``validity``
    ranges of its inputs as data: ``{"M": (5.0, 1000.0), ...}`` (``None`` = open end).
``requires`` / ``provides``
    names of the SI state quantities it reads and returns; the :class:`~camcontact.analysis.Analysis`
    builds its step graph from them.

The outputs of a model that is not built in (a plugin, a user's class or function) are checked
when it is called: every numeric output finite, and the family's ``positive_outputs`` > 0 and
``nonnegative_outputs`` >= 0 (a film, a life, a friction coefficient); a violation is a
:class:`~camcontact.errors.ModelOutputError` naming the model, the output and the value, which an
analysis reports as the failure of that model's step.

and implements :meth:`Model.evaluate` on SI floats/arrays (keyword arguments named as in
``requires``; units in brackets in the docstring). ``model(state)`` picks ``requires``
from a mapping and calls ``evaluate``.
"""

from __future__ import annotations

import abc
from collections.abc import Callable, Mapping
from types import ModuleType
from typing import Any, ClassVar

import numpy as np

from ..errors import InputError, ModelOutputError, UnknownModelError

__all__ = [
    "BUILTIN_MARK",
    "FAMILIES",
    "BearingFrictionModel",
    "DensityLaw",
    "FilmModel",
    "FrictionModel",
    "LifeModel",
    "Model",
    "MotionLaw",
    "TractionModel",
    "ViscosityLaw",
    "ViscosityPressureLaw",
    "ViscosityTemperatureLaw",
    "WearModel",
    "builtin",
    "builtin_classes",
    "check_family",
    "float_or_array",
    "is_builtin",
    "output_problems",
    "validity_messages",
]


def float_or_array(value):
    """``value`` as a Python float when it is a scalar, else as a float ndarray (model outputs)."""
    array = np.asarray(value, dtype=float)
    return float(array) if array.ndim == 0 else array


def validity_messages(
    validity: Mapping[str, tuple[float | None, float | None]], values: Mapping[str, Any]
) -> list[str]:
    """Messages for the ``values`` that fall outside ``validity`` ranges (empty = all inside)."""
    messages = []
    for key, (low, high) in validity.items():
        if key not in values or values[key] is None:
            continue
        array = np.atleast_1d(np.asarray(values[key], dtype=float))
        if low is not None and np.any(array < low):
            messages.append(f"{key} = {array.min():.4g} below the validated range [{low:g}, {high if high is not None else 'inf'}]")
        if high is not None and np.any(array > high):
            messages.append(f"{key} = {array.max():.4g} above the validated range [{low if low is not None else '-inf'}, {high:g}]")
    return messages


class Model(abc.ABC):
    """Common protocol of all plugin models (see the module docstring)."""

    family: ClassVar[str] = ""
    name: ClassVar[str] = ""
    reference: ClassVar[str] = ""
    validity: ClassVar[Mapping[str, tuple[float | None, float | None]]] = {}
    requires: ClassVar[tuple[str, ...]] = ()
    #: inputs passed to :meth:`evaluate` only when the state holds them (not None)
    optional_requires: ClassVar[tuple[str, ...]] = ()
    provides: ClassVar[tuple[str, ...]] = ()
    version: ClassVar[str] = "1"
    #: outputs that must be > 0 / >= 0 (checked for models that are not built in)
    positive_outputs: ClassVar[tuple[str, ...]] = ()
    nonnegative_outputs: ClassVar[tuple[str, ...]] = ()

    @classmethod
    def summary(cls) -> str:
        """First line of the class docstring."""
        return (cls.__doc__ or "").strip().splitlines()[0] if cls.__doc__ else cls.__name__

    @abc.abstractmethod
    def evaluate(self, **inputs: Any) -> dict[str, Any]:
        """Compute ``provides`` from the ``requires`` keyword arguments (SI)."""

    def __call__(self, state: Mapping[str, Any]) -> dict[str, Any]:
        missing = [key for key in self.requires if key not in state]
        if missing:
            optional = f" (optionally {list(self.optional_requires)})" if self.optional_requires else ""
            raise InputError(
                f"model {self.name!r} ({self.family}) needs {missing} which the state does not hold; "
                f"it requires {list(self.requires)}{optional}"
            )
        inputs = {key: state[key] for key in self.requires}
        inputs.update({key: state[key] for key in self.optional_requires if state.get(key) is not None})
        produced = self.evaluate(**inputs)
        if not is_builtin(type(self)):
            problems = output_problems(self, produced)
            if problems:
                raise ModelOutputError(f"model {self.name!r} ({self.family}, {type(self).__module__}."
                                       f"{type(self).__qualname__}) gave {'; '.join(problems)}")
        return produced

    def check_validity(self, values: Mapping[str, Any]) -> list[str]:
        """Messages for inputs outside :attr:`validity` (empty when all are inside)."""
        return validity_messages(self.validity, values)

    def __repr__(self) -> str:
        return f"<{self.family} model {self.name!r} ({type(self).__name__})>"


# ----------------------------------------------------------------- families
class ViscosityLaw(Model):
    """Family ``viscosity_laws``: pressure laws and temperature laws, told apart by ``kind``."""

    family = "viscosity_laws"
    kind: ClassVar[str] = ""


class ViscosityPressureLaw(ViscosityLaw):
    """Viscosity–pressure law: eta(p) from the ambient-pressure viscosity eta0 and alpha.

    Subclasses implement :meth:`log_viscosity_ratio` (ln(eta/eta0) on p [Pa]); the
    logarithmic form lets solvers work at very high pressure without overflow.
    """

    kind = "pressure"
    requires = ("pressure", "eta0", "alpha")
    provides = ("viscosity",)

    @abc.abstractmethod
    def log_viscosity_ratio(self, pressure, eta0: float, alpha: float):
        """ln(eta/eta0) [-] at gauge pressure ``pressure`` [Pa]."""

    def viscosity_ratio(self, pressure, eta0: float, alpha: float):
        """eta/eta0 [-]; raises :class:`InputError` instead of overflowing to inf."""
        log_ratio = np.asarray(self.log_viscosity_ratio(pressure, eta0, alpha), dtype=float)
        if np.any(log_ratio > 700.0):
            raise InputError(
                f"{self.name}: eta/eta0 = exp({log_ratio.max():.4g}) overflows float64 at "
                f"p = {np.max(pressure):.4g} Pa; use log_viscosity_ratio() for such pressures"
            )
        ratio = np.exp(log_ratio)
        return float(ratio) if ratio.ndim == 0 else ratio

    def viscosity(self, pressure, eta0: float, alpha: float):
        """Dynamic viscosity eta [Pa*s] at gauge pressure ``pressure`` [Pa]."""
        return eta0 * self.viscosity_ratio(pressure, eta0, alpha)

    def evaluate(self, pressure, eta0, alpha):
        return {"viscosity": self.viscosity(pressure, eta0, alpha)}


class ViscosityTemperatureLaw(ViscosityLaw):
    """Viscosity–temperature law fitted to data points.

    ``fit(temperatures [K], viscosities)`` returns a fitted copy; the fitted law gives
    :meth:`viscosity` at T [K] in the unit of the data (kinematic m^2/s for laws
    defined on kinematic viscosity) and :meth:`thermoviscous_coefficient` -d(ln nu)/dT [1/K].
    """

    kind = "temperature"
    requires = ("temperature",)
    provides = ("kinematic_viscosity",)
    #: minimum number of (T, viscosity) points needed by :meth:`fit`
    points_needed: ClassVar[int] = 2

    @abc.abstractmethod
    def fit(self, temperatures, viscosities) -> ViscosityTemperatureLaw:
        """See the class docstring."""

    @abc.abstractmethod
    def viscosity(self, temperature):
        """See the class docstring."""

    @abc.abstractmethod
    def thermoviscous_coefficient(self, temperature):
        """See the class docstring."""

    def evaluate(self, temperature):
        return {"kinematic_viscosity": self.viscosity(temperature)}


class DensityLaw(Model):
    """Family ``density_laws``: rho(p)/rho0 [-] at gauge pressure p [Pa]."""

    family = "density_laws"
    positive_outputs = ("density_ratio",)
    requires = ("pressure",)
    provides = ("density_ratio",)

    @abc.abstractmethod
    def density_ratio(self, pressure):
        """See the class docstring."""

    def evaluate(self, pressure):
        return {"density_ratio": self.density_ratio(pressure)}


class FilmModel(Model):
    """Family ``film_models``: film thickness of a lubricated contact.

    ``geometry`` is ``"line"`` (inputs: reduced radius ``R`` [m], load per unit length
    ``w`` [N/m]) or ``"point"`` (``Rx``, ``Ry`` [m], load ``F`` [N]); both take the reduced
    modulus ``E_reduced`` = E' [Pa] (Hamrock convention), entrainment speed
    ``u_m`` = (u1+u2)/2 [m/s], ``eta0`` [Pa*s] and ``alpha`` [1/Pa]. ``provides`` is a
    subset of ``("h_c", "h_min")`` [m]. ``can_disable`` lists the physical effects the
    model can represent switched off (``"piezoviscosity"``: alpha = 0; ``"elasticity"``:
    rigid surfaces); a formula fitted only to elastic-piezoviscous solutions lists none,
    and an Analysis whose scene switches such an effect off refuses it up front.
    """

    family = "film_models"
    positive_outputs = ("h_c", "h_min")
    geometry: ClassVar[str] = "line"
    can_disable: ClassVar[tuple[str, ...]] = ()


class FrictionModel(Model):
    """Family ``friction_models``: friction of a contact.

    ``provides`` includes ``"friction_coefficient"`` [-] and/or ``"friction_force"`` [N].
    """

    family = "friction_models"
    nonnegative_outputs = ("friction_coefficient",)


class WearModel(Model):
    """Family ``wear_models``: wear rate; ``provides`` includes ``"wear_rate"`` [m^3/s]."""

    family = "wear_models"
    nonnegative_outputs = ("wear_rate",)


class LifeModel(Model):
    """Family ``life_models``: fatigue life; ``provides`` includes ``"L10"`` [revolutions or cycles]."""

    family = "life_models"
    positive_outputs = ("L10",)


class TractionModel(Model):
    """Family ``traction_models``: lubricant shear stress / traction coefficient.

    ``provides`` includes ``"shear_stress"`` [Pa] and/or ``"traction_coefficient"`` [-].
    """

    family = "traction_models"


class BearingFrictionModel(Model):
    """Family ``bearing_friction_models``: frictional moment of a whole rolling bearing.

    ``provides`` includes ``"friction_moment"`` [N m] (and its parts, in N m); inputs are the bearing's
    loads [N], the relative speed of its rings ``speed`` [rev/s], ``kinematic_viscosity`` [m^2/s] and
    its size [m].
    """

    family = "bearing_friction_models"
    nonnegative_outputs = ("friction_moment",)


class MotionLaw(Model):
    """Family ``motion_laws``: a normalised cam motion law on x in [0, 1].

    :meth:`derivatives` returns (y, y', y'', y''') of the unit-lift segment with respect
    to x [-]; ``provides`` is ``("y", "dy", "d2y", "d3y")``.
    """

    family = "motion_laws"
    requires = ("x",)
    provides = ("y", "dy", "d2y", "d3y")

    @abc.abstractmethod
    def derivatives(self, x):
        """See the class docstring."""

    def evaluate(self, x):
        return dict(zip(self.provides, self.derivatives(x)))


#: family name -> base class (the entry-point group is ``"camcontact." + family``)
FAMILIES: dict[str, type[Model]] = {
    "motion_laws": MotionLaw,
    "viscosity_laws": ViscosityLaw,
    "density_laws": DensityLaw,
    "film_models": FilmModel,
    "friction_models": FrictionModel,
    "wear_models": WearModel,
    "life_models": LifeModel,
    "traction_models": TractionModel,
    "bearing_friction_models": BearingFrictionModel,
}


def check_family(family: str) -> None:
    """Raise :class:`~camcontact.errors.UnknownModelError` unless ``family`` is one of :data:`FAMILIES`."""
    if family not in FAMILIES:
        raise UnknownModelError(
            f"unknown model family {family!r}; families are: {', '.join(FAMILIES)}"
        )


#: the class attribute that :func:`builtin` sets (read from the class's own namespace, so a
#: subclass of a built-in is not a built-in)
BUILTIN_MARK = "__camcontact_builtin__"


def builtin(cls: type[Model]) -> type[Model]:
    """Class decorator marking ``cls`` as a built-in model of its ``family`` under ``cls.name``.

    It only marks the class (and checks its family and name); :mod:`camcontact.registry`
    registers the marked classes of a family's built-in modules when the family is first
    looked up, so the models do not depend on the registry.
    """
    check_family(cls.family)
    if not cls.name:
        raise TypeError(f"{cls.__qualname__} has no 'name'")
    setattr(cls, BUILTIN_MARK, True)
    return cls


def is_builtin(obj: Any) -> bool:
    """True for a class marked by :func:`builtin` itself (not by inheritance)."""
    return isinstance(obj, type) and vars(obj).get(BUILTIN_MARK, False) is True


def builtin_classes(module: ModuleType) -> list[type[Model]]:
    """The classes marked by :func:`builtin` that ``module`` defines, in definition order."""
    return [obj for obj in vars(module).values() if is_builtin(obj) and obj.__module__ == module.__name__]


def output_problems(model: Model, produced: Any) -> list[str]:
    """What is wrong with the outputs ``produced`` of ``model`` (empty: nothing): not a mapping, a name of
    its ``provides`` missing, a numeric output not finite, or outside the sign its family requires
    (``positive_outputs``, ``nonnegative_outputs`` of the family base class)."""
    if not isinstance(produced, Mapping):
        return [f"{type(produced).__name__} instead of a mapping of its outputs {list(model.provides)}"]
    family = FAMILIES.get(model.family, Model)
    problems = [f"no {name!r} (it declares provides = {list(model.provides)})"
                for name in model.provides if name not in produced]
    for name, value in produced.items():
        try:
            array = np.asarray(value, dtype=float)
        except (TypeError, ValueError):  # an object (a numerical solution, a record): not a number to check
            continue
        if not np.all(np.isfinite(array)):
            bad = array[~np.isfinite(array)] if array.ndim else array
            problems.append(f"{name} = {float(np.ravel(bad)[0])!r} (not finite)")
        elif name in family.positive_outputs and np.any(array <= 0.0):
            problems.append(f"{name} = {float(array.min())!r} (allowed: > 0)")
        elif name in family.nonnegative_outputs and np.any(array < 0.0):
            problems.append(f"{name} = {float(array.min())!r} (allowed: >= 0)")
    return problems


class CallableModel(Model):
    """Adapter that lets a user pass a plain function where a model is expected.

    The function is called with the state mapping's ``requires`` as keywords and must
    return a dict of the ``provides`` names.
    """

    def __init__(self, function: Callable[..., Mapping[str, Any]], family: str,
                 requires: tuple[str, ...], provides: tuple[str, ...]):
        self._function = function
        self.family = family  # type: ignore[misc]
        self.name = getattr(function, "__name__", "user_function")  # type: ignore[misc]
        self.reference = "user-supplied function"  # type: ignore[misc]
        self.requires = tuple(requires)  # type: ignore[misc]
        self.provides = tuple(provides)  # type: ignore[misc]

    def evaluate(self, **inputs: Any) -> dict[str, Any]:
        return dict(self._function(**inputs))
