"""Catalogue of the named quantities an Analysis can report: SI unit, display unit, meaning.

Reports hold plain float columns named ``"name [unit]"``; the unit is the display unit
below unless the caller asks for another (``Result.to_frame(units={"h_min": "nm"})``).
"""

from __future__ import annotations

import attrs

from .errors import InputError

__all__ = ["QUANTITIES", "QuantitySpec", "spec"]


@attrs.frozen
class QuantitySpec:
    """A reportable quantity."""

    name: str
    si_unit: str  #: pint unit of the SI value held inside ("" = dimensionless, None = text)
    display_unit: str  #: unit of the report column by default
    description: str
    #: the status cells that say why a value is NaN by design: (output, value) pairs, any of which in the
    #: same report row explains it (an unloaded roller has no Hertz width; a drive in gross slip no efficiency)
    nan_when: tuple[tuple[str, object], ...] = ()


def _q(name: str, si_unit: str | None, display_unit: str | None, description: str) -> QuantitySpec:
    return QuantitySpec(name, si_unit, display_unit if display_unit is not None else si_unit, description)


#: NaN by design, with the status that says so beside it
_UNLOADED = (("loaded", False), ("contact_regime", "unloaded"))
_NAN_WHEN = {
    **{f"{q}_{race}": _UNLOADED for q in ("b", "p_h", "h_c", "h_min", "Lambda", "flash_temperature",
                                          "rolling_resistance", "asperity_load_fraction", "h_c_mixed", "a_rolling",
                                          "a_transverse", "contact_length", "truncation_margin")
       for race in ("inner", "outer")},
    "contact_angle": _UNLOADED,
    "x_q_max": _UNLOADED,
    # a cam follower that has left the cam (contact_open) has no contact, so no film
    **{q: (("contact_open", True),) for q in ("h_c", "h_min", "Lambda_c", "Lambda_min", "h_c_isothermal",
                                              "h_min_isothermal")},
    "spike_pressure": (("pressure_spike", False),),
    "film_temperature_rise": (("film_thermal", False),),
    "friction_coefficient": (("friction_valid", False),),
    "friction_coefficient_inner": (("friction_valid_inner", False),),
    "friction_coefficient_outer": (("friction_valid_outer", False),),
    **{f"traction_margin_{side}": ((f"gross_slip_{side}", True),) for side in ("in", "out")},
    "efficiency": (("gross_slip_in", True), ("gross_slip_out", True)),
    "power_loss": (("gross_slip_in", True), ("gross_slip_out", True)),
}


QUANTITIES: dict[str, QuantitySpec] = {
    q.name: q
    for q in (
        _q("E_reduced", "Pa", "GPa", "reduced modulus E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2]"),
        _q("R", "m", "mm", "reduced radius of curvature 1/R = 1/R1 + 1/R2"),
        _q("w", "N/m", "N/mm", "load per unit length"),
        _q("u_m", "m/s", "m/s", "entrainment speed (u1 + u2)/2"),
        _q("u_s", "m/s", "m/s", "sliding speed u1 - u2"),
        _q("u1", "m/s", "m/s", "surface speed of body 1 (bearing: the ring at a raceway contact)"),
        _q("u2", "m/s", "m/s", "surface speed of body 2 (bearing: the roller at a raceway contact)"),
        _q("slide_roll_ratio", "", "", "slide-to-roll ratio (u1 - u2)/u_m"),
        _q("b", "m", "um", "Hertz half-width"),
        _q("p_h", "Pa", "MPa", "Hertz maximum pressure"),
        _q("p_mean", "Pa", "MPa", "Hertz mean pressure"),
        _q("approach", "m", "um", "elastic approach of the bodies"),
        _q("tau_max", "Pa", "MPa", "maximum in-plane principal shear stress (body 1)"),
        _q("x_tau_max", "m", "um", "position of tau_max along the rolling direction"),
        _q("z_tau_max", "m", "um", "depth of tau_max"),
        _q("tresca_max", "Pa", "MPa", "maximum 3-D (Tresca) shear stress (body 1)"),
        _q("z_tresca_max", "m", "um", "depth of tresca_max"),
        _q("von_mises_max", "Pa", "MPa", "maximum von Mises stress (body 1)"),
        _q("z_von_mises_max", "m", "um", "depth of von_mises_max"),
        _q("tau_xz_max", "Pa", "MPa", "maximum orthogonal shear stress"),
        _q("x_tau_xz_max", "m", "um", "position of tau_xz_max"),
        _q("z_tau_xz_max", "m", "um", "depth of tau_xz_max"),
        _q("tau_xz_range", "Pa", "MPa", "orthogonal shear range 2 tau_0 (fatigue amplitude)"),
        _q("temperature", "K", "degC", "lubricant (inlet) temperature"),
        _q("eta0", "Pa*s", "mPa*s", "dynamic viscosity at ambient pressure"),
        _q("viscosity_extrapolated", None, None, "the temperature lies outside the lubricant's viscosity data "
           "(the viscosity-temperature law is extrapolated)"),
        _q("kinematic_viscosity", "m^2/s", "cSt", "kinematic viscosity at ambient pressure"),
        _q("alpha", "1/Pa", "1/GPa", "pressure-viscosity coefficient"),
        _q("roelands_z", "", "", "Roelands pressure-viscosity index"),
        _q("thermoviscous_coefficient", "1/K", "1/K", "beta = -d ln(nu)/dT"),
        _q("U", "", "", "Hamrock speed parameter eta0 u_m/(E' R)"),
        _q("G", "", "", "Hamrock materials parameter alpha E'"),
        _q("W", "", "", "Hamrock load parameter"),
        _q("M", "", "", "Moes load parameter"),
        _q("L", "", "", "Moes lubricant parameter"),
        _q("h_c_isothermal", "m", "um", "isothermal central film thickness"),
        _q("h_min_isothermal", "m", "um", "isothermal minimum film thickness"),
        _q("thermal_loading", "", "", "thermal loading parameter beta eta0 (u1+u2)^2/k"),
        _q("thermal_loading_m", "", "", "thermal loading on the mean speed beta eta0 u_m^2 / k (Murch & Wilson)"),
        _q("thermal_valid", None, None, "True where the inlet thermal factor's fit applies (|u1-u2| <= |u1+u2|)"),
        _q("thermal_factor", "", "", "inlet shear-heating film reduction factor phi_T"),
        _q("h_c", "m", "um", "central film thickness"),
        _q("h_min", "m", "um", "minimum film thickness"),
        _q("x_min", "m", "um", "position of the minimum film from the contact centre, positive in the direction of "
                               "positive entrainment u_m (transient film)"),
        _q("sigma", "m", "um", "composite RMS roughness"),
        _q("Lambda_c", "", "", "specific film thickness h_c/sigma"),
        _q("Lambda_min", "", "", "specific film thickness h_min/sigma"),
        _q("regime", None, None, "lubrication regime from Lambda (h_min if available)"),
        _q("film_validity", None, None, "'ok' or where the film model is used outside its fitted range"),
        # cam–follower cycle (per cam angle)
        _q("cam_angle", "rad", "deg", "cam angle"),
        _q("lift", "m", "mm", "follower lift f above the base circle"),
        _q("follower_velocity", "m/s", "m/s", "follower velocity dS/dt"),
        _q("follower_acceleration", "m/s^2", "m/s^2", "follower acceleration d2S/dt2"),
        _q("follower_jerk", "m/s^3", "m/s^3", "follower jerk d3S/dt3"),
        _q("pressure_angle", "rad", "deg", "pressure angle A_p"),
        _q("cam_radius", "m", "mm", "cam radius of curvature at the contact (negative: concave)"),
        _q("u_cam", "m/s", "m/s", "cam surface speed relative to the contact point"),
        _q("u_follower", "m/s", "m/s", "follower surface speed relative to the contact point"),
        _q("angular_speed", "rad/s", "rad/s", "cam angular speed"),
        _q("profile_x", "m", "mm", "cam profile point, x in the cam frame"),
        _q("profile_y", "m", "mm", "cam profile point, y in the cam frame"),
        _q("contact_force", "N", "N", "cam force along the follower axis"),
        _q("inertia_force", "N", "N", "inertia part m d2S/dt2 of the contact force"),
        _q("damping_force", "N", "N", "damping part c dS/dt of the contact force"),
        _q("spring_force", "N", "N", "spring part k f of the contact force"),
        _q("preload_force", "N", "N", "spring preload part of the contact force"),
        _q("cam_torque", "N*m", "N*m", "cam drive torque F (dS/dt) / omega"),
        _q("normal_force", "N", "N", "normal contact force (0 while the contact is open)"),
        _q("contact_open", None, None, "True where the follower has left the cam"),
        _q("film_regime", None, None, "'ok', or why the film at this angle is special (u_m = 0, jump, validity)"),
        _q("film_valid", None, None, "True where the film model is inside its validity and converged (the reason "
                                     "text says why not)"),
        _q("H0", "", "", "rigid-body approach H0 of the numerical solution (Hertz units, x0 = b)"),
        _q("H_min", "", "", "minimum film H_min = h_min R / b^2 of the numerical solution"),
        _q("H_c", "", "", "central film H_c = h_c R / b^2 of the numerical solution"),
        _q("spike_pressure", "", "", "pressure spike height P_s = p_s / p_h of the numerical solution (NaN: no distinct spike)"),
        _q("pressure_spike", None, None, "True where the numerical solution has a distinct pressure spike"),
        _q("friction_force", "N", "N", "friction force at the contact"),
        _q("friction_coefficient", "", "", "friction force / normal force"),
        _q("friction_power", "W", "W", "friction power loss"),
        _q("friction_per_length", "N/m", "N/mm", "friction force per unit length of a line contact"),
        _q("friction_power_per_length", "W/m", "W/mm", "friction power loss per unit length of a line contact"),
        _q("tangential_force", "N", "N", "tangential (friction/traction) force on the follower along the cam surface's motion"),
        _q("friction_torque", "N*m", "N*m", "camshaft torque of the tangential force F_t p"),
        _q("cam_torque_with_friction", "N*m", "N*m", "camshaft drive torque with friction, F dS/dt / omega + F_t p"),
        _q("friction_arm", "m", "mm", "distance p of the contact's tangent from the cam axis"),
        _q("roller_slip", "", "", "roller slide-to-roll ratio u_s/u_m (0: rolling)"),
        _q("roller_slipping", None, None, "True where the roller slips (|u_s/u_m| > 1 %)"),
        _q("traction_exceeded", None, None, "True where the no-slip traction exceeds the traction available"),
        _q("traction_required", "N", "N", "tangential force that keeps the roller rolling (inertia + pin)"),
        _q("traction_available", "N", "N", "largest traction force the contact transmits (in the direction required)"),
        _q("pin_torque", "N*m", "N*m", "friction torque of the roller's pin bearing"),
        _q("asperity_load_fraction", "", "", "share of the load the asperities carry (Greenwood-Tripp, JGP split)"),
        _q("h_c_mixed", "m", "um", "central film at the fluid's share of the load (mixed lubrication)"),
        _q("Lambda_mixed", "", "", "mixed film over composite roughness h_c_mixed / sigma"),
        _q("lubrication_regime", None, None, "boundary, mixed or full_film (open: no contact)"),
        _q("asperity_capacity", "", "", "share of the load the asperities carry at zero separation"),
        _q("mixed_valid", None, None, "True where the load-sharing model can reach the boundary regime"),
        _q("fluid_traction_coefficient", "", "", "traction coefficient of the fluid film at the contact's sliding"),
        _q("traction_regime", None, None, "fluid traction regime: linear, nonlinear, plateau (open: no contact)"),
        _q("traction_temperature_rise", "K", "K", "contact temperature rise of the fluid traction (flash + film)"),
        _q("traction_valid", None, None, "True where the fluid traction coefficient is physical (<= 0.15)"),
        _q("traction_coefficient", "", "", "traction coefficient of the contact"),
        _q("traction_force", "N", "N", "traction force of the contact"),
        _q("traction_shear_stress", "Pa", "MPa", "mean shear stress of the film"),
        _q("roller_inertia", "kg*m^2", "kg*m^2", "roller's polar moment of inertia"),
        _q("wear_rate", "m^3/s", "mm^3/h", "worn volume rate"),
        # cam–follower cycle summaries
        _q("motion_continuity", None, None, "continuity of the motion program at its joints"),
        _q("natural_frequency", "1/s", "Hz", "undamped natural frequency of the 1-DOF valve train"),
        _q("k_min", "N/m", "N/m", "smallest spring stiffness without jump at the design speed"),
        _q("jump", None, None, "whether (and where) the follower leaves the cam"),
        _q("jump_margin", "N", "N", "smallest contact force over the cycle: the margin against jump (<= 0: jump)"),
        _q("contact_force_max", "N", "N", "largest contact force over the cycle"),
        _q("p_h_max", "Pa", "MPa", "largest Hertz pressure over the cycle"),
        _q("h_min_cycle", "m", "um", "smallest minimum film over the cycle"),
        _q("friction_power_mean", "W", "W", "cycle-mean friction power"),
        _q("friction_energy_per_cycle", "J", "J", "friction energy dissipated per cam turn"),
        _q("friction_torque_mean", "N*m", "N*m", "cycle-mean camshaft friction torque"),
        _q("cam_torque_with_friction_max", "N*m", "N*m", "largest camshaft drive torque with friction"),
        _q("wear_rate_mean", "m^3/s", "mm^3/h", "cycle-mean worn volume rate"),
        _q("wear_volume_per_cycle", "m^3", "mm^3", "worn volume per cam revolution"),
        # bearing (per roller: arrays over the index "roller")
        _q("roller", "", "", "roller number (row by row, 0-based)"),
        _q("roller_row", "", "", "row of the roller (1 or 2)"),
        _q("azimuth", "rad", "deg", "roller azimuth from the line of the radial load"),
        _q("Q", "N", "kN", "rolling-element load (roller or ball; inner and outer contact)"),
        _q("loaded", None, None, "True for a rolling element in contact (Q > 0)"),
        _q("roller_approach", "m", "um", "elastic approach of the roller's contacts (negative: gap)"),
        _q("Q_max", "N", "kN", "largest roller load"),
        _q("loaded_rollers", "", "", "number of rollers in contact"),
        _q("load_zone", "rad", "deg",
           "load-zone half-angle arccos(P_d/(2 delta_r)) (Harris & Kotzalas ch. 7; largest over the rows)"),
        _q("last_loaded_azimuth", "rad", "deg", "azimuth of the last loaded roller (largest over the rows)"),
        _q("delta_r", "m", "um", "radial displacement of the inner ring"),
        _q("delta_a", "m", "um", "axial displacement of the inner ring"),
        _q("force_residual", "", "", "relative force imbalance of the load distribution"),
        _q("cage_speed", "rad/s", "rpm", "cage speed (pure rolling)"),
        _q("roller_speed", "rad/s", "rpm", "roller speed about its own axis (bearing: pure rolling; cam roller: its spin dynamics)"),
        _q("b_inner", "m", "um", "Hertz half-width at the inner raceway"),
        _q("p_h_inner", "Pa", "MPa", "Hertz pressure at the inner raceway"),
        _q("b_outer", "m", "um", "Hertz half-width at the outer raceway"),
        _q("p_h_outer", "Pa", "MPa", "Hertz pressure at the outer raceway"),
        _q("contact_length_inner", "m", "mm", "length of the inner raceway contact along the roller (loaded laminae)"),
        _q("contact_length_outer", "m", "mm", "length of the outer raceway contact along the roller (loaded laminae)"),
        _q("edge_loaded_inner", None, None, "True where the inner contact reaches the roller's ends"),
        _q("edge_loaded_outer", None, None, "True where the outer contact reaches the roller's ends"),
        _q("h_c_inner", "m", "um", "central film at the inner raceway"),
        _q("h_min_inner", "m", "um", "minimum film at the inner raceway"),
        _q("h_c_outer", "m", "um", "central film at the outer raceway"),
        _q("h_min_outer", "m", "um", "minimum film at the outer raceway"),
        _q("h_min_bearing", "m", "um", "smallest film of all loaded contacts"),
        _q("Lambda_inner", "", "", "film / composite roughness at the inner raceway"),
        _q("Lambda_outer", "", "", "film / composite roughness at the outer raceway"),
        _q("Lambda_bearing", "", "", "smallest Lambda of all loaded contacts"),
        _q("contact_regime", None, None, "lubrication regime of the roller's worse contact, or 'unloaded'"),
        _q("P", "N", "kN", "dynamic equivalent load (ISO 281)"),
        _q("L10", "revolution_count", "Mrev", "basic rating life, a count of revolutions (ISO 281; shown in millions)"),
        _q("L10h", "s", "h", "basic rating life in operating hours"),
        _q("a1", "", "", "life modification factor for reliability (ISO 281 Table 12)"),
        _q("nu1", "m^2/s", "mm^2/s", "rated viscosity (ISO 281)"),
        _q("kappa", "", "", "viscosity ratio nu / nu1"),
        _q("a_ISO", "", "", "life modification factor (ISO 281; of radial roller or ball bearings)"),
        _q("L_nm", "revolution_count", "Mrev", "modified rating life, a count of revolutions (ISO 281; shown in millions)"),
        _q("L_nmh", "s", "h", "modified rating life in operating hours"),
        _q("friction_coefficient_inner", "", "", "friction coefficient at the inner raceway (fluid traction, with "
                                                 "mixed + boundary; or Kelley)"),
        _q("friction_coefficient_outer", "", "", "friction coefficient at the outer raceway (fluid traction, with "
                                                 "mixed + boundary; or Kelley)"),
        _q("friction_valid_inner", None, None, "True where the inner contact's friction model is inside its validity"),
        _q("friction_valid_outer", None, None, "True where the outer contact's friction model is inside its validity"),
        *(_q(f"{q}_{race}", unit, display, f"{text} at the {race} raceway")
          for race in ("inner", "outer")
          for q, unit, display, text in (
              ("asperity_load_fraction", "", "", "share of the roller load the asperities carry (Greenwood-Tripp)"),
              ("h_c_mixed", "m", "um", "central film at the fluid's share of the load"),
              ("lubrication_regime", None, None, "boundary, mixed or full_film (unknown: no film; unloaded: no contact)"),
              ("mixed_valid", None, None, "True where the load-sharing model can reach the boundary regime"))),
        _q("flash_temperature_inner", "K", "K", "flash temperature at the inner raceway"),
        _q("flash_temperature_outer", "K", "K", "flash temperature at the outer raceway"),
        _q("friction_moment_skf", "N*m", "N*m", "bearing frictional moment, SKF model (open bearing, no drag)"),
        _q("friction_power_skf", "W", "W", "bearing friction power loss, SKF model (moment x relative ring speed)"),
        _q("M_rr_skf", "N*m", "N*m", "rolling frictional moment phi_ish phi_rs M_rr of the SKF model"),
        _q("M_sl_skf", "N*m", "N*m", "sliding frictional moment M_sl of the SKF model"),
        _q("friction_moment_palmgren", "N*m", "N*m", "bearing frictional moment M0 + M1, Palmgren"),
        _q("friction_power_palmgren", "W", "W", "bearing friction power loss, Palmgren (moment x relative ring speed)"),
        _q("M0_palmgren", "N*m", "N*m", "load-independent (viscous) frictional moment M0, Palmgren"),
        _q("M1_palmgren", "N*m", "N*m", "load-dependent frictional moment M1 = f1 P1 d_m, Palmgren"),
        _q("rolling_resistance_inner", "N", "N", "hydrodynamic rolling resistance at the inner raceway (Goksem & Hargreaves)"),
        _q("rolling_resistance_outer", "N", "N", "hydrodynamic rolling resistance at the outer raceway (Goksem & Hargreaves)"),
        _q("rolling_resistance_moment", "N*m", "N*m", "bearing moment of the rollers' hydrodynamic rolling resistance"),
        _q("rolling_resistance_power", "W", "W", "power of the rollers' hydrodynamic rolling resistance sum(F_R u_m)"),
        # ball bearing (scenes.ball_bearing; per ball: arrays over the index "ball")
        _q("ball", "", "", "ball number (0-based, from the load line)"),
        _q("ball_azimuth", "rad", "deg", "ball azimuth from the line of the radial load"),
        _q("contact_angle", "rad", "deg", "contact angle of the ball under load (NaN unloaded)"),
        _q("ball_approach", "m", "um", "elastic deformation of the ball's two contacts (negative: gap)"),
        _q("loaded_balls", "", "", "number of balls in contact"),
        _q("ring_tilt", "rad", "deg", "tilt of the inner ring against the outer (0 when the shaft holds it square)"),
        _q("tilting_moment", "N*m", "N*m", "moment of the ball loads about the bearing centre"),
        _q("contact_angle_max", "rad", "deg", "largest contact angle of the loaded balls"),
        _q("contact_angle_min", "rad", "deg", "smallest contact angle of the loaded balls"),
        _q("ball_row", "", "", "bearing of a pair the ball belongs to (0: the one a positive axial load presses, 1)"),
        _q("axial_load_row0", "N", "kN", "axial load bearing 0 of a pair carries on its flanks (sum Q sin alpha)"),
        _q("axial_load_row1", "N", "kN", "axial load bearing 1 of a pair carries on its flanks (sum Q sin alpha)"),
        _q("preload_relieved", None, None, "True where one bearing of a pair carries no ball load (the axial load "
                                           "has relieved its preload)"),
        _q("a_rolling_inner", "m", "um", "Hertz semi-axis along rolling at the inner raceway"),
        _q("a_transverse_inner", "m", "um", "Hertz semi-axis across rolling at the inner raceway"),
        _q("a_rolling_outer", "m", "um", "Hertz semi-axis along rolling at the outer raceway"),
        _q("a_transverse_outer", "m", "um", "Hertz semi-axis across rolling at the outer raceway"),
        _q("most_loaded_race", None, None, "raceway of the contact with the highest pressure"),
        *(_q(f"truncation_margin_{race}", "rad", "deg", f"angle left between the {race} contact ellipse's edge and "
             "the shoulder (negative: truncated)") for race in ("inner", "outer")),
        *(_q(f"truncated_{race}", None, None, f"True where the {race} contact ellipse runs over the shoulder")
          for race in ("inner", "outer")),
        _q("truncated_balls", "", "", "number of balls whose contact ellipse runs over a shoulder"),
        _q("e", "", "", "ISO 281 limit of F_a/F_r for the axial-load factors"),
        _q("X", "", "", "ISO 281 radial load factor"),
        _q("Y", "", "", "ISO 281 axial load factor"),
        _q("P0", "N", "kN", "static equivalent load (ISO 76)"),
        _q("s0", "", "", "static safety factor C0/P0 (ISO 76)"),
        _q("L10r", "revolution_count", "Mrev", "basic reference rating life from the internal load distribution "
                                               "(ISO/TS 16281; shown in millions)"),
        _q("L10rh", "s", "h", "basic reference rating life in operating hours (ISO/TS 16281)"),
        _q("x_q_max", "m", "mm", "axial position of the roller's most loaded lamina (0: the middle)"),
        _q("lamina_moment", "N*m", "N*m", "moment the laminae exert on the rings (misalignment)"),
        # ball-cone CVT (scenes.ball_cone_cvt); _in / _out: the input / output cone contact
        _q("tilt", "rad", "deg", "ball tilt beta"),
        _q("reduction_ratio", "", "", "omega_in / omega_out"),
        _q("overrange", "", "", "largest / smallest ratio of the design"),
        _q("output_speed", "rad/s", "rpm", "output cone speed"),
        _q("ball_speed", "rad/s", "rpm", "ball speed about its axis"),
        *(q for side in ("in", "out") for q in (
            _q(f"rolling_radius_{side}", "m", "mm", f"ball rolling radius at the {side}put contact (BC, DE)"),
            _q(f"rolling_speed_{side}", "m/s", "m/s", f"rolling speed at the {side}put contact"),
            _q(f"psi_{side}", "", "", f"spin coefficient phi/omega_cone at the {side}put contact (Saccheto Eq. 5.57)"),
            _q(f"spin_{side}", "1/m", "1/m", f"spin creepage (spin / rolling speed) at the {side}put contact"),
            _q(f"tangential_force_{side}", "N", "N", f"tangential force per {side}put contact"),
            _q(f"traction_needed_{side}", "", "", f"F_t / F_n at the {side}put contact"),
            _q(f"h_c_{side}", "m", "um", f"central film at the {side}put contact"),
            _q(f"h_min_{side}", "m", "um", f"minimum film at the {side}put contact"),
            _q(f"Lambda_{side}", "", "", f"h_min / composite roughness at the {side}put contact"),
            _q(f"creepage_{side}", "", "", f"longitudinal creepage transmitting F_t at the {side}put contact"),
            _q(f"slip_fraction_{side}", "", "", f"slipping share of the contact area at the {side}put contact"),
            _q(f"traction_regime_{side}", None, None, f"viscous, plateau or gross slip (ehl_traction); partial slip or "
                                                      f"gross slip (fastsim) at the {side}put contact"),
            _q(f"tau0_{side}", "Pa", "MPa", f"life-relevant subsurface shear at the {side}put contact"),
            _q(f"z0_{side}", "m", "um", f"depth of tau0 at the {side}put contact"),
            _q(f"life_ball_{side}", "s", "h", f"L10 of one ball's {side}put track"),
            _q(f"life_cone_{side}", "s", "h", f"L10 of the {side}put cone's track"),
            _q(f"cycles_ball_{side}", "", "", f"L10 of one ball's {side}put track [stress cycles]"),
            _q(f"cycles_cone_{side}", "", "", f"L10 of the {side}put cone's track [stress cycles]"),
            _q(f"spin_roll_{side}", "", "", f"spin angular velocity / ball angular velocity at the {side}put contact"),
            _q(f"gross_slip_{side}", None, None, f"True where the {side}put contact cannot transmit its force"),
            _q(f"traction_capacity_{side}", "N", "N", f"largest tangential force of the {side}put contact with its spin"),
            _q(f"traction_margin_{side}", "", "", f"1 - F_t/capacity at the {side}put contact"),
            _q(f"spin_moment_{side}", "N*m", "N*mm", f"spin moment on the ball at the {side}put contact"),
            _q(f"creep_loss_{side}", "W", "W", f"creep power loss of one {side}put contact"),
            _q(f"spin_loss_{side}", "W", "W", f"spin power loss of one {side}put contact"),
            _q(f"power_loss_{side}", "W", "W", f"power loss of one {side}put contact (creep + spin)"),
            _q(f"traction_temperature_rise_{side}", "K", "K", f"lumped film temperature rise at the {side}put contact"),
            _q(f"traction_valid_{side}", None, None, f"True where the {side}put contact's thermal balance converged"),
            _q(f"asperity_load_fraction_{side}", "", "", f"share of the normal force the asperities carry at the "
                                                         f"{side}put contact (Greenwood-Tripp, JGP split)"),
            _q(f"h_c_mixed_{side}", "m", "um", f"central film at the fluid's share of the load, {side}put contact"),
            _q(f"Lambda_mixed_{side}", "", "", f"h_c_mixed / composite roughness at the {side}put contact"),
            _q(f"lubrication_regime_{side}", None, None, f"boundary, mixed or full_film at the {side}put contact"),
            _q(f"asperity_capacity_{side}", "", "", f"share of the load the asperities carry at zero separation, "
                                                    f"{side}put contact"),
            _q(f"mixed_valid_{side}", None, None, f"True where the load-sharing model can reach the boundary regime at "
                                                  f"the {side}put contact"),
        )),
        _q("psi_total", "", "", "sum of the input and output spin coefficients"),
        _q("efficiency", "", "", "1 - contact power loss / transmitted power"),
        _q("power_loss", "W", "W", "power lost in the drive's traction contacts (creep + spin, all balls)"),
        _q("torque", "N*m", "N*m", "input torque"),
        _q("output_torque", "N*m", "N*m", "output torque (no loss)"),
        _q("cam_axial_force", "N", "N", "axial force of the loading cam"),
        _q("mu_min", "", "", "traction the input contact needs, F_t/F_n (Saccheto Eq. 6.19)"),
        _q("traction_check", None, None, "needed traction against the fluid's traction coefficient"),
        _q("traction_sufficient", None, None, "True where both contacts need F_t/F_n below the traction coefficient"),
        _q("a_rolling", "m", "um", "Hertz semi-axis along the rolling direction"),
        _q("a_transverse", "m", "um", "Hertz semi-axis across the rolling direction"),
        _q("ellipticity", "", "", "Hamrock's ellipticity k = a_transverse/a_rolling of a point contact"),
        _q("Rx", "m", "mm", "reduced radius along the rolling direction"),
        _q("Ry", "m", "mm", "reduced radius across the rolling direction"),
        _q("pressure_check", None, None, "peak pressure against the thesis's 1.1 GPa EHL threshold"),
        _q("stress_limit_exceeded", None, None,
           "True where the Hertz peak pressure exceeds the component's contact_stress_limit (default ISO 76: 4.2 GPa)"),
        _q("life_system", "s", "h", "L10 of the CVT's rolling contacts (Weibull combination)"),
        # single roller-raceway contact (Delabenetta 2021 chain, scenes.raceway_contact)
        _q("E_star", "Pa", "GPa", "E* = E'/2 (Johnson; Delabenetta Eq. 3)"),
        _q("R_x", "m", "mm", "R_x = 2R' (Seabra's equivalent radius; Delabenetta Eq. 1)"),
        _q("contact_area", "m^2", "mm^2", "Hertz contact area 2 b l"),
        _q("tau_oct_max", "Pa", "MPa", "maximum octahedral shear stress"),
        _q("roughness_amplitude", "m", "um",
           "amplitude A of the roughness sinusoid: sqrt(2) sigma, or sigma/sqrt(2) in the thesis's reading (Eq. 30)"),
        _q("p_full_contact_roughness", "Pa", "GPa",
           "pressure flattening the roughness sinusoid, p* = pi E* A / lambda (Johnson 1985 §13.2)"),
        _q("tau_roughness", "Pa", "GPa", "stress due to roughness (Delabenetta Eq. 8; its code calls it the peak pressure)"),
        _q("u_raceway", "m/s", "m/s", "raceway surface speed"),
        _q("u_roller", "m/s", "m/s", "roller surface speed"),
        _q("slide_roll_measure", "", "", "V_e = |u1 - u2|/(u1 + u2) (Delabenetta Eq. 45)"),
        _q("speed_basis", None, None, "how the surface speeds were obtained"),
        _q("walther_m", "", "", "slope m of the Walther (ASTM D341) line"),
        _q("walther_n", "", "", "intercept n of the Walther (ASTM D341) line"),
        _q("lubricant_conductivity", "W/(m*K)", "W/(m*K)", "thermal conductivity of the lubricant"),
        _q("lubricant_specific_heat", "J/(kg*K)", "J/(kg*K)", "specific heat of the lubricant"),
        _q("starvation_factor", "", "", "film factor phi_A for the lubricant supply (1 oil, 0.7 grease)"),
        _q("roughness_factor", "", "", "film factor phi_R for the roughness"),
        _q("h_c_corrected", "m", "um", "corrected central film h_oc = phi_T phi_A phi_R h_c (Delabenetta Eq. 43)"),
        _q("Lambda_oc", "", "", "specific film thickness h_oc/sigma (Delabenetta Eq. 13)"),
        _q("friction_validity", None, None, "'ok' or why the friction correlation does not apply"),
        _q("friction_valid", None, None, "True when the contact is inside the Kelley validity ranges"),
        _q("flash_temperature", "K", "K", "flash temperature rise T_F (Delabenetta Eq. 48)"),
        _q("surface_temperature_max", "K", "degC", "maximum surface temperature T + T_F (Eq. 47)"),
        _q("viscosity_at_mean_pressure", "Pa*s", "Pa*s", "viscosity at the mean Hertz pressure (Roelands)"),
        _q("film_temperature_rise", "K", "K", "mid-film Couette temperature rise above the surface"),
        _q("film_thermal", None, None, "True where the film's energy equation ran at the angle (thermal transient: "
                                       "both surfaces move with the entrainment); False: no film temperature"),
        _q("lubricant_temperature_max", "K", "degC", "lubricant's maximum temperature (thesis: the rise read as a temperature)"),
        _q("lubricant_temperature_check", None, None, "maximum lubricant temperature against the upper service limit"),
        _q("yield_check", None, None, "plastic-deformation check of the subsurface shear"),
        _q("fatigue_check", None, None, "fatigue check of the orthogonal shear range (thesis rule)"),
    )
}


QUANTITIES.update({name: attrs.evolve(QUANTITIES[name], nan_when=reasons) for name, reasons in _NAN_WHEN.items()})


def spec(name: str) -> QuantitySpec:
    """The catalogue entry of ``name`` (InputError listing the names if unknown)."""
    try:
        return QUANTITIES[name]
    except KeyError:
        raise InputError(f"unknown quantity {name!r}; known: {', '.join(QUANTITIES)}") from None
