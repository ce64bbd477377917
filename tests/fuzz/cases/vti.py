"""Fuzz cases for the .vti reader: mutations of one valid ASCII image (2x2x2 points with
point scalars)."""

from fuzz_helpers import check_cases

READER = "vti"


def vti(whole="0 1 0 1 0 1", extent=None, origin="0 0 0", spacing="1 1 1", values="1 2 3 4 5 6 7 8",
        vtype="Float32", ncomp="1", inner="", extra=""):
    extent = whole if extent is None else extent
    return ('<?xml version="1.0"?>\n'
            '<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">\n'
            f'<ImageData WholeExtent="{whole}" Origin="{origin}" Spacing="{spacing}"{extra}>\n'
            f'<Piece Extent="{extent}">\n<PointData Scalars="v">\n'
            f'<DataArray type="{vtype}" Name="v" NumberOfComponents="{ncomp}" format="ascii">{values}</DataArray>\n'
            f"</PointData>\n{inner}</Piece>\n</ImageData>\n</VTKFile>\n").encode()


def cases(work):
    good = vti()
    files = {f"trunc-{int(f * 100)}": good[: int(len(good) * f)] for f in (0.1, 0.3, 0.5, 0.7, 0.9)}
    files.update({
        "nan-origin": vti(origin="nan 0 0"),
        "text-origin": vti(origin="0 zero 0"),
        "short-origin": vti(origin="0 0"),
        "inf-spacing": vti(spacing="1 inf 1"),
        "text-spacing": vti(spacing="1 1 one"),
        "zero-spacing": vti(spacing="0 1 1"),
        "negative-spacing": vti(spacing="1 -1 1"),
        "tiny-spacing": vti(spacing="1e-200 1e-200 1e-200"),
        "huge-origin": vti(origin="1e300 0 0"),
        "nan-direction": vti(extra=' Direction="1 0 0 0 nan 0 0 0 1"'),
        "huge-extent": vti(whole="0 99999 0 99999 0 99999"),
        "reversed-extent": vti(whole="1 0 0 1 0 1"),
        "short-extent": vti(whole="0 1 0 1"),
        "text-extent": vti(whole="0 1x 0 1 0 1"),
        "piece-outside-extent": vti(extent="0 5 0 1 0 1"),
        "short-values": vti(values="1 2 3"),
        # VTK read both silently: values past the extent's points ignored, the Piece's extent
        # placed in the whole one.
        "long-values": vti(values="1 2 3 4 5 6 7 8 9 10"),
        "piece-extent-not-whole": vti(extent="0 1 0 1 0 2", values="1 2 3 4 5 6 7 8 9 10 11 12"),
        "nan-value": vti(values="1 2 nan 4 5 6 7 8"),
        "text-value": vti(values="1 2 three 4 5 6 7 8"),
        "no-data": vti().replace(b'<PointData Scalars="v">', b"<!--").replace(b"</PointData>", b"-->"),
        "deep-nesting": vti(inner="<b>" * 50000 + "</b>" * 50000),
        "control-bytes": vti(vtype="Float\x00\x01\x02"),
        "long-token": vti(origin="0 0 " + "9" * 3000),
        # Read as given, these were a mirrored image drawn unmirrored, the first component of
        # a vector, and no voxel at all (a NaN threshold, or none above it) passing every check.
        "mirrored-direction": vti(extra=' Direction="-1 0 0 0 1 0 0 0 1"'),
        "rotated-direction": vti(extra=' Direction="0 1 0 -1 0 0 0 0 1"'),
        "two-components": vti(ncomp="2", values="1 2 3 4 5 6 7 8 1 2 3 4 5 6 7 8"),
        "nan-threshold": vti().replace(b"<Piece ", b'<FieldData><DataArray type="Float32" Name="vobench_threshold" '
                                                    b'NumberOfTuples="1" format="ascii">nan</DataArray></FieldData>\n<Piece '),
        "all-below-threshold": vti(values="-1 -2 -3 -4 0 0 0 0"),
        "float-overflow": vti(vtype="Float64", values="1 2 1e300 4 5 6 7 8"),
        "garbage": bytes((i * 53 + 3) % 256 for i in range(2000)),
        "empty": b"",
    })
    return check_cases(files, "vti", "distance-sort")
