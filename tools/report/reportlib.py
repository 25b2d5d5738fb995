"""Shared pieces of the sloshsph reports: reading a run directory, the steady-state analysis of
harmonically excited runs, and the HTML page.

Python 3 with numpy, scipy and matplotlib only (Debian python3-numpy/-scipy/-matplotlib).
"""
import base64
import csv
import datetime
import html
import io
import json
import math
import os
import re
import sys

import numpy as np

# The reader of the particle snapshots lives one folder up (tools/vtu.py).
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from scipy import signal  # noqa: E402

try:
    import tomllib  # Python >= 3.11
except ImportError:  # pragma: no cover - older Pythons
    tomllib = None

RUN_FILES = ("summary.json", "timeseries.csv", "case.toml", "run.json")
DEFAULT_CUTOFF_HZ = 5.0  # thesis 2.6.3: experiments and ISPH results low-pass filtered at 5 Hz
DEFAULT_CYCLES = 10


# --------------------------------------------------------------------------------------------
# Reading


def read_json(path, notes):
    """A JSON file as a dict, or {} (with a note) when it is missing or unreadable."""
    if not os.path.exists(path):
        return {}
    try:
        with open(path, encoding="utf-8") as fh:
            value = json.load(fh)
        return value if isinstance(value, dict) else {}
    except (OSError, ValueError) as err:
        notes.append(f"{os.path.basename(path)} could not be read: {err}")
        return {}


def read_text(path):
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            return fh.read()
    except OSError:
        return None


def _minimal_toml(text):
    """Fallback for Pythons without tomllib: flat `key = number|string` under [tables] only."""
    out = {}
    current = out
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        m = re.match(r"^\[([\w.]+)\]$", line)
        if m:
            current = out
            for part in m.group(1).split("."):
                current = current.setdefault(part, {})
            continue
        m = re.match(r"^(\w+)\s*=\s*(.+)$", line)
        if m:
            value = m.group(2).strip()
            try:
                current[m.group(1)] = float(value)
            except ValueError:
                current[m.group(1)] = value.strip("'\"")
    return out


def parse_toml(text, notes):
    if text is None:
        return {}
    try:
        return tomllib.loads(text) if tomllib else _minimal_toml(text)
    except Exception as err:  # a broken case.toml must not stop the report
        notes.append(f"case.toml could not be parsed: {err}")
        return {}


def read_timeseries(path, notes):
    """timeseries.csv as (column names, {name: float array}).

    Tolerant: rows with a wrong number of fields (e.g. a line cut short by an interruption) or
    unparsable numbers are dropped with a note, as are rows whose time does not increase.
    """
    if not os.path.exists(path):
        return [], {}
    with open(path, newline="", encoding="utf-8", errors="replace") as fh:
        rows = list(csv.reader(fh))
    if not rows:
        notes.append("timeseries.csv is empty (no header)")
        return [], {}
    header = [h.strip() for h in rows[0]]
    values, bad = [], 0
    for row in rows[1:]:
        if not row or all(not f.strip() for f in row):
            continue
        if len(row) != len(header):
            bad += 1
            continue
        try:
            values.append([float(f) if f.strip() else math.nan for f in row])
        except ValueError:
            bad += 1
    if bad:
        notes.append(f"timeseries.csv: {bad} malformed row(s) skipped")
    data = np.array(values, dtype=float).reshape(-1, len(header))
    columns, names = {}, []
    for i, name in enumerate(header):
        if name in columns:
            notes.append(f"timeseries.csv: duplicate column {name!r} ignored")
            continue
        columns[name] = data[:, i]
        names.append(name)
    if "time" in columns and len(columns["time"]) > 1:
        t = columns["time"]
        keep = np.ones(len(t), dtype=bool)
        last = -math.inf
        for i, ti in enumerate(t):
            if not (ti > last):
                keep[i] = False
            else:
                last = ti
        if not keep.all():
            notes.append(f"timeseries.csv: {int((~keep).sum())} row(s) with non-increasing time skipped")
            columns = {k: v[keep] for k, v in columns.items()}
    elif "time" not in columns and names:
        notes.append("timeseries.csv has no 'time' column: time histories are not plotted")
    return names, columns


class Run:
    """Everything the report needs from a run directory (missing parts are empty)."""

    def __init__(self, run_dir):
        self.dir = os.path.abspath(run_dir)
        self.notes = []
        self.summary = read_json(os.path.join(self.dir, "summary.json"), self.notes)
        self.run_info = read_json(os.path.join(self.dir, "run.json"), self.notes)
        self.case_text = read_text(os.path.join(self.dir, "case.toml"))
        self.case = parse_toml(self.case_text, self.notes)
        self.names, self.columns = read_timeseries(os.path.join(self.dir, "timeseries.csv"), self.notes)
        self.units = self.summary.get("columns", {}) if isinstance(self.summary.get("columns"), dict) else {}

    # Case values -------------------------------------------------------------------------
    def case_value(self, dotted, default=None):
        node = self.case
        for part in dotted.split("."):
            if not isinstance(node, dict) or part not in node:
                return default
            node = node[part]
        return node

    def case_float(self, dotted):
        value = self.case_value(dotted)
        try:
            value = float(value)
        except (TypeError, ValueError):
            return None
        return value if math.isfinite(value) else None

    def summary_float(self, key):
        try:
            value = float(self.summary.get(key))
        except (TypeError, ValueError):
            return None
        return value if math.isfinite(value) else None

    # Derived -----------------------------------------------------------------------------
    @property
    def title(self):
        title = self.case_value("title") or ""
        return str(title) if title else os.path.basename(self.dir.rstrip(os.sep))

    @property
    def status(self):
        if not self.summary:
            return "unknown"
        return str(self.summary.get("status", "unknown"))

    @property
    def time(self):
        return self.columns.get("time", np.zeros(0))

    def unit(self, name):
        if name in self.units:
            return str(self.units[name])
        return default_unit(name)

    def fluid_mass(self):
        """m_w (kg/m; 3D: kg): summary fluid_mass_kg_per_m (3D: fluid_mass_kg), else the first fluid_mass sample."""
        m = self.summary_float("fluid_mass_kg_per_m")
        if m is None:
            m = self.summary_float("fluid_mass_kg")  # a 3D run: the whole tank's
        if m is None and len(self.columns.get("fluid_mass", [])):
            m = float(self.columns["fluid_mass"][0])
        return m if m and m > 0 else None

    def omega(self):
        w = self.summary_float("excitation_omega_rad_s")
        if w is None and self.case_value("excitation.frequency") is not None:
            f = self.case_float("excitation.frequency")
            w = 2 * math.pi * f if f else None
        return w if w and w > 0 else None

    def is_harmonic(self):
        kind = self.case_value("excitation.type", "harmonic" if self.omega() else "none")
        return kind == "harmonic" and self.omega() is not None


_DEFAULT_UNITS = {
    "time": "s", "x_base": "m", "v_base": "m/s", "a_base": "m/s^2", "F_w": "N/m", "F_sw": "N/m",
    "F_wy": "N/m", "W_base": "J/m", "fluid_mass": "kg/m", "E_kin": "J/m", "E_pot": "J/m",
    "leaked": "1", "max_speed": "m/s", "dt": "s", "ppe_iterations": "1", "wall_contacts": "1", "pair_contacts": "1",
    "closest_pair": "dp", "x_s": "m", "v_s": "m/s",
    "a_s": "m/s^2", "F_TLD": "N/m",
}


def default_unit(name):
    if name in _DEFAULT_UNITS:
        return _DEFAULT_UNITS[name]
    if name.startswith("eta:"):
        return "m"
    if name.startswith("p:"):
        return "Pa"
    if name.startswith("F_"):
        return "N/m"
    return ""


def is_run_dir(path):
    return os.path.isdir(path) and any(os.path.exists(os.path.join(path, f)) for f in RUN_FILES)


def read_admittance(path, band, natural_frequency):
    """admittance.csv (thesis eq. 4.30: f_Hz, H2_displacement, H2_wave, H2_structure_alone, ...)
    as {column: array}, kept within the load's band (lo, hi) (outside it the force has no power;
    None: the record less f = 0) and up to 2.5 f_n (beyond it a tank does nothing to see)."""
    data = np.genfromtxt(path, delimiter=",", names=True)
    f = data["f_Hz"]
    lo, hi = band[:2] if band else (f[1], f[-1])
    keep = (f >= lo) & (f <= min(hi, 2.5 * natural_frequency))
    return {name: data[name][keep] for name in data.dtype.names}


def sub_run_dirs(folder):
    """The run directories in `folder` (a sweep's points, a folder of runs to compare), sorted."""
    return [os.path.join(folder, name) for name in sorted(os.listdir(folder))
            if name != "plots" and is_run_dir(os.path.join(folder, name))]


# --------------------------------------------------------------------------------------------
# Signal analysis


def sample_rate(t):
    """Samples per second from the median spacing, or None for fewer than two samples."""
    if len(t) < 2:
        return None
    dt = float(np.median(np.diff(t)))
    return 1.0 / dt if dt > 0 else None


def lowpass(t, x, cutoff_hz, order=4):
    """Zero-phase Butterworth low-pass (forward-backward, scipy sosfiltfilt), thesis 2.6.3.

    Returns (filtered array or None, reason when None).
    """
    if not cutoff_hz or cutoff_hz <= 0:
        return None, "filter disabled"
    fs = sample_rate(t)
    if fs is None or len(x) < 16:
        return None, "too few samples to filter"
    if cutoff_hz >= 0.5 * fs:
        return None, f"cut-off {cutoff_hz:g} Hz is not below the Nyquist frequency {0.5 * fs:g} Hz"
    if not np.all(np.isfinite(x)):
        return None, "non-finite samples"
    sos = signal.butter(order, cutoff_hz, btype="low", fs=fs, output="sos")
    padlen = min(3 * (2 * len(sos) + 1), len(x) - 1)
    return signal.sosfiltfilt(sos, x, padlen=padlen), ""


def analysis_window(t, period, n_cycles, t_stop=None, t_min=None):
    """The last whole cycles of `period` ending at the last sample (or at t_stop, when the base
    stopped earlier) and starting no earlier than t_min (e.g. the end of the ramp).

    Returns (t_start, t_end, cycles) or None when not one whole cycle fits.
    """
    if len(t) < 2 or not period or period <= 0 or n_cycles < 1:
        return None
    t_end = float(t[-1])
    if t_stop is not None and t[0] < t_stop < t_end:
        t_end = float(t_stop)
    t_first = float(t[0]) if t_min is None else max(float(t[0]), float(t_min))
    fit = int(math.floor((t_end - t_first) / period * (1.0 + 1e-12)))
    if fit < 1:
        return None
    cycles = min(fit, int(n_cycles))
    return t_end - cycles * period, t_end, cycles


def _parabola_vertex_value(t, x, i):
    """Extreme value of the parabola through samples i-1, i, i+1 (sub-sample peak refinement)."""
    h0, h1 = t[i] - t[i - 1], t[i + 1] - t[i]
    d0, d1 = (x[i] - x[i - 1]) / h0, (x[i + 1] - x[i]) / h1
    curvature = 2.0 * (d1 - d0) / (h0 + h1)
    if curvature == 0.0:
        return x[i]
    slope = (d0 * h1 + d1 * h0) / (h0 + h1)
    return x[i] - 0.5 * slope * slope / curvature


def steady_state_amplitude(t, x, period, window):
    """Average of the per-cycle maxima and minima (thesis 2.6.3, 4.3.1) over the cycles of
    `window` = (t_start, t_end, cycles), counted back from t_end: cycle k is
    [t_end - k T, t_end - (k - 1) T]. A maximum that is a local extremum of the whole record is
    refined by the vertex of the parabola through it and its neighbours (the same rule as
    src/sloshsph/analysis/steady_state.cpp). Returns a dict, or None on a bad series.
    """
    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    if window is None or len(t) != len(x) or len(t) < 2:
        return None
    _, t_end, cycles = window
    maxima, minima = [], []
    for k in range(1, cycles + 1):
        lo, hi = t_end - k * period, t_end - (k - 1) * period
        first = int(np.searchsorted(t, lo, side="left"))
        last = int(np.searchsorted(t, hi, side="right"))
        seg = x[first:last]
        if last <= first or not np.all(np.isfinite(seg)):
            return None
        imax = first + int(np.argmax(seg))
        imin = first + int(np.argmin(seg))
        maxima.append(_refined(t, x, imax, +1))
        minima.append(_refined(t, x, imin, -1))
    scale = max(abs(float(np.mean(maxima))), abs(float(np.mean(minima))), 1e-300)
    return {
        # (largest - smallest per-cycle maximum) / |average|: large values mean no steady state yet
        "max_spread_rel": float((np.max(maxima) - np.min(maxima)) / scale),
        "avg_max": float(np.mean(maxima)),
        "avg_min": float(np.mean(minima)),
        "avg_amplitude": float(0.5 * (np.mean(maxima) - np.mean(minima))),
        "cycles": cycles,
        "per_cycle_max": [float(v) for v in maxima[::-1]],  # oldest first
        "per_cycle_min": [float(v) for v in minima[::-1]],
    }


def _refined(t, x, i, sign):
    if 0 < i < len(x) - 1 and sign * x[i] >= sign * x[i - 1] and sign * x[i] >= sign * x[i + 1]:
        v = _parabola_vertex_value(t, x, i)
        return float(max(x[i], v) if sign > 0 else min(x[i], v))
    return float(x[i])


def energy_per_cycle(t, force, displacement, window, force_is_interval_mean=True):
    """Energy dissipated per cycle, thesis eq. 4.28: E_w = closed integral of F_w dX, averaged
    over the cycles of `window`.

    sloshsph writes F_w as the mean over the steps since the previous row (docs/case-format.md),
    i.e. row i holds the force of the interval (t[i-1], t[i]]: then the work of that interval is
    F_i (X_i - X_{i-1}) (no half-sample lag). For point-sampled forces
    (force_is_interval_mean=False) the trapezoid (F_{i-1} + F_i)/2 (X_i - X_{i-1}) is used.
    The window ends are linearly interpolated. Returns J/m per cycle, or None.
    """
    t = np.asarray(t, dtype=float)
    f = np.asarray(force, dtype=float)
    x = np.asarray(displacement, dtype=float)
    if window is None or len(t) < 2 or len(f) != len(t) or len(x) != len(t):
        return None
    t0, t1, cycles = window
    a = np.clip(t[:-1], t0, t1)
    b = np.clip(t[1:], t0, t1)
    dx = np.interp(b, t, x) - np.interp(a, t, x)
    if force_is_interval_mean:
        f_interval = f[1:]
    else:
        f_interval = 0.5 * (np.interp(a, t, f) + np.interp(b, t, f))
    inside = b > a
    if not np.all(np.isfinite(f_interval[inside])) or not np.all(np.isfinite(dx[inside])):
        return None
    return float(np.sum(f_interval[inside] * dx[inside]) / cycles)


def free_decay(t, x, t_start, min_periods=3):
    """Damping ratio and frequency of a free decay after t_start (a gauge after the base stopped).

    The period is the mean spacing of the zero up-crossings of x - mean(x); in each whole period
    from t_start the half height (max - min) / 2 is taken, and zeta = -slope / omega from a least-
    squares line through the logarithms of the half heights against time (the standard error of
    the slope gives zeta_se). None when fewer than `min_periods` whole periods follow t_start."""
    m = (t >= t_start) & np.isfinite(x)
    t, x = t[m], x[m]
    if len(t) < 8:
        return None
    x = x - np.mean(x)
    up = np.where((x[:-1] < 0) & (x[1:] >= 0))[0]
    crossings = t[up] - x[up] * (t[up + 1] - t[up]) / (x[up + 1] - x[up])
    if len(crossings) < min_periods + 1:
        return None
    period = float((crossings[-1] - crossings[0]) / (len(crossings) - 1))
    omega = 2 * math.pi / period
    heights, times = [], []
    k = 0
    while crossings[0] + (k + 1) * period <= t[-1]:
        w = (t >= crossings[0] + k * period) & (t < crossings[0] + (k + 1) * period)
        heights.append(0.5 * float(x[w].max() - x[w].min()))
        times.append(float(crossings[0] + (k + 0.5) * period))
        k += 1
    if len(heights) < min_periods or min(heights) <= 0:
        return None
    coef, cov = np.polyfit(times, np.log(heights), 1, cov=True) if len(heights) > 3 else (
        np.polyfit(times, np.log(heights), 1), np.full((2, 2), np.nan))
    return {"omega_rad_s": omega, "frequency_hz": omega / (2 * math.pi), "periods": len(heights),
            "zeta": float(-coef[0] / omega), "zeta_se": float(math.sqrt(cov[0, 0]) / omega),
            "first_half_height": heights[0], "last_half_height": heights[-1],
            "times": times, "half_heights": heights}


def work_increase_per_cycle(t, work, window):
    """(W(t_end) - W(t_start)) / cycles from the cumulative work column W_base."""
    if window is None or len(t) < 2:
        return None
    t0, t1, cycles = window
    value = (np.interp(t1, t, work) - np.interp(t0, t, work)) / cycles
    return float(value) if math.isfinite(value) else None


def normalised_energy(energy, water_mass, amplitude, omega):
    """Thesis eq. 4.27: E'_w = E_w / (0.5 m_w (X0 omega)^2)."""
    return energy / (0.5 * water_mass * (amplitude * omega) ** 2)


# --------------------------------------------------------------------------------------------
# Figures


def save_figure(fig, plots_dir, stem, svg=True, dpi=110):
    """Writes plots_dir/stem.png (and .svg); returns the PNG bytes for embedding."""
    os.makedirs(plots_dir, exist_ok=True)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)
    png = buf.getvalue()
    with open(os.path.join(plots_dir, stem + ".png"), "wb") as fh:
        fh.write(png)
    if svg:
        fig.savefig(os.path.join(plots_dir, stem + ".svg"), format="svg")
    plt.close(fig)
    return png


def data_uri_png(png_bytes):
    return "data:image/png;base64," + base64.b64encode(png_bytes).decode("ascii")


def fmt(value, digits=4):
    """A number for a table: None/NaN as a dash, otherwise `digits` significant digits."""
    if value is None:
        return "–"
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, int):
        return f"{value:,}".replace(",", "\u2009")
    if isinstance(value, float):
        if not math.isfinite(value):
            return str(value)
        return f"{value:.{digits}g}"
    return str(value)


def fmt_duration(seconds):
    if seconds is None or not math.isfinite(seconds):
        return "–"
    s = int(round(seconds))
    h, rem = divmod(s, 3600)
    m, s = divmod(rem, 60)
    return f"{h}:{m:02d}:{s:02d}" if h else f"{m}:{s:02d}"


# --------------------------------------------------------------------------------------------
# HTML

CSS = """
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,Helvetica,Arial,sans-serif;margin:0;
 color:#1b1f24;background:#fafafa;line-height:1.45}
main{max-width:1180px;margin:0 auto;padding:1.2em 1.6em 3em;background:#fff;
 box-shadow:0 0 6px rgba(0,0,0,.08)}
h1{font-size:1.6em;margin:.2em 0 .1em}h2{border-bottom:2px solid #d0d7de;padding-bottom:.2em;
 margin-top:2em}h3{margin-top:1.4em}
.sub{color:#57606a;margin:0 0 1em}
nav{background:#f3f5f7;border:1px solid #d0d7de;border-radius:6px;padding:.4em .9em;margin:1em 0}
nav a{margin-right:1.1em;text-decoration:none;color:#0969da}
table{border-collapse:collapse;margin:.6em 0;font-size:.92em}.table-wrap{overflow-x:auto;max-width:100%}
th,td{border:1px solid #d0d7de;padding:.25em .6em;text-align:right;vertical-align:top}
th{background:#f3f5f7}td.l,th.l{text-align:left}
table.kv td:first-child{text-align:left;color:#57606a}
figure{margin:1em 0 1.6em}figure img{max-width:100%;height:auto;border:1px solid #eaeef2}
figcaption{color:#57606a;font-size:.9em;margin-top:.3em}
details{margin:.5em 0;border:1px solid #d0d7de;border-radius:6px;padding:.3em .8em}
summary{cursor:pointer;font-weight:600}
pre{background:#f6f8fa;padding:.7em;overflow:auto;font-size:.85em;max-height:40em}
.banner{padding:.8em 1em;border-radius:6px;margin:1em 0;font-weight:600}
.banner.bad{background:#ffebe9;border:1px solid #ff8182;color:#82071e}
.banner.warn{background:#fff8c5;border:1px solid #d4a72c;color:#633c01}
.badge{display:inline-block;padding:.05em .6em;border-radius:1em;font-size:.85em;font-weight:600}
.badge.ok{background:#dafbe1;color:#116329}.badge.bad{background:#ffebe9;color:#82071e}
.badge.warn{background:#fff8c5;color:#633c01}
.notes li{color:#57606a}
.grid{display:flex;flex-wrap:wrap;gap:1.5em}
"""


def esc(text):
    return html.escape(str(text), quote=True)


def status_badge(status):
    cls = "ok" if status == "completed" else (
        "warn" if status in ("interrupted", "unknown", "running", "stopped", "not started", "no summary") else "bad")
    return f'<span class="badge {cls}">{esc(status)}</span>'


def kv_table(pairs):
    rows = "".join(f"<tr><td>{esc(k)}</td><td class='l'>{v}</td></tr>" for k, v in pairs)
    return f'<table class="kv">{rows}</table>'


def table(header, rows, left_columns=1):
    """header: list of str; rows: list of lists of already-escaped HTML cells."""
    def cell(tag, i, v):
        cls = ' class="l"' if i < left_columns else ""
        return f"<{tag}{cls}>{v}</{tag}>"
    head = "".join(cell("th", i, esc(h)) for i, h in enumerate(header))
    body = "".join("<tr>" + "".join(cell("td", i, v) for i, v in enumerate(r)) + "</tr>" for r in rows)
    # Wide tables (a sweep's points: one column per recorded quantity) scroll inside the page
    # instead of widening it (seen in Chromium by tools/report/check_in_browser.py: 1880 px).
    return f'<div class="table-wrap"><table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table></div>'


def figure_html(png_bytes, caption, alt):
    return (f'<figure><img alt="{esc(alt)}" src="{data_uri_png(png_bytes)}">'
            f"<figcaption>{esc(caption)}</figcaption></figure>")


def details(summary_text, body_html, open_=False):
    return f"<details{' open' if open_ else ''}><summary>{esc(summary_text)}</summary>{body_html}</details>"


def page(title, body_html, subtitle=""):
    stamp = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    return (
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
        f"<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\"><title>{esc(title)}</title>"
        f"<style>{CSS}</style></head><body><main>{body_html}"
        f"<p class=\"sub\" style=\"margin-top:3em\">Generated {esc(stamp)} by sloshsph tools/report. "
        f"{esc(subtitle)}</p></main></body></html>\n"
    )


def write_json(path, value):
    def clean(v):
        if isinstance(v, float) and not math.isfinite(v):
            return None
        if isinstance(v, dict):
            return {k: clean(x) for k, x in v.items()}
        if isinstance(v, (list, tuple)):
            return [clean(x) for x in v]
        if isinstance(v, np.generic):
            return clean(v.item())
        return v
    with open(path, "w", encoding="utf-8") as fh:
        json.dump(clean(value), fh, indent=2, sort_keys=False)
        fh.write("\n")
