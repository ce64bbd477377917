"""Fuzz cases for the .pvtu reader (VTK's parallel XML reader): a valid cube piece (the .vtu
fuzz module's) named by mutated .pvtu files, and bad pieces behind a valid .pvtu."""
import importlib.util
import pathlib

READER = "pvtu"

_spec = importlib.util.spec_from_file_location("fuzz_cases_vtu_for_pvtu", pathlib.Path(__file__).parent / "vtu.py")
_vtu = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_vtu)


def pvtu(sources=("p0.vtu",), ptype="PUnstructuredGrid", extra=""):
    return ('<?xml version="1.0"?>\n'
            f'<VTKFile type="{ptype}" version="0.1" byte_order="LittleEndian">\n'
            '<PUnstructuredGrid GhostLevel="0">\n<PPointData Scalars="s">\n'
            '<PDataArray type="Float64" Name="s"/>\n</PPointData>\n'
            '<PPoints>\n<PDataArray type="Float64" NumberOfComponents="3"/>\n</PPoints>\n' + extra +
            "".join(f'<Piece Source="{s}"/>\n' for s in sources) +
            "</PUnstructuredGrid>\n</VTKFile>\n").encode()


def case(name, files, names="m.pvtu"):
    return {"name": name, "files": files,
            "argv": ["check", "--algorithm", "mpvo", "--input", "{dir}/m.pvtu", "--views", "2", "--size", "32x32"],
            "names": names}


def cases(work):
    good_piece = _vtu.vtu()
    good = pvtu()
    out = [case(f"trunc-{n}", {"m.pvtu": good[:n], "p0.vtu": good_piece}) for n in (0, 30, 120, len(good) - 20)]
    out += [
        case("no-pieces", {"m.pvtu": pvtu(sources=()), "p0.vtu": good_piece}),
        case("missing-piece", {"m.pvtu": pvtu(sources=("p0.vtu", "p1.vtu")), "p0.vtu": good_piece}, "p1.vtu"),
        case("wrong-type", {"m.pvtu": pvtu(ptype="UnstructuredGrid"), "p0.vtu": good_piece}),
        case("piece-is-pvtu", {"m.pvtu": pvtu(sources=("m.pvtu",))}),
        case("piece-truncated", {"m.pvtu": pvtu(), "p0.vtu": good_piece[:200]}, "p0.vtu"),
        case("piece-inverted", {"m.pvtu": pvtu(), "p0.vtu": _vtu.vtu(conn="0 3 2 1 4 7 6 5")}),
        case("piece-nan", {"m.pvtu": pvtu(), "p0.vtu": _vtu.vtu(points=_vtu.moved(6, ("nan", 1, 1)))}),
        case("garbage", {"m.pvtu": bytes((i * 67 + 1) % 256 for i in range(1200))}),
    ]
    return out
