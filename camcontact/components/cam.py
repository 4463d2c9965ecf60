"""Cam, follower and valve train: the components of a cam–follower scene.

Geometry conventions (Tsuha 2015 §3.2–3.4): the cam turns counter-clockwise at ``speed``;
the follower translates along the vertical axis above the cam centre (offset ``offset`` to
+x for a roller follower). The lift f(θ) of the cam's :class:`MotionProgram` is measured above
the base circle. For a roller follower the prime (pitch) circle radius is
R_po = base_radius + roller radius, and the roller centre sits at S = sqrt(R_po² − ε²) + f.
"""

from __future__ import annotations

import math

import attrs

from ..errors import InputError
from ..units import (Component, Quantity, in_range, instance_of, non_negative, number_field, one_of, positive,
                     quantity_field, text)
from .material import Material

__all__ = ["STEEL_DENSITY", "Cam", "Follower", "ValveTrain"]

#: density assumed for a roller whose material gives none [kg/m^3] (carbon and bearing steels 7800-7850)
STEEL_DENSITY = 7850.0


def _motion_program(instance, attribute, value):
    from ..kinematics.motion_program import MotionProgram

    if not isinstance(value, MotionProgram):
        raise InputError(
            f"{type(instance).__name__}.{attribute.name} = {value!r}: expected a MotionProgram "
            "(e.g. MotionProgram.rise_return_dwell(...))"
        )


@attrs.frozen(kw_only=True)
class Cam(Component):
    """A plate cam: motion program, base circle, width and material.

    Parameters
    ----------
    program : MotionProgram
        Lift f(θ) above the base circle over a full turn.
    base_radius : Quantity or str
        Base-circle radius [length] (> 0). For a flat-faced follower this is R_o of Tsuha
        (2015) Eq. 3.1; for a roller follower R_po = base_radius + roller radius.
    width : Quantity or str
        Cam width = contact length of the line contact [length] (> 0).
    material : Material
    roughness : Quantity or str, optional
        RMS roughness [length], for Lambda.
    name : str
    """

    name: str = attrs.field(default="cam", validator=text)
    program: object = attrs.field(validator=_motion_program)
    base_radius: Quantity = quantity_field("[length]", validators=[positive("m")])
    width: Quantity = quantity_field("[length]", validators=[positive("m")])
    material: Material = attrs.field(validator=instance_of(Material))
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])


@attrs.frozen(kw_only=True)
class Follower(Component):
    """A translating follower: flat-faced, or a roller with an offset.

    Parameters
    ----------
    kind : {"roller", "flat"}
    material : Material
    roller_radius : Quantity or str, optional
        Roller radius R_f [length] (> 0); required for ``kind="roller"``.
    offset : Quantity or str
        Offset ε of the follower axis from the cam centre [length] (roller only; sign as Tsuha
        2015 Eq. 3.19, tan A_p = (f' − ε)/S).
    max_pressure_angle : Quantity or str
        Design limit of the pressure angle (default 30°, Tsuha 2015 §2.1 after Uicker et al.).
    roughness : Quantity or str, optional
        RMS roughness [length].
    roller_width : Quantity or str, optional
        Width of the roller [length] (> 0; roller only), for its inertia; default: the cam's width.
    roller_inertia : Quantity or str, optional
        Polar moment of inertia of the roller about its pin [mass*length²] (> 0; roller only); default: a
        solid cylinder, (π/2) ρ w R_f⁴, of the follower material's density (7850 kg/m³, steel, when the
        material gives none).
    pin_radius : Quantity or str, optional
        Radius of the pin (the roller's bearing seat) [length] (0 < r_pin < R_f; roller only); default
        0.4 R_f (a needle bearing on a pin of 40 % of the roller's diameter, typical proportions of
        automotive roller lifters; an assumption — give the design's value).
    pin_friction_coefficient : float
        Friction coefficient of the pin bearing referred to the pin radius (0 <= μ_pin <= 0.3; roller only):
        torque μ_pin N r_pin. Default 0.0025, the constant friction coefficient of needle roller bearings
        with a cage in the SKF general catalogue (friction, table of μ); a plain bush runs about 0.05–0.15.
    name : str
    """

    name: str = attrs.field(default="follower", validator=text)
    kind: str = attrs.field(default="roller", validator=one_of("roller", "flat"))
    material: Material = attrs.field(validator=instance_of(Material))
    roller_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    offset: Quantity = quantity_field("[length]", default="0 mm")
    max_pressure_angle: Quantity = quantity_field(
        "[angle]", default="30 deg", validators=[in_range(0.0, math.pi / 2, lower_inclusive=False, unit="rad")]
    )
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])
    roller_width: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    roller_inertia: Quantity = quantity_field("[mass]*[length]**2", optional=True, validators=[positive("kg*m^2")])
    pin_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    pin_friction_coefficient: float = number_field(default=0.0025, validators=[in_range(0.0, 0.3)])

    def __attrs_post_init__(self) -> None:
        where = f"Follower {self.name!r}"
        if self.kind == "roller" and self.roller_radius is None:
            raise InputError(f"{where}: kind='roller' needs roller_radius")
        if self.kind == "roller" and self.pin_radius is not None and not self.si.pin_radius < self.si.roller_radius:
            raise InputError(f"{where}: pin_radius = {self.pin_radius} must be smaller than roller_radius = "
                             f"{self.roller_radius}")
        if self.kind == "flat":
            given = [n for n in ("roller_radius", "roller_width", "roller_inertia", "pin_radius")
                     if getattr(self, n) is not None]
            if given:
                raise InputError(f"{where}: a flat-faced follower has no {given[0]} (got {getattr(self, given[0])})")
            if self.si.offset != 0.0:
                raise InputError(
                    f"{where}: offset = {self.offset} has no effect on a flat-faced follower's kinematics; "
                    "give 0 mm (or use kind='roller')"
                )

    @classmethod
    def roller(cls, *, radius, material: Material, offset="0 mm", **kwargs) -> Follower:
        """An offset roller follower of roller radius ``radius`` and offset ``offset`` [length] (Quantity or str)."""
        return cls(kind="roller", roller_radius=radius, offset=offset, material=material, **kwargs)

    def roller_inertia_si(self, cam_width: float) -> float:
        """The roller's polar moment of inertia [kg m^2]: ``roller_inertia``, else a solid cylinder of
        ``roller_width`` (default ``cam_width`` [m]) and the material's density (7850 kg/m^3 without one)."""
        if self.kind != "roller":
            raise InputError(f"Follower {self.name!r} is flat-faced: it has no roller inertia")
        if self.roller_inertia is not None:
            return self.si.roller_inertia
        from ..dynamics.roller_follower import solid_roller_inertia

        width = self.si.roller_width if self.roller_width is not None else cam_width
        density = self.material.si.density if self.material.density is not None else STEEL_DENSITY
        return solid_roller_inertia(self.si.roller_radius, width, density)

    @property
    def pin_radius_si(self) -> float:
        """The pin radius [m]: ``pin_radius``, else 0.4 R_f."""
        if self.kind != "roller":
            raise InputError(f"Follower {self.name!r} is flat-faced: it has no pin")
        return self.si.pin_radius if self.pin_radius is not None else 0.4 * self.si.roller_radius

    @classmethod
    def flat(cls, *, material: Material, **kwargs) -> Follower:
        """A translating flat-faced follower."""
        return cls(kind="flat", material=material, **kwargs)


@attrs.frozen(kw_only=True)
class ValveTrain(Component):
    """Equivalent 1-DOF valve train at the follower, optionally with a lumped multi-DOF model.

    F = m S̈ + c Ṡ + k f + F_pl (Tsuha 2015 Eq. 3.46 with the preload of its Chapter 6).

    Parameters
    ----------
    mass : Quantity or str
        Effective mass m at the follower [mass] (> 0).
    stiffness : Quantity or str
        Effective spring stiffness k [force/length] (> 0).
    preload : Quantity or str
        Spring preload F_pl [force] (>= 0).
    damping_ratio : float, optional
        ζ (0 <= ζ < 1); c = 2 ζ sqrt(k m) (Tsuha 2015 Eqs. 3.54–3.56). Default 0.06
        (Koster 1974; Norton 2009) unless ``damping`` is given.
    damping : Quantity or str, optional
        Damping coefficient c [force*time/length] instead of ``damping_ratio``.
    lumped : LumpedValveTrain, optional
        2-DOF or 5-DOF model (Ferrarese & Uehara) used when a scene switches the
        ``dynamics`` effect on.
    name : str
    """

    name: str = attrs.field(default="valve train", validator=text)
    mass: Quantity = quantity_field("[mass]", validators=[positive("kg")])
    stiffness: Quantity = quantity_field("[force]/[length]", validators=[positive("N/m")])
    preload: Quantity = quantity_field("[force]", default="0 N", validators=[non_negative("N")])
    damping_ratio: float = number_field(optional=True, validators=[in_range(0.0, 1.0, upper_inclusive=False)])
    damping: Quantity = quantity_field("[force]*[time]/[length]", optional=True, validators=[non_negative("N*s/m")])
    lumped: object = None

    def __attrs_post_init__(self) -> None:
        if self.damping_ratio is not None and self.damping is not None:
            raise InputError(f"ValveTrain {self.name!r}: give damping_ratio or damping, not both")
        if self.lumped is not None:
            from ..dynamics.valve_train_ode import LumpedValveTrain

            if not isinstance(self.lumped, LumpedValveTrain):
                raise InputError(f"ValveTrain.lumped = {self.lumped!r}; allowed: None or a LumpedValveTrain "
                                 f"(ValveTrain {self.name!r})")

    @property
    def c(self) -> float:
        """Damping coefficient c [N s/m]."""
        if self.damping is not None:
            return self.si.damping
        zeta = 0.06 if self.damping_ratio is None else self.damping_ratio
        return 2.0 * zeta * math.sqrt(self.si.stiffness * self.si.mass)

    @property
    def zeta(self) -> float:
        """Damping ratio ζ = c / (2 sqrt(k m)) [-]."""
        return self.c / (2.0 * math.sqrt(self.si.stiffness * self.si.mass))

    @property
    def natural_frequency(self) -> float:
        """Undamped natural frequency ω_n = sqrt(k/m) [rad/s]."""
        return math.sqrt(self.si.stiffness / self.si.mass)

    @classmethod
    def from_pushrod_train(
        cls, *, lifter_mass, pushrod_mass, rocker_inertia, valve_mass, spring_mass, pushrod_stiffness,
        valve_stiffness, spring_stiffness, pushrod_arm, valve_arm, preload="0 N", damping_ratio=0.06,
        name="push-rod valve train",
    ) -> ValveTrain:
        """Equivalent system of a push-rod valve train (Tsuha 2015 §6, after Rothbart 2004).

        .. math::
            m = m_l + m_{pr} + J_{ra}/l_{pr}^2 + (m_{vs} + m_{cs}/3)(l_{vs}/l_{pr})^2

            1/k = (l_{pr}/l_{vs})^2/k_{cs} + (l_{pr}/l_{vs})^2/k_{vs} + 1/k_{pr}

        Lifter and rocker are rigid; one third of the spring mass moves with the valve.
        Arguments are Quantities or strings (masses [kg], inertia [kg m²], stiffnesses [N/m],
        lever arms [m]: rocker pivot to push rod and to valve).
        """
        from ..units import si_value, to_quantity

        def si(value, dimension, field):
            magnitude = float(si_value(to_quantity(value, dimension, where=f"ValveTrain.from_pushrod_train {field}")))
            if magnitude <= 0.0:
                raise InputError(f"ValveTrain.from_pushrod_train: {field} = {value} must be > 0")
            return magnitude

        m_l, m_pr, m_vs, m_cs = (si(v, "[mass]", f) for v, f in ((lifter_mass, "lifter_mass"), (pushrod_mass, "pushrod_mass"),
                                                                  (valve_mass, "valve_mass"), (spring_mass, "spring_mass")))
        J = si(rocker_inertia, "[mass]*[length]**2", "rocker_inertia")
        k_pr, k_vs, k_cs = (si(v, "[force]/[length]", f) for v, f in ((pushrod_stiffness, "pushrod_stiffness"),
                                                                      (valve_stiffness, "valve_stiffness"),
                                                                      (spring_stiffness, "spring_stiffness")))
        l_pr, l_vs = si(pushrod_arm, "[length]", "pushrod_arm"), si(valve_arm, "[length]", "valve_arm")
        ratio = l_vs / l_pr
        mass = m_l + m_pr + J / l_pr**2 + (m_vs + m_cs / 3.0) * ratio**2
        stiffness = 1.0 / (1.0 / (ratio**2 * k_cs) + 1.0 / (ratio**2 * k_vs) + 1.0 / k_pr)
        return cls(mass=f"{mass!r} kg", stiffness=f"{stiffness!r} N/m", preload=preload, damping_ratio=damping_ratio,
                   name=name)

    @classmethod
    def ls1(cls) -> ValveTrain:
        """The LS-1 push-rod valve train of Tsuha (2015) Table 6.1 (m = 0.662 kg, k = 1.199e5 N/m,
        ζ = 0.06, F_pl = 1000 N), rounded as the thesis uses them (reference §0 item 3)."""
        return cls(mass="0.662 kg", stiffness="1.199e5 N/m", preload="1000 N", damping_ratio=0.06,
                   name="LS-1 push-rod valve train (Tsuha 2015)")
