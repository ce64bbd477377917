"""The cells of a .vtu as vobench writes it (VTK XML, appended binary, zlib blocks or raw),
read with the standard library and numpy only: for sorters without VTK's Python module."""
import re
import zlib

import numpy as np

TYPES = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4", "UInt8": "u1"}


def read_vtu(path):
    """-> points (n, 3) float64, connectivity, offsets (end of each cell's ids), VTK cell types."""
    data = open(path, "rb").read()
    head, _, blob = data.partition(b'<AppendedData encoding="raw">')
    blob = blob[blob.index(b"_") + 1:]
    word = np.dtype("<u8" if b'header_type="UInt64"' in head else "<u4")
    compressed = b"compressor=" in head
    arrays = {}
    for tag in re.findall(rb"<DataArray[^>]*>", head):
        attr = {k.decode(): v.decode() for k, v in re.findall(rb'(\w+)="([^"]*)"', tag)}
        start = int(attr["offset"])
        if compressed:  # [blocks, block size, last block size, compressed sizes...] + blocks
            blocks = int(np.frombuffer(blob, word, 1, start)[0])
            sizes = np.frombuffer(blob, word, blocks, start + 3 * word.itemsize)
            pos, raw = start + (3 + blocks) * word.itemsize, b""
            for s in sizes:
                raw += zlib.decompress(blob[pos:pos + int(s)])
                pos += int(s)
        else:  # [byte count] + bytes
            n = int(np.frombuffer(blob, word, 1, start)[0])
            raw = blob[start + word.itemsize:start + word.itemsize + n]
        arrays[attr["Name"]] = np.frombuffer(raw, TYPES[attr["type"]])
    return arrays["Points"].reshape(-1, 3), arrays["connectivity"], arrays["offsets"], arrays["types"]
