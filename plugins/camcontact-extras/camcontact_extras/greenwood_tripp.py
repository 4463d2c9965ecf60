"""Greenwood–Tripp (1970) asperity contact and the mixed-lubrication friction coefficient.

For two Gaussian rough surfaces (composite RMS sigma, summit density eta, summit radius
beta) whose mean planes are a distance h apart, the nominal asperity pressure is

.. math::
    p_a = \\frac{8\\sqrt{2}}{15}\\,\\pi\\,(\\eta\\beta\\sigma)^2 \\sqrt{\\frac{\\sigma}{\\beta}}\\;
          E'\\,F_{5/2}\\!\\left(\\frac{h}{\\sigma}\\right),\\qquad
    F_n(\\lambda) = \\frac{1}{\\sqrt{2\\pi}}\\int_\\lambda^\\infty (s - \\lambda)^n e^{-s^2/2}\\,ds

(the usual 16 sqrt(2)/15 with Johnson's E* = E'/2). F_n is evaluated exactly through the
parabolic-cylinder function, F_n(lambda) = Gamma(n+1)/sqrt(2 pi) e^(-lambda^2/4) D_-(n+1)(lambda).
The asperity load W_a = p_a A over the nominal area A carries the fraction
f_a = min(W_a/F, 1) of the load; the mixed friction coefficient is
mu = mu_b f_a + mu_f (1 - f_a) with a boundary coefficient mu_b on the asperities and a
fluid traction coefficient mu_f on the rest (0 by default: boundary part only).
"""

from __future__ import annotations

import math

import attrs
import numpy as np
from scipy import special

from camcontact.errors import InputError
from camcontact.models.base import FrictionModel

__all__ = ["GreenwoodTripp", "greenwood_tripp_pressure", "gaussian_moment"]


def gaussian_moment(n: float, lam):
    """F_n(lambda) [-] of the unit Gaussian (exact, any n > -1, any real lambda)."""
    lam = np.asarray(lam, dtype=float)
    d, _ = special.pbdv(-(n + 1.0), lam)
    value = math.gamma(n + 1.0) / math.sqrt(2.0 * math.pi) * np.exp(-0.25 * lam * lam) * d
    return float(value) if value.ndim == 0 else value


def greenwood_tripp_pressure(h, sigma, E_reduced, eta_beta_sigma, sigma_over_beta):
    """Nominal asperity contact pressure p_a [Pa] at mean-plane separation h [m]."""
    if not (sigma > 0 and E_reduced > 0 and eta_beta_sigma > 0 and sigma_over_beta > 0):
        raise InputError(
            "Greenwood–Tripp: sigma, E', eta*beta*sigma and sigma/beta must be > 0; got "
            f"{sigma!r}, {E_reduced!r}, {eta_beta_sigma!r}, {sigma_over_beta!r}"
        )
    factor = 8.0 * math.sqrt(2.0) / 15.0 * math.pi * eta_beta_sigma**2 * math.sqrt(sigma_over_beta)
    return factor * E_reduced * gaussian_moment(2.5, np.asarray(h, dtype=float) / sigma)


@attrs.frozen
class GreenwoodTripp(FrictionModel):
    """Mixed-lubrication friction from the Greenwood–Tripp asperity load share.

    Parameters
    ----------
    eta_beta_sigma : float
        Roughness parameter eta*beta*sigma [-] (summit density x summit radius x sigma).
    sigma_over_beta : float
        sigma/beta [-] (RMS roughness over summit radius).
    boundary_friction : float
        Friction coefficient on the asperity-carried load [-].
    fluid_friction : float
        Traction coefficient on the fluid-carried load [-] (0: report the boundary part).

    Inputs (``requires``): film (mean-plane separation) ``h_c`` [m], composite roughness
    ``sigma`` [m], ``E_reduced`` [Pa], nominal contact area ``contact_area`` [m^2], normal
    load ``F`` [N].

    References
    ----------
    Greenwood, J.A. & Tripp, J.H. (1970) The contact of two nominally flat rough surfaces,
    Proc. Inst. Mech. Eng. 185:625–633.
    """

    name = "greenwood_tripp"
    reference = "Greenwood & Tripp (1970) Proc. IMechE 185:625-633"
    requires = ("h_c", "sigma", "E_reduced", "contact_area", "F")
    provides = ("asperity_pressure", "asperity_load_fraction", "friction_coefficient")
    validity = {"lambda": (0.0, 4.0)}

    eta_beta_sigma: float = 0.05
    sigma_over_beta: float = 1e-3
    boundary_friction: float = 0.1
    fluid_friction: float = 0.0

    def evaluate(self, h_c, sigma, E_reduced, contact_area, F):
        if not (contact_area > 0 and F > 0):
            raise InputError(f"greenwood_tripp: contact_area = {contact_area!r} m^2 and F = {F!r} N must be > 0")
        p_a = greenwood_tripp_pressure(h_c, sigma, E_reduced, self.eta_beta_sigma, self.sigma_over_beta)
        fraction = np.minimum(p_a * contact_area / F, 1.0)
        mu = self.boundary_friction * fraction + self.fluid_friction * (1.0 - fraction)
        return {"asperity_pressure": p_a, "asperity_load_fraction": fraction, "friction_coefficient": mu}
