#!/usr/bin/python3
"""Test of tools/validate/validate.py (`sloshsph validate`) on a made-up build tree.

    /usr/bin/python3 tools/validate/test_validate.py      (exit code 0 on success)

The build tree is a hand-written CTestTestfile.cmake with three tests that stand for the real
ones: `Fake.Passes` (label validation) records two passing checks and a curve, `Fake.Fails`
(validation) records a failing check and a known miss and exits 1, `FakeLong.NotRun` (long) is not
run without --long. Checked:
- the exit code is 3 when a test fails, 0 when every test that ran passed;
- validation.md has the summary, a row per check with its verdict (pass, **FAIL**, known miss),
  the long test as not run, the curve's plot, and the notes below the tables;
- a second invocation that runs only Fake.Passes keeps Fake.Fails's earlier result, with the
  commit and date it came from;
- an invocation keeps what another one wrote into results.json while it ran (`Fake.Meanwhile`,
  when the marker file exists, writes a result for FakeLong.NotRun as a parallel invocation would);
- a result written meanwhile for a test added to the build tree during the run (`Fake.Grows`)
  is kept, since the tests that exist are listed again after the run;
- a stored result is dropped when its test left a label the build tree has, and kept when the
  build tree has no test of its label (that test executable was not built);
- `--no-run` rewrites the page from results.json, with a "not run" row for a test of the build
  tree that has no stored result yet.
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
VALIDATE = os.path.join(HERE, "validate.py")
PY = sys.executable or "/usr/bin/python3"
failures = []


def check(condition, what):
    print(("  ok: " if condition else "  FAIL: ") + what)
    if not condition:
        failures.append(what)


def record(name, rows):
    """A shell command that writes the JSON lines of `rows` as test `name` would."""
    lines = "\\n".join(json.dumps(dict(test=name, **r)).replace("'", "") for r in rows)
    return f"printf '{lines}\\n' > \"$SLOSHSPH_VALIDATION_RECORD/{name}.jsonl\""


def meanwhile(docs, marker):
    """A shell command that, if `marker` exists, stores a result for FakeLong.NotRun in results.json."""
    script = (f"import json; p = {os.path.join(docs, 'validation', 'results.json')!r}; d = json.load(open(p)); "
              "d['tests']['FakeLong.NotRun'] = dict(label='long', status='passed', seconds=7.0, commit='abc', "
              "date='elsewhere', checks=[], figures=[]); json.dump(d, open(p, 'w'))")
    return f"if [ -f {marker} ]; then {PY} -c \"{script}\"; fi"


def grows(build, docs, marker):
    """A shell command that, if `marker` exists, adds the test FakeLong.Added to the build tree and
    stores a result for it, as a rebuild and a parallel invocation of the new test would."""
    script = os.path.join(os.path.dirname(marker), "grow.py")
    with open(script, "w") as f:
        f.write(f"""import json
with open({os.path.join(build, 'CTestTestfile.cmake')!r}, 'a') as f:
    f.write('add_test([=[FakeLong.Added]=] "/bin/sh" "-c" "exit 0")\\n')
    f.write('set_tests_properties([=[FakeLong.Added]=] PROPERTIES LABELS "long")\\n')
p = {os.path.join(docs, 'validation', 'results.json')!r}
d = json.load(open(p))
d['tests']['FakeLong.Added'] = dict(label='long', status='failed', seconds=9.0, commit='def', date='added',
                                    checks=[], figures=[])
json.dump(d, open(p, 'w'))
""")
    return f"if [ -f {marker} ]; then {PY} {script}; fi"


def make_build_tree(build, docs, marker):
    os.makedirs(build)
    passing = [
        dict(quantity="pressure at the floor", unit="Pa", measured=2456.0, kind="relative", reference=2452.5,
             tolerance=0.02, source="hydrostatics", asserted=True, **{"pass": True}),
        dict(quantity="particles leaked", unit="", measured=0, kind="at_most", reference=0, tolerance=None,
             source="none may leave", asserted=True, **{"pass": True}),
    ]
    failing = [
        dict(quantity="front RMS error", unit="m", measured=0.28, kind="at_most", reference=0.05, tolerance=None,
             source="Koshizuka and Oka", asserted=True, **{"pass": False}),
        dict(quantity="front RMS, unshifted", unit="m", measured=0.27, kind="at_most", reference=0.05,
             tolerance=None, source="known miss", asserted=False, **{"pass": False}),
    ]
    curve = json.dumps(dict(test="Fake.Passes", name="profile", title="a profile", x_label="y (m)",
                            y_label="p (Pa)", x=[0.0, 0.1, 0.2], measured=[2456.0, 1475.0, 490.0],
                            reference_label="hydrostatic", reference_x=[0.0, 0.2], reference_y=[2452.5, 490.5],
                            reference_as_points=False))
    curve_cmd = f"printf '%s' '{curve}' > \"$SLOSHSPH_VALIDATION_RECORD/Fake.Passes.profile.curve.json\""
    tests = [
        ("Fake.Passes", "validation", record("Fake.Passes", passing) + " && " + curve_cmd),
        ("Fake.Fails", "validation", record("Fake.Fails", failing) + " && exit 1"),
        ("FakeLong.NotRun", "long", "exit 1"),
        ("Fake.Meanwhile", "validation", meanwhile(docs, marker)),
        ("Fake.Grows", "validation", grows(build, docs, marker + "-grow")),
    ]
    with open(os.path.join(build, "CTestTestfile.cmake"), "w") as f:
        for name, label, command in tests:
            escaped = command.replace("\\", "\\\\").replace('"', '\\"')
            f.write(f'add_test([=[{name}]=] "/bin/sh" "-c" "{escaped}")\n')
            f.write(f'set_tests_properties([=[{name}]=] PROPERTIES LABELS "{label}")\n')


def run(build, docs, *extra):
    out = subprocess.run([PY, VALIDATE, "--build-dir", build, "--docs", docs, "--source-dir", HERE, *extra],
                         capture_output=True, text=True)
    return out.returncode, out.stdout + out.stderr


def main():
    with tempfile.TemporaryDirectory() as tmp:
        build, docs = os.path.join(tmp, "build"), os.path.join(tmp, "docs")
        marker = os.path.join(tmp, "write-meanwhile")
        make_build_tree(build, docs, marker)
        os.makedirs(os.path.join(docs, "validation"))
        with open(os.path.join(docs, "validation", "notes.md"), "w") as f:
            f.write("<!-- header -->\nThe discussion, by hand.\n")

        code, log = run(build, docs)
        check(code == 3, f"a failing test gives exit code 3 (got {code})")
        page = open(os.path.join(docs, "validation.md")).read()
        check("4 of 5 tests have results: 3 passed, 1 failed" in page, "summary counts the tests")
        check("| pressure at the floor | 2452 Pa (hydrostatics) | ± 2 % | 2456 Pa (+0.14 %) | pass |" in page,
              "a relative check's row: reference, tolerance, measured with its deviation, verdict")
        check("| front RMS error | Koshizuka and Oka | ≤ 0.05 m | 0.2800 m | **FAIL** |" in page, "a failed check")
        check("fail (known miss, not asserted)" in page, "a recorded known miss")
        check("| `FakeLong.NotRun` | long | not run |" in page, "the long test is listed as not run")
        check("figures/validation/Fake.Passes.profile.png" in page
              and os.path.exists(os.path.join(docs, "figures", "validation", "Fake.Passes.profile.png")),
              "the curve is plotted and linked")
        check(page.rstrip().endswith("The discussion, by hand.") and "<!-- header -->" not in page,
              "the notes follow the tables, without their header comment")
        first = json.load(open(os.path.join(docs, "validation", "results.json")))["tests"]["Fake.Fails"]
        check(not [d for d in os.listdir(build) if d.startswith("validation-records")],
              "the invocation's own records folder is removed (two invocations never share one)")

        code, log = run(build, docs, "--filter", "^Fake\\.Passes$")
        check(code == 0, f"only the passing test: exit code 0 (got {code})")
        kept = json.load(open(os.path.join(docs, "validation", "results.json")))["tests"]["Fake.Fails"]
        check(kept == first, "a test that did not run keeps its earlier result, commit and date")
        page = open(os.path.join(docs, "validation.md")).read()
        check("1 test ran" in page and "**failed**" in page, "the page says what ran and still shows the old failure")

        open(marker, "w").close()
        code, log = run(build, docs, "--filter", "^Fake\\.Meanwhile$")
        stored = json.load(open(os.path.join(docs, "validation", "results.json")))["tests"]
        check(code == 0 and stored["FakeLong.NotRun"].get("date") == "elsewhere"
              and stored["Fake.Meanwhile"]["status"] == "passed",
              "a result written by another invocation during the run is kept beside this run's")

        open(marker + "-grow", "w").close()
        code, log = run(build, docs, "--filter", "^Fake\\.Grows$")
        stored = json.load(open(os.path.join(docs, "validation", "results.json")))["tests"]
        check(stored.get("FakeLong.Added", {}).get("date") == "added",
              "a result for a test added to the build tree during the run is kept (not dropped as removed)")
        os.remove(marker + "-grow")

        results_path = os.path.join(docs, "validation", "results.json")
        d = json.load(open(results_path))
        d["tests"]["Theory.NotBuilt"] = dict(label="unit-theory", status="passed", seconds=1.0, commit="abc",
                                             date="earlier", checks=[], figures=[])
        d["tests"]["Fake.Removed"] = dict(label="validation", status="passed", seconds=1.0, commit="abc",
                                          date="earlier", checks=[], figures=[])
        json.dump(d, open(results_path, "w"))
        code, log = run(build, docs, "--filter", "^Fake\\.Passes$")
        stored = json.load(open(results_path))["tests"]
        check("Theory.NotBuilt" in stored, "a stored test of a label absent from the build tree (not built) is kept")
        check("Fake.Removed" not in stored, "a stored test missing from its label's tests in the build tree is dropped")

        os.remove(os.path.join(docs, "validation.md"))
        with open(os.path.join(build, "CTestTestfile.cmake"), "a") as f:
            f.write('add_test([=[FakeLong.New]=] "/bin/sh" "-c" "exit 0")\n')
            f.write('set_tests_properties([=[FakeLong.New]=] PROPERTIES LABELS "long")\n')
        code, log = run(build, docs, "--no-run")
        check(code == 0 and os.path.exists(os.path.join(docs, "validation.md")), "--no-run rewrites the page")
        check("| `FakeLong.New` | long | not run |" in open(os.path.join(docs, "validation.md")).read(),
              "--no-run lists a test new to the build tree as not run")

        code, log = run(os.path.join(tmp, "nothing"), docs)
        check(code == 2 and ("cannot list the tests" in log or "no tests labelled" in log),
              f"not a build tree: exit code 2 (got {code})")
    if failures:
        print(f"{len(failures)} validate checks failed")
        return 1
    print("all validate tests passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
