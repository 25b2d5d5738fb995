#!/usr/bin/env python3
"""A screen-solidity study of the Tait (2005) tank (thesis 2.6.3.3): three solidities of its two
Ergun slat screens times five frequency ratios, with the response curves (the steady-state wave
crest at the right wall, and the energy dissipated per cycle, against beta).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/screen_solidity.py [--quick] [--jobs 2]

Fifteen runs of 40 s at dp = 7 mm: about 35 minutes on two cores, two at a time (an estimate from the
120 s run, 677 s on 2 threads: not timed). --quick: two
solidities x two ratios of 3 s at dp = 14 mm, under a minute. Each solidity is one sweep
directory under --out (resumable: the same command skips finished points), and the curves are
DIR/screen_solidity.png.
"""

import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import sloshsph  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "..", "..", "cases")
SLAT_HEIGHT = 0.005  # m, the case's slats; the solidity is set by the gap: S = h / (h + gap)


def case_with_solidity(solidity, quick):
    case = sloshsph.Case.from_file(os.path.join(CASES, "tait2005_screens.toml"))
    gap = SLAT_HEIGHT * (1.0 - solidity) / solidity
    for screen in (0, 1):
        case.set(f"screens.{screen}.slat_height", SLAT_HEIGHT).set(f"screens.{screen}.slat_gap", gap)
    if quick:
        case.set("particles.dp", 0.014).set("time.end", 3.0)
    else:
        case.set("time.end", 40.0)
    return case


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="2 solidities x 2 ratios, short and coarse (CI)")
    parser.add_argument("--out", default="out/examples/screen_solidity", help="output folder")
    parser.add_argument("--jobs", type=int, default=2, help="runs at the same time")
    args = parser.parse_args()

    solidities = [0.3, 0.6] if args.quick else [0.3, 0.42, 0.6]
    betas = [0.9, 1.1] if args.quick else list(np.linspace(0.85, 1.15, 5))
    curves = {}
    for s in solidities:
        sweep = sloshsph.sweep(case_with_solidity(s, args.quick), beta=betas, jobs=args.jobs,
                               out=os.path.join(args.out, f"solidity_{s:.2f}"))
        curves[s] = sweep.table
        for beta, crest, energy in zip(sweep.table["beta"], sweep.table["eta_max"], sweep.table["energy_per_cycle"]):
            print(f"S = {s:.2f}  beta = {beta:.3f}  crest {1000 * crest:7.2f} mm  energy/cycle {energy:.4g} J/m")

    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    for s, table in curves.items():
        a.plot(table["beta"], 1000 * table["eta_max"], "o-", label=f"S = {s:.2f}")
        b.plot(table["beta"], table["energy_per_cycle"], "o-", label=f"S = {s:.2f}")
    a.set_xlabel("beta = omega / omega_1")
    a.set_ylabel("steady-state crest at the right wall [mm]")
    b.set_xlabel("beta = omega / omega_1")
    b.set_ylabel("energy dissipated per cycle [J/m]")
    a.legend()
    fig.suptitle("Tait (2005) tank with two Ergun screens: screen solidity")
    fig.tight_layout()
    png = os.path.join(args.out, "screen_solidity.png")
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
