"""Particle snapshots: the VTU files a run writes (particles/particles_NNNNNN.vtu, listed in
particles.pvd), read into NumPy arrays without VTK."""

import os
import xml.etree.ElementTree as ET

import numpy as np

_TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32, "Int64": np.int64,
          "UInt8": np.uint8, "UInt64": np.uint64}


def read_vtu(path):
    """One snapshot as a dict of arrays, one entry per particle:

    ``x``, ``y`` (m), ``vx``, ``vy`` (m/s), ``pressure`` (Pa), ``density`` (kg/m^3), ``kind``
    (0 fluid, 1 wall), ``id``; and ``points`` (n x 3) and ``velocity`` (n x 3) as written. The
    values are those of the file (float32, as ParaView reads them).
    """
    path = os.fspath(path)
    with open(path, "rb") as f:
        data = f.read()
    marker = data.find(b'<AppendedData encoding="raw">')
    if marker < 0:
        raise ValueError(f"{path}: not a VTU file with raw appended data (as sloshsph writes)")
    start = data.index(b"_", marker) + 1  # the appended block starts after the underscore
    header = data[:marker].decode("utf-8") + "</VTKFile>"
    root = ET.fromstring(header)
    piece = root.find("./UnstructuredGrid/Piece")
    n = int(piece.get("NumberOfPoints"))
    arrays = {}
    for node in piece.iter("DataArray"):
        name = node.get("Name") or "points"
        dtype = np.dtype(_TYPES[node.get("type")]).newbyteorder("<")
        offset = start + int(node.get("offset"))
        size = int(np.frombuffer(data, dtype="<u8", count=1, offset=offset)[0])
        values = np.frombuffer(data, dtype=dtype, count=size // dtype.itemsize, offset=offset + 8)
        components = int(node.get("NumberOfComponents", "1"))
        arrays[name] = values.reshape(-1, components) if components > 1 else values
    out = {
        "x": arrays["points"][:, 0],
        "y": arrays["points"][:, 1],
        "vx": arrays["velocity"][:, 0],
        "vy": arrays["velocity"][:, 1],
        "pressure": arrays["pressure"],
        "density": arrays["density"],
        "kind": arrays["kind"],
        "id": arrays["id"],
        "points": arrays["points"],
        "velocity": arrays["velocity"],
    }
    if len(out["x"]) != n:
        raise ValueError(f"{path}: {len(out['x'])} points, the header says {n}")
    return out


def read_pvd(path):
    """The snapshots a particles.pvd lists: [(time, path of the .vtu), ...] in time order."""
    path = os.fspath(path)
    folder = os.path.dirname(path)
    with open(path, "rb") as f:
        text = f.read().decode("utf-8")
    root = ET.fromstring(text)
    entries = [(float(d.get("timestep")), os.path.join(folder, d.get("file"))) for d in root.iter("DataSet")]
    return sorted(entries, key=lambda e: e[0])
