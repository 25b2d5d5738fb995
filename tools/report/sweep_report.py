#!/usr/bin/python3
"""Frequency-response plots and a self-contained HTML report of a sloshsph frequency sweep.

    /usr/bin/python3 tools/report/sweep_report.py SWEEP_DIR [--reference FILE.csv]
            [--reference-label TEXT] [--reference-normalised] [--csv-normalised]
            [--depth M] [--amplitude M] [--mass KG_PER_M] [--gauge NAME] [--point-reports]

SWEEP_DIR holds frequency_response.csv (columns beta, omega, eta_max, eta_min, F_sw_max,
F_sw_min, energy_per_cycle, status, and possibly more; any may be missing) and one run directory
per point. Writes SWEEP_DIR/plots/*.png (+ .svg) and SWEEP_DIR/report.html.

- The CSV values are plotted as they are (SI: m, N/m, J/m per cycle, unless --csv-normalised).
- When the depth h, amplitude X0 and water mass m_w are known (from the points' run directories,
  or --depth/--amplitude/--mass) the thesis's normalised curves are drawn too: eta/h,
  F_sw/(m_w X0 omega^2), E_w/(0.5 m_w (X0 omega)^2) (eqs. 4.23-4.27).
- --reference FILE.csv (columns beta and any of the same names) is overlaid on the curves of the
  same name: on the as-recorded plots, or on the normalised ones with --reference-normalised.
  A reference column NAME_norm always goes to the normalised plot of NAME.
- Without frequency_response.csv the points are computed from the run directories (first gauge
  or --gauge, low-pass filtered at 5 Hz, last 10 cycles).

Exit codes: 0 report written; 2 SWEEP_DIR holds neither frequency_response.csv nor run
directories, a bad --reference file, or the output cannot be written.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

import reportlib as rl
from reportlib import esc, fmt, plt

KNOWN = ["beta", "omega", "eta_max", "eta_min", "F_sw_max", "F_sw_min", "energy_per_cycle", "status"]
RUN_DIR_COLUMNS = ("run_dir", "dir", "directory", "path", "run", "out")
# (stem, title, [(column, label)], y label as recorded, y label normalised, normalisation kind)
GROUPS = [
    ("sweep_wave_height", "Wave height", [("eta_max", "η max"), ("eta_min", "η min")],
     "wave height η (m)", "η / h", "eta"),
    ("sweep_sloshing_force", "Sloshing force", [("F_sw_max", "F_sw max"), ("F_sw_min", "F_sw min")],
     "sloshing force F_sw (N/m)", "F_sw / (m_w X0 ω²)", "force"),
    ("sweep_energy", "Energy dissipated per cycle", [("energy_per_cycle", "E_w")],
     "energy per cycle E_w (J/m)", "E_w / (½ m_w (X0 ω)²)", "energy"),
]


# --------------------------------------------------------------------------------------------
# Reading


def read_table(path):
    """A CSV as (header, {column: list of raw strings}); numeric columns converted later."""
    with open(path, newline="", encoding="utf-8", errors="replace") as fh:
        rows = [r for r in csv.reader(fh) if r and any(f.strip() for f in r)]
    if not rows:
        return [], {}
    header = [h.strip() for h in rows[0]]
    cols = {h: [] for h in header}
    for r in rows[1:]:
        r = (r + [""] * len(header))[:len(header)]
        for h, v in zip(header, r):
            cols[h].append(v.strip())
    return header, cols


def as_float(values):
    out = []
    for v in values:
        try:
            out.append(float(v))
        except (TypeError, ValueError):
            out.append(math.nan)
    return np.array(out, dtype=float)


def is_numeric(values):
    parsed = [v for v in values if v not in ("", None)]
    if not parsed:
        return False
    try:
        [float(v) for v in parsed]
        return True
    except ValueError:
        return False


class Point:
    def __init__(self):
        self.values = {}
        self.texts = {}  # the swept keys' values as written (set:<key> columns), numeric or not
        self.status = ""
        self.run_dir = None
        self.run = None


def load_points(sweep_dir, notes, args):
    """Points from frequency_response.csv (or rebuilt from the run directories)."""
    csv_path = os.path.join(sweep_dir, "frequency_response.csv")
    runs = {}
    for d in rl.sub_run_dirs(sweep_dir):
        runs[d] = rl.Run(d)
    header, points = [], []
    if os.path.exists(csv_path):
        header, cols = read_table(csv_path)
        n = len(next(iter(cols.values()))) if cols else 0
        numeric = {h for h in header if is_numeric(cols[h])}
        for i in range(n):
            p = Point()
            for h in header:
                if h in numeric:
                    p.values[h] = as_float([cols[h][i]])[0]
            p.status = cols["status"][i] if "status" in cols else ""
            p.texts = {h: cols[h][i] for h in header if h.startswith("set:")}
            for key in RUN_DIR_COLUMNS:
                if key in cols and cols[key][i]:
                    path = os.path.join(sweep_dir, cols[key][i])
                    if rl.is_run_dir(path):
                        p.run_dir = os.path.abspath(path)
            points.append(p)
        if "beta" not in numeric:
            notes.append("frequency_response.csv has no numeric 'beta' column: nothing can be plotted vs β")
        match_runs(points, runs, notes)
    elif runs:
        notes.append("no frequency_response.csv: the points were computed from the run directories")
        header = KNOWN[:]
        points = points_from_runs(runs, notes, gauge=args.gauge)
    for p in points:
        if p.run_dir and p.run_dir in runs:
            p.run = runs[p.run_dir]
        elif p.run_dir:
            p.run = rl.Run(p.run_dir)
    return header, points, runs


def match_runs(points, runs, notes):
    """Links rows without a run-directory column to the run whose ω (or β) equals theirs."""
    unlinked = [p for p in points if p.run_dir is None]
    if not unlinked or not runs:
        return
    keyed = []
    for d, r in runs.items():
        w, w1 = r.omega(), r.summary_float("omega1_linear_rad_s")
        beta = r.case_float("excitation.beta") or (w / w1 if (w and w1) else None)
        keyed.append((d, w, beta))
    taken = set()
    for p in unlinked:
        for d, w, beta in keyed:
            if d in taken:
                continue
            pw, pb = p.values.get("omega"), p.values.get("beta")
            if (w and pw and abs(w - pw) <= 1e-6 * abs(pw)) or (beta and pb and abs(beta - pb) <= 1e-6 * abs(pb)):
                p.run_dir = d
                taken.add(d)
                break
    missing = sum(1 for p in points if p.run_dir is None)
    if missing:
        notes.append(f"{missing} of {len(points)} point(s) could not be matched to a run directory")


def points_from_runs(runs, notes, gauge=None, cycles=rl.DEFAULT_CYCLES, cutoff=rl.DEFAULT_CUTOFF_HZ):
    points = []
    for d, run in runs.items():
        p = Point()
        p.run_dir, p.run, p.status = d, run, run.status
        w, w1 = run.omega(), run.summary_float("omega1_linear_rad_s")
        p.values["omega"] = w if w else math.nan
        p.values["beta"] = run.case_float("excitation.beta") or (w / w1 if (w and w1) else math.nan)
        if w and len(run.time) > 1:
            period = 2 * math.pi / w
            window = rl.analysis_window(run.time, period, cycles, t_min=run.case_float("excitation.ramp"))
            gauges = [n for n in run.names if n.startswith("eta:")]
            name = f"eta:{gauge}" if gauge else (gauges[0] if gauges else None)
            for col, key in ((name, "eta"), ("F_sw", "F_sw")):
                if col in run.columns:
                    y, _ = rl.lowpass(run.time, run.columns[col], cutoff)
                    res = rl.steady_state_amplitude(run.time, run.columns[col] if y is None else y, period, window)
                    if res:
                        p.values[f"{key}_max"], p.values[f"{key}_min"] = res["avg_max"], res["avg_min"]
            if "F_w" in run.columns and "x_base" in run.columns:
                e = rl.energy_per_cycle(run.time, run.columns["F_w"], run.columns["x_base"], window)
                if e is not None:
                    p.values["energy_per_cycle"] = e
        points.append(p)
    return points


def read_reference(path):
    header, cols = read_table(path)
    if "beta" not in cols or not is_numeric(cols["beta"]):
        raise ValueError(f"{path}: needs a numeric 'beta' column (has: {', '.join(header) or 'nothing'})")
    return {h: as_float(v) for h, v in cols.items() if is_numeric(v)}


# --------------------------------------------------------------------------------------------
# Normalisation


def normalisation_factors(points, args, notes):
    """Per point (h, X0, m_w, ω) for eqs. 4.23-4.27; None where unknown."""
    out = []
    for p in points:
        run = p.run
        depth = args.depth or (run.case_float("fill.depth") if run else None)
        x0 = args.amplitude or (run.case_float("excitation.amplitude") if run else None)
        m_w = args.mass or (run.fluid_mass() if run else None)
        w = p.values.get("omega")
        if (w is None or not math.isfinite(w)) and run:
            w = run.omega()
        out.append([depth, x0, m_w, w])
    # A frequency sweep varies ω only: points without a run directory take h, X0, m_w from the
    # others when those all agree.
    for k, name in enumerate(("depth", "amplitude", "water mass")):
        known = {round(f[k], 12) for f in out if f[k]}
        if len(known) == 1 and any(not f[k] for f in out):
            for f in out:
                f[k] = f[k] or next(iter(known))
            notes.append(f"{name} of the points without a run directory taken from the others ({next(iter(known)):g})")
    return [tuple(f) for f in out]


def normalised(values, kind, factors):
    out = np.full(len(values), math.nan)
    for i, (v, (depth, x0, m_w, w)) in enumerate(zip(values, factors)):
        if kind == "eta" and depth:
            out[i] = v / depth
        elif kind == "force" and x0 and m_w and w:
            out[i] = v / (m_w * x0 * w * w)
        elif kind == "energy" and x0 and m_w and w:
            out[i] = v / (0.5 * m_w * (x0 * w) ** 2)
    return out


# --------------------------------------------------------------------------------------------
# Plots


def abscissa(header, points):
    """The x of the curves: beta; or, when beta is the same at every point and a key was swept
    (`--set KEY=A:B:N`, column set:KEY), the first swept key with numeric values. Every other
    swept key splits the points into one curve per value."""
    beta = np.array([p.values.get("beta", math.nan) for p in points], dtype=float)
    axes = [h for h in header if h.startswith("set:")]
    finite = beta[np.isfinite(beta)]
    beta_varies = len(finite) > 1 and np.ptp(finite) > 1e-9 * max(1.0, float(np.max(np.abs(finite))))
    numeric = [h for h in axes if points and all(h in p.values for p in points)]
    if beta_varies or not numeric:
        name, x, label, short = "beta", beta, "frequency ratio β = ω / ω1", "β"
    else:
        name = numeric[0]
        x = np.array([p.values[name] for p in points], dtype=float)
        label = short = name[len("set:"):]
    others = [h for h in axes if h != name]
    groups = None
    if others:
        groups = np.array([", ".join(f"{h[len('set:'):]} = {p.texts.get(h, '')}" for h in others) for p in points])
    return {"name": name, "values": x, "label": label, "short": short, "groups": groups}


def response_figure(rep, stem, title, series, ylabel, reference, beta, ok):
    """series: [(column, label, values)]; reference: [(label, beta, values)]. A figure that cannot
    be made becomes a visible note instead of a crash."""
    try:
        return _response_figure(rep, stem, title, series, ylabel, reference, beta, ok)
    except Exception as err:  # noqa: BLE001 - the report must still be written
        plt.close("all")
        rep["notes"].append(f"plot '{title}' failed: {type(err).__name__}: {err}")
        return f"<div class='banner warn'>{esc(title)}: the plot could not be made ({esc(err)}).</div>"


def _response_figure(rep, stem, title, series, ylabel, reference, beta, ok):
    fig, ax = plt.subplots(figsize=(8, 4.6), constrained_layout=True)
    order = np.argsort(beta)
    groups = rep["x"]["groups"]
    group_names = [None] if groups is None else list(dict.fromkeys(groups[order]))
    k = 0
    for col, lab, values in series:
        for group in group_names:
            c = f"C{k % 10}"
            k += 1
            members = order if group is None else order[groups[order] == group]
            sel = members[np.isfinite(values[members])]
            ax.plot(beta[sel], values[sel], "-o", color=c, lw=1.2, ms=4,
                    label=lab if group is None else f"{lab}, {group}")
            bad = sel[~ok[sel]]
            if len(bad):
                ax.plot(beta[bad], values[bad], "o", mfc="none", mec="red", ms=7,
                        label="run not completed" if k == 1 else None)
    for j, (lab, rb, rv) in enumerate(reference):
        sel = np.isfinite(rb) & np.isfinite(rv)
        idx = np.argsort(rb[sel])
        ax.plot(rb[sel][idx], rv[sel][idx], "--", color="0.25", mfc="none", ms=4, lw=0.9,
                label=lab, alpha=0.9, marker=["s", "^", "v", "D"][j % 4])
    if any(np.nanmin(v) < 0 < np.nanmax(v) for _, _, v in series if np.isfinite(v).any()):
        ax.axhline(0, color="0.5", lw=0.6)
    ax.set_xlabel(rep["x"]["label"])
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=12)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    png = rl.save_figure(fig, rep["plots_dir"], stem, svg=not rep["args"].no_svg, dpi=rep["args"].dpi)
    return rl.figure_html(png, f"{title} vs {rep['x']['short']}. File plots/{stem}.png (and .svg).", title)


def build(sweep_dir, args):
    notes = []
    header, points, runs = load_points(sweep_dir, notes, args)
    rep = {"plots_dir": os.path.join(sweep_dir, "plots"), "args": args, "notes": notes}
    parts = [f"<h1>Frequency sweep: {esc(os.path.basename(os.path.abspath(sweep_dir)))}</h1>",
             f"<p class='sub'>{esc(os.path.abspath(sweep_dir))} — {len(points)} point(s), "
             f"{len(runs)} run director{'y' if len(runs) == 1 else 'ies'}</p>"]
    reference = {}
    if args.reference:
        reference = read_reference(args.reference)  # errors handled by main
    rep["x"] = abscissa(header, points)
    beta = rep["x"]["values"]  # the curves' abscissa: beta, or a swept key
    if rep["x"]["name"] != "beta":
        reference = {}  # a reference curve is given against beta: it does not belong on these axes
    ok = np.array([(p.status in ("", "completed")) for p in points], dtype=bool)
    not_ok = [p for p in points if p.status not in ("", "completed")]
    if not_ok:
        parts.append(f"<div class='banner bad'>{len(not_ok)} point(s) did not complete "
                     f"(status {esc(', '.join(sorted(set(p.status for p in not_ok))))}); they are drawn "
                     "as red circles.</div>")
    if not points or not np.isfinite(beta).any():
        parts.append("<div class='banner warn'>No point with a numeric β: nothing to plot.</div>")
    factors = normalisation_factors(points, args, notes)
    can_normalise = (not args.csv_normalised) and any(all(f) for f in factors)
    sections = []
    if points and np.isfinite(beta).any():
        html_as, html_norm = [], []
        for stem, title, cols, ylabel, ylabel_n, kind in GROUPS:
            series = [(c, lab, np.array([p.values.get(c, math.nan) for p in points], dtype=float))
                      for c, lab in cols if any(c in p.values for p in points)]
            if not series:
                continue
            ref_as = [] if args.reference_normalised else [
                (f"{args.reference_label}: {c}", reference["beta"], reference[c]) for c, _, _ in series
                if c in reference]
            ref_norm = [(f"{args.reference_label}: {c}", reference["beta"], reference[c + "_norm"])
                        for c, _, _ in series if c + "_norm" in reference]
            if args.reference_normalised:
                ref_norm += [(f"{args.reference_label}: {c}", reference["beta"], reference[c])
                             for c, _, _ in series if c in reference]
            yl = ylabel_n if args.csv_normalised else ylabel
            html_as.append(response_figure(rep, stem, title, series, yl, ref_as, beta, ok))
            if can_normalise:
                nseries = [(c, lab, normalised(v, kind, factors)) for c, lab, v in series]
                if any(np.isfinite(v).any() for _, _, v in nseries):
                    html_norm.append(response_figure(rep, stem + "_normalised", f"{title}, normalised",
                                                     nseries, ylabel_n, ref_norm, beta, ok))
        extra = [h for h in header if h not in KNOWN and h not in RUN_DIR_COLUMNS and not h.startswith("set:")
                 and any(h in p.values for p in points)]
        for h in extra:
            series = [(h, h, np.array([p.values.get(h, math.nan) for p in points], dtype=float))]
            ref = [(f"{args.reference_label}: {h}", reference["beta"], reference[h])] if h in reference else []
            html_as.append(response_figure(rep, "sweep_" + safe(h), h, series, h, ref, beta, ok))
        label_as = "normalised, as in frequency_response.csv" if args.csv_normalised else \
            "as recorded in frequency_response.csv (SI units)"
        if not html_as:
            html_as.append("<p>frequency_response.csv holds no response column (eta_max, eta_min, F_sw_max, "
                           "F_sw_min, energy_per_cycle, or others): nothing to plot.</p>")
        sections.append(("curves", "Frequency response", f"<p>Values {esc(label_as)}.</p>" + "".join(html_as)))
        if html_norm:
            sections.append(("normalised", "Normalised frequency response",
                             "<p>Normalised as in the thesis: η/h (eq. 4.23), F_sw/(m_w X0 ω²) (eq. 4.25), "
                             "E_w/(½ m_w (X0 ω)²) (eq. 4.27), with h, X0 and m_w of each point's run "
                             "directory (or the command line).</p>" + "".join(html_norm)))
    table_html = points_table(sweep_dir, header, points, args)
    csv_text = rl.read_text(os.path.join(sweep_dir, "frequency_response.csv"))
    if csv_text is not None:
        table_html += rl.details("frequency_response.csv", f"<pre>{esc(csv_text)}</pre>")
    if args.reference:
        ref_text = rl.read_text(args.reference)
        if ref_text is not None:
            table_html += rl.details(f"reference: {os.path.basename(args.reference)}", f"<pre>{esc(ref_text)}</pre>")
    sections.append(("points", "Points", table_html))
    if notes:
        sections.append(("notes", "Notes", "<ul class='notes'>" + "".join(f"<li>{esc(n)}</li>" for n in notes)
                         + "</ul>"))
    nav = "<nav>" + "".join(f"<a href='#{sid}'>{esc(t)}</a>" for sid, t, _ in sections) + "</nav>"
    body = "".join(parts) + nav + "".join(f"<h2 id='{sid}'>{esc(t)}</h2>{h}" for sid, t, h in sections)
    return rl.page(f"sloshsph sweep: {os.path.basename(os.path.abspath(sweep_dir))}", body), notes


def safe(name):
    return "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in name)


def points_table(sweep_dir, header, points, args):
    cols = [h for h in header if h not in ("status",) + RUN_DIR_COLUMNS]
    if not cols:
        cols = sorted({k for p in points for k in p.values})
    rows = []
    order = sorted(range(len(points)), key=lambda i: (points[i].values.get("beta", math.inf)
                                                       if math.isfinite(points[i].values.get("beta", math.nan))
                                                       else math.inf))
    for i in order:
        p = points[i]
        link = "–"
        if p.run_dir:
            rel = os.path.relpath(p.run_dir, sweep_dir)
            if args.point_reports:
                import report
                report.main([p.run_dir, "--no-svg"])
            target = os.path.join(rel, "report.html")
            link = (f"<a href='{esc(target)}'>{esc(rel)}</a>" if os.path.exists(os.path.join(p.run_dir, "report.html"))
                    else esc(rel))
        rows.append([fmt(p.values.get(c)) for c in cols] + [rl.status_badge(p.status) if p.status else "–", link])
    return rl.table(cols + ["status", "run directory"], rows, left_columns=0)


def parse_args(argv):
    ap = argparse.ArgumentParser(description="Frequency-response report of a sloshsph sweep directory.")
    ap.add_argument("sweep_dir")
    ap.add_argument("--reference", help="CSV with column beta and any of the frequency_response.csv names")
    ap.add_argument("--reference-label", default="reference", help="legend label of the reference")
    ap.add_argument("--reference-normalised", action="store_true",
                    help="the reference holds normalised values (eqs. 4.23-4.27): overlay on the normalised plots")
    ap.add_argument("--csv-normalised", action="store_true",
                    help="frequency_response.csv already holds normalised values")
    ap.add_argument("--depth", type=float, help="still-water depth h (m) for the normalisation")
    ap.add_argument("--amplitude", type=float, help="excitation amplitude X0 (m) for the normalisation")
    ap.add_argument("--mass", type=float, help="water mass m_w (kg/m) for the normalisation")
    ap.add_argument("--gauge", help="gauge name when the points are computed from the run directories")
    ap.add_argument("--point-reports", action="store_true",
                    help="also write report.html in each point's run directory (slow) and link them")
    ap.add_argument("--dpi", type=int, default=110)
    ap.add_argument("--no-svg", action="store_true")
    return ap.parse_args(argv)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    d = args.sweep_dir
    if not os.path.isdir(d) or not (os.path.exists(os.path.join(d, "frequency_response.csv")) or rl.sub_run_dirs(d)):
        print(f"sweep_report.py: {d} is not a sweep directory (no frequency_response.csv and no run "
              "directories)", file=sys.stderr)
        return 2
    if args.reference:
        try:
            read_reference(args.reference)
        except (OSError, ValueError) as err:
            print(f"sweep_report.py: bad --reference: {err}", file=sys.stderr)
            return 2
    try:
        os.makedirs(os.path.join(d, "plots"), exist_ok=True)
    except OSError as err:
        print(f"sweep_report.py: cannot write to {d}: {err}", file=sys.stderr)
        return 2
    html_text, notes = build(d, args)
    try:
        with open(os.path.join(d, "report.html"), "w", encoding="utf-8") as fh:
            fh.write(html_text)
    except OSError as err:
        print(f"sweep_report.py: cannot write the report: {err}", file=sys.stderr)
        return 2
    print(f"sweep_report.py: {os.path.join(os.path.abspath(d), 'report.html')}")
    for n in notes:
        print(f"  note: {n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
