"""Every error the program reports with exit 2 raises sloshsph.CaseError with the same message
(issue 32, 3), and nothing is written."""

import glob
import os

import pytest
import sloshsph
from conftest import CASES, SOURCE_DIR, cli, cli_error, small_case, small_sets

BAD = sorted(glob.glob(os.path.join(SOURCE_DIR, "tests", "cli", "bad_cases", "*.toml")))


def python_error(call):
    with pytest.raises(sloshsph.CaseError) as info:
        call()
    return str(info.value)


def test_the_corpus_is_there():
    assert len(BAD) >= 80  # tests/cli/bad_cases: 87 files on 2026-12-04


@pytest.mark.parametrize("path", BAD, ids=[os.path.basename(p) for p in BAD])
def test_bad_case_files(path, tmp_path):
    code, _, err = cli("run", path, "--out", tmp_path / "cli")
    assert code == 2, err
    message = python_error(lambda: sloshsph.run(path, out=tmp_path / "py", threads=1, progress=False))
    assert message == cli_error(err)
    assert not (tmp_path / "cli").exists() and not (tmp_path / "py").exists()


def test_unknown_key_by_override(tmp_path):
    path = os.path.join(CASES, "hydrostatic.toml")
    code, _, err = cli("run", path, "--set", "particles.dpx=1", "--out", tmp_path / "cli")
    assert code == 2
    case = sloshsph.Case.from_file(path).set("particles.dpx", 1)
    message = python_error(case.validate)
    assert message == cli_error(err)
    with pytest.raises(sloshsph.CaseError) as info:
        case.validate()
    assert info.value.key == "particles.dpx"
    assert python_error(lambda: sloshsph.run(case, out=tmp_path / "py")) == message


def test_too_fine_dp_by_override(tmp_path):
    path = os.path.join(CASES, "hydrostatic_plate.toml")
    code, _, err = cli("run", path, "--set", "particles.dp=1e-9", "--out", tmp_path / "cli")
    assert code == 2
    case = sloshsph.Case.from_file(path).set("particles.dp", 1e-9)
    assert python_error(lambda: sloshsph.run(case, out=tmp_path / "py")) == cli_error(err)


def test_missing_case_file(tmp_path):
    code, _, err = cli("run", "no-such.toml")
    assert code == 2
    assert python_error(lambda: sloshsph.Case.from_file("no-such.toml")) == cli_error(err)


def test_existing_run_directory_without_force(tmp_path):
    out = tmp_path / "busy"
    out.mkdir()
    (out / "keep.txt").write_text("user data")
    code, _, err = cli("run", os.path.join(CASES, "liu_lin_2008.toml"), *small_sets(), "--out", out)
    assert code == 2
    assert python_error(lambda: sloshsph.run(small_case(), out=out)) == cli_error(err)
    assert (out / "keep.txt").read_text() == "user data"


def test_resume_without_checkpoint(tmp_path):
    out = tmp_path / "done"
    sloshsph.run(small_case(**{"time.end": 0.1}), out=out, threads=1, progress=False)
    code, _, err = cli("resume", out)
    assert code == 2
    assert python_error(lambda: sloshsph.resume(out)) == cli_error(err)
    code, _, err = cli("resume", tmp_path)
    assert code == 2
    assert python_error(lambda: sloshsph.resume(tmp_path)) == cli_error(err)


def test_modes_options_need_a_structure():
    path = os.path.join(CASES, "liu_lin_2008.toml")
    code, _, err = cli("modes", path, "--tank-damping", "0.02")
    assert code == 2
    assert python_error(lambda: sloshsph.modes(path, tank_damping=[0.02])) == cli_error(err)


def test_tune_out_of_reach():
    path = os.path.join(CASES, "liu_lin_2008.toml")
    code, _, err = cli("tune", path, "--target-omega", "50")
    assert code == 2
    assert python_error(lambda: sloshsph.tune(path, 50.0)) == cli_error(err)


def test_bad_sweep_range():
    path = os.path.join(CASES, "liu_lin_2008.toml")
    with pytest.raises(sloshsph.CaseError, match="beta"):
        sloshsph.sweep(path, beta="1:0.5:x", progress=False)


def test_directory_locked_by_a_running_program(tmp_path):
    import subprocess
    import time

    from conftest import PROGRAM

    out = tmp_path / "busy"
    runner = subprocess.Popen([PROGRAM, "run", os.path.join(CASES, "liu_lin_2008.toml"), *small_sets(**{"time.end": 30.0}),
                               "--threads", "1", "--quiet", "--out", str(out)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(600):  # the run directory appears once the fluid has settled
            if (out / "timeseries.csv").exists():
                break
            time.sleep(0.05)
        assert (out / "timeseries.csv").exists()
        code, _, err = cli("run", os.path.join(CASES, "liu_lin_2008.toml"), *small_sets(), "--force", "--out", out)
        assert code == 2
        message = python_error(lambda: sloshsph.run(small_case(), out=out, force=True, progress=False))
        assert message == cli_error(err)
        assert "another process" in message or str(runner.pid) in message
    finally:
        runner.kill()
        runner.wait()


def test_resume_after_case_toml_changed(tmp_path):
    out = tmp_path / "stopped"
    sloshsph.run(small_case(), out=out, threads=1, progress=lambda p: p.time < 0.2)
    with open(out / "case.toml", "a", encoding="utf-8") as f:
        f.write("# edited\n")
    code, _, err = cli("resume", out)
    assert code == 2
    message = python_error(lambda: sloshsph.resume(out))
    assert message == cli_error(err)
    assert "case.toml changed" in message
