"""The LS-1 flat-faced follower over a turn, flooded and starved, through both entrainment reversals (issue 22).

The flat follower of Tsuha (2015) §6.2 (LS-1 cam, base radius 49.7494 mm, 1000 rpm): its entrainment speed
changes sign near 66 and 114 deg, where a quasi-steady film would vanish. Each run is the transient march of
the scene (effect ``squeeze``, :func:`camcontact.ehl.line_transient.transient_cycle`) with

* ``reynolds``: cavitation by clipping (the exit film is not tracked; flooded ends);
* ``flooded``: mass-conserving cavitation (the film the contact leaves behind is what it meets after a reversal;
  flooded domain ends);
* ``starved h_oil``: mass-conserving, fed by a layer of h_oil (``CamFollower.oil_layer``) at the inflow end.

Per run (median time of ``--repeats``): the minimum film over the turn, the cam angle where it occurs and its
position in the contact (``x_min``, from the contact centre, positive in the direction of positive u_m), the
central film on the base circle and at the fastest flank angle, the angles whose step did not converge.

Published films for comparison, in order of magnitude only: a quasi-static cam / flat-faced follower analysis
of a Leeds valve-train chapter (a copy at https://th4.ilovetranslation.com/OhFBkYGv9OX=d, author not shown;
case inputs not in the copy) gives lambda 4-6.5 on the flanks and 0.2-0.4 at the nose with Ra 0.2 um on both
surfaces, i.e. about 1.1-1.8 um and 0.06-0.11 um of film; quasi-static theory gives no film at the reversal, a
transient one a finite film there. No transient cam–tappet film with its inputs (Dowson, Taylor & Zhu 1992;
Messé & Lubrecht 2000; Kushwaha & Rahnejat 2002) was available to this project.

    python benchmarks/starved_cam_cycle.py            # level 8, 1 degree, layers 0.8 / 0.3 / 0.1 um, 3 repeats
    python benchmarks/starved_cam_cycle.py --quick    # level 6, 4 degrees, one layer, one repeat (the tests)

Writes ``starved_cam_cycle.csv`` (and ``.png``: films over the turn) into ``--out``. Timings are reported, never
asserted.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import attrs
import numpy as np
import pandas as pd

import camcontact as cc
from camcontact.models.film_multigrid import Multigrid
from camcontact.scene_file import load_scene

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the shared benchmarks/_output.py
from _output import arguments, timed, write_results  # noqa: E402

EFFECTS = {"elasticity", "piezoviscosity", "compressibility", "squeeze"}
OUTPUTS = ["cam_angle", "u_m", "h_c", "h_min", "x_min", "film_valid"]


def flat_ls1(step: str):
    """The default scene's LS-1 cam with Tsuha's flat-faced follower (base radius sqrt(50^2 - 5^2) mm)."""
    scene = load_scene()
    follower = cc.Follower.flat(material=scene.component.follower.material)
    return attrs.evolve(scene.component, follower=follower, angle_step=step,
                        cam=attrs.evolve(scene.component.cam, base_radius="49.7494 mm"))


def run(name: str, level: int, step: str, cavitation: str, layer: str | None, repeats: int) -> tuple[dict, pd.DataFrame]:
    scene = attrs.evolve(flat_ls1(step), oil_layer=layer)
    model = {"film": Multigrid(levels=level, tolerance=1e-7, cavitation=cavitation)}

    def march():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", cc.ConvergenceWarning)
            return cc.Analysis(scene, outputs=OUTPUTS, models=model, effects=EFFECTS).run()

    result, seconds = timed(march, repeats)
    angle = np.degrees(np.asarray(result["cam_angle"], dtype=float))
    u = np.asarray(result["u_m"], dtype=float)
    h_c, h_min = np.asarray(result["h_c"], dtype=float), np.asarray(result["h_min"], dtype=float)
    x_min = np.asarray(result["x_min"], dtype=float)
    valid = np.asarray(result["film_valid"], dtype=bool)
    k = int(np.argmin(h_min))
    fastest = int(np.argmax(u))
    row = {"run": name, "level": level, "step": step, "time [s]": seconds, "h_min over turn [nm]": h_min[k] * 1e9,
           "at cam angle [deg]": angle[k], "x_min there [um]": x_min[k] * 1e6, "u_m there [m/s]": u[k],
           "h_c base circle [nm]": h_c[-1] * 1e9, "h_c fastest flank [nm]": h_c[fastest] * 1e9,
           "not converged": int((~valid).sum()), "angles": angle.size}
    turn = pd.DataFrame({"run": name, "cam angle [deg]": angle, "u_m [m/s]": u, "h_c [nm]": h_c * 1e9,
                         "h_min [nm]": h_min * 1e9, "x_min [um]": x_min * 1e6})
    return row, turn


def plot(frame: pd.DataFrame, turns: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for name, turn in turns.groupby("run", sort=False):
        top.plot(turn["cam angle [deg]"], turn["h_min [nm]"], label=name)
        bottom.plot(turn["cam angle [deg]"], turn["x_min [um]"], label=name)
    top.set(yscale="log", ylabel="h_min [nm]", title="LS-1 flat follower, 1000 rpm: flooded and starved transient films")
    bottom.set(xlabel="cam angle [deg]", ylabel="x_min [µm] (+: direction of u_m > 0)", xlim=(0, 180))
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
    top.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv: list[str] | None = None) -> pd.DataFrame:
    args = arguments(__doc__, "level 6, 4 degree steps, one layer, one repeat", argv)
    level, step, repeats = (6, "4 deg", 1) if args.quick else (8, "1 deg", args.repeats)
    layers = ("0.3 um",) if args.quick else ("0.8 um", "0.3 um", "0.1 um")
    cases = [("reynolds", "reynolds", None), ("flooded", "mass_conserving", None)]
    cases += [(f"starved {layer}", "mass_conserving", layer) for layer in layers]
    rows, turns = [], []
    for name, cavitation, layer in cases:
        row, turn = run(name, level, step, cavitation, layer, repeats)
        rows.append(row)
        turns.append(turn)
    frame = pd.DataFrame(rows)
    turns = pd.concat(turns, ignore_index=True)
    written = write_results(frame, args.out, "starved_cam_cycle", lambda f, path: plot(f, turns, path),
                            lambda f: f.set_index("run"))
    turns.to_csv(Path(args.out) / "starved_cam_cycle_turns.csv", index=False)
    return written


if __name__ == "__main__":
    main()
