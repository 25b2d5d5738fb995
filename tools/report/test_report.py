#!/usr/bin/python3
"""Test of tools/report: report.py and sweep_report.py on synthetic run and sweep directories.

    /usr/bin/python3 tools/report/test_report.py      (exit code 0 on success)

References (all closed forms, tolerance 1% as asked of the steady-state analysis):
- wave gauge eta = c + A sin(w t): average per-cycle max = c + A, min = c - A;
- base shear F = F0 sin(w t + phi) against X = X0 sin(w t): energy per cycle
  closed integral F dX = pi F0 X0 sin(phi) (thesis eq. 4.28), written like sloshsph writes F_w
  (the mean over each sample interval, docs/case-format.md), and W_base = its exact integral;
- a point-sampled F with the trapezoid rule gives the same within 1%.
"""
import html.parser
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import reportlib as rl  # noqa: E402
import vtu  # noqa: E402  (tools/vtu.py; reportlib puts tools/ on sys.path)

PY = sys.executable or "/usr/bin/python3"

# The synthetic harmonic run.
F_EXC = 0.8  # Hz
OMEGA = 2 * math.pi * F_EXC
X0 = 0.004  # m
DEPTH = 0.12  # m
M_W = 60.0  # kg/m
ETA_A, ETA_C = 0.02, 0.001  # m
F0, PHI = 7.5, 0.6  # N/m, rad
T_END, DT = 30.0, 0.01


def check(cond, what):
    if not cond:
        raise AssertionError(what)
    print(f"  ok: {what}")


def near(value, ref, rel, what):
    ok = value is not None and abs(value - ref) <= rel * abs(ref)
    check(ok, f"{what}: {value!r} vs {ref!r} (tolerance {rel:.0%})")


# --------------------------------------------------------------------------------------------
# Synthetic run directory


def write_vtu(path, points, fields):
    """Minimal VTU writer like sloshsph's: appended raw binary, UInt64 byte-count headers."""
    arrays = []  # (xml attributes, bytes)
    for name, (vtype, arr, ncomp) in fields.items():
        comp = f' NumberOfComponents="{ncomp}"' if ncomp > 1 else ""
        arrays.append((f'type="{vtype}" Name="{name}"{comp}', np.ascontiguousarray(arr).tobytes()))
    pts = np.ascontiguousarray(points, dtype=np.float32).tobytes()
    blobs, offset, xml_arrays = [], 0, []
    for attrs, data in arrays + [('type="Float32" NumberOfComponents="3"', pts)]:
        xml_arrays.append(f'<DataArray {attrs} format="appended" offset="{offset}"/>')
        blob = struct.pack("<Q", len(data)) + data
        blobs.append(blob)
        offset += len(blob)
    n = len(points)
    xml = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" '
           f'header_type="UInt64">\n<UnstructuredGrid>\n<Piece NumberOfPoints="{n}" NumberOfCells="0">\n'
           "<PointData>\n" + "\n".join(xml_arrays[:-1]) + "\n</PointData>\n<Points>\n" + xml_arrays[-1]
           + "\n</Points>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_")
    with open(path, "wb") as fh:
        fh.write(xml.encode() + b"".join(blobs) + b"\n</AppendedData>\n</VTKFile>\n")


def make_particles(dp=0.01, length=0.4):
    xs = np.arange(dp / 2, length, dp)
    ys = np.arange(dp / 2, DEPTH, dp)
    fx, fy = np.meshgrid(xs, ys)
    fluid = np.column_stack([fx.ravel(), fy.ravel()])
    wall = np.array([[x, -dp / 2] for x in np.arange(-dp / 2, length + dp, dp)]
                    + [[-dp / 2, y] for y in np.arange(dp / 2, 0.2, dp)]
                    + [[length + dp / 2, y] for y in np.arange(dp / 2, 0.2, dp)])
    pts = np.vstack([fluid, wall])
    n_f = len(fluid)
    pts3 = np.column_stack([pts, np.zeros(len(pts))])
    kind = np.r_[np.zeros(n_f, np.uint8), np.ones(len(wall), np.uint8)]
    pressure = np.where(kind == 0, 1000 * 9.81 * (DEPTH - pts[:, 1]), 0.0).astype(np.float32)
    vel = np.zeros((len(pts), 3), np.float32)
    vel[:n_f, 0] = 0.05 * np.sin(math.pi * fluid[:, 0] / length)
    fields = {
        "velocity": ("Float32", vel, 3), "pressure": ("Float32", pressure, 1),
        "density": ("Float32", np.full(len(pts), 1000.0, np.float32), 1),
        "kind": ("UInt8", kind, 1), "id": ("Int32", np.arange(len(pts), dtype=np.int32), 1),
    }
    return pts3, fields


def make_run(run_dir, status="completed"):
    os.makedirs(os.path.join(run_dir, "particles"))
    t = np.round(np.arange(0.0, T_END + DT / 2, DT), 10)
    x = X0 * np.sin(OMEGA * t)
    v = X0 * OMEGA * np.cos(OMEGA * t)
    a = -X0 * OMEGA ** 2 * np.sin(OMEGA * t)
    # F_w as sloshsph writes it: the mean of F0 sin(w s + phi) over (t[i-1], t[i]]; 0 at t = 0.
    f_w = np.zeros_like(t)
    f_w[1:] = F0 * (np.cos(OMEGA * t[:-1] + PHI) - np.cos(OMEGA * t[1:] + PHI)) / (OMEGA * np.diff(t))
    w_base = 0.5 * F0 * X0 * (OMEGA * t * math.sin(PHI) + 0.5 * (math.cos(PHI) - np.cos(2 * OMEGA * t + PHI)))
    cols = {
        "time": t, "x_base": x, "v_base": v, "a_base": a,
        "eta:left": ETA_C + ETA_A * np.sin(OMEGA * t + 0.3),
        "eta:right": -ETA_C - ETA_A * np.sin(OMEGA * t + 0.3),
        "p:bottom": 1177.2 + 50 * np.sin(2 * OMEGA * t),
        "F_w": f_w, "F_sw": f_w - M_W * a, "F_wy": np.where(t > 0, M_W * 9.81, 0.0), "W_base": w_base,
        "fluid_mass": np.full_like(t, M_W), "E_kin": 0.01 * np.sin(OMEGA * t) ** 2,
        "E_pot": 8.0 + 0.01 * np.cos(OMEGA * t) ** 2, "leaked": np.zeros_like(t),
        "max_speed": 0.1 + 0.01 * np.sin(OMEGA * t), "dt": np.where(t > 0, 5e-4, 0.0),
        "ppe_iterations": np.full_like(t, 40.0),
        "x_s": 0.01 * np.sin(2 * math.pi * 0.5 * t), "a_s": -0.01 * (math.pi) ** 2 * np.sin(2 * math.pi * 0.5 * t),
        "F_screen:s1": 0.5 * np.sin(OMEGA * t),
    }
    names = list(cols)
    with open(os.path.join(run_dir, "timeseries.csv"), "w") as fh:
        fh.write(",".join(names) + "\n")
        for i in range(len(t)):
            fh.write(",".join(f"{cols[n][i]:.10g}" for n in names) + "\n")
    summary = {
        "status": status, "steps": 60000, "simulated_time_s": T_END, "wall_time_s": 123.4,
        "fluid_particles": 480, "wall_particles": 120, "leaked_particles": 0,
        "particle_steps_per_second": 3.0e5, "excitation_omega_rad_s": OMEGA,
        "omega1_linear_rad_s": OMEGA, "fluid_mass_kg_per_m": M_W, "dp_m": 0.01,
        "columns": {n: rl.default_unit(n) for n in names},
    }
    # A structure block and admittance.csv as a coupled run writes them: the admittance of an SDOF
    # of 0.5 Hz and 2 % damping, and the structure alone's of 1 %.
    f = np.arange(0.0, 2.0, 0.01)
    r = f / 0.5
    h2 = 1.0 / ((1 - r ** 2) ** 2 + (2 * 0.02 * r) ** 2)
    h2_alone = 1.0 / ((1 - r ** 2) ** 2 + (2 * 0.01 * r) ** 2)
    with open(os.path.join(run_dir, "admittance.csv"), "w") as fh:
        fh.write("f_Hz,H2_displacement,H2_wave,H2_structure_alone\n")
        for k in range(len(f)):
            fh.write(f"{f[k]:.10g},{h2[k]:.10g},{3 * h2[k]:.10g},{h2_alone[k]:.10g}\n")
    summary["structure"] = {
        "damping_ratio": 0.01,
        "admittance": {"natural_frequency_Hz": 0.5, "effective_damping_ratio": 0.02, "band_Hz": [0.1, 1.5],
                       "wave_gauge": "right"},
        "acceleration": {"peak_milli_g": 7.5, "rms_milli_g": 2.0, "peak_ratio_to_without_tank": 0.75,
                         "rms_ratio_to_without_tank": 0.71},
        "displacement": {"peak_m": 0.1, "rms_m": 0.03},
        "structure_without_tank": {"effective_damping_ratio": 0.0101,
                                   "acceleration": {"peak_milli_g": 10.0, "rms_milli_g": 2.8}},
        "equivalent_tmd": {"convective_mass_fraction": 0.757, "mass_ratio": 0.00615, "tuning_ratio": 0.981,
                           "optimum": {"tank_damping_ratio": 0.0405, "effective_damping_ratio": 0.0273},
                           "tank_damping_for_measured_effective_damping": 0.0134},
    }
    # The pressure probe's first impact peak as sloshsph writes it (run/probe_summary.hpp); the
    # report shows it as it is.
    summary["pressure_probes"] = [{
        "name": "bottom", "column": "p:bottom", "from": [0.2, 0.0955], "to": [0.2, 0.1045], "face_length_m": 0.009,
        "impact_peak": {"baseline_Pa": 1177.2, "peak_Pa": 1227.2, "peak_time_s": 0.3125, "rise_start_s": 0.02,
                        "rise_end_s": 0.28, "rise_time_s": 0.26, "end_s": 0.6, "impulse_Pa_s": 17.5}}]
    if status != "completed":
        summary["failure"] = "synthetic failure for the test"
    with open(os.path.join(run_dir, "summary.json"), "w") as fh:
        json.dump(summary, fh)
    with open(os.path.join(run_dir, "run.json"), "w") as fh:
        json.dump({"command": "synthetic", "version": "test"}, fh)
    with open(os.path.join(run_dir, "case.toml"), "w") as fh:
        fh.write(f'title = "Synthetic sine <test> & co"\n\n[excitation]\namplitude = {X0}\ntype = "harmonic"\n'
                 f'ramp = 0.0\nstop = -1.0\n\n[fill]\ndepth = {DEPTH}\n\n[particles]\ndp = 0.01\n')
    pts, fields = make_particles()
    entries = []
    for k, ts in enumerate((0.0, 15.0, 30.0)):
        name = f"particles/particles_{k:06d}.vtu"
        write_vtu(os.path.join(run_dir, name), pts, fields)
        entries.append(f'<DataSet timestep="{ts:g}" part="0" file="{name}"/>')
    with open(os.path.join(run_dir, "particles.pvd"), "w") as fh:
        fh.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0">\n<Collection>\n'
                 + "\n".join(entries) + "\n</Collection>\n</VTKFile>\n")
    return pts, fields


# --------------------------------------------------------------------------------------------
# Checks


class TagChecker(html.parser.HTMLParser):
    """Counts tags and checks that the non-void elements are balanced."""
    VOID = {"meta", "img", "br", "hr", "link", "input"}

    def __init__(self):
        super().__init__()
        self.stack, self.errors, self.tags, self.ids = [], [], {}, set()

    def handle_starttag(self, tag, attrs):
        self.tags[tag] = self.tags.get(tag, 0) + 1
        for k, v in attrs:
            if k == "id":
                self.ids.add(v)
        if tag not in self.VOID:
            self.stack.append(tag)

    def handle_endtag(self, tag):
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"unbalanced </{tag}> (open: {self.stack[-3:]})")
        else:
            self.stack.pop()


def check_html(path, sections, min_images):
    text = open(path, encoding="utf-8").read()
    p = TagChecker()
    p.feed(text)
    check(not p.errors and not p.stack, f"{os.path.basename(path)} is well formed ({p.errors[:2]}, open {p.stack})")
    for sid in sections:
        check(sid in p.ids, f"section '{sid}' present")
    n_img = text.count('src="data:image/png;base64,')
    check(n_img >= min_images and n_img == p.tags.get("img", 0),
          f"{n_img} embedded PNG images (>= {min_images}), no external image")
    check("<script" not in text.lower(), "no JavaScript")
    check("http://" not in text and "https://" not in text, "no network reference")
    return text


def check_in_browser(html_path, tmp):
    for exe in ("/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"):
        if os.path.exists(exe):
            shot = os.path.join(tmp, "shot.png")
            subprocess.run([exe, "--headless", "--no-sandbox", "--disable-gpu", f"--screenshot={shot}",
                            "--window-size=1280,2000", "file://" + html_path], capture_output=True, timeout=120)
            check(os.path.exists(shot) and os.path.getsize(shot) > 10000, f"{exe} renders the report")
            return
    print("  note: no headless Chromium installed: the browser rendering check is skipped")


def run_tool(script, *args):
    res = subprocess.run([PY, os.path.join(HERE, script), *args], capture_output=True, text=True, timeout=600)
    if res.returncode not in (0, 2):
        print(res.stdout, res.stderr)
    return res


def test_analysis_functions():
    print("analysis functions (closed forms)")
    t = np.arange(0.0, 20.0 + 1e-9, 0.01)
    period = 2 * math.pi / OMEGA
    win = rl.analysis_window(t, period, 10)
    check(win is not None and win[2] == 10 and abs(win[1] - 20.0) < 1e-12, "window = last 10 whole periods")
    res = rl.steady_state_amplitude(t, ETA_C + ETA_A * np.sin(OMEGA * t), period, win)
    near(res["avg_max"], ETA_C + ETA_A, 0.01, "avg max of c + A sin")
    near(res["avg_min"], ETA_C - ETA_A, 0.01, "avg min of c + A sin")
    f_point = F0 * np.sin(OMEGA * t + PHI)
    e = rl.energy_per_cycle(t, f_point, X0 * np.sin(OMEGA * t), win, force_is_interval_mean=False)
    near(e, math.pi * F0 * X0 * math.sin(PHI), 0.01, "trapezoid energy per cycle of point-sampled F")
    check(rl.analysis_window(t[:50], period, 10) is None, "no window when not one period fits")
    check(rl.lowpass(t[:5], t[:5], 5.0)[0] is None, "no filter on 5 samples")


def test_vtu_roundtrip(tmp):
    print("VTU reader")
    pts, fields = make_particles()
    path = os.path.join(tmp, "one.vtu")
    write_vtu(path, pts, fields)
    d = vtu.read_vtu(path)
    check(np.allclose(d["points"], pts.astype(np.float32)), "points read back")
    check(np.array_equal(d["kind"], fields["kind"][1]) and d["velocity"].shape == (len(pts), 3),
          "kind and velocity read back")
    with open(path, "rb") as fh:
        cut = fh.read()[:-2000]
    with open(path, "wb") as fh:
        fh.write(cut)
    try:
        vtu.read_vtu(path)
        check(False, "a truncated VTU raises ValueError")
    except ValueError:
        check(True, "a truncated VTU raises ValueError")


def test_run_report(tmp):
    print("report.py on a synthetic harmonic run")
    run_dir = os.path.join(tmp, "run")
    make_run(run_dir)
    res = run_tool("report.py", run_dir)
    check(res.returncode == 0, f"report.py exit code 0 ({res.stderr.strip()[:300]})")
    html_path = os.path.join(run_dir, "report.html")
    check(os.path.exists(html_path), "report.html written")
    text = check_html(html_path, ["histories", "steady", "structure", "snapshots", "gauges", "forces", "energy",
                                  "diagnostics", "base"], min_images=10)
    check("Synthetic sine &lt;test&gt; &amp; co" in text, "title escaped in the header")
    check("<details>" in text and "Resolved case (case.toml)" in text, "case.toml in a collapsible block")
    check("<td class=\"l\">face 9 mm</td><td>1227</td><td>0.3125</td><td>0.26</td><td>17.5</td>" in text,
          "the first impact peak of p:bottom in the page (face 9 mm, 1227 Pa at 0.3125 s, rise 0.26 s, 17.5 Pa s)")
    for stem in ("gauges", "forces", "pressure", "energy", "diagnostics", "base_motion", "hysteresis",
                 "structure", "structure_psd", "admittance", "screen_forces"):
        for ext in ("png", "svg"):
            check(os.path.exists(os.path.join(run_dir, "plots", f"{stem}.{ext}")), f"plots/{stem}.{ext}")
    check(os.path.exists(os.path.join(run_dir, "plots", "snapshot_00.png")), "plots/snapshot_00.png")

    a = json.load(open(os.path.join(run_dir, "analysis.json")))
    h = a["harmonic"]
    check(h["cycles_used"] == 10, "10 cycles used")
    check(a["impact_peaks"]["p:bottom"]["peak_Pa"] == 1227.2, "analysis.json: the impact peak of p:bottom")
    for series in ("raw", "filtered"):
        g = h["signals"]["eta:left"][series]
        near(g["avg_max"], ETA_C + ETA_A, 0.01, f"eta:left {series} avg max")
        near(g["avg_min"], ETA_C - ETA_A, 0.01, f"eta:left {series} avg min")
        near(g["avg_max_normalised"], (ETA_C + ETA_A) / DEPTH, 0.01, f"eta:left {series} avg max / h")
        gr = h["signals"]["eta:right"][series]
        near(gr["avg_min"], -ETA_C - ETA_A, 0.01, f"eta:right {series} avg min")
        f = h["signals"]["F_w"][series]
        near(f["avg_max"], F0, 0.01, f"F_w {series} avg max")
        near(f["avg_min"], -F0, 0.01, f"F_w {series} avg min")
        near(f["avg_max_normalised"], F0 / (M_W * X0 * OMEGA ** 2), 0.01, f"F_w {series} normalised")
    amp_sw = abs(complex(F0 * math.cos(PHI), F0 * math.sin(PHI)) + M_W * X0 * OMEGA ** 2)  # F_w - m_w a
    near(h["signals"]["F_sw"]["raw"]["avg_max"], amp_sw, 0.01, "F_sw raw avg max (phasor sum)")
    e_ref = math.pi * F0 * X0 * math.sin(PHI)
    en = h["energy_per_cycle"]
    near(en["E_w_J_per_m"], e_ref, 0.01, "E_w = closed integral of F_w dX (pi F0 X0 sin phi)")
    near(en["from_W_base_J_per_m"], e_ref, 0.01, "E_w from the W_base column")
    near(en["E_w_normalised"], e_ref / (0.5 * M_W * (X0 * OMEGA) ** 2), 0.01, "E'_w (eq. 4.27)")
    check("structure" in a and abs(a["structure"]["x_s"]["psd_peak_hz"] - 0.5) < 0.1, "structure PSD peak at 0.5 Hz")
    adm = a["structure"].get("admittance", {})
    check(adm.get("effective_damping_ratio") == 0.02, "admittance: zeta_eff from summary.json")
    near(adm.get("peak_H2_displacement", 0.0), 1.0 / (2 * 0.02) ** 2, 0.01, "admittance peak 1/(2 zeta)^2 at f_n")
    check("structure alone, same load" in text and "<td>1.01</td>" in text and "<td>0.75</td>" in text,
          "the with/without table in the page (zeta 1.01 % alone, peak ratio 0.75)")
    check("at a damping ratio ζ_t = 1.34 %" in text and "ζ_eff = 2.73 %" in text,
          "the linear equivalent-TMD estimate in the page (tank damping 1.34 %, optimum 2.73 %)")
    check_in_browser(html_path, tmp)

    print("report.py --out, on a failed run with a cut-short CSV and a truncated snapshot")
    bad = os.path.join(tmp, "failed")
    make_run(bad, status="failed")
    with open(os.path.join(bad, "timeseries.csv"), "r+") as fh:
        content = fh.read()
        fh.seek(0)
        fh.truncate()
        fh.write(content[:len(content) // 3 - 7])  # ends in the middle of a row
    with open(os.path.join(bad, "particles", "particles_000002.vtu"), "r+b") as fh:
        fh.truncate(1500)
    out = os.path.join(tmp, "failed_out")
    res = run_tool("report.py", bad, "--out", out, "--no-svg")
    check(res.returncode == 0, "exit code 0 on a failed run")
    text = open(os.path.join(out, "report.html"), encoding="utf-8").read()
    check("banner bad" in text and "synthetic failure for the test" in text, "failure banner shown")
    check("malformed row" in text and "particles_000002.vtu skipped" in text, "notes on the damaged files")
    check(os.path.exists(os.path.join(out, "analysis.json")), "analysis.json in --out")

    print("report.py on an empty run and on a directory that is not a run")
    empty = os.path.join(tmp, "empty")
    os.makedirs(empty)
    with open(os.path.join(empty, "timeseries.csv"), "w") as fh:
        fh.write("time,x_base,eta:a,F_w\n")
    res = run_tool("report.py", empty)
    check(res.returncode == 0 and os.path.exists(os.path.join(empty, "report.html")), "header-only CSV: exit 0")
    res = run_tool("report.py", os.path.join(tmp, "nothing-here"))
    check(res.returncode == 2 and "not a sloshsph run directory" in res.stderr, "not a run directory: exit 2")
    return run_dir


def test_sweep_report(tmp, run_dir):
    print("sweep_report.py on a synthetic sweep")
    sweep = os.path.join(tmp, "sweep")
    os.makedirs(sweep)
    shutil.copytree(run_dir, os.path.join(sweep, "beta_1.000"))
    betas = np.linspace(0.8, 1.2, 9)
    with open(os.path.join(sweep, "frequency_response.csv"), "w") as fh:
        fh.write("beta,omega,eta_max,eta_min,F_sw_max,F_sw_min,energy_per_cycle,status,extra_metric\n")
        for b in betas:
            r = 1 / math.hypot(1 - b * b, 0.1 * b)
            status = "failed" if abs(b - 0.9) < 1e-9 else "completed"
            fh.write(f"{b:.3f},{b * OMEGA:.9f},{0.004 * r:.6g},{-0.0035 * r:.6g},{2 * r:.6g},{-1.8 * r:.6g},"
                     f"{0.01 * r:.6g},{status},{b * 2:.3f}\n")
    ref = os.path.join(tmp, "reference.csv")
    with open(ref, "w") as fh:
        fh.write("beta,eta_max,F_sw_max_norm\n0.8,0.01,1.0\n1.0,0.035,3.0\n1.2,0.01,1.0\n")
    res = run_tool("sweep_report.py", sweep, "--reference", ref, "--reference-label", "test reference")
    check(res.returncode == 0, f"sweep_report.py exit code 0 ({res.stderr.strip()[:300]})")
    html_path = os.path.join(sweep, "report.html")
    text = check_html(html_path, ["curves", "normalised", "points"], min_images=7)
    for stem in ("sweep_wave_height", "sweep_sloshing_force", "sweep_energy", "sweep_wave_height_normalised",
                 "sweep_sloshing_force_normalised", "sweep_energy_normalised", "sweep_extra_metric"):
        check(os.path.exists(os.path.join(sweep, "plots", stem + ".png")), f"plots/{stem}.png")
    check("did not complete" in text, "failed point flagged")
    check("beta_1.000" in text, "the point's run directory is linked in the table")

    print("sweep_report.py without frequency_response.csv (points from the run directories)")
    os.remove(os.path.join(sweep, "frequency_response.csv"))
    res = run_tool("sweep_report.py", sweep)
    check(res.returncode == 0, "exit code 0")
    text = open(html_path, encoding="utf-8").read()
    check("computed from the run directories" in text, "rebuilt points noted")
    res = run_tool("sweep_report.py", os.path.join(tmp, "nothing-here"))
    check(res.returncode == 2, "not a sweep directory: exit 2")


def test_free_decay_report(tmp):
    print("report.py on a synthetic free decay (the base stops, the wave decays at a known rate)")
    run_dir = os.path.join(tmp, "decay")
    os.makedirs(run_dir)
    omega_d, zeta, stop = 5.0, 0.02, 2.0
    t = np.round(np.arange(0.0, 20.0 + 0.005, 0.005), 10)
    eta = np.where(t < stop, 0.0, 0.01 * np.exp(-zeta * omega_d * (t - stop)) * np.sin(omega_d * (t - stop)))
    with open(os.path.join(run_dir, "timeseries.csv"), "w") as fh:
        fh.write("time,x_base,eta:right\n")
        for k in range(len(t)):
            fh.write(f"{t[k]:.10g},0,{eta[k]:.12g}\n")
    with open(os.path.join(run_dir, "summary.json"), "w") as fh:
        json.dump({"status": "completed", "excitation_omega_rad_s": omega_d, "simulated_time_s": 20.0}, fh)
    with open(os.path.join(run_dir, "case.toml"), "w") as fh:
        fh.write('title = "free decay"\n\n[excitation]\ntype = "harmonic"\namplitude = 0.001\n'
                 f'stop = {stop}\n\n[fill]\ndepth = 0.1\n')
    res = run_tool("report.py", run_dir, "--snapshots", "0", "--cutoff", "0")
    check(res.returncode == 0, f"exit code 0 ({res.stderr.strip()[:300]})")
    a = json.load(open(os.path.join(run_dir, "analysis.json")))
    g = a.get("free_decay", {}).get("gauges", {}).get("eta:right")
    check(g is not None, "a free-decay entry for the gauge")
    # Reference: the signal's own zeta (the envelope exp(-zeta omega t) with omega = omega_d here).
    near(g["zeta"], zeta, 0.02, "zeta from the decay of the half heights")
    near(g["omega_rad_s"], omega_d, 0.002, "omega from the zero up-crossings")
    check(os.path.exists(os.path.join(run_dir, "plots", "free_decay.png")), "plots/free_decay.png")
    text = open(os.path.join(run_dir, "report.html"), encoding="utf-8").read()
    check("Free decay" in text, "the section in the page")


def test_compare_report(tmp):
    print("compare_report.py on a folder of two synthetic coupled runs, one of them still running")
    folder = os.path.join(tmp, "designs")
    make_run(os.path.join(folder, "tank_a"))
    make_run(os.path.join(folder, "tank_b"), status="interrupted")
    status = os.path.join(tmp, "status.json")
    with open(status, "w") as fh:
        json.dump([{"dir": os.path.join(folder, "tank_b"), "state": "running", "time_s": 31.5, "leaked_particles": 2}], fh)
    res = run_tool("compare_report.py", folder, "--status", status)
    check(res.returncode == 0, f"compare_report.py exit code 0 ({res.stderr.strip()[:300]})")
    html_path = os.path.join(folder, "report.html")
    text = open(html_path, encoding="utf-8").read()
    check(text.count("<img") == 2, "two figures: admittance and ratios")
    for stem in ("comparison_admittance", "comparison_ratios"):
        check(os.path.exists(os.path.join(folder, "plots", stem + ".png")), f"plots/{stem}.png")
    rows = {r["name"]: r for r in json.load(open(os.path.join(folder, "comparison.json")))}
    check(sorted(rows) == ["tank_a", "tank_b"], "one row per run directory")
    near(rows["tank_a"]["zeta_eff_percent"], 2.0, 1e-9, "zeta_eff of tank_a from its summary.json, in %")
    near(rows["tank_a"]["peak_acceleration_ratio"], 0.75, 1e-9, "peak ratio of tank_a")
    near(rows["tank_a"]["linear_tmd_tank_damping_percent"], 1.34, 1e-9, "linear TMD tank damping of tank_a, in %")
    check(rows["tank_a"]["status"] == "completed", "tank_a: its summary's status")
    check(rows["tank_b"]["status"] == "running" and rows["tank_b"]["simulated_time_s"] == 31.5
          and rows["tank_b"]["leaked_particles"] == 2, "tank_b: the state, time and leaks that --status gives")
    check(">running<" in text, "the running run's state in the table")
    check_in_browser(html_path, tmp)
    res = run_tool("compare_report.py", os.path.join(tmp, "nothing-here"))
    check(res.returncode == 2 and "holds no run directories" in res.stderr, "no run directories: exit 2")


def main():
    tmp = tempfile.mkdtemp(prefix="sloshsph_report_test_")
    try:
        test_analysis_functions()
        test_vtu_roundtrip(tmp)
        run_dir = test_run_report(tmp)
        test_sweep_report(tmp, run_dir)
        test_free_decay_report(tmp)
        test_compare_report(tmp)
    except AssertionError as err:
        print(f"FAILED: {err}")
        print(f"(files kept in {tmp})")
        return 1
    shutil.rmtree(tmp, ignore_errors=True)
    print("all report tests passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
