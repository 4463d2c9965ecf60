"""Traction models of a rolling contact with creep and spin (family ``traction_models``).

=========== ================================================ ===========================================
name        what                                             requires
=========== ================================================ ===========================================
constant    Ct given (Saccheto's baseline Ct = mu_min, or a  normal_force
            fluid of Tabelas 4.2/4.3); limit Ct N
fastsim     Kalker's FASTSIM creep forces, spin moment and   normal_force, a_rolling, b_lateral,
            slip fraction for a Coulomb bound Ct p           traction_coefficient, shear_modulus,
                                                             creepage_x, creepage_y, spin_creepage
=========== ================================================ ===========================================

All inputs are SI floats or arrays (they broadcast; ``fastsim`` runs once per point). Sign
conventions of ``fastsim`` are those of :mod:`camcontact.contact.fastsim` (Kalker's): x is the
rolling direction, forces act on the body whose creepages are given and oppose the creepage.
"""

from __future__ import annotations

from typing import NamedTuple

import attrs
import numpy as np

from ..contact.fastsim import DEFAULT_NX, DEFAULT_NY, DEFAULT_PRESSURE, check_pressure, fastsim
from ..contact.kalker import B_OVER_A_RANGE
from ..errors import InputError
from ..units import in_range, number_field
from .base import TractionModel, builtin, float_or_array

__all__ = ["SACCHETO_MU_MIN", "TRACTION_FLUIDS", "ConstantTraction", "Fastsim", "TractionFluid"]

#: Saccheto (2008) §7.3 baseline: Ct = mu_min = tan(eta) R_cam/(sin(alpha) R_cont) (Eq. 6.19) = 0.08813 [-]
SACCHETO_MU_MIN = 0.08813


class TractionFluid(NamedTuple):
    """A traction coefficient from the literature (a range when the source gives one)."""

    label: str  #: the fluid as printed
    low: float  #: lowest Ct [-]
    high: float  #: highest Ct [-]
    source: str  #: where it is printed


_FORTI = "Saccheto (2008) Tabela 4.3 (Forti 2003)"
#: Traction coefficients of Saccheto (2008) Tabelas 4.2 and 4.3. Santotrac 50 appears in both with
#: different values (0.095 in Tabela 4.2, 0.100 in Tabela 4.3); both are kept.
TRACTION_FLUIDS: dict[str, TractionFluid] = {
    "santotrac_50": TractionFluid("SANTOTRAC 50", 0.095, 0.095, "Saccheto (2008) Tabela 4.2 (www.santotrac.com)"),
    "ester_silicate": TractionFluid("Ester-silicate oil", 0.045, 0.045, _FORTI),
    "paraffinic": TractionFluid("Paraffinic", 0.050, 0.050, _FORTI),
    "automatic_transmission_fluid": TractionFluid("Automatic transmission fluids", 0.055, 0.055, _FORTI),
    "mil_h_5606": TractionFluid("MIL H-5606 hydraulic oil", 0.060, 0.060, _FORTI),
    "naphthenic": TractionFluid("Naphthenic oil", 0.058, 0.065, _FORTI),
    "ester_naphthenic": TractionFluid("Ester-naphthenic oil", 0.066, 0.066, _FORTI),
    "silicone": TractionFluid("Silicones", 0.075, 0.075, _FORTI),
    "santotrac_30": TractionFluid("SANTOTRAC 30", 0.084, 0.084, _FORTI),
    "santotrac_40_50_70": TractionFluid("SANTOTRAC 40, 50, 70", 0.100, 0.100, _FORTI),
}


@builtin
@attrs.frozen
class ConstantTraction(TractionModel):
    """Constant traction coefficient: the Coulomb limit of a traction contact.

    .. math:: C_t = \\text{const}, \\qquad F_{t,max} = C_t N

    Saccheto's CVT simulation uses a constant Ct, by default Ct = mu_min (§7.3, Eq. 6.19:
    :data:`SACCHETO_MU_MIN` = 0.08813) so that the slip is visible, and varies it in §7.7.
    :meth:`for_fluid` picks a value of :data:`TRACTION_FLUIDS`.

    Parameters
    ----------
    coefficient : float
        Ct [-], 0 <= Ct <= 1.
    fluid : str
        Free label of the fluid (reported only); default "".

    Inputs (``requires``): ``normal_force`` N [N] (>= 0). Returns ``traction_coefficient`` Ct [-]
    and ``traction_limit`` Ct N [N].

    References
    ----------
    Saccheto (2008) §4.4, §7.3, Tabelas 4.2, 4.3 (Forti 2003), Eq. 6.19.
    """

    name = "constant"
    reference = "Saccheto (2008) §4.4, §7.3 (Ct = mu_min, Eq. 6.19), Tabelas 4.2-4.3 (Forti 2003)"
    requires = ("normal_force",)
    provides = ("traction_coefficient", "traction_limit")

    coefficient: float = number_field(validators=[in_range(0.0, 1.0)], doc="traction coefficient Ct [-]")
    fluid: str = attrs.field(default="", validator=attrs.validators.instance_of(str))

    @classmethod
    def for_fluid(cls, fluid: str) -> ConstantTraction:
        """The model with Ct of ``fluid`` (a key of :data:`TRACTION_FLUIDS`); where the source
        gives a range the lower end is taken (the conservative traction capacity)."""
        entry = TRACTION_FLUIDS.get(fluid)
        if entry is None:
            raise InputError(f"fluid = {fluid!r} is not in the traction-fluid table; allowed: "
                             f"{', '.join(sorted(TRACTION_FLUIDS))}")
        return cls(coefficient=entry.low, fluid=entry.label)

    def evaluate(self, normal_force):
        """Ct [-] and the traction limit Ct N [N] for N [N]."""
        N = np.asarray(normal_force, dtype=float)
        if not np.all(np.isfinite(N)) or np.any(N < 0.0):
            raise InputError(f"traction model 'constant': normal_force = {normal_force!r} N; allowed: finite, >= 0")
        return {"traction_coefficient": float_or_array(np.full(N.shape, self.coefficient)),
                "traction_limit": float_or_array(self.coefficient * N)}


def _grid_count(instance, attribute, value):
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise InputError(f"{type(instance).__name__}.{attribute.name} = {value!r}; allowed: an integer >= 1")


def _pressure_choice(instance, attribute, value):
    check_pressure(value, f"{type(instance).__name__}.{attribute.name}")


_OUTPUTS = ("creep_force_x", "creep_force_y", "spin_moment", "slip_fraction", "traction_ratio")


@builtin
@attrs.frozen
class Fastsim(TractionModel):
    """Kalker's FASTSIM: creep forces, spin moment and slip of an elliptical contact.

    .. math::
        T_x = \\left(\\frac{\\nu_x}{L_1} - \\frac{\\phi y}{L_3}\\right)(x - a(y)), \\quad
        T_y = \\frac{\\nu_y}{L_2}(x - a(y)) + \\frac{\\phi}{2 L_3}(x^2 - a(y)^2)
        \\quad \\text{(stick)}, \\qquad |T| \\le C_t\\,p

    strip by strip from the leading edge, clipped to Ct p in the direction of the predicted
    traction where it exceeds it; L1..L3 from Kalker's C_ij (Saccheto Tabela 5.1 at b/a). The
    pressure p of the bound is Kalker's parabolic one, p = 2N/(pi a b)(1 - x^2/a^2 - y^2/b^2), for
    which L1..L3 are calibrated (default), or the semi-ellipsoidal Hertz pressure
    (``Fastsim(pressure="hertz")``, the reading of Saccheto's simulation). See
    :func:`camcontact.contact.fastsim.fastsim`.

    Parameters
    ----------
    nx, ny : int
        Elements per strip and number of strips; default 40 x 40.
    compiled : bool
        numba kernel (default) or its plain-Python twin.
    pressure : {"parabolic", "hertz"}
        Pressure of the traction bound; default "parabolic" (Kalker's FASTSIM).

    Inputs (``requires``): ``normal_force`` N [N] (>= 0; 0 gives zeros), ``a_rolling`` semi-axis
    along rolling [m], ``b_lateral`` lateral semi-axis [m] (0.1 <= b/a <= 10), ``traction_coefficient``
    Ct [-], ``shear_modulus`` G [Pa], ``creepage_x``, ``creepage_y`` [-], ``spin_creepage`` phi
    [1/m]. Returns ``creep_force_x``, ``creep_force_y`` [N] on the body (small creepage:
    -C11 G a b nu_x and -C22 G a b nu_y - C23 G (ab)^1.5 phi), ``spin_moment`` [N*m] about +z,
    ``slip_fraction`` [-] and ``traction_ratio`` |F|/(Ct N) [-].

    References
    ----------
    Kalker, J.J. (1982) A fast algorithm for the simplified theory of rolling contact, Vehicle
    System Dynamics 11:1–13 (parabolic bound); Saccheto (2008) Eqs 5.36–5.54, Tabela 5.1.
    """

    name = "fastsim"
    reference = ("Kalker (1982) Vehicle System Dynamics 11:1-13 (parabolic traction bound); "
                 "Saccheto (2008) Eqs 5.36-5.54, Tabela 5.1")
    requires = ("normal_force", "a_rolling", "b_lateral", "traction_coefficient", "shear_modulus",
                "creepage_x", "creepage_y", "spin_creepage")
    provides = _OUTPUTS
    #: b_over_a = b_lateral / a_rolling, the range of Kalker's table (outside it: InputError)
    validity = {"b_over_a": B_OVER_A_RANGE}

    nx: int = attrs.field(default=DEFAULT_NX, validator=_grid_count)
    ny: int = attrs.field(default=DEFAULT_NY, validator=_grid_count)
    compiled: bool = attrs.field(default=True, validator=attrs.validators.instance_of(bool))
    pressure: str = attrs.field(default=DEFAULT_PRESSURE, validator=_pressure_choice)

    def _point(self, N, a, b, mu, G, nu_x, nu_y, phi) -> tuple[float, ...]:
        if N == 0.0:
            return (0.0,) * len(_OUTPUTS)
        r = fastsim(a, b, N, mu, G, nu_x, nu_y, phi, nx=self.nx, ny=self.ny, compiled=self.compiled,
                    pressure=self.pressure)
        return r.Fx, r.Fy, r.Mz, r.slip_fraction, r.traction_ratio

    def evaluate(self, normal_force, a_rolling, b_lateral, traction_coefficient, shear_modulus,
                 creepage_x, creepage_y, spin_creepage):
        """See the class docstring (SI inputs; outputs in N, N, N*m, -, -)."""
        arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (
            normal_force, a_rolling, b_lateral, traction_coefficient, shear_modulus,
            creepage_x, creepage_y, spin_creepage)))
        out = np.empty((len(_OUTPUTS),) + arrays[0].shape)
        for index in np.ndindex(arrays[0].shape):
            out[(slice(None),) + index] = self._point(*(float(v[index]) for v in arrays))
        return {key: float_or_array(value) for key, value in zip(_OUTPUTS, out)}
