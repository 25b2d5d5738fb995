"""Reader for the VTU snapshots sloshsph writes (appended raw binary, UInt64 headers)."""
import re
import numpy as np

_TYPES = {"Float32": np.float32, "Float64": np.float64, "UInt8": np.uint8, "Int32": np.int32, "Int64": np.int64}


def read_vtu(path):
    """Returns a dict: 'points' (N x 3) and each point-data array by name."""
    raw = open(path, "rb").read()
    head, _, rest = raw.partition(b"<AppendedData encoding=\"raw\">")
    data = rest[rest.index(b"_") + 1:]
    out = {}
    for m in re.finditer(rb"<DataArray ([^>]*)/>", head):
        attrs = dict(re.findall(rb'(\w+)="([^"]*)"', m.group(1)))
        name = attrs.get(b"Name", b"points").decode()
        dtype = _TYPES[attrs[b"type"].decode()]
        off = int(attrs[b"offset"])
        nbytes = int(np.frombuffer(data[off:off + 8], dtype=np.uint64)[0])
        arr = np.frombuffer(data[off + 8:off + 8 + nbytes], dtype=dtype)
        ncomp = int(attrs.get(b"NumberOfComponents", b"1"))
        out[name] = arr.reshape(-1, ncomp) if ncomp > 1 else arr
    return out
