#!/usr/bin/env python3
"""A resonance run with a plot: the Liu & Lin (2008) tank shaken at its first sloshing frequency
(thesis 2.6.2), the wave at the left wall against time, with the steady-state amplitude.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/resonance.py [--quick] [--out DIR]

About 80 s on two cores (dp = 5 mm, 10 s; measured 2026-12-04); --quick: dp = 10 mm, 3 s, 7 s.
Writes DIR/run/ (the run directory) and DIR/resonance.png.
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a coarse, short run (CI)")
    parser.add_argument("--out", default="out/examples/resonance", help="output folder")
    parser.add_argument("--threads", type=int, default=None)
    args = parser.parse_args()

    case = sloshsph.Case.from_file(os.path.join(CASES, "liu_lin_2008.toml"))
    case.set("excitation.beta", 1.0)  # at the first linear sloshing frequency
    if args.quick:
        case.set("particles.dp", 0.01).set("time.end", 3.0)
    else:
        case.set("time.end", 10.0)
    modes = sloshsph.modes(case, count=1)["modes"]
    print(f"first sloshing mode: {modes[0]['omega']:.4f} rad/s ({modes[0]['frequency']:.4f} Hz)")

    run = sloshsph.run(case, out=os.path.join(args.out, "run"), force=True, threads=args.threads)
    ts = run.timeseries
    t, eta = ts["time"], ts["eta:left"]
    period = 2 * np.pi / run.summary["excitation_omega_rad_s"]
    cycles = min(3, int(t[-1] / period))
    steady = sloshsph.analysis.steady_state_amplitude(t, sloshsph.analysis.lowpass(eta, t[1] - t[0]), period,
                                                      cycles)
    print(f"left-wall wave over the last {steady['cycles']} cycles: +{1000 * steady['avg_max']:.2f} / "
          f"{1000 * steady['avg_min']:.2f} mm")

    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.plot(t, 1000 * eta, lw=1, label="SPH, eta at the left wall")
    ax.axhline(1000 * steady["avg_max"], color="k", ls=":", lw=1, label="steady-state mean crest and trough")
    ax.axhline(1000 * steady["avg_min"], color="k", ls=":", lw=1)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("eta [mm]")
    ax.set_title(f"Liu & Lin (2008) tank at resonance, omega = {run.summary['excitation_omega_rad_s']:.3f} rad/s")
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    png = os.path.join(args.out, "resonance.png")
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
