"""Fuzz cases for Exodus II files in netCDF classic form (CDF-1 and CDF-2): headers whose
counts, names, types or dimension ids do not fit, written from the format's grammar. The
netCDF library under VTK takes a header's counts on trust (a mutated variable count crashed
it: SIGSEGV in NC_hashmapadd); datasets/io/netcdf_prescan.cpp walks them first."""
import struct

from fuzz_helpers import check_cases

READER = "exodus"

DIMENSION, VARIABLE, ATTRIBUTE = 0x0A, 0x0B, 0x0C


def header(version=1, dims=None, dim_count=None, var_count=None, var_dim_id=0, attr_type=2, attr_count=None,
           dim_name=None, var_tag=VARIABLE):
    """One dimension "n" of 4, one global text attribute, one int variable "v"(n). Counts,
    lengths, sizes and ids are 32-bit, 64-bit in CDF-5 (version 5); tags are 32-bit."""
    big = ">Q" if version == 5 else ">I"

    def n(value):
        return struct.pack(big, value)

    def name(text, length=None):
        raw = text.encode()
        return n(len(raw) if length is None else length) + raw + b"\0" * ((-len(raw)) % 4)

    h = b"CDF" + bytes([version]) + n(0)
    dims = [("n", 4)] if dims is None else dims
    h += struct.pack(">I", DIMENSION) + n(len(dims) if dim_count is None else dim_count)
    for i, (nm, size) in enumerate(dims):
        h += (name(*dim_name) if dim_name is not None and i == 0 else name(nm)) + n(size)
    text = b"vobench"
    h += struct.pack(">I", ATTRIBUTE) + n(1) + name("title") + struct.pack(">I", attr_type)
    h += n(len(text) if attr_count is None else attr_count) + text + b"\0"
    h += struct.pack(">I", var_tag) + n(1 if var_count is None else var_count) + name("v")
    h += n(1) + n(var_dim_id) + struct.pack(">I", 0) + n(0) + struct.pack(">I", 4) + n(16)
    begin = len(h) + (4 if version == 1 else 8)
    h += struct.pack(">I", begin) if version == 1 else struct.pack(">Q", begin)
    return h + struct.pack(">4i", 1, 2, 3, 4)


def cases(work):
    files = {
        "variables-past-the-file": header(var_count=738197519),
        "variables-past-the-file-cdf2": header(version=2, var_count=738197519),
        "dimensions-past-the-file": header(dim_count=1 << 30),
        "attribute-values-past-the-file": header(attr_count=1 << 29),
        "attribute-type-unknown": header(attr_type=9),
        "variables-past-the-file-cdf5": header(version=5, var_count=1 << 40),
        "name-longer-than-the-file": header(dim_name=("n", 1 << 30)),
        "name-empty": header(dim_name=("", 0)),
        "dimension-id-unknown": header(var_dim_id=7),
        "list-tag-wrong": header(var_tag=DIMENSION),
        "header-cut": header()[:40],
    }
    return check_cases(files, "exo", "mpvo")
