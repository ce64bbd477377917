"""Fuzz cases for the .inr (INRIMAGE-4) reader: mutations of one valid 2x2x2 unsigned
8-bit volume."""

import gzip
import struct

from fuzz_helpers import check_cases

READER = "inr"


def inr(fields=None, data=bytes(range(1, 9)), magic="#INRIMAGE-4#{"):
    fields = {"XDIM": "2", "YDIM": "2", "ZDIM": "2", "VDIM": "1", "TYPE": "unsigned fixed",
              "PIXSIZE": "8 bits", "CPU": "decm", "VX": "1", "VY": "1", "VZ": "1"} if fields is None else fields
    head = magic + "\n" + "".join(f"{k}={v}\n" for k, v in fields.items())
    head += "\n" * ((252 - len(head)) % 256) + "##}\n"
    return head.encode("latin-1") + data


def with_field(key, value):
    f = {"XDIM": "2", "YDIM": "2", "ZDIM": "2", "VDIM": "1", "TYPE": "unsigned fixed",
         "PIXSIZE": "8 bits", "CPU": "decm", "VX": "1", "VY": "1", "VZ": "1"}
    if value is None:
        del f[key]
    else:
        f[key] = value
    return inr(f)


def cases(work):
    good = inr()
    files = {f"trunc-{n}": good[:n] for n in (10, 100, 255, 258, 260, 263)}
    files.update({
        "xdim-junk": with_field("XDIM", "4abc"),
        "xdim-zero": with_field("XDIM", "0"),
        "xdim-negative": with_field("XDIM", "-2"),
        "xdim-space": with_field("XDIM", "2 "),
        "xdim-huge": with_field("XDIM", "99999999999999999999"),
        "dims-too-big-for-file": with_field("ZDIM", "100000"),
        "ydim-missing": with_field("YDIM", None),
        "vdim-3": with_field("VDIM", "3"),
        "type-bogus": with_field("TYPE", "complex"),
        "pixsize-odd": with_field("PIXSIZE", "12 bits"),
        "pixsize-junk": with_field("PIXSIZE", "8bits!"),
        "cpu-vax": with_field("CPU", "vax"),
        "vx-nan": with_field("VX", "nan"),
        "vx-zero": with_field("VX", "0"),
        "vx-junk": with_field("VX", "1.5mm"),
        "vx-tiny": with_field("VX", "1e-300"),
        "all-tiny": inr({"XDIM": "2", "YDIM": "2", "ZDIM": "2", "TYPE": "unsigned fixed", "PIXSIZE": "8 bits",
                         "VX": "1e-200", "VY": "1e-200", "VZ": "1e-200"}),
        "vx-huge": with_field("VX", "1e200"),
        "control-bytes": with_field("TYPE", "\x01\x02\x1b[0m"),
        "long-token": with_field("TYPE", "x" * 150),
        "bad-magic": inr(magic="#INRIMAGE-5#{"),
        "float-nan": inr({"XDIM": "2", "YDIM": "1", "ZDIM": "1", "TYPE": "float", "PIXSIZE": "32 bits",
                          "CPU": "decm"}, data=b"\x00\x00\xc0\x7f\x00\x00\x80\x3f"),
        "garbage": bytes((i * 13 + 17) % 256 for i in range(700)),
        "empty": b"",
        # Data the header does not describe (a 2x2x2 header on a longer volume), a key given
        # twice, a volume of no voxel above 0, a double beyond float's range.
        "data-longer-than-dims": inr(data=bytes(range(1, 17))),
        "xdim-twice": inr({"XDIM": "2", "YDIM": "2", "ZDIM": "2", "TYPE": "unsigned fixed", "PIXSIZE": "8 bits"})
        .replace(b"XDIM=2\n", b"XDIM=2\nXDIM=1\n", 1),
        "all-zero": inr(data=bytes(8)),
        "float64-overflow": inr({"XDIM": "2", "YDIM": "1", "ZDIM": "1", "TYPE": "float", "PIXSIZE": "64 bits"},
                                data=struct.pack("<2d", 1.0, 1e300)),
    })
    out = check_cases(files, "inr", "distance-sort")
    # .inr.gz: inflated only as far as the header promises; more is refused, not held.
    gz = {"gz-data-longer-than-dims": gzip.compress(inr(data=bytes(range(1, 9)) + bytes(1 << 20))),
          "gz-all-zero": gzip.compress(inr(data=bytes(8))),
          # zlib's gzread ignored bytes after the last member: the file read as good.
          "gz-trailing-junk": gzip.compress(inr()) + b"garbage!",
          "gz-trailing-zeros": gzip.compress(inr()) + bytes(512)}
    out += check_cases(gz, "inr.gz", "distance-sort")
    for c in out[-2:]:
        c["names"] += ": gzip member 1: ends at byte"
    return out
