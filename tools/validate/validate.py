#!/usr/bin/python3
"""The living validation report: `sloshsph validate [--long]` (app/cmd_validate.cpp) runs this.

1. runs the validation tests of a build tree with ctest (label `validation`, plus `long` with
   --long), each test recording its checks in $SLOSHSPH_VALIDATION_RECORD
   (tests/validation/validation_check.hpp: one JSON line per check, one JSON file per curve);
2. merges what ran into docs/validation/results.json (tests that did not run keep their last
   recorded result, with the commit and date it came from, so that the page never mixes a fresh
   number with an unlabelled old one);
3. plots each recorded curve beside its reference, and one summary of every check's deviation in
   units of its tolerance, into docs/figures/validation/;
4. writes docs/validation.md: the summary, the table (test, quantity, reference and its source,
   tolerance, measured, verdict), the plots, then the hand-written discussion from
   docs/validation/notes.md.

Exit codes: 0 every test and asserted check that ran passed; 3 one failed; 2 bad usage; 1 internal.
Python 3 with numpy and matplotlib (Debian's python3-numpy, python3-matplotlib).
"""
import argparse
import datetime
import glob
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

EXIT_OK, EXIT_INTERNAL, EXIT_USAGE, EXIT_FAILED = 0, 1, 2, 3
RESULTS = os.path.join("validation", "results.json")
ALL_LABELS = ["validation", "unit-theory", "long"]  # the labels whose tests the page lists
NOTES = os.path.join("validation", "notes.md")
FIGURES = os.path.join("figures", "validation")


def fail_usage(message):
    print(f"validate: error: {message}", file=sys.stderr)
    sys.exit(EXIT_USAGE)


# --------------------------------------------------------------------------------------------
# ctest

def list_tests(build_dir, labels, strict=True):
    """{name: label} of the tests in the build tree that carry one of the labels. When ctest cannot
    list them: an error (strict), or {} (not strict: the results of a run must still be kept)."""
    out = subprocess.run(["ctest", "--test-dir", build_dir, "--show-only=json-v1"],
                         capture_output=True, text=True)
    if out.returncode != 0:
        if not strict:
            return {}
        fail_usage(f"{build_dir}: ctest cannot list the tests: {out.stderr.strip()}")
    tests = {}
    for t in json.loads(out.stdout).get("tests", []):
        for prop in t.get("properties", []):
            if prop.get("name") == "LABELS":
                hit = [lab for lab in prop.get("value", []) if lab in labels]
                if hit:
                    tests[t["name"]] = hit[0]
    return tests


def run_tests(build_dir, labels, name_filter, jobs, records):
    """Runs the tests; returns {name: {"status": "passed"|"failed", "seconds": s}}."""
    junit = os.path.join(records, "ctest.xml")
    cmd = ["ctest", "--test-dir", build_dir, "-L", "^(" + "|".join(labels) + ")$", "-j", str(jobs),
           "--output-on-failure", "--output-junit", junit]
    if name_filter:
        cmd += ["-R", name_filter]
    env = dict(os.environ, SLOSHSPH_VALIDATION_RECORD=records)
    print("validate: " + " ".join(cmd), flush=True)
    subprocess.run(cmd, env=env)
    if not os.path.exists(junit):
        print("validate: error: ctest wrote no results (no test matched?)", file=sys.stderr)
        sys.exit(EXIT_USAGE)
    outcome = {}
    for case in ET.parse(junit).getroot().iter("testcase"):
        status = case.get("status", "run")
        failed = case.find("failure") is not None or status == "fail"
        if status in ("notrun", "disabled"):
            continue
        outcome[case.get("name")] = {"status": "failed" if failed else "passed",
                                     "seconds": float(case.get("time", "nan"))}
    return outcome


def read_records(records, name):
    checks = []
    path = os.path.join(records, name + ".jsonl")
    if os.path.exists(path):
        with open(path) as f:
            checks = [json.loads(line) for line in f if line.strip()]
    curves = []
    for p in sorted(glob.glob(os.path.join(glob.escape(records), glob.escape(name) + ".*.curve.json"))):
        with open(p) as f:
            curves.append(json.load(f))
    return checks, curves


def git_revision(source_dir):
    def git(*args):
        r = subprocess.run(["git", "-C", source_dir, *args], capture_output=True, text=True)
        return r.stdout.strip() if r.returncode == 0 else ""
    rev = git("rev-parse", "--short", "HEAD") or "unknown"
    dirty = git("status", "--porcelain", "--untracked-files=no")
    return rev + ("+changes" if dirty else "")


# --------------------------------------------------------------------------------------------
# Plots

def slug(text):
    return "".join(c if c.isalnum() or c in "._-" else "_" for c in text)


def plot_curve(curve, path):
    fig, ax = plt.subplots(figsize=(7.0, 3.6))
    sparse = len(curve["x"]) < 50  # a profile of a few probes: show the points
    ax.plot(curve["x"], curve["measured"], lw=1.3, marker="s" if sparse else None, ms=4, label="sloshsph")
    ref_x, ref_y = curve.get("reference_x") or [], curve.get("reference_y") or []
    if ref_x and ref_y:
        style = dict(ls="none", marker="o", ms=4, color="k") if curve.get("reference_as_points") else dict(
            lw=1.1, ls="--", color="k")
        ax.plot(ref_x, ref_y, label=curve.get("reference_label") or "reference", **style)
    if curve.get("log_y"):
        ax.set_yscale("log")
    ax.set_xlabel(curve.get("x_label", ""))
    ax.set_ylabel(curve.get("y_label", ""))
    ax.set_title(curve.get("title", ""), fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def deviation_in_tolerances(c):
    """Where the measured value sits in units of its tolerance: 0 at the reference (the middle of a
    range), +-1 at the edges. A one-sided bound has no scale: a value inside it is not drawn, one
    beyond it is drawn past 1 by its excess relative to the bound."""
    m, r, tol, kind = c.get("measured"), c.get("reference"), c.get("tolerance"), c.get("kind")
    if m is None or r is None:
        return None
    try:
        if kind == "relative" and tol:
            return (m / r - 1.0) / tol
        if kind == "absolute" and tol:
            return (m - r) / tol
        if kind == "between" and tol is not None and tol > r:
            return (m - 0.5 * (r + tol)) / (0.5 * (tol - r))
        if kind in ("at_most", "at_least"):
            scale = abs(r) if r else 1.0
            over = (m - r) / scale if kind == "at_most" else (r - m) / scale
            return 1.0 + over if over > 0 else None  # inside a one-sided bound: no scale to show
    except (ZeroDivisionError, TypeError):
        return None
    return None


def plot_summary(results, path):
    rows = []
    for name in sorted(results):
        for c in results[name].get("checks", []):
            d = deviation_in_tolerances(c)
            if d is not None:
                colour = "tab:green" if c.get("pass") else "tab:red" if c.get("asserted", True) else "tab:orange"
                rows.append((f"{name.split('.', 1)[-1]}: {c['quantity']}"[:90], d, colour))
    if not rows:
        return False
    fig, ax = plt.subplots(figsize=(11.0, 0.22 * len(rows) + 1.4))
    y = range(len(rows))
    clipped = [max(-3.0, min(3.0, d)) for _, d, _ in rows]
    ax.barh(list(y), clipped, color=[colour for _, _, colour in rows])
    ax.axvline(-1.0, color="k", lw=0.8, ls="--")
    ax.axvline(1.0, color="k", lw=0.8, ls="--")
    ax.axvline(0.0, color="k", lw=0.6)
    ax.set_yticks(list(y))
    ax.set_yticklabels([r[0] for r in rows], fontsize=6)
    ax.invert_yaxis()
    ax.set_xlim(-3.2, 3.2)
    ax.set_xlabel("(measured - reference) / tolerance: |x| <= 1 passes (clipped at 3)")
    ax.set_title("Checks against their tolerance: every two-sided one, and one-sided bounds exceeded\n"
                 "(green pass, red fail, orange a known miss recorded but not asserted)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return True


# --------------------------------------------------------------------------------------------
# The page

def num(v, unit="", pad=True):
    """4 significant digits; `pad` keeps trailing zeros (measured values), else drops them (bounds)."""
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "n/a"
    text = "0" if v == 0 else (f"{v:#.4g}".rstrip(".") if pad else f"{v:.4g}")
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = mantissa.rstrip(".") + "e" + exponent
    return text + (f" {unit}" if unit else "")


def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def reference_text(c):
    unit = c.get("unit", "")
    kind = c.get("kind")
    if kind in ("relative", "absolute"):
        return f"{num(c.get('reference'), unit)} ({c.get('source', '')})"
    return c.get("source", "")


def tolerance_text(c):
    unit, kind, r, tol = c.get("unit", ""), c.get("kind"), c.get("reference"), c.get("tolerance")
    if kind == "relative":
        return f"± {100.0 * tol:.3g} %"
    if kind == "absolute":
        return f"± {num(tol, unit, pad=False)}"
    if kind == "at_most":
        return f"≤ {num(r, unit, pad=False)}"
    if kind == "at_least":
        return f"≥ {num(r, unit, pad=False)}"
    if kind == "between":
        return f"{num(r, pad=False)} to {num(tol, unit, pad=False)}"
    return "?"


def measured_text(c):
    """The measured value, and for a two-sided check how far it is from the reference."""
    text = num(c.get("measured"), c.get("unit", ""))
    m, r = c.get("measured"), c.get("reference")
    if c.get("kind") == "relative" and m is not None and r:
        text += f" ({100.0 * (m / r - 1.0):+.2g} %)"
    elif c.get("kind") == "absolute" and m is not None and r is not None:
        text += f" ({m - r:+.3g})"
    return text


def verdict_text(c):
    if c.get("asserted", True):
        return "pass" if c.get("pass") else "**FAIL**"
    return "pass (not asserted)" if c.get("pass") else "fail (known miss, not asserted)"


def test_status_text(entry):
    status = entry.get("status", "not run")
    if status == "failed":
        return "**failed**"
    if status == "passed" and not entry.get("checks"):
        return "passed (no checks recorded)"
    return status


def write_page(path, results, run_info, notes_text, figures_rel, summary_plot):
    # The unit-theory label also holds unit tests of errors and meshes: only those with checks show.
    names = [n for n in results if results[n].get("label") != "unit-theory" or results[n].get("checks")]
    order = {"validation": 0, "unit-theory": 1, "long": 2}
    names.sort(key=lambda n: (order.get(results[n].get("label"), 3), n))
    ran = [n for n in names if results[n].get("status") in ("passed", "failed")]
    checks = [c for n in ran for c in results[n].get("checks", [])]
    asserted = [c for c in checks if c.get("asserted", True)]
    lines = [
        "# Validation",
        "",
        "<!-- Generated by `sloshsph validate` (tools/validate/validate.py). Do not edit by hand: the",
        "     discussion is docs/validation/notes.md, the numbers docs/validation/results.json. -->",
        "",
        f"This page is written by `sloshsph validate` ({run_info}). Each row is one check of a test in",
        "`tests/validation/` or of the linear-theory unit tests (label `unit-theory`, `tests/unit/linear/`):",
        "the measured number, the reference it is held to (theory, a table of the",
        "thesis, an experiment in `data/refdata/`), the tolerance, and the verdict. A test that did not",
        "run in the latest invocation keeps its last recorded result, with the commit and date it came",
        "from; the long tests (ctest label `long`) run only with `sloshsph validate --long`",
        "(`scripts/test.sh --long` runs them without rewriting this page).",
        "",
        f"**{len(ran)} of {len(names)} tests have results: "
        f"{sum(results[n]['status'] == 'passed' for n in ran)} passed, "
        f"{sum(results[n]['status'] == 'failed' for n in ran)} failed. "
        f"{len(checks)} checks: {sum(bool(c.get('pass')) for c in asserted)} of {len(asserted)} asserted checks "
        f"pass; {sum(not c.get('asserted', True) for c in checks)} are recorded known misses or "
        "reported numbers (not asserted, explained in the notes).**",
        "",
        "## Tests",
        "",
        "| test | label | status | checks passed | wall time | result from |",
        "|---|---|---|---|---|---|",
    ]
    for n in names:
        e = results[n]
        cs = e.get("checks", [])
        seconds = e.get("seconds")
        wall = f"{seconds:.0f} s" if isinstance(seconds, (int, float)) and math.isfinite(seconds) else "–"
        origin = f"{e['commit']}, {e['date']}" if e.get("commit") else "–"
        lines.append(f"| `{n}` | {e.get('label', '')} | {test_status_text(e)} | "
                     f"{sum(bool(c.get('pass')) for c in cs)} / {len(cs)} | {wall} | {origin} |")
    lines += ["", "## Checks", "",
              "| test | quantity | reference (source) | tolerance | measured | result |",
              "|---|---|---|---|---|---|"]
    for n in names:
        first = True
        for c in results[n].get("checks", []):
            lines.append(f"| {'`' + n.split('.', 1)[-1] + '`' if first else ''} | {cell(c['quantity'])} | "
                         f"{cell(reference_text(c))} | {cell(tolerance_text(c))} | "
                         f"{cell(measured_text(c))} | {verdict_text(c)} |")
            first = False
    lines += ["", "## Comparison plots", ""]
    if summary_plot:
        lines += [f"![every check against its tolerance]({figures_rel}/summary.png)", ""]
    for n in names:
        for fig in results[n].get("figures", []):
            lines += [f"**{n}** ({results[n].get('commit', '')}):", "", f"![{n}]({fig})", ""]
    if notes_text:
        lines += ["## Discussion", "", notes_text.strip(), ""]
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(path + ".tmp", path)


# --------------------------------------------------------------------------------------------

def load_stored(results_path):
    """The stored results and the last invocation's description (empty if there are none)."""
    if not os.path.exists(results_path):
        return {}, ""
    with open(results_path) as f:
        stored = json.load(f)
    return stored.get("tests", {}), stored.get("last_invocation", "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build-dir", required=True)
    ap.add_argument("--docs", required=True)
    ap.add_argument("--source-dir", default=os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--long", action="store_true")
    ap.add_argument("--filter", default="")
    ap.add_argument("--no-run", action="store_true")
    a = ap.parse_args()

    labels = ALL_LABELS if a.long else ["validation", "unit-theory"]
    os.makedirs(os.path.join(a.docs, "validation"), exist_ok=True)
    figures_dir = os.path.join(a.docs, FIGURES)
    os.makedirs(figures_dir, exist_ok=True)
    results_path = os.path.join(a.docs, RESULTS)
    results, last_invocation = load_stored(results_path)

    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    revision = git_revision(a.source_dir)
    failed = False
    if a.no_run:
        run_info = (last_invocation + "; " if last_invocation else "") + f"page rewritten {now} without running tests"
        # Tests of the build tree with no stored result yet get their "not run" row (none is
        # dropped here: without running, nothing says a stored test is gone for good).
        for n, label in list_tests(os.path.abspath(a.build_dir), ALL_LABELS, strict=False).items():
            results.setdefault(n, {"status": "not run", "label": label})
    else:
        build_dir = os.path.abspath(a.build_dir)
        known = list_tests(build_dir, ALL_LABELS)
        if not known:
            fail_usage(f"{build_dir}: no tests labelled validation or long (was the project built with its tests?)")
        # A folder of this invocation's own: two invocations on one build tree must not clear
        # each other's records (a shared folder lost the records of the tests run before the
        # other one started).
        records = tempfile.mkdtemp(prefix="validation-records-", dir=build_dir)
        try:
            outcome = run_tests(build_dir, labels, a.filter, a.jobs, records)
            ran = {n: (o, read_records(records, n)) for n, o in outcome.items()}
        finally:
            shutil.rmtree(records, ignore_errors=True)
        # Read again after the run (hours, with --long): another invocation on other tests may
        # have written its results meanwhile, and they are kept.
        results, last_invocation = load_stored(results_path)
        # Which tests exist is also read again: the build tree may have gained tests during a
        # long run (another invocation's results for a test added meanwhile were dropped as
        # "no longer existing" when the list from the start was used). The tests that ran stay.
        known = {**known, **list_tests(build_dir, ALL_LABELS, strict=False)}
        # Drop the tests that no longer exist. A label none of whose tests is in this build tree
        # (its test executable was not built: scripts/build.sh with targets) keeps its stored results.
        present = set(known.values())
        results = {n: e for n, e in results.items() if n in known or e.get("label") not in present}
        for n, label in known.items():
            results.setdefault(n, {"status": "not run"})["label"] = label
        for n, (o, (checks, curves)) in ran.items():
            for old in glob.glob(os.path.join(glob.escape(figures_dir), glob.escape(slug(n)) + ".*.png")):
                os.remove(old)
            figures = []
            for curve in curves:
                fname = f"{slug(n)}.{slug(curve['name'])}.png"
                plot_curve(curve, os.path.join(figures_dir, fname))
                figures.append(f"{FIGURES}/{fname}")
            results[n] = {"label": known.get(n, ""), "status": o["status"], "seconds": o["seconds"],
                          "commit": revision, "date": now, "checks": checks, "figures": figures}
            if o["status"] == "failed" or any(c.get("asserted", True) and not c.get("pass") for c in checks):
                failed = True
        what = " and ".join(f"`{lab}`" for lab in labels)
        run_info = (f"latest invocation {now}, commit {revision}, labels {what}"
                    + (f", tests matching `{a.filter}`" if a.filter else "")
                    + f": {len(outcome)} test{'' if len(outcome) == 1 else 's'} ran")
        last_invocation = run_info

    summary_plot = plot_summary(results, os.path.join(figures_dir, "summary.png"))
    notes_path = os.path.join(a.docs, NOTES)
    notes_text = open(notes_path).read() if os.path.exists(notes_path) else ""
    if notes_text.lstrip().startswith("<!--"):  # the file's own header comment is not for the page
        notes_text = notes_text.split("-->", 1)[1]
    with open(results_path + ".tmp", "w") as f:
        json.dump({"generated_by": "sloshsph validate", "last_invocation": last_invocation, "tests": results}, f,
                  indent=1, sort_keys=True)
        f.write("\n")
    os.replace(results_path + ".tmp", results_path)
    write_page(os.path.join(a.docs, "validation.md"), results, run_info, notes_text, FIGURES, summary_plot)
    return EXIT_FAILED if failed else EXIT_OK


if __name__ == "__main__":
    try:
        sys.exit(main())
    except SystemExit:
        raise
    except Exception as e:  # noqa: BLE001 - any other failure is an internal error with its reason
        print(f"validate: internal error: {type(e).__name__}: {e}", file=sys.stderr)
        sys.exit(EXIT_INTERNAL)
