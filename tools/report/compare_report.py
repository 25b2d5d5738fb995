#!/usr/bin/python3
"""A side-by-side report of the run directories in a folder (e.g. the four tanks of a TLD
design, or the one-hour building runs), from their summary.json and admittance.csv.

    /usr/bin/python3 tools/report/compare_report.py DIR [--out OUT] [--no-svg] [--dpi DPI]

Writes OUT/plots/comparison_*.png (+ .svg), OUT/report.html and OUT/comparison.json (the table's
values); OUT defaults to DIR. Each run is a subdirectory of DIR holding summary.json, case.toml,
run.json or timeseries.csv. A run whose summary is not "completed" is shown with its status: its
values are those of its last summary, up to the time it gives.

With a [structure] (coupled runs): the effective damping ratio, the peak and RMS acceleration and
displacement of the structure with the tank and without it under the same load, and their
ratios (summary.json `structure`), and one plot of every run's mechanical admittance beside the
structure alone's (admittance.csv, thesis eq. 4.30).

Exit codes: 0 report written; 2 DIR holds no run directories, or the output cannot be written.
"""
import argparse
import json
import os
import sys

import numpy as np

import reportlib as rl
from reportlib import esc, fmt, plt


def get(tree, *keys):
    """tree[k0][k1]... as a float, or None when missing or not a number."""
    for k in keys:
        if not isinstance(tree, dict) or k not in tree:
            return None
        tree = tree[k]
    try:
        value = float(tree)
    except (TypeError, ValueError):
        return None
    return value if np.isfinite(value) else None


def read_status(path):
    """`sloshsph status --json` output (a list of objects with `dir`) as {basename: object}."""
    if not path:
        return {}
    with open(path, encoding="utf-8") as fh:
        entries = json.load(fh)
    return {os.path.basename(str(e.get("dir", "")).rstrip(os.sep)): e for e in entries if isinstance(e, dict)}


def percent(ratio):
    return 100 * ratio if ratio is not None else None


def run_row(run_dir, notes, status=None):
    summary = rl.read_json(os.path.join(run_dir, "summary.json"), notes)
    case = rl.parse_toml(rl.read_text(os.path.join(run_dir, "case.toml")), notes)
    s = summary.get("structure", {}) if isinstance(summary, dict) else {}
    alone = s.get("structure_without_tank", {}) if isinstance(s, dict) else {}
    zeta = get(s, "admittance", "effective_damping_ratio")
    zeta_alone = get(alone, "effective_damping_ratio")
    row = {
        "name": os.path.basename(run_dir.rstrip(os.sep)),
        "title": str(case.get("title", "")) if isinstance(case, dict) else "",
        "status": str(summary.get("status", "unknown")) if summary else "no summary",
        "simulated_time_s": get(summary, "simulated_time_s"),
        "end_time_s": get(case, "time", "end"),
        "leaked_particles": get(summary, "leaked_particles"),
        "wall_seconds_per_simulated_second": get(summary, "wall_seconds_per_simulated_second"),
        "structure": bool(s),
        "zeta_eff_percent": percent(zeta),
        "zeta_eff_without_tank_percent": percent(zeta_alone),
        "peak_acceleration_milli_g": get(s, "acceleration", "peak_milli_g"),
        "peak_acceleration_without_tank_milli_g": get(alone, "acceleration", "peak_milli_g"),
        "peak_acceleration_ratio": get(s, "acceleration", "peak_ratio_to_without_tank"),
        "rms_acceleration_milli_g": get(s, "acceleration", "rms_milli_g"),
        "rms_acceleration_ratio": get(s, "acceleration", "rms_ratio_to_without_tank"),
        "peak_displacement_m": get(s, "displacement", "peak_m"),
        "peak_displacement_ratio": get(s, "displacement", "peak_ratio_to_without_tank"),
        "natural_frequency_Hz": get(s, "admittance", "natural_frequency_Hz"),
        "band_Hz": s.get("admittance", {}).get("band_Hz") if isinstance(s.get("admittance"), dict) else None,
        # The tank damping of the linear equivalent TMD that gives this zeta_eff (summary.json, since e9a4192).
        "linear_tmd_tank_damping_percent": percent(get(s, "equivalent_tmd",
                                                       "tank_damping_for_measured_effective_damping")),
    }
    if status:
        # What `sloshsph status` read (the lock's holder, rows past the last summary): the run's
        # state now, the time it has reached and its leaks so far; the rest is the last summary's.
        row["status"] = str(status.get("state", row["status"]))
        row["summary_time_s"] = row["simulated_time_s"]
        for key, src in (("simulated_time_s", "time_s"), ("leaked_particles", "leaked_particles")):
            if get(status, src) is not None:
                row[key] = get(status, src)
    return row


def runs_table(rows, out_dir, folder):
    header = ["run", "status", "time (s)", "leaked", "wall s / sim s"]
    structure = any(r["structure"] for r in rows)
    if structure:
        header += ["ζ_eff (%)", "ζ_eff alone (%)", "linear TMD ζ_t (%)", "peak a_s (milli-g)", "peak ratio", "RMS a_s (milli-g)",
                   "RMS ratio", "peak x_s (m)", "peak x_s ratio"]
    cells = []
    for r in rows:
        link = os.path.relpath(os.path.join(folder, r["name"], "report.html"), out_dir)
        name = esc(r["name"])
        if os.path.exists(os.path.join(folder, r["name"], "report.html")):
            name = f"<a href='{esc(link)}'>{name}</a>"
        if r["title"]:
            name += f"<br><small>{esc(r['title'])}</small>"
        time = fmt(r["simulated_time_s"]) + (f" / {fmt(r['end_time_s'])}" if r["end_time_s"] is not None else "")
        row = [name, rl.status_badge(r["status"]), time, fmt(r["leaked_particles"]),
               fmt(r["wall_seconds_per_simulated_second"], 3)]
        if structure:
            row += [fmt(r[k]) for k in ("zeta_eff_percent", "zeta_eff_without_tank_percent",
                                        "linear_tmd_tank_damping_percent", "peak_acceleration_milli_g", "peak_acceleration_ratio",
                                        "rms_acceleration_milli_g", "rms_acceleration_ratio", "peak_displacement_m",
                                        "peak_displacement_ratio")]
        cells.append(row)
    return rl.table(header, cells)


def admittance_figure(folder, rows, save):
    """Every run's |H(f)|² of the displacement, within the load's band and up to 2.5 f_n, with the
    structure alone's (analytic, from the first run that has it)."""
    fig, ax = plt.subplots(figsize=(10, 4.6), constrained_layout=True)
    drawn, alone = 0, None
    for r in rows:
        path = os.path.join(folder, r["name"], "admittance.csv")
        if not os.path.exists(path) or r["natural_frequency_Hz"] is None:
            continue
        data = rl.read_admittance(path, r["band_Hz"], r["natural_frequency_Hz"])
        label = f"{r['name']}: ζ_eff = {fmt(r['zeta_eff_percent'], 3)} %"
        ax.semilogy(data["f_Hz"], data["H2_displacement"], lw=1.0, label=label)
        if alone is None and "H2_structure_alone" in data:
            alone = (data["f_Hz"], data["H2_structure_alone"])
        drawn += 1
    if not drawn:
        plt.close(fig)
        return ""
    if alone is not None:
        ax.semilogy(alone[0], alone[1], color="k", ls="--", lw=0.9, label="structure alone")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("|H(f)|² of the displacement")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Mechanical admittance of the structure with each run's tank (thesis eq. 4.30)", fontsize=11)
    return rl.figure_html(save(fig, "comparison_admittance"),
                          "Mechanical admittance of every coupled run. File plots/comparison_admittance.png.",
                          "admittance of every run")


def ratios_figure(rows, save):
    """ζ_eff and the peak and RMS acceleration ratios (with / without the tank) of each run."""
    rows = [r for r in rows if r["structure"]]
    if not rows:
        return ""
    names = [r["name"] for r in rows]
    x = np.arange(len(rows))
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.8), constrained_layout=True)
    left.bar(x, [r["zeta_eff_percent"] or 0.0 for r in rows], color="C0")
    alone = [r["zeta_eff_without_tank_percent"] for r in rows if r["zeta_eff_without_tank_percent"] is not None]
    if alone:
        left.axhline(alone[0], color="k", ls="--", lw=0.9, label="structure alone")
        left.legend(fontsize=8)
    left.set_ylabel("ζ_eff (%)")
    width = 0.38
    right.bar(x - width / 2, [r["peak_acceleration_ratio"] or 0.0 for r in rows], width, label="peak a_s")
    right.bar(x + width / 2, [r["rms_acceleration_ratio"] or 0.0 for r in rows], width, label="RMS a_s")
    right.axhline(1.0, color="k", lw=0.8)
    right.set_ylabel("with the tank ÷ without")
    right.legend(fontsize=8)
    for ax in (left, right):
        ax.set_xticks(x)
        ax.set_xticklabels(names, rotation=30, ha="right", fontsize=8)
        ax.grid(True, axis="y", alpha=0.3)
    fig.suptitle("Effective damping, and the structure's acceleration with the tank against without it", fontsize=11)
    return rl.figure_html(save(fig, "comparison_ratios"),
                          "Effective damping and acceleration ratios. File plots/comparison_ratios.png.",
                          "damping and acceleration ratios")


def build(folder, out_dir, args):
    notes = []
    states = read_status(args.status)
    rows = [run_row(d, notes, states.get(os.path.basename(d))) for d in rl.sub_run_dirs(folder)]
    plots = os.path.join(out_dir, "plots")

    def save(fig, stem):
        return rl.save_figure(fig, plots, stem, svg=not args.no_svg, dpi=args.dpi)

    body = [f"<h1>Comparison of the runs in {esc(os.path.basename(os.path.abspath(folder)))}</h1>"
            f"<p>{len(rows)} run directories in <code>{esc(os.path.abspath(folder))}</code>. The values of a run "
            "that has not completed are those of its last summary.json (up to the time it gives), or none "
            "when it has not written one yet; its state and the time it has reached are its state now.</p>",
            runs_table(rows, out_dir, folder)]
    body.append(admittance_figure(folder, rows, save))
    body.append(ratios_figure(rows, save))
    if notes:
        body.append("<ul class='notes'>" + "".join(f"<li>{esc(n)}</li>" for n in notes) + "</ul>")
    return rl.page(f"sloshsph comparison: {os.path.basename(os.path.abspath(folder))}", "".join(body)), rows


def parse_args(argv):
    ap = argparse.ArgumentParser(description="A side-by-side report of the run directories in a folder.")
    ap.add_argument("folder", help="a folder of sloshsph run directories")
    ap.add_argument("--out", help="write plots/, report.html and comparison.json here (default: FOLDER)")
    ap.add_argument("--status", help="the runs' states from `sloshsph status --json` (sloshsph report passes them)")
    ap.add_argument("--dpi", type=int, default=110, help="PNG resolution (default 110)")
    ap.add_argument("--no-svg", action="store_true", help="do not write .svg files")
    return ap.parse_args(argv)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if not os.path.isdir(args.folder) or not rl.sub_run_dirs(args.folder):
        print(f"compare_report.py: {args.folder} holds no run directories", file=sys.stderr)
        return 2
    out_dir = os.path.abspath(args.out or args.folder)
    try:
        os.makedirs(os.path.join(out_dir, "plots"), exist_ok=True)
        html_text, rows = build(args.folder, out_dir, args)
        with open(os.path.join(out_dir, "report.html"), "w", encoding="utf-8") as fh:
            fh.write(html_text)
        rl.write_json(os.path.join(out_dir, "comparison.json"), rows)
    except (OSError, ValueError) as err:
        print(f"compare_report.py: cannot write the report to {out_dir}: {err}", file=sys.stderr)
        return 2
    print(f"compare_report.py: {os.path.join(out_dir, 'report.html')} ({len(rows)} runs)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
