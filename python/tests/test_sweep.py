"""Sweeps from Python: the program's sweep directory and table, in parallel processes (issue 32, 1)."""

import os

import numpy as np
import pytest
import sloshsph
from conftest import CASES, cli, small_case

FIXED = {"time.end": 2.0}
BETAS = [0.9, 1.1]
AMPLITUDES = [0.005, 0.0075]


@pytest.fixture(scope="module")
def sweeps(tmp_path_factory):
    root = tmp_path_factory.mktemp("sweep")
    code, _, err = cli("sweep", os.path.join(CASES, "liu_lin_2008.toml"), "--beta", "0.9,1.1", "--jobs", 2,
                       "--threads", 1, "--quiet", "--out", root / "cli", "--set", "particles.dp=0.01",
                       "--set", "time.end=2.0", "--set", "excitation.amplitude=0.005,0.0075")
    assert code == 0, err
    py = sloshsph.sweep(small_case(**FIXED), beta=BETAS, sets={"excitation.amplitude": AMPLITUDES}, jobs=2,
                        threads=1, out=root / "py", progress=False)
    return root, py


def test_same_table_as_the_program(sweeps):
    root, py = sweeps
    cli_table = sloshsph.read_frequency_response(root / "cli" / "frequency_response.csv")
    assert list(py.table) == list(cli_table)
    assert "set:excitation.amplitude" in py.table
    for name, column in cli_table.items():
        if name in ("wall_time_s", "run_dir"):
            continue
        np.testing.assert_array_equal(py.table[name], column, err_msg=name)
    assert list(py.table["status"]) == ["completed"] * 4
    np.testing.assert_allclose(py.table["beta"], [0.9, 0.9, 1.1, 1.1])
    assert not py.failed
    for run in py.points:
        assert run.status == "completed"
        assert os.path.isfile(run.path + ".log")
        cli_dir = root / "cli" / os.path.basename(run.path)
        with open(cli_dir / "timeseries.csv", "rb") as a, open(os.path.join(run.path, "timeseries.csv"), "rb") as b:
            assert a.read() == b.read()


def test_again_skips_finished_points(sweeps):
    root, py = sweeps
    stamps = [os.path.getmtime(os.path.join(r.path, "summary.json")) for r in py.points]
    again = sloshsph.sweep(small_case(**FIXED), beta=BETAS, sets={"excitation.amplitude": AMPLITUDES}, jobs=2,
                           threads=1, out=root / "py", progress=False)
    assert [os.path.getmtime(os.path.join(r.path, "summary.json")) for r in again.points] == stamps
    np.testing.assert_array_equal(again.table["eta_max"], py.table["eta_max"])


def test_other_settings_in_the_same_directory_are_refused(sweeps):
    root, _ = sweeps
    with pytest.raises(sloshsph.CaseError, match="different case or --set values"):
        sloshsph.sweep(small_case(**{"time.end": 2.5}), beta=BETAS, sets={"excitation.amplitude": AMPLITUDES},
                       out=root / "py", progress=False)
