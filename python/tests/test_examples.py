"""The example scripts run, shortened (issue 32, 2 and 3)."""

import os
import subprocess
import sys

import pytest
from conftest import SOURCE_DIR

EXAMPLES = os.path.join(SOURCE_DIR, "examples", "python")


@pytest.mark.parametrize("script, picture", [("resonance.py", "resonance.png"),
                                             ("screen_solidity.py", "screen_solidity.png"),
                                             ("building_admittance.py", "admittance.png")])
def test_example_runs(script, picture, tmp_path):
    out = tmp_path / "out"
    p = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), "--quick", "--out", str(out)],
                       capture_output=True, text=True, env=os.environ, timeout=600)
    assert p.returncode == 0, p.stderr[-2000:]
    assert (out / picture).stat().st_size > 10000
    assert f"wrote {out / picture}" in p.stdout
