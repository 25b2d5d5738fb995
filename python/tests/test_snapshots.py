"""Reading a run directory the program made: the snapshot arrays are the VTU files' (issue 32, 3)."""

import os
import re
import struct

import numpy as np
import pytest
import sloshsph
from conftest import CASES, cli

SETS = ["--set", "particles.dp=0.01", "--set", "time.end=0.5", "--set", "output.snapshot_interval=0.25",
        "--threads", "1", "--quiet"]


def raw_arrays(path):
    """The VTU's arrays by a parse of its own (regular expressions and struct, not sloshsph.vtu):
    each DataArray's name, type, components and offset from the header, the values from the
    appended block (UInt64 byte count, then little-endian values)."""
    data = open(path, "rb").read()
    start = data.index(b'<AppendedData encoding="raw">')
    block = data.index(b"_", start) + 1
    formats = {"Float32": "f", "Int32": "i", "Int64": "q", "UInt8": "B"}
    arrays = {}
    for m in re.finditer(rb'<DataArray type="(\w+)"(?: Name="(\w+)")?(?: NumberOfComponents="(\d)")? '
                         rb'format="appended" offset="(\d+)"/>', data[:start]):
        kind, name, comps, offset = m.group(1).decode(), (m.group(2) or b"points").decode(), int(m.group(3) or 1), \
            int(m.group(4))
        (size,) = struct.unpack_from("<Q", data, block + offset)
        count = size // struct.calcsize(formats[kind])
        values = struct.unpack_from(f"<{count}{formats[kind]}", data, block + offset + 8)
        arrays[name] = np.array(values).reshape(-1, comps) if comps > 1 else np.array(values)
    return arrays


@pytest.fixture(scope="module")
def cli_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("snap") / "hydrostatic"
    code, _, err = cli("run", os.path.join(CASES, "hydrostatic.toml"), *SETS, "--out", out)
    assert code == 0, err
    return sloshsph.read_run(out)


def test_snapshot_list(cli_run):
    times = [t for t, _ in cli_run.snapshots]
    assert times == pytest.approx([0.0, 0.25, 0.5])
    assert all(os.path.isfile(p) for _, p in cli_run.snapshots)


def test_snapshot_arrays_match_the_file(cli_run):
    for k, (t, path) in enumerate(cli_run.snapshots):
        mine, raw = cli_run.snapshot(k), raw_arrays(path)
        assert mine["time"] == t
        np.testing.assert_array_equal(mine["points"], raw["points"])
        np.testing.assert_array_equal(mine["velocity"], raw["velocity"])
        for name in ("pressure", "density", "kind", "id"):
            np.testing.assert_array_equal(mine[name], raw[name])
        np.testing.assert_array_equal(mine["x"], raw["points"][:, 0])
        np.testing.assert_array_equal(mine["vy"], raw["velocity"][:, 1])


def test_snapshot_is_the_hydrostatic_tank(cli_run):
    snap = cli_run.snapshot(-1)
    fluid = snap["kind"] == 0
    assert fluid.sum() == cli_run.summary["fluid_particles"]
    assert len(np.unique(snap["id"])) == len(snap["id"])
    x, y = snap["x"][fluid], snap["y"][fluid]
    assert x.min() > 0.0 and x.max() < 0.5 and y.min() > 0.0 and y.max() < 0.26
    # Hydrostatics (thesis 2.6.1): below the surface layers, p = rho g (H - y) within 5% of
    # rho g H (H = 0.25 m); 0.5 s after the settle the tank is at rest.
    deep = fluid & (snap["y"] < 0.25 - 0.03)
    p_theory = 1000.0 * 9.81 * (0.25 - snap["y"][deep])
    assert np.max(np.abs(snap["pressure"][deep] - p_theory)) < 0.05 * 1000.0 * 9.81 * 0.25
