"""Runs from Python: the same bits as the program, progress, stopping, resuming, the GIL, reading
run directories (issue 32, 1 and 3)."""

import os
import threading

import numpy as np
import pytest
import sloshsph
import sloshsph._toml
from conftest import CASES, cli, small_case, small_sets


def read(path):
    with open(path, "rb") as f:
        return f.read()


def test_same_time_series_as_the_program(tmp_path):
    code, _, err = cli("run", os.path.join(CASES, "liu_lin_2008.toml"), *small_sets(), "--threads", 1,
                       "--out", tmp_path / "cli", "--quiet")
    assert code == 0, err
    run = sloshsph.run(small_case(), out=tmp_path / "py", threads=1, progress=False)
    assert run.status == "completed"
    assert read(tmp_path / "py" / "timeseries.csv") == read(tmp_path / "cli" / "timeseries.csv")
    assert read(tmp_path / "py" / "case.toml") == read(tmp_path / "cli" / "case.toml")
    cli_run = sloshsph.read_run(tmp_path / "cli")
    assert set(cli_run.summary) == set(run.summary)
    assert cli_run.summary["response"] == run.summary["response"]


def test_reading_a_run(tmp_path):
    run = sloshsph.run(small_case(), out=tmp_path / "r", threads=1, progress=False)
    ts = run.timeseries
    assert list(ts)[0] == "time"
    assert ts["time"][-1] == pytest.approx(1.0)
    assert len(ts["time"]) == 101  # output.sample_interval = 0.01 s, t = 0 included
    assert all(isinstance(v, np.ndarray) and v.dtype == np.float64 for v in ts.values())
    assert run.units["eta:left"] == "m"
    assert run.case["time.end"] == 1.0
    assert run.info["program"] == "sloshsph"
    assert "sloshsph.run" in run.info["command"]
    # The steady-state response recomputed from the series is summary.json's (the same code).
    again = sloshsph.analysis.steady_state_response(run)
    assert again == run.response


def test_dataframe_when_pandas_is_installed(tmp_path):
    run = sloshsph.run(small_case(**{"time.end": 0.1}), out=tmp_path / "r", threads=1, progress=False)
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="python3-pandas"):
            run.dataframe()
        return
    frame = run.dataframe()
    assert list(frame.columns) == list(run.timeseries)[1:]
    np.testing.assert_array_equal(frame["eta:left"].to_numpy(), run.timeseries["eta:left"])


def test_progress_callback_sees_every_sample(tmp_path):
    seen = []
    sloshsph.run(small_case(), out=tmp_path / "r", threads=1, progress=seen.append)
    times = [p.time for p in seen]
    assert len(seen) == 100  # every row after t = 0
    assert times == sorted(times) and times[-1] == pytest.approx(1.0)
    assert seen[-1].fraction == pytest.approx(1.0) and seen[-1].steps == 2000


def test_callback_returning_false_stops_and_the_run_resumes_bitwise(tmp_path):
    sloshsph.run(small_case(), out=tmp_path / "whole", threads=1, progress=False)

    def stop_at_half(p):
        return p.time < 0.5 - 1e-9

    stopped = sloshsph.run(small_case(), out=tmp_path / "split", threads=1, progress=stop_at_half)
    assert stopped.status == "interrupted"
    assert os.path.isfile(tmp_path / "split" / "checkpoint.bin")
    assert stopped.summary["simulated_time_s"] == pytest.approx(0.5)
    resumed = sloshsph.resume(tmp_path / "split", threads=1, progress=False)
    assert resumed.status == "completed"
    assert read(tmp_path / "split" / "timeseries.csv") == read(tmp_path / "whole" / "timeseries.csv")


def test_an_exception_in_the_callback_stops_the_run_cleanly(tmp_path):
    class Oops(Exception):
        pass

    def fail(p):
        if p.time > 0.3:
            raise Oops("from the callback")

    with pytest.raises(Oops, match="from the callback"):
        sloshsph.run(small_case(), out=tmp_path / "r", threads=1, progress=fail)
    run = sloshsph.read_run(tmp_path / "r")
    assert run.status == "interrupted" and os.path.isfile(tmp_path / "r" / "checkpoint.bin")
    assert sloshsph.resume(tmp_path / "r", threads=1, progress=False).status == "completed"


def test_the_engine_releases_the_gil(tmp_path):
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.01)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        sloshsph.run(small_case(), out=tmp_path / "r", threads=1, progress=False)
    finally:
        done.set()
        counter.join()
    assert len(ticks) > 20  # the run takes about 2 s: about 200 ticks when the lock is free


def test_runs_in_two_threads_at_once(tmp_path):
    errors = []

    def one(name):
        try:
            sloshsph.run(small_case(), out=tmp_path / name, threads=1, progress=False)
        except Exception as e:  # noqa: BLE001
            errors.append(e)

    threads = [threading.Thread(target=one, args=(n,)) for n in ("a", "b")]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert read(tmp_path / "a" / "timeseries.csv") == read(tmp_path / "b" / "timeseries.csv")


def test_failed_run_raises_the_programs_message(tmp_path):
    # The thesis's free surface with the implicit solve runs away while the building case settles
    # (tests/cli: cli.settle_blows_up): exit 3 from the program, RunFailed here, same message.
    path = os.path.join(CASES, "building_sf_10mg.toml")
    sets = {"scheme.free_surface": "thesis", "time.end": 1.0}
    code, _, err = cli("run", path, *[a for k, v in sets.items() for a in ("--set", f"{k}={sloshsph._toml.value(v)}")],
                       "--threads", 1, "--quiet", "--out", tmp_path / "cli")
    assert code == 3
    case = sloshsph.Case.from_file(path)
    for k, v in sets.items():
        case.set(k, v)
    with pytest.raises(sloshsph.RunFailed) as info:
        sloshsph.run(case, out=tmp_path / "py", threads=1, progress=False)
    expected = [line for line in err.splitlines() if line.startswith("sloshsph: run failed: ")][0]
    assert "sloshsph: " + str(info.value) == expected
    assert "while the fluid settled" in str(info.value)
