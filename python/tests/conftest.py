"""Fixtures of the Python module's tests (run by ctest: python/tests/CMakeLists.txt sets the paths)."""

import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("SLOSHSPH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
PROGRAM = os.environ.get("SLOSHSPH_PROGRAM", os.path.join(SOURCE_DIR, "build", "app", "sloshsph"))
CASES = os.path.join(SOURCE_DIR, "cases")

# A short, coarse run of the Liu & Lin tank at resonance: about 2 s of wall time on one core.
SMALL = {"time.end": 1.0, "particles.dp": 0.01}


def cli(*args, cwd=None):
    """Runs the sloshsph program; returns (exit code, stdout, stderr)."""
    p = subprocess.run([PROGRAM, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


def cli_error(stderr):
    """The message of the program's `sloshsph: error: MESSAGE` line."""
    for line in stderr.splitlines():
        if line.startswith("sloshsph: error: "):
            return line[len("sloshsph: error: "):]
    raise AssertionError(f"no error line in: {stderr!r}")


def small_case(**extra):
    import sloshsph

    case = sloshsph.Case.from_file(os.path.join(CASES, "liu_lin_2008.toml"))
    for key, value in {**SMALL, **extra}.items():
        case.set(key, value)
    return case


def small_sets(**extra):
    """The same overrides as --set options of the program."""
    import sloshsph._toml as t

    out = []
    for key, value in {**SMALL, **extra}.items():
        out += ["--set", f"{key}={t.value(value)}"]
    return out


@pytest.fixture
def cases():
    return CASES
