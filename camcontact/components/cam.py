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
from ..units import Component, Quantity, in_range, instance_of, non_negative, number_field, positive, quantity_field
from .material import Material

__all__ = ["Cam", "Follower", "ValveTrain"]


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

    name: str = "cam"
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
    name : str
    """

    name: str = "follower"
    kind: str = attrs.field(default="roller", validator=attrs.validators.in_(("roller", "flat")))
    material: Material = attrs.field(validator=instance_of(Material))
    roller_radius: Quantity = quantity_field("[length]", optional=True, validators=[positive("m")])
    offset: Quantity = quantity_field("[length]", default="0 mm")
    max_pressure_angle: Quantity = quantity_field(
        "[angle]", default="30 deg", validators=[in_range(0.0, math.pi / 2, lower_inclusive=False, unit="rad")]
    )
    roughness: Quantity = quantity_field("[length]", optional=True, validators=[non_negative("m")])

    def __attrs_post_init__(self) -> None:
        where = f"Follower {self.name!r}"
        if self.kind == "roller" and self.roller_radius is None:
            raise InputError(f"{where}: kind='roller' needs roller_radius")
        if self.kind == "flat":
            if self.roller_radius is not None:
                raise InputError(f"{where}: a flat-faced follower has no roller_radius (got {self.roller_radius})")
            if self.si.offset != 0.0:
                raise InputError(
                    f"{where}: offset = {self.offset} has no effect on a flat-faced follower's kinematics; "
                    "give 0 mm (or use kind='roller')"
                )

    @classmethod
    def roller(cls, *, radius, material: Material, offset="0 mm", **kwargs) -> Follower:
        """An offset roller follower of roller radius ``radius``."""
        return cls(kind="roller", roller_radius=radius, offset=offset, material=material, **kwargs)

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

    name: str = "valve train"
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
                raise InputError(f"ValveTrain {self.name!r}: lumped = {self.lumped!r}; expected a LumpedValveTrain")

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
