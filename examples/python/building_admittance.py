#!/usr/bin/env python3
"""A tank-building run with its admittance plot: the thesis's chapter 4 building (an SDOF of
0.134 Hz) with its TLD under random wind (10 milli-g), the mechanical admittance |H(f)|^2 of the
building with the TLD against the building alone, and the effective damping (thesis eq. 4.30,
Vickery et al. 1983).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/building_admittance.py [--quick] [--hour]

Default: cases/building_tld_10mg_short.toml (dp = 0.2 m, 120 s), about 20 s on two cores: a
demonstration only, since 120 s holds 16 cycles of the building and the Welch grid is 0.033 Hz
wide; --hour: the thesis's one-hour run (dp = 0.1 m, about 80 minutes on one core), whose
admittance is converged enough to compare with thesis Fig. 4.23; --quick: 40 s (CI).
Writes DIR/run/ and DIR/admittance.png.
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
    parser.add_argument("--quick", action="store_true", help="40 s of the short case (CI)")
    parser.add_argument("--hour", action="store_true", help="the one-hour run of the thesis (building_tld_10mg)")
    parser.add_argument("--out", default="out/examples/building_admittance", help="output folder")
    parser.add_argument("--threads", type=int, default=None)
    args = parser.parse_args()

    name = "building_tld_10mg.toml" if args.hour else "building_tld_10mg_short.toml"
    case = sloshsph.Case.from_file(os.path.join(CASES, name))
    if args.quick:
        case.set("time.end", 40.0)
    tmd = sloshsph.modes(case)["equivalent_tmd"]
    print(f"before the run, as a linear TMD: optimum tank damping {tmd['optimum']['tank_damping_ratio']:.4f}, "
          f"effective damping {tmd['optimum']['effective_damping_ratio']:.4f}")

    run = sloshsph.run(case, out=os.path.join(args.out, "run"), force=True, threads=args.threads)
    structure = run.summary["structure"]
    ts = run.timeseries
    milli_g = 9.80665e-3
    print(f"building RMS acceleration {np.sqrt(np.mean(ts['a_s'] ** 2)) / milli_g:.3f} milli-g, "
          f"peak {np.max(np.abs(ts['a_s'])) / milli_g:.3f} milli-g")

    t, x = ts["time"], ts["x_s"]
    dt = t[1] - t[0]
    segment = min(len(t) // 4, int(600.0 / dt))
    f, s_x = sloshsph.analysis.welch_psd(x, dt, segment)
    fn = structure["natural_frequency_Hz"]
    stiffness = structure["stiffness_N_per_m"]
    h2 = sloshsph.analysis.admittance(f, s_x, stiffness, force_psd=sloshsph.analysis.welch_psd(ts["F_e"], dt,
                                                                                              segment)[1])
    band = (f >= 0.05) & (f <= 0.5)
    zeta = sloshsph.analysis.effective_damping_ratio(f[band], h2[band], fn, 0.05, 0.5)
    alone = sloshsph.analysis.sdof_admittance(f, fn, structure["damping_ratio"])
    print(f"effective damping from the admittance of this record (Welch area): {zeta:.4f}; "
          f"the building alone: {structure['damping_ratio']:.4f}")
    if "admittance" in structure:  # the run's own (whole-record Parseval area, docs/case-format.md)
        print(f"summary.json: effective damping {structure['admittance']['effective_damping_ratio']:.4f}")

    fig, ax = plt.subplots(figsize=(7, 4))
    ax.semilogy(f[band], h2[band], label=f"building + TLD (zeta_eff = {zeta:.3f})")
    ax.semilogy(f[band], alone[band], "k--", label=f"building alone (zeta = {structure['damping_ratio']:.3f})")
    ax.axvline(fn, color="grey", lw=0.8)
    ax.set_xlabel("f [Hz]")
    ax.set_ylabel("|H(f)|^2")
    ax.set_title(f"Mechanical admittance, {os.path.splitext(name)[0]}, {t[-1]:.0f} s")
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(args.out, "admittance.png")
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
