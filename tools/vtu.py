"""Reader for the VTU snapshots sloshsph writes, and for the particles.pvd index.

sloshsph writes VTK XML UnstructuredGrid files with the arrays in appended raw binary and UInt64
block headers (docs: README "What a run writes"). This reader also accepts UInt32 headers, either
byte order, and inline `ascii` or uncompressed base64 `binary` arrays, so files re-saved by
ParaView can be read too. Compressed files are refused with a clear message.

Only the standard library and numpy are used.
"""
import base64
import os
import re

import numpy as np

_TYPES = {
    "Int8": np.int8, "UInt8": np.uint8, "Int16": np.int16, "UInt16": np.uint16,
    "Int32": np.int32, "UInt32": np.uint32, "Int64": np.int64, "UInt64": np.uint64,
    "Float32": np.float32, "Float64": np.float64,
}

_ATTR = re.compile(rb'([\w:]+)\s*=\s*"([^"]*)"')
# A DataArray either self-closes (appended) or holds its data inline.
_ARRAY = re.compile(rb"<DataArray\b([^>]*?)(/>|>(.*?)</DataArray\s*>)", re.S)


def _attrs(text):
    return {k.decode(): v.decode() for k, v in _ATTR.findall(text)}


def _array_name(attrs, section):
    if "Name" in attrs:
        return attrs["Name"]
    return "points" if section == "Points" else "unnamed"


def _section_of(head, pos):
    """The enclosing section (PointData, Points, Cells, CellData, FieldData) of byte offset pos."""
    best, best_at = "", -1
    for tag in (b"PointData", b"CellData", b"Points", b"Cells", b"FieldData"):
        at = head.rfind(b"<" + tag, 0, pos)
        if at > best_at and head.find(b"</" + tag, at, pos) < 0:
            best, best_at = tag.decode(), at
    return best


def read_vtu(path, skip_cells=False):
    """Reads a VTU file.

    Returns a dict: 'points' (N x 3) and each point-data array by name (N or N x components).
    With skip_cells the cell arrays (connectivity, offsets, types) are not read (faster).
    Raises ValueError with the file name on a file that is truncated, compressed or not VTU.
    """
    with open(path, "rb") as fh:
        raw = fh.read()
    marker = re.search(rb"<AppendedData\b([^>]*)>", raw)
    head = raw[:marker.start()] if marker else raw
    root = re.search(rb"<VTKFile\b([^>]*)>", head)
    if not root:
        raise ValueError(f"{path}: not a VTK XML file")
    vtk = _attrs(root.group(1))
    if vtk.get("type", "UnstructuredGrid") != "UnstructuredGrid":
        raise ValueError(f"{path}: VTK type {vtk.get('type')!r}, expected UnstructuredGrid")
    if "compressor" in vtk:
        raise ValueError(f"{path}: compressed VTU ({vtk['compressor']}) is not supported")
    order = "<" if vtk.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
    header = np.dtype(order + ("u8" if vtk.get("header_type", "UInt32") == "UInt64" else "u4"))

    appended = b""
    if marker:
        enc = _attrs(marker.group(1)).get("encoding", "raw")
        if enc != "raw":
            raise ValueError(f"{path}: appended encoding {enc!r} is not supported (only raw)")
        rest = raw[marker.end():]
        underscore = rest.find(b"_")
        if underscore < 0:
            raise ValueError(f"{path}: AppendedData without the '_' marker (truncated file?)")
        appended = rest[underscore + 1:]

    out = {}
    for m in _ARRAY.finditer(head):
        attrs = _attrs(m.group(1))
        section = _section_of(head, m.start())
        if skip_cells and section == "Cells":
            continue
        name = _array_name(attrs, section)
        type_name = attrs.get("type", "")
        if type_name not in _TYPES:
            raise ValueError(f"{path}: array {name!r} has unsupported type {type_name!r}")
        dtype = np.dtype(_TYPES[type_name]).newbyteorder(order)
        fmt = attrs.get("format", "appended")
        if fmt == "appended":
            off = int(attrs.get("offset", "0"))
            if off + header.itemsize > len(appended):
                raise ValueError(f"{path}: array {name!r} lies beyond the end of the file (truncated?)")
            nbytes = int(np.frombuffer(appended, dtype=header, count=1, offset=off)[0])
            start = off + header.itemsize
            if start + nbytes > len(appended):
                raise ValueError(f"{path}: array {name!r} is cut short (truncated file?)")
            arr = np.frombuffer(appended, dtype=dtype, count=nbytes // dtype.itemsize, offset=start)
        elif fmt == "ascii":
            arr = np.array((m.group(3) or b"").split(), dtype=dtype.newbyteorder("="))
        elif fmt == "binary":
            blob = base64.b64decode(b"".join((m.group(3) or b"").split()))
            nbytes = int(np.frombuffer(blob, dtype=header, count=1)[0])
            arr = np.frombuffer(blob, dtype=dtype, count=nbytes // dtype.itemsize, offset=header.itemsize)
        else:
            raise ValueError(f"{path}: array {name!r} has unsupported format {fmt!r}")
        arr = arr.astype(arr.dtype.newbyteorder("="), copy=False)
        ncomp = int(attrs.get("NumberOfComponents", "1"))
        if ncomp > 1:
            if arr.size % ncomp:
                raise ValueError(f"{path}: array {name!r} size {arr.size} is not a multiple of {ncomp}")
            arr = arr.reshape(-1, ncomp)
        out[name] = arr
    if "points" not in out:
        raise ValueError(f"{path}: no Points array")
    return out


def read_pvd(path):
    """Reads a ParaView collection (.pvd): a list of (time, absolute file path), in file order.

    Entries without a timestep get time NaN. Paths are resolved against the .pvd's folder.
    """
    with open(path, "rb") as fh:
        text = fh.read()
    base = os.path.dirname(os.path.abspath(path))
    out = []
    for m in re.finditer(rb"<DataSet\b([^>]*)/?>", text):
        attrs = _attrs(m.group(1))
        if "file" not in attrs:
            continue
        try:
            t = float(attrs.get("timestep", "nan"))
        except ValueError:
            t = float("nan")
        out.append((t, os.path.join(base, attrs["file"])))
    return out
