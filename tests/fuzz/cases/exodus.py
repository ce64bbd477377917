"""Fuzz cases for Exodus II files in netCDF classic form (CDF-1 and CDF-2): headers whose
counts, names, types or dimension ids do not fit, written from the format's grammar. The
netCDF library under VTK takes a header's counts on trust (a mutated variable count crashed
it: SIGSEGV in NC_hashmapadd); datasets/io/netcdf_prescan.cpp walks them first.
And well-formed netCDF files whose Exodus content does not hold: an element block (not the
first) whose type attribute or count dimension has another name made VTK's reader crash
(SIGSEGV in GetSortedObjectInfo); datasets/io/exodus_reader.cpp asks the Exodus library for
every block's parameters first."""
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


NC_CHAR, NC_INT, NC_FLOAT, NC_DOUBLE = 2, 4, 5, 6
SIZE = {NC_CHAR: 1, NC_INT: 4, NC_FLOAT: 4, NC_DOUBLE: 8}


def exodus_file(bad=0, attr="elem_type", count=None, numrecs=0):
    """Three tetrahedra around an edge in three element blocks, an Exodus II file in
    netCDF classic form (CDF-1); block `bad` (1-based, 0: none) gets the type attribute
    named `attr` and, if given, the count dimension named `count`; `numrecs` records (time
    steps) are declared, none written."""
    def pad(b):
        return b + b"\0" * ((-len(b)) % 4)

    def name(text):
        return struct.pack(">I", len(text)) + pad(text.encode())

    def raw(typ, vals):
        if typ == NC_CHAR:
            return vals if isinstance(vals, bytes) else vals.encode()
        return b"".join(struct.pack({NC_INT: ">i", NC_FLOAT: ">f", NC_DOUBLE: ">d"}[typ], v) for v in vals)

    def attrs(items):
        if not items:
            return b"\0" * 8
        out = struct.pack(">II", ATTRIBUTE, len(items))
        for n, typ, vals in items:
            r = raw(typ, vals)
            out += name(n) + struct.pack(">II", typ, len(r) // SIZE[typ]) + pad(r)
        return out

    blocks = [1, 2, 3]
    counts = {k: (count if k == bad and count else f"num_el_in_blk{k}") for k in blocks}
    dims = [("len_string", 33), ("len_name", 33), ("four", 4), ("num_dim", 3), ("num_nodes", 6),
            ("num_elem", 3), ("num_el_blk", 3)]
    for k in blocks:
        dims += [(counts[k], 1), (f"num_nod_per_el{k}", 4)]
    dims.append(("time_step", 0))  # the record dimension
    dim_id = {n: i for i, (n, _) in enumerate(dims)}
    xyz = [(0.0, 0.0, 1.0, 0.0, -1.0, 0.5), (0.0, 0.0, 0.0, 1.0, 0.5, -1.0), (0.0, 1.0, 0.0, 0.0, 0.0, 0.0)]
    variables = [("eb_status", ["num_el_blk"], [], NC_INT, [1, 1, 1]),
                 ("eb_prop1", ["num_el_blk"], [("name", NC_CHAR, "ID")], NC_INT, blocks),
                 ("coordx", ["num_nodes"], [], NC_DOUBLE, xyz[0]),
                 ("coordy", ["num_nodes"], [], NC_DOUBLE, xyz[1]),
                 ("coordz", ["num_nodes"], [], NC_DOUBLE, xyz[2]),
                 ("coor_names", ["num_dim", "len_name"], [], NC_CHAR,
                  b"".join(c.encode().ljust(33, b"\0") for c in "xyz"))]
    connect = {1: [1, 2, 3, 4], 2: [1, 2, 4, 5], 3: [1, 2, 5, 6]}
    for k in blocks:
        variables.append((f"connect{k}", [counts[k], f"num_nod_per_el{k}"],
                          [(attr if k == bad else "elem_type", NC_CHAR, "TETRA")], NC_INT, connect[k]))
    variables.append(("time_whole", ["time_step"], [], NC_DOUBLE, []))  # no records
    global_attrs = [("api_version", NC_FLOAT, [8.11]), ("version", NC_FLOAT, [8.11]),
                    ("floating_point_word_size", NC_INT, [8]), ("file_size", NC_INT, [1]),
                    ("maximum_name_length", NC_INT, [32]), ("title", NC_CHAR, "vobench")]

    def header(begins):
        h = b"CDF\x01" + struct.pack(">I", numrecs)
        h += struct.pack(">II", DIMENSION, len(dims)) + b"".join(name(n) + struct.pack(">I", k) for n, k in dims)
        h += attrs(global_attrs) + struct.pack(">II", VARIABLE, len(variables))
        for (n, ds, va, typ, vals), begin in zip(variables, begins):
            h += name(n) + struct.pack(">I", len(ds)) + b"".join(struct.pack(">I", dim_id[d]) for d in ds)
            size = SIZE[typ] if ds == ["time_step"] else len(pad(raw(typ, vals)))
            h += attrs(va) + struct.pack(">III", typ, size, begin)
        return h

    begins, at = [], len(header([0] * len(variables)))
    for _, _, _, typ, vals in variables:
        begins.append(at)
        at += len(pad(raw(typ, vals)))
    return header(begins) + b"".join(pad(raw(typ, vals)) for _, _, _, typ, vals in variables)


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
        "block-type-attribute-renamed": exodus_file(bad=2, attr="elem_typf"),
        "block-count-dimension-renamed": exodus_file(bad=3, count="num_el_rn_blk3"),
        "first-block-count-dimension-renamed": exodus_file(bad=1, count="num_el_rn_blk1"),
        "record-count-past-the-file": exodus_file(numrecs=0x7FFFFFF0),
    }
    # Cut inside its fixed-size variables (coordinates, connectivity, names): libnetcdf read
    # the missing bytes as fill values and the mesh or its variable names changed silently.
    whole = exodus_file()
    for cut in (4, 16, 64):
        files[f"cut-{cut}-bytes-short"] = whole[:-cut]
    out = check_cases(files, "exo", "mpvo")
    # Cut inside its last record (a time step declared, its value missing or half there):
    # libnetcdf read the missing bytes as zeros, silently. A closed file holds its records
    # whole; at most 3 bytes of padding may be missing.
    records = {"record-missing": exodus_file(numrecs=1), "record-half-written": exodus_file(numrecs=1) + bytes(4)}
    for c in check_cases(records, "exo", "mpvo"):
        c["names"] += ": record 0: the last of 1 records of 8 bytes ends at byte"
        out.append(c)
    return out
