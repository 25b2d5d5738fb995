#!/usr/bin/python3
"""Plots and a self-contained HTML report of one sloshsph run directory.

    /usr/bin/python3 tools/report/report.py RUN_DIR [--out DIR] [--cycles N] [--cutoff HZ]
                                            [--snapshots K] [--no-svg] [--dpi DPI]

Writes DIR/plots/*.png (+ .svg for the line plots), DIR/report.html (images embedded as base64,
inline CSS, no script) and DIR/analysis.json (steady-state amplitudes, energy per cycle,
structure response); DIR defaults to RUN_DIR.

Exit codes: 0 report written (a failed, interrupted or empty run still gets a report, with a
banner and notes); 2 RUN_DIR is not a run directory, or the output cannot be written.
"""
import argparse
import io
import json
import math
import os
import sys
import traceback

import numpy as np

import reportlib as rl
from reportlib import esc, fmt, plt

import vtu  # tools/vtu.py (reportlib puts tools/ on sys.path)

DESCRIPTIONS = {
    "x_base": "base displacement X", "v_base": "base velocity", "a_base": "base acceleration",
    "F_w": "base shear F_w", "F_sw": "sloshing force F_sw = F_w − m_w·Ẍ", "F_wy": "vertical wall force",
    "E_kin": "kinetic energy (tank frame)", "E_pot": "potential energy", "W_base": "work of the base ∫F_w dX",
    "max_speed": "largest fluid speed", "dt": "time step", "ppe_iterations": "pressure-solve iterations",
    "leaked": "leaked particles", "fluid_mass": "fluid mass in the tank",
    "wall_contacts": "wall-contact corrections (cumulative)",
    "pair_contacts": "pair-contact corrections (cumulative)", "closest_pair": "closest two fluid particles (/ dp)",
    "x_s": "structure displacement", "v_s": "structure velocity", "a_s": "structure acceleration",
    "F_TLD": "TLD force on the structure",
    # 3D runs (summary.json "dimensions": 3): y is the breadth, z is up.
    "y_base": "base displacement along y", "v_base_y": "base velocity along y", "a_base_y": "base acceleration along y",
    "F_sw_y": "sloshing force along y, F_wy − m_w·Ÿ", "F_wz": "vertical wall force",
    "M_w": "moment of the wall force about output.moment_point",
    "M_wx": "moment of the wall force about x", "M_wy": "moment of the wall force about y",
    "M_wz": "moment of the wall force about z (vertical)",
    "x_s_y": "structure displacement along y", "v_s_y": "structure velocity along y",
    "a_s_y": "structure acceleration along y", "F_TLD_y": "TLD force on the structure along y",
}
BASE = ["x_base", "y_base", "v_base", "v_base_y", "a_base", "a_base_y"]
FORCES = ["F_w", "F_sw", "F_wy", "F_sw_y", "F_wz", "M_w", "M_wx", "M_wy", "M_wz"]


def three_d(run):
    return run.summary.get("dimensions") == 3


def description(run, name):
    if name == "F_wy" and three_d(run):
        return "wall force along y (the breadth)"
    return DESCRIPTIONS.get(name)


def per_what(run):
    """The extent the run's forces and energies are for: per metre of a 2D tank, or a whole 3D one."""
    return "whole tank" if three_d(run) else "per metre"
ENERGY = ["E_kin", "E_pot", "W_base"]
DIAGNOSTICS = ["max_speed", "dt", "ppe_iterations", "leaked", "wall_contacts", "pair_contacts", "closest_pair",
               "fluid_mass"]
STRUCTURE = ["x_s", "x_s_y", "v_s", "v_s_y", "a_s", "a_s_y", "F_TLD", "F_TLD_y"]  # _y: a 3D 2-DOF structure
MAX_PANELS = 10  # per figure; more columns are split over several figures


def label(run, name):
    unit = run.unit(name)
    return f"{name} ({unit})" if unit and unit != "1" else name


# --------------------------------------------------------------------------------------------
# Context shared by the sections


class Report:
    def __init__(self, run, args, out_dir):
        self.run = run
        self.args = args
        self.out_dir = out_dir
        self.plots_dir = os.path.join(out_dir, "plots")
        self.sections = []  # (id, title, html)
        self.analysis = {"run_dir": run.dir, "status": run.status, "notes": run.notes}
        self.window = None  # steady-state window (t_start, t_end, cycles)
        self.steady = {}  # name -> {'raw': ..., 'filtered': ...}
        self.filtered = {}  # name -> filtered array (cache)

    def save(self, fig, stem, svg=True):
        return rl.save_figure(fig, self.plots_dir, stem, svg=svg and not self.args.no_svg, dpi=self.args.dpi)

    def skips_first_row(self, name):
        """Forces are zero in the t = 0 row (no step taken yet, docs/case-format.md): that row is
        not drawn and does not enter the filter (it would ring)."""
        y = self.run.columns[name]
        return ((name.startswith("F_") or name == "dt") and len(y) > 2 and self.run.time[0] == 0.0 and y[0] == 0.0)

    def filtered_series(self, name):
        if name not in self.filtered:
            x = self.run.columns[name]
            if self.skips_first_row(name):
                x = x.copy()
                x[0] = x[1]
            y, why = rl.lowpass(self.run.time, x, self.args.cutoff)
            self.filtered[name] = y
            if y is None and why and why != "filter disabled" and "filter_note" not in self.analysis:
                self.analysis["filter_note"] = why
                self.run.notes.append(f"no low-pass filtering: {why}")
        return self.filtered[name]

    def normaliser(self, name):
        """(factor, label) for the thesis normalisation of a column, or None (eqs. 4.23-4.25)."""
        run = self.run
        if name.startswith("eta:"):
            depth = run.case_float("fill.depth")
            return (1.0 / depth, f"{name}/h") if depth else None
        if name in ("F_w", "F_sw"):
            m, x0, w = run.fluid_mass(), run.case_float("excitation.amplitude"), run.omega()
            if m and x0 and w and run.is_harmonic():
                return 1.0 / (m * x0 * w * w), f"{name}/(m_w X0 ω²)"
        return None


# --------------------------------------------------------------------------------------------
# Header


def header_section(rep):
    run = rep.run
    s = run.summary
    status = run.status
    parts = [f"<h1>{esc(run.title)}</h1>",
             f"<p class='sub'>{esc(run.dir)} — status {rl.status_badge(status)}</p>"]
    if not s:
        parts.append("<div class='banner warn'>No summary.json: the run is still going, was killed, or "
                     "did not start. The report shows what the directory holds.</div>")
    elif status != "completed":
        text = f"Run status: {status}."
        if s.get("failure"):
            text += f" {s['failure']}"
        if status == "interrupted":
            text += " The outputs are consistent up to the time it stopped."
        parts.append(f"<div class='banner bad'>{esc(text)}</div>")
    t = run.time
    if len(t) < 2:
        parts.append("<div class='banner warn'>The time series holds fewer than two samples: "
                     "there is nothing to plot over time.</div>")

    wall = run.summary_float("wall_time_s")
    pairs = [
        ("steps", fmt(s.get("steps"))),
        ("simulated time", f"{fmt(run.summary_float('simulated_time_s'))} s" if "simulated_time_s" in s else
         (f"{fmt(float(t[-1]))} s (last sample)" if len(t) else "–")),
        ("wall time", f"{rl.fmt_duration(wall)} ({fmt(wall)} s)" if wall is not None else "–"),
        ("wall time per simulated second", fmt(run.summary_float("wall_seconds_per_simulated_second"))),
        ("particles (fluid + wall)", f"{fmt(s.get('fluid_particles'))} + {fmt(s.get('wall_particles'))}"),
        ("leaked particles", fmt(s.get("leaked_particles"))),
        ("throughput", f"{fmt(run.summary_float('particle_steps_per_second'), 3)} particle-steps/s"),
        ("threads", fmt(s.get("threads"))),
        ("dp, h", f"{fmt(run.summary_float('dp_m'))} m, {fmt(run.summary_float('h_m'))} m"),
        ("dt", f"{fmt(run.summary_float('dt_s'))} s" + (" (adaptive)" if s.get("dt_adaptive") else "")),
        ("fluid mass m_w", f"{fmt(run.fluid_mass())} {run.unit('fluid_mass')} (final "
                           f"{fmt(run.summary_float('final_fluid_mass_kg' if three_d(run) else 'final_fluid_mass_kg_per_m'))})"),
        ("first sloshing frequency ω1 (linear)", f"{fmt(run.summary_float('omega1_linear_rad_s'))} rad/s"),
    ]
    if run.omega():
        w1 = run.summary_float("omega1_linear_rad_s")
        beta = f", β = ω/ω1 = {fmt(run.omega() / w1)}" if w1 else ""
        pairs.append(("excitation", f"X0 = {fmt(run.case_float('excitation.amplitude'))} m, "
                      f"ω = {fmt(run.omega())} rad/s (T = {fmt(2 * math.pi / run.omega())} s){beta}"))
    info = run.run_info
    pairs.append(("version, revision", f"{fmt(s.get('version', info.get('version')))}, "
                  f"{fmt(s.get('git_revision', info.get('git_revision')))}"))
    if info.get("command"):
        pairs.append(("command", f"<code>{esc(info['command'])}</code>"))
    if info.get("started"):
        pairs.append(("started – finished", f"{esc(info.get('started'))} – {esc(info.get('finished', '?'))}"))
    if info.get("host"):
        pairs.append(("host", esc(info["host"])))
    parts.append(rl.kv_table([(k, v if k in ("command", "started – finished", "host") else esc(v))
                              for k, v in pairs]))
    if run.case_text is not None:
        parts.append(rl.details("Resolved case (case.toml)", f"<pre>{esc(run.case_text)}</pre>"))
    if run.run_info:
        parts.append(rl.details("run.json", f"<pre>{esc(_json_text(run.run_info))}</pre>"))
    if s:
        parts.append(rl.details("summary.json", f"<pre>{esc(_json_text(s))}</pre>"))
    return "".join(parts)


def _json_text(value):
    return json.dumps(value, indent=2)


# --------------------------------------------------------------------------------------------
# Time histories


def history_figure(rep, names, stem, suptitle, filtered=True, normalise=True, extra=None, panel_height=2.1):
    """One panel per column: raw (and low-pass filtered) over time, the steady-state window shaded.

    extra(ax, name) may add to a panel. Returns the HTML of the figure(s).
    """
    run = rep.run
    t = run.time
    out = []
    for part in range(0, len(names), MAX_PANELS):
        chunk = names[part:part + MAX_PANELS]
        fig, axes = plt.subplots(len(chunk), 1, figsize=(10, 1.2 + panel_height * len(chunk)), sharex=True,
                                 squeeze=False, constrained_layout=True)
        for ax, name in zip(axes[:, 0], chunk):
            y = run.columns[name]
            y_f = rep.filtered_series(name) if filtered else None
            if rep.skips_first_row(name):
                y = y.copy()
                y[0] = np.nan
                if y_f is not None:
                    y_f = y_f.copy()
                    y_f[0] = np.nan
            if y_f is not None:
                ax.plot(t, y, color="0.65", lw=0.7, label="raw")
                ax.plot(t, y_f, color="C0", lw=1.3, label=f"low-pass {rep.args.cutoff:g} Hz")
            else:
                ax.plot(t, y, color="C0", lw=1.0, label="raw")
            if rep.window and filtered:
                ax.axvspan(rep.window[0], rep.window[1], color="gold", alpha=0.15, lw=0,
                           label=f"steady-state window ({rep.window[2]} cycles)")
            desc = description(run, name)
            ax.set_title(f"{name}: {desc}" if desc else name, fontsize=10, loc="left")
            ax.set_ylabel(label(run, name))
            ax.grid(True, alpha=0.3)
            norm = rep.normaliser(name) if normalise else None
            if norm:
                k, nlabel = norm
                sec = ax.secondary_yaxis("right", functions=(lambda v, k=k: v * k, lambda v, k=k: v / k))
                sec.set_ylabel(nlabel)
            if extra:
                extra(ax, name)
        if filtered:  # above the first panel, right of its title: never over the curves
            axes[0, 0].legend(loc="lower right", bbox_to_anchor=(1.0, 1.0), fontsize=8, ncol=3, frameon=False,
                              borderaxespad=0.1)
        axes[-1, 0].set_xlabel("time t (s)")
        fig.suptitle(suptitle, fontsize=12)
        suffix = "" if part == 0 else f"_{part // MAX_PANELS + 1}"
        png = rep.save(fig, stem + suffix)
        out.append(rl.figure_html(png, f"{suptitle}. File plots/{stem + suffix}.png (and .svg).", suptitle))
    return "".join(out)


def steady_lines(rep):
    """Adds the filtered steady-state average max/min as dashed lines over the window."""
    def draw(ax, name):
        st = rep.steady.get(name, {})
        res = st.get("filtered") or st.get("raw")
        if res and rep.window:
            for v in (res["avg_max"], res["avg_min"]):
                ax.hlines(v, rep.window[0], rep.window[1], colors="C3", linestyles="--", lw=1.0)
    return draw


def histories_section(rep):
    run = rep.run
    cols = run.columns
    if len(run.time) < 2:
        return "<p>Fewer than two samples in timeseries.csv: no time histories.</p>"
    parts = []
    gauges = [n for n in run.names if n.startswith("eta:")]
    probes = [n for n in run.names if n.startswith("p:")]
    forces = [n for n in FORCES if n in cols]
    screens = [n for n in run.names if n.startswith("F_screen:")]
    caption_filter = (f"Grey: raw samples; blue: zero-phase 4th-order Butterworth low-pass at "
                      f"{rep.args.cutoff:g} Hz (thesis 2.6.3)." if rep.args.cutoff > 0 else "")
    if rep.window:
        caption_filter += (" Shaded: the steady-state window; red dashes: the average of the per-cycle "
                           "maxima and minima there.")
    if caption_filter:
        parts.append(f"<p>{esc(caption_filter)}</p>")
    if gauges:
        parts.append("<h3 id='gauges'>Wave gauges</h3>")
        parts.append(history_figure(rep, gauges, "gauges", "Free-surface elevation at the wave gauges",
                                    extra=steady_lines(rep)))
    else:
        parts.append("<p>No wave gauges (eta:*) in the time series.</p>")
    if probes:
        parts.append("<h3 id='probes'>Pressure probes</h3>")
        peaks = impact_peaks(run)
        parts.append(history_figure(rep, probes, "pressure", "Pressure at the probes", extra=impact_marks(peaks)))
        parts.append(impact_table(rep, peaks))
    if forces:
        parts.append("<h3 id='forces'>Forces</h3>")
        parts.append(history_figure(rep, forces, "forces", f"Forces of the walls on the fluid ({per_what(run)})",
                                    extra=steady_lines(rep)))
    if screens:
        parts.append("<h3>Screen forces</h3>")
        parts.append(history_figure(rep, screens, "screen_forces", "Forces on the screens (per metre)"))
    plates = [n for n in run.names if n.split(":")[0] in ("plate_dx", "plate_dy", "plate_mid_dx", "plate_mid_dy")]
    plate_forces = [n for n in run.names if n.split(":")[0] in ("F_plate_x", "F_plate_y")]
    if plates:
        parts.append("<h3 id='plates'>Elastic plates</h3>")
        parts.append(history_figure(rep, plates, "plates", "Elastic plates: displacement of the tip (the `to` end) "
                                    "and of the middle", filtered=False, normalise=False))
        parts.append(history_figure(rep, plate_forces, "plate_forces", "Force of the fluid on the plates (per metre)"))
    base = [n for n in BASE if n in cols]
    if base:
        parts.append("<h3 id='base'>Base motion</h3>")
        parts.append(history_figure(rep, base, "base_motion", "Tank (base) motion", filtered=False,
                                    normalise=False, panel_height=1.7))
    parts.append(energy_figure(rep))
    diag = [n for n in DIAGNOSTICS if n in cols]
    if diag:
        parts.append("<h3 id='diagnostics'>Diagnostics</h3>")
        parts.append(history_figure(rep, diag, "diagnostics", "Run diagnostics", filtered=False,
                                    normalise=False, panel_height=1.5))
    known = set(["time"] + BASE + FORCES + ENERGY + DIAGNOSTICS + STRUCTURE + gauges + probes + screens + plates
                + plate_forces)
    other = [n for n in run.names if n not in known]
    if other:
        parts.append("<h3>Other columns</h3>")
        parts.append(history_figure(rep, other, "other", "Other columns of timeseries.csv", filtered=False,
                                    normalise=False))
    return "".join(parts)


def impact_peaks(run):
    """summary.json `pressure_probes`: {column: probe object} (docs/case-format.md)."""
    probes = run.summary.get("pressure_probes") if isinstance(run.summary, dict) else None
    if not isinstance(probes, list):
        return {}
    return {p["column"]: p for p in probes if isinstance(p, dict) and "column" in p}


def impact_marks(peaks):
    """Marks each probe's first impact peak (red triangle) and shades its rise and fall."""
    def draw(ax, name):
        pk = (peaks.get(name) or {}).get("impact_peak")
        if pk:
            ax.axvspan(pk["rise_start_s"], pk["end_s"], color="C3", alpha=0.10, lw=0)
            ax.plot([pk["peak_time_s"]], [pk["peak_Pa"]], "v", color="C3", ms=6, label="first impact peak")
    return draw


def impact_table(rep, peaks):
    """The first impact peak of each pressure probe, as summary.json gives it (analysis/impact_peak.hpp)."""
    if not peaks:
        return ""
    rows, info = [], {}
    for column, probe in peaks.items():
        face = probe.get("face_length_m") or 0.0
        where = f"face {fmt(face * 1000)} mm" if face > 0 else "point"
        pk = probe.get("impact_peak")
        info[column] = pk
        if not pk:
            rows.append([esc(column), esc(where), "no rise above the first sample", "", "", "", ""])
            continue
        rows.append([esc(column), esc(where), fmt(pk["peak_Pa"]), fmt(pk["peak_time_s"]), fmt(pk["rise_time_s"]),
                     fmt(pk["impulse_Pa_s"]), fmt(pk["baseline_Pa"])])
    rep.analysis["impact_peaks"] = info
    return ("<p>First impact peak of each probe (red triangle; shaded: from the 10 % level of the rise to the "
            "end of the peak). Rise time: from 10 % to 90 % of the peak above the first sample p0; impulse: "
            "∫(p − p0) dt over the shaded interval (docs/physics.md, \"Impact peak\").</p>"
            + rl.table(["probe", "sensor", "peak (Pa)", "at (s)", "rise time 10–90 % (s)", "impulse (Pa·s)",
                        "p0 (Pa)"], rows, left_columns=2))


def energy_figure(rep):
    run = rep.run
    cols = run.columns
    present = [n for n in ENERGY if n in cols]
    if not present:
        return ""
    t = run.time
    fig, ax = plt.subplots(figsize=(10, 3.6), constrained_layout=True)
    if "E_kin" in cols:
        ax.plot(t, cols["E_kin"], lw=1.0, label="E_kin: kinetic energy (tank frame)")
    if "E_pot" in cols:
        e0 = cols["E_pot"][0] if np.isfinite(cols["E_pot"][0]) else 0.0
        ax.plot(t, cols["E_pot"] - e0, lw=1.0, label=f"E_pot − E_pot(0)  [E_pot(0) = {fmt(float(e0))} {run.unit('E_pot')}]")
    if "W_base" in cols:
        ax.plot(t, cols["W_base"], lw=1.3, label="W_base: work done by the base, ∫F_w dX")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel(f"energy ({rep.run.unit('E_kin')})")
    ax.set_title("Energies of the fluid", fontsize=12)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    png = rep.save(fig, "energy")
    return "<h3 id='energy'>Energies</h3>" + rl.figure_html(
        png, "Kinetic and potential energy of the fluid, and the cumulative work of the base. "
        "File plots/energy.png (and .svg).", "energies")


# --------------------------------------------------------------------------------------------
# Steady state (harmonic excitation)


def compute_steady_state(rep):
    """Fills rep.window, rep.steady and rep.analysis['harmonic']; returns notes for the section."""
    run = rep.run
    if not run.is_harmonic():
        return "The run has no harmonic excitation (no excitation_omega_rad_s in summary.json)."
    w = run.omega()
    period = 2 * math.pi / w
    t = run.time
    ramp = run.case_float("excitation.ramp") or 0.0
    stop = run.case_float("excitation.stop")
    rep.window = rl.analysis_window(t, period, rep.args.cycles, t_stop=stop if stop and stop > 0 else None,
                                    t_min=ramp)
    x0 = run.case_float("excitation.amplitude")
    depth = run.case_float("fill.depth")
    m_w = run.fluid_mass()
    h = {
        "omega_rad_s": w, "period_s": period, "amplitude_X0_m": x0, "depth_m": depth,
        "fluid_mass_kg_per_m": m_w, "cycles_requested": rep.args.cycles,
        "filter": {"type": "Butterworth low-pass, zero phase (forward-backward)", "order": 4,
                   "cutoff_hz": rep.args.cutoff if rep.args.cutoff > 0 else None},
        "method": "average of the per-cycle maxima and minima over the last whole excitation periods "
                  "ending at the last sample (thesis 2.6.3, 4.3.1); peaks refined by a parabola through "
                  "three samples",
        "force_scale_N_per_m": m_w * x0 * w * w if (m_w and x0) else None,
        "energy_scale_J_per_m": 0.5 * m_w * (x0 * w) ** 2 if (m_w and x0) else None,
    }
    rep.analysis["harmonic"] = h
    if rep.window is None:
        h["cycles_used"] = 0
        return (f"Not one whole excitation period (T = {period:.4g} s) fits in the record after the ramp: "
                "no steady-state amplitudes.")
    t0, t1, cycles = rep.window
    h.update({"cycles_used": cycles, "window_s": [t0, t1]})
    signals = {}
    names = [n for n in run.names if n.startswith("eta:")] + [n for n in ("F_w", "F_sw") if n in run.columns]
    names += [n for n in run.names if n.startswith("p:")]
    for name in names:
        entry = {"unit": run.unit(name)}
        norm = rep.normaliser(name)
        raw = rl.steady_state_amplitude(t, run.columns[name], period, rep.window)
        y_f = rep.filtered_series(name)
        fil = rl.steady_state_amplitude(t, y_f, period, rep.window) if y_f is not None else None
        for key, res in (("raw", raw), ("filtered", fil)):
            if res is None:
                entry[key] = None
                continue
            if norm:
                res["avg_max_normalised"] = res["avg_max"] * norm[0]
                res["avg_min_normalised"] = res["avg_min"] * norm[0]
                entry["normalised_by"] = norm[1]
            entry[key] = res
        signals[name] = entry
        rep.steady[name] = entry
    h["signals"] = signals
    if "F_w" in run.columns and "x_base" in run.columns:
        e = rl.energy_per_cycle(t, run.columns["F_w"], run.columns["x_base"], rep.window)
        ew = rl.work_increase_per_cycle(t, run.columns["W_base"], rep.window) if "W_base" in run.columns else None
        h["energy_per_cycle"] = {
            "E_w_J_per_m": e,
            "E_w_normalised": rl.normalised_energy(e, m_w, x0, w) if (e is not None and m_w and x0) else None,
            "from_W_base_J_per_m": ew,
            "from_W_base_normalised": rl.normalised_energy(ew, m_w, x0, w) if (ew is not None and m_w and x0) else None,
            "cycles": cycles,
            "method": "closed integral of F_w dX over the window divided by the cycles (thesis eq. 4.28), "
                      "F_w taken as the mean over each sample interval; normalised by 0.5 m_w (X0 ω)² "
                      "(eq. 4.27). from_W_base: increase of the column W_base over the window per cycle.",
        }
    return ""


def steady_section(rep, note):
    h = rep.analysis.get("harmonic")
    if not h:
        return f"<p>{esc(note)}</p>"
    parts = [f"<p>Excitation ω = {fmt(h['omega_rad_s'])} rad/s, T = {fmt(h['period_s'])} s, "
             f"X0 = {fmt(h['amplitude_X0_m'])} m, depth h = {fmt(h['depth_m'])} m, "
             f"m_w = {fmt(h['fluid_mass_kg_per_m'])} {rep.run.unit('fluid_mass')}.</p>"]
    if note:
        parts.append(f"<div class='banner warn'>{esc(note)}</div>")
        return "".join(parts)
    t0, t1 = h["window_s"]
    cycles = h["cycles_used"]
    if rep.run.status != "completed":
        parts.append(f"<div class='banner warn'>The run did not complete (status {esc(rep.run.status)}): the "
                     "last cycles before it stopped are used, and need not be a steady state.</div>")
    short = "" if cycles >= h["cycles_requested"] else (
        f" (fewer than the {h['cycles_requested']} requested: the record is short, the response may not "
        "be steady yet)")
    parts.append(f"<p>Averages of the per-cycle maxima and minima over the last {cycles} excitation "
                 f"period(s){esc(short)}, t = {fmt(t0)} … {fmt(t1)} s. Normalised as in the thesis: "
                 "η/h (eq. 4.23), F/(m_w X0 ω²) (eqs. 4.24-4.25).</p>")
    rows = []
    for name, e in h.get("signals", {}).items():
        for key in ("filtered", "raw"):
            res = e.get(key)
            if not res:
                continue
            rows.append([esc(name), esc(key if key == "raw" else f"low-pass {rep.args.cutoff:g} Hz"),
                         esc(e["unit"]), fmt(res["avg_max"]), fmt(res["avg_min"]),
                         fmt(res.get("avg_max_normalised")), fmt(res.get("avg_min_normalised")),
                         esc(e.get("normalised_by", "–")), f"{100 * res['max_spread_rel']:.1f} %"])
    parts.append(rl.table(["signal", "series", "unit", "avg max", "avg min", "avg max (norm.)",
                           "avg min (norm.)", "normalised as", "spread of the maxima"], rows, left_columns=3))
    parts.append("<p class='sub'>Spread of the maxima: (largest − smallest per-cycle maximum) / |average|; "
                 "a few per cent or more means the response is not steady yet.</p>")
    en = h.get("energy_per_cycle")
    if en:
        parts.append("<h3>Energy dissipated per cycle</h3>")
        parts.append(rl.table(
            ["quantity", "E_w (J/m per cycle)", "E'_w = E_w / (½ m_w (X0 ω)²)"],
            [["closed integral of F_w dX (eq. 4.28)", fmt(en["E_w_J_per_m"]), fmt(en["E_w_normalised"])],
             ["increase of W_base per cycle (check)", fmt(en["from_W_base_J_per_m"]),
              fmt(en["from_W_base_normalised"])]]))
        parts.append(hysteresis_figure(rep))
    parts.append(zoom_figure(rep))
    parts.append("<p>All numbers are also in <code>analysis.json</code>.</p>")
    return "".join(parts)


def zoom_figure(rep):
    """The steady-state window alone, normalised as in the thesis (eqs. 4.23-4.25)."""
    run = rep.run
    names = [n for n in rep.steady if (n.startswith("eta:") or n in ("F_w", "F_sw"))]
    if not names:
        return ""
    t = run.time
    t0, t1, cycles = rep.window
    sel = (t >= t0 - 1e-9) & (t <= t1 + 1e-9)
    fig, axes = plt.subplots(len(names), 1, figsize=(10, 1.2 + 1.9 * len(names)), sharex=True, squeeze=False,
                             constrained_layout=True)
    for ax, name in zip(axes[:, 0], names):
        norm = rep.normaliser(name)
        k, ylab = norm if norm else (1.0, label(run, name))
        y_f = rep.filtered_series(name)
        ax.plot(t[sel], run.columns[name][sel] * k, color="0.65", lw=0.7, label="raw")
        if y_f is not None:
            ax.plot(t[sel], y_f[sel] * k, color="C0", lw=1.3, label=f"low-pass {rep.args.cutoff:g} Hz")
        res = rep.steady[name].get("filtered") or rep.steady[name].get("raw")
        if res:
            for v in (res["avg_max"], res["avg_min"]):
                ax.axhline(v * k, color="C3", ls="--", lw=1.0)
        ax.set_ylabel(ylab)
        ax.grid(True, alpha=0.3)
    axes[0, 0].legend(loc="lower right", bbox_to_anchor=(1.0, 1.0), fontsize=8, ncol=3, frameon=False,
                      borderaxespad=0.1)
    axes[-1, 0].set_xlabel("time t (s)")
    fig.suptitle(f"Steady-state window: last {cycles} excitation period(s), normalised", fontsize=12)
    png = rep.save(fig, "steady_state")
    return rl.figure_html(png, "The window the averages are taken over; red dashes: average per-cycle maximum "
                          "and minimum. File plots/steady_state.png (and .svg).", "steady-state window")


def hysteresis_figure(rep):
    run = rep.run
    t = run.time
    t0, t1, cycles = rep.window
    sel = (t >= t0) & (t <= t1)
    if sel.sum() < 3:
        return ""
    fig, ax = plt.subplots(figsize=(6.5, 4.6), constrained_layout=True)
    x = run.columns["x_base"][sel]
    ax.plot(x, run.columns["F_w"][sel], color="0.6", lw=0.7, label="F_w raw")
    y_f = rep.filtered_series("F_w")
    if y_f is not None:
        ax.plot(x, y_f[sel], color="C0", lw=1.3, label=f"F_w low-pass {rep.args.cutoff:g} Hz")
    e = rep.analysis["harmonic"]["energy_per_cycle"]["E_w_J_per_m"]
    ax.set_xlabel(label(run, "x_base"))
    ax.set_ylabel(label(run, "F_w"))
    ax.set_title(f"Base shear vs base displacement, last {cycles} cycle(s)\n"
                 f"enclosed area per cycle E_w = {fmt(e)} J/m", fontsize=11)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    png = rep.save(fig, "hysteresis")
    return rl.figure_html(png, "The area enclosed by the F_w–X loop is the energy per cycle (eq. 4.28). "
                          "File plots/hysteresis.png (and .svg).", "hysteresis loop")


# --------------------------------------------------------------------------------------------
# Particle snapshots


def pick_snapshots(entries, k):
    """k evenly spread entries over the run plus the last one (no duplicates)."""
    n = len(entries)
    if n == 0 or k <= 0:
        return []
    idx = sorted(set(int(round(v)) for v in np.linspace(0, n - 1, min(k, n - 1) + 1))) if n > 1 else [0]
    return [entries[i] for i in idx]


def snapshot_entries(run_dir, notes):
    pvd = os.path.join(run_dir, "particles.pvd")
    entries = []
    if os.path.exists(pvd):
        try:
            entries = [(t, f) for t, f in vtu.read_pvd(pvd) if os.path.exists(f)]
        except OSError as err:
            notes.append(f"particles.pvd could not be read: {err}")
    if not entries:
        folder = os.path.join(run_dir, "particles")
        if os.path.isdir(folder):
            files = sorted(f for f in os.listdir(folder) if f.endswith(".vtu"))
            entries = [(math.nan, os.path.join(folder, f)) for f in files]
    return entries


def view_axes(run):
    """The two coordinates a snapshot shows: x and y in 2D; x and z (a side view, the breadth's
    particles overlaid) in 3D."""
    return (0, 2) if three_d(run) else (0, 1)


def particle_spacing(run, pts):
    dp = run.case_float("particles.dp") or run.summary_float("dp_m")
    if dp:
        return dp
    if len(pts) > 1:
        from scipy.spatial import cKDTree
        d, _ = cKDTree(pts[:, :2]).query(pts[:2000, :2], k=2)
        return float(np.median(d[:, 1]))
    return 0.01


def snapshots_section(rep):
    run = rep.run
    entries = snapshot_entries(run.dir, run.notes)
    if not entries:
        return "<p>No particle snapshots in the run directory.</p>"
    chosen = pick_snapshots(entries, rep.args.snapshots)
    loaded = []
    for t, path in chosen:
        try:
            loaded.append((t, path, vtu.read_vtu(path, skip_cells=True)))
        except (OSError, ValueError, KeyError) as err:
            run.notes.append(f"snapshot {os.path.basename(path)} skipped: {err}")
    if not loaded:
        return "<p>The particle snapshots could not be read (see the notes).</p>"
    p_lo, p_hi, v_hi = colour_limits(loaded)
    a, b = view_axes(run)
    all_pts = np.concatenate([d["points"][:, [a, b]] for _, _, d in loaded])
    bounds = (all_pts[:, 0].min(), all_pts[:, 0].max(), all_pts[:, 1].min(), all_pts[:, 1].max())
    dp = particle_spacing(run, loaded[0][2]["points"])
    parts = [f"<p>{len(loaded)} of {len(entries)} snapshots. Fluid particles coloured by pressure (left) and "
             "speed (right), one colour scale for all snapshots; wall particles grey. "
             "Crosses: leaked particles (if any)."
             + (" A 3D run is seen from the side (x, z), the particles across its breadth overlaid." if three_d(run)
                else "") + "</p>"]
    for i, (t, path, d) in enumerate(loaded):
        png = snapshot_figure(rep, t, d, (p_lo, p_hi, v_hi), bounds, dp)
        stem = f"snapshot_{i:02d}"
        with open(os.path.join(rep.plots_dir, stem + ".png"), "wb") as fh:
            fh.write(png)
        when = f"t = {t:.3f} s" if math.isfinite(t) else os.path.basename(path)
        parts.append(rl.figure_html(png, f"Particles at {when} ({os.path.basename(path)}). "
                                    f"File plots/{stem}.png.", f"particles at {when}"))
    return "".join(parts)


def colour_limits(loaded):
    ps, vs = [], []
    for _, _, d in loaded:
        fluid = fluid_mask(d)
        if "pressure" in d:
            ps.append(np.asarray(d["pressure"], dtype=float)[fluid])
        if "velocity" in d:
            v = np.asarray(d["velocity"], dtype=float)
            vs.append(np.linalg.norm(v[fluid, :3], axis=1))
    p = np.concatenate(ps) if ps else np.zeros(1)
    v = np.concatenate(vs) if vs else np.zeros(1)
    p = p[np.isfinite(p)] if np.isfinite(p).any() else np.zeros(1)
    v = v[np.isfinite(v)] if np.isfinite(v).any() else np.zeros(1)
    p_lo = min(0.0, float(np.percentile(p, 0.5)))
    p_hi = max(float(np.percentile(p, 99.5)), p_lo + 1e-9)
    v_hi = max(float(np.percentile(v, 99.5)), 1e-9)
    return p_lo, p_hi, v_hi


def fluid_mask(d):
    n = len(d["points"])
    if "kind" in d and len(d["kind"]) == n:
        return np.asarray(d["kind"]) == 0
    return np.ones(n, dtype=bool)


def snapshot_figure(rep, t, d, limits, bounds, dp):
    from mpl_toolkits.axes_grid1 import make_axes_locatable
    run = rep.run
    p_lo, p_hi, v_hi = limits
    x0, x1, y0, y1 = bounds
    pad = 2 * dp
    w, h = (x1 - x0) + 2 * pad, (y1 - y0) + 2 * pad
    panel_w = 5.0
    panel_h = float(np.clip(panel_w * h / w, 1.6, 7.0))
    fig, axes = plt.subplots(1, 2, figsize=(2 * panel_w + 2.2, panel_h + 1.1))
    a, b = view_axes(run)
    pts = np.asarray(d["points"], dtype=float)[:, [a, b]]
    fluid = fluid_mask(d)
    fields = []
    if "pressure" in d:
        fields.append(("pressure p (Pa)", np.asarray(d["pressure"], dtype=float), "viridis", p_lo, p_hi))
    if "velocity" in d:
        v = np.asarray(d["velocity"], dtype=float)
        fields.append(("speed |u| (m/s)", np.linalg.norm(v[:, :3], axis=1), "magma", 0.0, v_hi))
    when = f"t = {t:.3f} s" if math.isfinite(t) else ""
    leaks = [(l.get("x"), l.get("z" if three_d(run) else "y")) for l in run.summary.get("leaks_first_100", []) or []
             if isinstance(l, dict) and (not math.isfinite(t) or l.get("time_s", 0) <= t + 1e-9)]
    collections = []
    for k, ax in enumerate(axes):
        ax.set_xlim(x0 - pad, x1 + pad)
        ax.set_ylim(y0 - pad, y1 + pad)
        ax.set_aspect("equal")
        collections.append(ax.scatter(pts[~fluid, 0], pts[~fluid, 1], s=1, c="0.6", marker="s", lw=0,
                                      rasterized=True))
        cax = make_axes_locatable(ax).append_axes("right", size="3.5%", pad=0.08)
        if k < len(fields):
            title, values, cmap, lo, hi = fields[k]
            sc = ax.scatter(pts[fluid, 0], pts[fluid, 1], s=1, c=values[fluid], cmap=cmap, vmin=lo, vmax=hi,
                            lw=0, rasterized=True)
            fig.colorbar(sc, cax=cax, label=title)
            ax.set_title(f"{title.split(' (')[0]}, {when}", fontsize=10)
        else:
            sc = ax.scatter(pts[fluid, 0], pts[fluid, 1], s=1, c="C0", lw=0, rasterized=True)
            cax.set_visible(False)
        collections.append(sc)
        if leaks:
            lx, ly = np.array(leaks, dtype=float).T
            ax.plot(lx, ly, "rx", ms=5, label="leaked")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("z (m)" if three_d(run) else "y (m)")
    fig.tight_layout()
    size = marker_size(fig, axes[0], dp)
    for c in collections:
        c.set_sizes([size])
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=rep.args.dpi, bbox_inches="tight", pad_inches=0.12)
    plt.close(fig)
    return buf.getvalue()


def marker_size(fig, ax, dp):
    """Scatter size (points²) for a marker about one particle spacing wide on screen."""
    ax.apply_aspect()
    pos = ax.get_position()
    width_pt = pos.width * fig.get_figwidth() * 72.0
    x_lo, x_hi = ax.get_xlim()
    per_metre = width_pt / max(x_hi - x_lo, 1e-12)
    return float(np.clip((0.95 * dp * per_metre) ** 2, 0.3, 400.0))


# --------------------------------------------------------------------------------------------
# Structure (coupled runs)


def structure_section(rep):
    run = rep.run
    present = [n for n in STRUCTURE if n in run.columns]
    if not present or len(run.time) < 2:
        return None
    parts = [history_figure(rep, present, "structure", "Structure response", filtered=False, normalise=False)]
    info = {}
    rows = []
    for name in present:
        y = run.columns[name]
        ok = np.isfinite(y)
        if not ok.any():
            continue
        tail = y[ok][len(y[ok]) // 2:]
        entry = {"unit": run.unit(name), "peak_abs": float(np.max(np.abs(y[ok]))),
                 "rms": float(np.sqrt(np.mean(y[ok] ** 2))),
                 "rms_second_half": float(np.sqrt(np.mean(tail ** 2))) if len(tail) else None}
        info[name] = entry
        rows.append([esc(name), esc(entry["unit"]), fmt(entry["peak_abs"]), fmt(entry["rms"]),
                     fmt(entry["rms_second_half"])])
    parts.append(rl.table(["signal", "unit", "peak |value|", "RMS", "RMS, second half"], rows))
    psd_html = structure_psd(rep, [n for n in ("x_s", "a_s", "x_s_y", "a_s_y") if n in run.columns], info)
    parts.append(psd_html or "<p>The record is too short for a power spectral density (PSD).</p>")
    parts.append(admittance_part(rep, info))
    parts.append(admittance_part(rep, info, "_y"))
    rep.analysis["structure"] = info
    return "".join(parts)


def free_decay_section(rep):
    """After the base stops (excitation.stop > 0), each gauge's free decay: its frequency and its
    damping ratio from the logarithmic decrement of the half heights per period (5 Hz low-passed,
    from one excitation period after the stop). None without a stop or a free decay of 3 periods."""
    run = rep.run
    stop = run.case_float("excitation.stop")
    if not stop or stop <= 0 or len(run.time) < 8:
        return None
    period = 2 * math.pi / run.omega() if run.omega() else 0.0
    t_start = stop + period
    rows, info, curves = [], {}, []
    for name in [n for n in run.names if n.startswith("eta:")]:
        y = rep.filtered_series(name)
        res = rl.free_decay(run.time, y if y is not None else run.columns[name], t_start)
        if res is None:
            continue
        curves.append((name, res))
        info[name] = {k: v for k, v in res.items() if k not in ("times", "half_heights")}
        rows.append([esc(name), fmt(res["omega_rad_s"]), fmt(res["frequency_hz"]),
                     f"{100 * res['zeta']:.3g} ± {100 * res['zeta_se']:.2g}", str(res["periods"]),
                     f"{fmt(res['first_half_height'])} → {fmt(res['last_half_height'])}"])
    if not rows:
        return None
    rep.analysis["free_decay"] = {"from_s": t_start, "gauges": info,
                                  "method": "half heights (max - min)/2 per period from the zero up-crossings, "
                                            "zeta = -slope/omega of a least-squares line through their logarithms"}
    fig, ax = plt.subplots(figsize=(10, 3.6), constrained_layout=True)
    for name, res in curves:
        times = np.array(res["times"])
        ax.semilogy(times, res["half_heights"], "o", ms=3, label=f"{name}: ζ = {100 * res['zeta']:.3g} %")
        ax.semilogy(times, res["half_heights"][0] * np.exp(-res["zeta"] * res["omega_rad_s"] * (times - times[0])),
                    lw=0.8, color="0.4")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("half wave height (m)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    png = rep.save(fig, "free_decay")
    return (f"<p>The base stopped at t = {fmt(stop)} s; from t = {fmt(t_start)} s each gauge's half wave "
            "height per period (5 Hz low-passed) falls as exp(−ζωt): ζ from the slope of its logarithm "
            "(± the standard error of the fit).</p>"
            + rl.table(["gauge", "ω (rad/s)", "f (Hz)", "ζ (%)", "periods", "half height (m)"], rows)
            + rl.figure_html(png, "Half wave heights per period and the fitted decay. File plots/free_decay.png.",
                             "free decay"))


def admittance_part(rep, info, suffix=""):
    """The mechanical admittance |H(f)|² of admittance.csv (thesis eq. 4.30) beside the structure
    alone's and beside the SDOF of the effective damping ratio (the same area, Vickery et al.
    1983), and the table of what the tank does to the structure (summary.json `structure`).
    suffix "_y": the sway along y of a 3D 2-DOF structure (admittance_y.csv, `structure_y`)."""
    path = os.path.join(rep.run.dir, f"admittance{suffix}.csv")
    block = rep.run.summary.get("structure" + suffix, {}) if isinstance(rep.run.summary, dict) else {}
    adm = block.get("admittance") if isinstance(block, dict) else None
    if not os.path.exists(path) or not isinstance(adm, dict):
        return ""
    f_n, zeta = float(adm["natural_frequency_Hz"]), float(adm["effective_damping_ratio"])
    data = rl.read_admittance(path, adm.get("band_Hz"), f_n)
    lo, hi = adm.get("band_Hz", [data["f_Hz"][0], data["f_Hz"][-1]])[:2]
    f, h2 = data["f_Hz"], data["H2_displacement"]
    wave = "H2_wave" in data and np.any(data["H2_wave"] > 0)
    fig, axes = plt.subplots(2 if wave else 1, 1, figsize=(10, 6.6 if wave else 3.8), squeeze=False,
                             constrained_layout=True)
    ax = axes[0, 0]
    ax.semilogy(f, h2, lw=1.0, label=f"with the tank(s): ζ_eff = {100 * zeta:.3g} %")
    if "H2_structure_alone" in data:
        ax.semilogy(f, data["H2_structure_alone"], lw=0.9, ls="--", color="0.3",
                    label=f"structure alone, ζ = {100 * float(block.get('damping_ratio', 0.0)):.3g} %")
    r = f / f_n
    ax.semilogy(f, 1.0 / ((1 - r ** 2) ** 2 + (2 * zeta * r) ** 2), lw=0.9, ls=":", color="C3",
                label="SDOF of ζ_eff (the same area)")
    ax.set_ylabel("|H(f)|² of the displacement")
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    if wave:
        axes[1, 0].semilogy(f, data["H2_wave"], lw=1.0, color="C2")
        axes[1, 0].set_ylabel(f"|H(f)|² of the wave height at gauge {adm.get('wave_gauge', '?')}")
        axes[1, 0].grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("frequency (Hz)")
    along = " along y" if suffix else ""
    fig.suptitle(f"Mechanical admittance{along} (thesis eq. 4.30), within the load's band {lo:g}-{hi:g} Hz",
                 fontsize=11)
    png = rep.save(fig, "admittance" + suffix)
    alone = block.get("structure_without_tank", {})
    acc, disp = block.get("acceleration", {}), block.get("displacement", {})
    rows = [
        ["effective damping ratio ζ_eff (%)", fmt(100 * zeta),
         fmt(100 * alone["effective_damping_ratio"]) if "effective_damping_ratio" in alone else "–", "–"],
        ["peak acceleration (milli-g)", fmt(acc.get("peak_milli_g")),
         fmt(alone.get("acceleration", {}).get("peak_milli_g")), fmt(acc.get("peak_ratio_to_without_tank"))],
        ["RMS acceleration (milli-g)", fmt(acc.get("rms_milli_g")),
         fmt(alone.get("acceleration", {}).get("rms_milli_g")), fmt(acc.get("rms_ratio_to_without_tank"))],
        ["peak displacement (m)", fmt(disp.get("peak_m")), fmt(alone.get("displacement", {}).get("peak_m")),
         fmt(disp.get("peak_ratio_to_without_tank"))],
        ["RMS displacement (m)", fmt(disp.get("rms_m")), fmt(alone.get("displacement", {}).get("rms_m")),
         fmt(disp.get("rms_ratio_to_without_tank"))],
    ]
    info["admittance" + suffix] = {"effective_damping_ratio": zeta, "natural_frequency_Hz": f_n,
                                   "peak_H2_displacement": float(np.max(h2)) if len(h2) else None}
    return (rl.figure_html(png, f"Mechanical admittance{along} |H(f)|² = S(f)·K²/S0(f) of the structure's "
                                f"displacement (and of the wave height). File plots/admittance{suffix}.png (and .svg).",
                           "admittance" + suffix)
            + rl.table(["", "with the tank(s)", "structure alone, same load", "ratio"],
                       [[esc(c) if k == 0 else c for k, c in enumerate(row)] for row in rows])
            + linear_estimate_html(block.get("equivalent_tmd"), zeta))


def linear_estimate_html(tmd, zeta):
    """summary.json structure.equivalent_tmd: the tank's first mode as a linear TMD, and the tank
    damping such a TMD needs to give this run's ζ_eff."""
    if not isinstance(tmd, dict) or "optimum" not in tmd:
        return ""
    best = tmd["optimum"]
    z = tmd.get("tank_damping_for_measured_effective_damping")
    meaning = (f"this run's ζ_eff = {fmt(100 * zeta)} % is what such a tank gives at a damping ratio ζ_t = "
               f"{fmt(100 * z)} %" if z is not None else
               f"no damping of such a tank gives this run's ζ_eff = {fmt(100 * zeta)} %")
    return (f"<p>Linear estimate (summary.json <code>structure.equivalent_tmd</code>; "
            f"<code>sloshsph modes CASE --tank-damping Z</code>): mode 1 sloshes "
            f"{fmt(100 * tmd['convective_mass_fraction'])} % of the liquid, "
            f"m<sub>1</sub>/M<sub>s</sub> = {fmt(100 * tmd['mass_ratio'])} %, tuned to "
            f"f<sub>1</sub>/f<sub>s</sub> = {fmt(tmd['tuning_ratio'])}. The best linear tank of this mass and "
            f"tuning (ζ_t = {fmt(100 * best['tank_damping_ratio'])} %) gives ζ_eff = "
            f"{fmt(100 * best['effective_damping_ratio'])} %; {meaning}.</p>")


def structure_psd(rep, names, info):
    run = rep.run
    t = run.time
    fs = rl.sample_rate(t)
    n = len(t)
    if not names or fs is None or n < 128:
        return ""
    from scipy import signal
    # Segments of half the record (3 averages with 50 % overlap): resolution matters more than
    # variance for locating the structure's peak; zero padding (nfft) smooths the curve.
    nperseg = int(min(n, max(128, 2 ** int(math.floor(math.log2(n / 2))))))
    fig, axes = plt.subplots(len(names), 1, figsize=(10, 1.4 + 2.4 * len(names)), squeeze=False,
                             constrained_layout=True)
    for ax, name in zip(axes[:, 0], names):
        y = run.columns[name]
        if not np.all(np.isfinite(y)):
            ax.text(0.5, 0.5, "non-finite samples", transform=ax.transAxes, ha="center")
            continue
        f, pxx = signal.welch(y - np.mean(y), fs=fs, nperseg=nperseg, nfft=4 * nperseg)
        ax.semilogy(f[1:], pxx[1:], lw=1.0)
        top = float(np.max(pxx[1:]))
        if top > 0:
            ax.set_ylim(top * 1e-8, top * 3)
        k = 1 + int(np.argmax(pxx[1:]))
        info[name]["psd_peak_hz"] = float(f[k])
        ax.axvline(f[k], color="C3", ls="--", lw=0.8, label=f"peak {f[k]:.3g} Hz")
        if run.omega():
            ax.axvline(run.omega() / (2 * math.pi), color="0.4", ls=":", lw=0.8, label="excitation")
        unit = run.unit(name)
        squared = (f"({unit})²" if "/" in unit or "^" in unit else f"{unit}²") if unit else "1"
        ax.set_ylabel(f"PSD of {name} ({squared}/Hz)")
        ax.set_xlim(0, min(fs / 2, max(5 * f[k], 2.0)))
        ax.grid(True, alpha=0.3, which="major")
        ax.legend(fontsize=8)
    axes[-1, 0].set_xlabel("frequency (Hz)")
    fig.suptitle(f"Power spectral density of the structure response (Welch, {nperseg} samples per segment)",
                 fontsize=11)
    png = rep.save(fig, "structure_psd")
    return rl.figure_html(png, "Welch PSD of the structure response. File plots/structure_psd.png (and .svg).",
                          "structure PSD")


# --------------------------------------------------------------------------------------------
# Assembly


def guarded(rep, title, fn, *args):
    """Runs one section; an error becomes a visible note instead of a crash."""
    try:
        return fn(*args)
    except Exception as err:  # noqa: BLE001 - the report must still be written
        plt.close("all")
        rep.run.notes.append(f"section '{title}' failed: {type(err).__name__}: {err}")
        if os.environ.get("SLOSHSPH_REPORT_DEBUG"):
            traceback.print_exc()
        return f"<div class='banner warn'>This section could not be made: {esc(type(err).__name__)}: {esc(err)}</div>"


def build(rep):
    run = rep.run
    head = guarded(rep, "header", header_section, rep)
    steady_note = guarded(rep, "steady state", compute_steady_state, rep)
    sections = [("histories", "Time histories", guarded(rep, "time histories", histories_section, rep))]
    if run.is_harmonic():
        sections.append(("steady", "Steady-state response", guarded(rep, "steady state", steady_section, rep,
                                                                    steady_note if isinstance(steady_note, str) else "")))
    decay = guarded(rep, "free decay", free_decay_section, rep)
    if decay:
        sections.append(("decay", "Free decay", decay))
    struct = guarded(rep, "structure", structure_section, rep)
    if struct:
        sections.append(("structure", "Structure", struct))
    if not rep.args.snapshots <= 0:
        sections.append(("snapshots", "Particle snapshots", guarded(rep, "snapshots", snapshots_section, rep)))
    if run.notes:
        items = "".join(f"<li>{esc(n)}</li>" for n in run.notes)
        sections.append(("notes", "Notes", f"<ul class='notes'>{items}</ul>"))
    nav = "<nav>" + "".join(f"<a href='#{sid}'>{esc(title)}</a>" for sid, title, _ in sections) + "</nav>"
    body = head + nav + "".join(f"<h2 id='{sid}'>{esc(title)}</h2>{html}" for sid, title, html in sections)
    return rl.page(f"sloshsph report: {run.title}", body)


def parse_args(argv):
    ap = argparse.ArgumentParser(description="Plots and an HTML report of a sloshsph run directory.")
    ap.add_argument("run_dir", help="the run directory (holds summary.json, timeseries.csv, ...)")
    ap.add_argument("--out", help="write plots/, report.html and analysis.json here (default: RUN_DIR)")
    ap.add_argument("--cycles", type=int, default=rl.DEFAULT_CYCLES,
                    help="excitation periods for the steady-state averages (default 10, or as many as fit)")
    ap.add_argument("--cutoff", type=float, default=rl.DEFAULT_CUTOFF_HZ,
                    help="low-pass cut-off in Hz (default 5, the thesis's; 0 disables the filter)")
    ap.add_argument("--snapshots", type=int, default=4,
                    help="evenly spread particle snapshots to show, plus the last (default 4; 0: none)")
    ap.add_argument("--dpi", type=int, default=110, help="PNG resolution (default 110)")
    ap.add_argument("--no-svg", action="store_true", help="do not write .svg files")
    return ap.parse_args(argv)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.cycles < 1:
        print("report.py: --cycles must be at least 1", file=sys.stderr)
        return 2
    if not rl.is_run_dir(args.run_dir):
        print(f"report.py: {args.run_dir} is not a sloshsph run directory (none of "
              f"{', '.join(rl.RUN_FILES)} found)", file=sys.stderr)
        return 2
    out_dir = os.path.abspath(args.out or args.run_dir)
    try:
        os.makedirs(os.path.join(out_dir, "plots"), exist_ok=True)
    except OSError as err:
        print(f"report.py: cannot write to {out_dir}: {err}", file=sys.stderr)
        return 2
    run = rl.Run(args.run_dir)
    rep = Report(run, args, out_dir)
    html_text = build(rep)
    try:
        with open(os.path.join(out_dir, "report.html"), "w", encoding="utf-8") as fh:
            fh.write(html_text)
        rl.write_json(os.path.join(out_dir, "analysis.json"), rep.analysis)
    except OSError as err:
        print(f"report.py: cannot write the report to {out_dir}: {err}", file=sys.stderr)
        return 2
    print(f"report.py: {os.path.join(out_dir, 'report.html')} ({run.status}"
          + (f"; {len(run.notes)} note(s)" if run.notes else "") + ")")
    for n in run.notes:
        print(f"  note: {n}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
