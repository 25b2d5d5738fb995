"""Ctrl-C (SIGINT) during a Python run leaves a resumable run directory (issue 32, 3)."""

import os
import signal
import subprocess
import sys
import textwrap

import sloshsph
from conftest import small_case

CHILD = textwrap.dedent("""
    import os, signal, sys
    sys.path.insert(0, {tests!r})
    import sloshsph
    from conftest import small_case
    def report(p):
        print(f"t {{p.time:.6f}}", flush=True)
    try:
        sloshsph.run(small_case(**{{"time.end": 2.0}}), out={out!r}, threads=1, progress=report)
        print("COMPLETED", flush=True)
    except sloshsph.Interrupted as e:
        print("INTERRUPTED", e.result.status, flush=True)
        # Python's own handler is back: a second SIGINT is an ordinary KeyboardInterrupt.
        try:
            os.kill(os.getpid(), signal.SIGINT)
            import time; time.sleep(5)
        except KeyboardInterrupt as again:
            print("KEYBOARD", type(again).__name__, flush=True)
        sys.exit(4)
""")


def test_sigint_stops_cleanly_and_the_run_resumes_bitwise(tmp_path):
    whole = tmp_path / "whole"
    sloshsph.run(small_case(**{"time.end": 2.0}), out=whole, threads=1, progress=False)
    out = tmp_path / "split"
    script = CHILD.format(tests=os.path.dirname(__file__), out=str(out))
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, env=os.environ)
    lines = []
    for line in child.stdout:
        lines.append(line.strip())
        if line.startswith("t ") and float(line.split()[1]) >= 0.5:
            child.send_signal(signal.SIGINT)
            break
    rest, _ = child.communicate(timeout=120)
    lines += rest.split("\n")
    assert child.returncode == 4, lines[-5:]
    assert "INTERRUPTED interrupted" in lines
    assert "KEYBOARD KeyboardInterrupt" in lines
    run = sloshsph.read_run(out)
    assert run.status == "interrupted"
    assert 0.5 <= run.summary["simulated_time_s"] < 2.0
    assert os.path.isfile(out / "checkpoint.bin")
    resumed = sloshsph.resume(out, threads=1, progress=False)
    assert resumed.status == "completed"
    with open(out / "timeseries.csv", "rb") as a, open(whole / "timeseries.csv", "rb") as b:
        assert a.read() == b.read()
