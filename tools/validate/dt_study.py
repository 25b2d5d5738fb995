#!/usr/bin/env python3
"""Time-step study (issue 29): compare run directories of one case made with different time steps.

For each run: the average crest and trough of a gauge over the last N excitation periods (the
per-period maximum and minimum of the raw samples, as docs/performance.md's earlier adaptive-step
study), their period-to-period standard deviation, the energy per cycle over the same periods
(from the base work W_base, as the program's steady-state analysis does), the steps and the mean
step. Differences are relative to the reference run (the first directory given, the smallest step).

    tools/validate/dt_study.py REF_DIR OTHER_DIR... [--gauge right] [--cycles 20] [--json out.json]
"""
import argparse
import csv
import json
import math
import sys
from pathlib import Path


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = rows[0]
    names = [h.split(" [")[0] for h in header]
    data = {n: [] for n in names}
    for row in rows[1:]:
        if not row or row[0].startswith("#"):
            continue
        for n, v in zip(names, row):
            data[n].append(float(v))
    return data


def mean_sd(values):
    m = sum(values) / len(values)
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1)) if len(values) > 1 else 0.0
    return m, sd


def interpolate(t, y, t0):
    for i in range(1, len(t)):
        if t[i] >= t0:
            w = (t0 - t[i - 1]) / (t[i] - t[i - 1])
            return (1.0 - w) * y[i - 1] + w * y[i]
    return y[-1]


def analyse(run_dir, gauge, cycles):
    run_dir = Path(run_dir)
    summary = json.loads((run_dir / "summary.json").read_text())
    omega = summary["excitation_omega_rad_s"]
    period = 2.0 * math.pi / omega
    data = read_columns(run_dir / "timeseries.csv")
    t = data["time"]
    eta = data["eta:" + gauge]
    t_end = t[-1]
    crests, troughs = [], []
    for k in range(cycles):
        lo, hi = t_end - (k + 1) * period, t_end - k * period
        window = [e for tt, e in zip(t, eta) if lo < tt <= hi]
        crests.append(max(window))
        troughs.append(min(window))
    work = data["W_base"]
    energy = (work[-1] - interpolate(t, work, t_end - cycles * period)) / cycles
    dts = data["dt"]
    window_dt = [d for tt, d in zip(t, dts) if tt > t_end - cycles * period]
    crest, crest_sd = mean_sd(crests)
    trough, trough_sd = mean_sd(troughs)
    return {
        "run": run_dir.name,
        "steps": summary["steps"],
        "mean_dt_s": sum(window_dt) / len(window_dt),
        "crest_m": crest,
        "crest_sd_m": crest_sd,
        "trough_m": trough,
        "trough_sd_m": trough_sd,
        "energy_per_cycle_J_per_m": energy,
        "leaked": summary.get("leaked_particles"),
        "wall_contacts": summary.get("wall_contacts"),
        "period_s": period,
        "window_s": [t_end - cycles * period, t_end],
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="run directories; the first is the reference")
    ap.add_argument("--gauge", default="right")
    ap.add_argument("--cycles", type=int, default=20)
    ap.add_argument("--json", help="write the table as JSON here")
    a = ap.parse_args()
    rows = [analyse(r, a.gauge, a.cycles) for r in a.runs]
    ref = rows[0]
    for r in rows:
        r["crest_diff"] = r["crest_m"] / ref["crest_m"] - 1.0
        r["trough_diff"] = r["trough_m"] / ref["trough_m"] - 1.0
        r["energy_diff"] = r["energy_per_cycle_J_per_m"] / ref["energy_per_cycle_J_per_m"] - 1.0
    print(f"last {a.cycles} periods (T = {ref['period_s']:.4f} s), gauge {a.gauge}; differences against {ref['run']}")
    print("| run | steps | mean dt (ms) | crest (mm) | sd | trough (mm) | sd | energy/cycle (J/m) | crest | trough | energy | leaked |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['run']} | {r['steps']} | {1e3 * r['mean_dt_s']:.3f} | {1e3 * r['crest_m']:.2f} | "
              f"{1e3 * r['crest_sd_m']:.2f} | {1e3 * r['trough_m']:.2f} | {1e3 * r['trough_sd_m']:.2f} | "
              f"{r['energy_per_cycle_J_per_m']:.4f} | {100 * r['crest_diff']:+.2f}% | {100 * r['trough_diff']:+.2f}% | "
              f"{100 * r['energy_diff']:+.2f}% | {r['leaked']} |")
    if a.json:
        Path(a.json).write_text(json.dumps(rows, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
