"""The LS-1 valve train of Tsuha (2015) over the cam cycle: Tables 6.3, 6.8 and 6.4, the equivalent
system, k_min, the Hertz spot check and the derived kinematics of the reference.

Source: ../shared/reference/cam_follower_ehl_tsuha2015.md — §3 (inputs: Tables 6.1, 6.2, 6.7),
§0 (facts established by the reference's own reproduction: P-1/P-2 motion law, eta0 from the
Roelands consistency, c = 33.808 N s/m unrounded, reduced radius and u_m = R_cam omega for the
roller, the mean-speed convention of the thesis), §4.3/§4.4/§4.7 (the tables), §8 (acceptance
tests). Tolerances are the printed precision unless stated.
"""

import math

import attrs
import numpy as np
import pytest

import camcontact as cc
from camcontact.kinematics.motion_program import MotionProgram

STEEL = cc.Material(E="210 GPa", nu=0.3)
#: eta0 is not printed; alpha and z with p0 = 1.96e8 Pa give 0.0358352 Pa s (reference §0 item 2)
OIL = cc.Lubricant(name="Tsuha 2015", alpha="2.2e-8 1/Pa", roelands_z=0.68, viscosity_pressure_law="roelands")
ANGLES = np.arange(0, 180, 15.0)

# Table 6.3 (roller, 1000 rpm): angle -> (M, L, R [m], u_m [m/s], F [N])
TABLE_6_3 = {
    0: (4.005, 15.245, 0.00800, 4.188, 1000.000), 15: (2.238, 21.803, 0.00952, 20.858, 1360.530),
    30: (3.644, 19.570, 0.00926, 13.169, 1736.091), 45: (7.521, 16.029, 0.00836, 5.351, 2170.113),
    60: (11.177, 14.932, 0.00783, 3.772, 2619.769), 75: (13.405, 14.669, 0.00767, 3.441, 2969.977),
    90: (13.784, 14.720, 0.00770, 3.503, 3087.990), 105: (12.787, 14.764, 0.00773, 3.558, 2891.925),
    120: (10.256, 15.082, 0.00791, 3.968, 2478.873), 135: (6.949, 16.046, 0.00837, 5.378, 2011.174),
    150: (3.801, 18.664, 0.00911, 10.714, 1619.927), 165: (2.402, 20.836, 0.00943, 17.223, 1320.266),
}
# Table 6.8 (flat face, 1000 rpm)
TABLE_6_8 = {
    0: (2.036, 8.573, 0.049749, 2.6049, 1000.000), 15: (1.301, 9.379, 0.088544, 6.6402, 1360.530),
    30: (1.646, 9.341, 0.090031, 6.6439, 1736.091), 45: (3.206, 8.789, 0.065253, 3.7738, 2170.113),
    60: (10.853, 6.735, 0.039625, 0.7903, 2619.769), 75: (16.213, 6.980, 0.027995, -0.6442, 2969.977),
    90: (15.203, 7.478, 0.027046, -0.8198, 3087.990), 105: (15.788, 6.980, 0.027996, -0.6441, 2891.925),
    120: (10.269, 6.735, 0.039625, 0.7903, 2478.873), 135: (2.971, 8.789, 0.065253, 3.7738, 2011.174),
    150: (1.536, 9.341, 0.090031, 6.6439, 1619.927), 165: (1.262, 9.379, 0.088544, 6.6402, 1320.266),
}
# Table 6.4 (roller, 1000 rpm, EHL): angle -> (|H0|, H_m, H_c)
TABLE_6_4 = {
    45: (0.2435, 0.2895, 0.3325), 60: (0.3766, 0.1801, 0.2061), 75: (0.4187, 0.146, 0.1665),
    90: (0.4238, 0.1419, 0.1617), 105: (0.4084, 0.1543, 0.1762), 120: (0.3532, 0.1991, 0.2281),
    135: (0.2115, 0.3155, 0.3628),
}


def ls1_scene(kind="roller", convention="thesis", speed="1000 rpm", angles=ANGLES, **extra):
    cam_radius = "40 mm" if kind == "roller" else f"{math.sqrt(50**2 - 5**2)!r} mm"  # Table 6.7: R_o = 49.7494 mm
    follower = (cc.Follower.roller(radius="10 mm", offset="5 mm", material=STEEL) if kind == "roller"
                else cc.Follower.flat(material=STEEL))
    return cc.CamFollower(
        cam=cc.Cam(program=MotionProgram.thesis_ls1(), base_radius=cam_radius, width="15 mm", material=STEEL),
        follower=follower, valve_train=cc.ValveTrain.ls1(), speed=speed,
        angles=cc.Q_(np.asarray(angles, dtype=float), "deg"), lubricant=OIL, convention=convention, **extra,
    )


PARAMETERS = ["M", "L", "R", "u_m", "contact_force"]


@pytest.mark.parametrize("kind, table", [("roller", TABLE_6_3), ("flat", TABLE_6_8)], ids=["table_6_3", "table_6_8"])
def test_cycle_parameter_tables(kind, table):
    """M and L to +-0.002 (reference §8 item 4: the thesis rounds; its own reproduction differs by up to
    0.002), R and u_m to the printed digits, F to +-0.01 N (the reference reproduces F to 0.0075 N
    with c = 33.808 N s/m unrounded; this implementation differs by at most 0.008 N at 75°)."""
    result = cc.Analysis(ls1_scene(kind), outputs=PARAMETERS).run()
    for i, angle in enumerate(ANGLES):
        M, L, R, u_m, F = table[int(angle)]
        assert result["M"][i] == pytest.approx(M, abs=0.002), angle
        assert result["L"][i] == pytest.approx(L, abs=0.002), angle
        digits_R = 5 if kind == "roller" else 6
        # Table 6.8 at 75° prints R = 0.027995 but 0.027996 at the symmetric 105° (the kinematics of the
        # flat face are symmetric about the nose): checked to 1.5e-6 there
        tolerance_R = 1.5e-6 if (kind, int(angle)) == ("flat", 75) else 0.5 * 10**-digits_R + 1e-12
        assert result["R"][i] == pytest.approx(R, abs=tolerance_R), angle
        # u_m errata of the printed tables (reference §8 item 4, "note the Table u_m erratum"):
        # Table 6.3 prints 4.188 on the base circle where R_b omega = 0.040 * 104.7198 = 4.18879 m/s, and
        # 3.503 at 90° for 3.50370: some entries are truncated, not rounded (5.351 for 5.3507 is rounded),
        # so the roller's u_m is checked to one unit of the last printed digit (1e-3); Table 6.8 prints -0.6442 at 75° but -0.6441 at
        # the symmetric 105° (same |u_m| by the symmetry of the flat-face kinematics: checked to 1.5e-4)
        tolerance_u = 1e-3 if kind == "roller" else {75: 1.5e-4}.get(int(angle), 0.5e-4 + 1e-12)
        assert result["u_m"][i] == pytest.approx(u_m, abs=tolerance_u), angle
        assert result["contact_force"][i] == pytest.approx(F, abs=0.01), angle


def test_table_6_4_roller_ehl_in_both_conventions():
    """Table 6.4 (roller, 1000 rpm, 45°–135°): |H0|, H_min and H_c within +-5e-4 at level 9 in the
    thesis-compatible convention; the consistent convention (sum speed twice the thesis's, exact
    surface speeds) is computed beside it and gives thicker films, as the reference §0 item 10 says
    (the thesis's films correspond to half the physical entrainment speed). The thesis solved on the domain
    [-4, 1.5] (reference §8 item 8; H0 depends on the domain by definition); the default automatic domain gives
    these films (H_c 0.16-0.25) a longer inlet, 0.6-2.0 % thicker films and a different H0."""
    angles = sorted(TABLE_6_4)
    outputs = ["H0", "H_min", "H_c", "h_min", "film_regime"]
    multigrid = cc.registry.get("film_models", "multigrid", levels=9)
    thesis_domain = attrs.evolve(multigrid, domain=(-4.0, 1.5))
    thesis = cc.Analysis(ls1_scene(angles=angles), outputs=outputs, models={"film": thesis_domain}).run()
    longer = cc.Analysis(ls1_scene(angles=angles), outputs=["H_c", "film_regime"], models={"film": multigrid}).run()
    consistent = cc.Analysis(ls1_scene(angles=angles, convention="consistent"), outputs=outputs,
                             models={"film": multigrid}).run()
    for i, angle in enumerate(angles):
        H0, H_m, H_c = TABLE_6_4[angle]
        assert thesis["film_regime"][i] == "ok"
        assert abs(thesis["H0"][i]) == pytest.approx(H0, abs=5e-4), angle
        assert thesis["H_min"][i] == pytest.approx(H_m, abs=5e-4), angle
        assert thesis["H_c"][i] == pytest.approx(H_c, abs=5e-4), angle
        assert longer["film_regime"][i] == "ok" and 1.005 < longer["H_c"][i] / thesis["H_c"][i] < 1.03, angle
        assert consistent["film_regime"][i] == "ok"
        ratio = consistent["h_min"][i] / thesis["h_min"][i]
        # h ~ u^0.7 at equal load: 2^0.7 = 1.62 from the factor 2 alone; the exact roller surface
        # speed differs from R_cam omega by up to ~20 % away from the nose, and the consistent films' automatic
        # domain has a longer inlet than the thesis's [-4, 1.5] (h_min 1.2-2.0 % thicker than on the earlier
        # automatic domain, X_a = -4 sqrt(2 H)): the band
        assert 1.4 < ratio < 2.4, (angle, ratio)


def test_hertz_spot_check_roller_nose():
    """Reference §8 item 7: roller, 1000 rpm, 90°: p_h = 991.0 MPa, b = 132.25 um (thesis convention,
    axial force F = 3087.99 N on 15 mm, R = 7.70 mm)."""
    result = cc.Analysis(ls1_scene(angles=[90.0]), outputs=["p_h", "b"]).run()
    assert result["p_h"][0] == pytest.approx(991.0e6, abs=0.05e6)
    assert result["b"][0] == pytest.approx(132.25e-6, abs=0.005e-6)


def test_equivalent_valve_train_and_minimum_stiffness():
    """Table 6.1 reduced as in Tsuha §6: m = 0.662 kg, k = 1.199e5 N/m (reference §8 item 2, rtol 1e-3);
    c = 2 zeta sqrt(k m) = 33.8 N s/m, f_n = 67.6–67.7 Hz; k_min = 9.42e4 N/m at 3000 rpm (rtol 2e-3: the
    reference's recomputation gives 9.4105e4)."""
    train = cc.ValveTrain.from_pushrod_train(
        lifter_mass="0.122 kg", pushrod_mass="0.052 kg", rocker_inertia="0.0000386 kg*m^2", valve_mass="0.114 kg",
        spring_mass="0.069 kg", pushrod_stiffness="5.25e7 N/m", valve_stiffness="8.23e7 N/m",
        spring_stiffness="4.03e4 N/m", pushrod_arm="0.022 m", valve_arm="0.038 m")
    assert train.si.mass == pytest.approx(0.662, rel=1e-3)
    assert train.si.stiffness == pytest.approx(1.199e5, rel=1e-3)
    ls1 = cc.ValveTrain.ls1()
    assert ls1.c == pytest.approx(33.8, abs=0.05)
    assert ls1.natural_frequency / (2 * math.pi) == pytest.approx(67.65, abs=0.1)
    result = cc.Analysis(ls1_scene(max_speed="3000 rpm"), outputs=["k_min", "natural_frequency"]).run()
    assert result["k_min"] == pytest.approx(9.42e4, rel=2e-3)


def test_derived_kinematics_of_the_reference():
    """Reference §4.3 [DERIVED]: pressure angle and cam radius of curvature of the roller at the table
    angles; pressure-angle extremes +16.62° at 45.05° and -25.20° at 136.56° (Fig. 6.3/6.4); flat-face
    u_m sign changes at 66.045° and 113.955° (§2.4; the root of R_o + f + 2 f'' = 0 of the exact P-1/P-2
    program is 66.0476°, so the reference's derived value is checked to 0.003°)."""
    pressure = [-5.74, 0.78, 12.11, 16.62, 13.07, 5.04, -4.10, -13.20, -21.21, -25.16, -21.93, -12.00]
    cam_radius = [0.04000, 0.19918, 0.12576, 0.05110, 0.03602, 0.03286, 0.03346, 0.03398, 0.03789, 0.05136,
                  0.10231, 0.16447]
    result = cc.Analysis(ls1_scene(), outputs=["pressure_angle", "cam_radius"]).run()
    assert np.degrees(result["pressure_angle"]) == pytest.approx(pressure, abs=0.005)
    assert result["cam_radius"] == pytest.approx(cam_radius, abs=5e-6)
    fine = np.arange(0.0, 180.0, 0.01)
    sweep = cc.Analysis(ls1_scene(angles=fine), outputs=["pressure_angle"]).run()["pressure_angle"]
    assert np.degrees(sweep.max()) == pytest.approx(16.62, abs=0.005)
    assert fine[np.argmax(sweep)] == pytest.approx(45.05, abs=0.02)
    assert np.degrees(sweep.min()) == pytest.approx(-25.20, abs=0.005)
    assert fine[np.argmin(sweep)] == pytest.approx(136.56, abs=0.02)
    from camcontact.kinematics.follower import sign_changes

    flat = cc.Analysis(ls1_scene("flat", angles=fine), outputs=["u_m"]).run()["u_m"]
    assert np.degrees(sign_changes(np.radians(fine), flat)) == pytest.approx([66.045, 113.955], abs=0.003)
