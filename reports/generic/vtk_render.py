"""What VTK shows: the runs of `vobench-vtk render` (vtk/render) found beside the results, in
`vtk/NAME/render.json` under the report's folder or a results file's folder, as one table per
run (per sorter: views and pixels differing from the first exact orderer's image in VTK's
projected-tetrahedra mapper, frame time over VTK's own sort) with the view where VTK's sort
differs most, and a link to the run's render.html. A suite whose vtk_render entry was not run,
was interrupted or failed (vtk/status-SUITE.json) is named with the reason, never left out."""
import glob
import json
import os


def find(out, results, pattern):
    dirs = [out] + [p if os.path.isdir(p) else os.path.dirname(os.path.abspath(p)) for p in results]
    found = []
    for d in dirs:
        for p in sorted(glob.glob(os.path.join(d, "vtk", pattern))):
            if os.path.abspath(p) not in [os.path.abspath(f) for f in found]:
                found.append(p)
    return found


# vobench run / reproduce record how a suite's vtk_render entry went (harness/cli/vtk_render_child.h).
STATE_TEXT = {"not run": "not run", "interrupted": "interrupted", "failed": "failed",
              "running": "not finished (still running, or its run was killed)"}


def scene_name(scene):
    """The records' way of naming a scene: name(key=value,...), or an input file's name."""
    if "input" in scene:
        return os.path.basename(scene["input"])
    sets = scene.get("set") or {}
    return scene.get("name", "?") + (f"({','.join(f'{k}={v}' for k, v in sorted(sets.items()))})" if sets else "")


def section(page, out, results):
    runs = [p for p in find(out, results, os.path.join("*", "render.json"))  # not a scene still being drawn
            if not os.path.dirname(p).endswith((".partial", ".old"))]
    statuses = [json.load(open(p)) for p in find(out, results, "status-*.json")]
    if not runs and not statuses:
        return
    page.heading(2, "What VTK shows")
    page.para("The same orders drawn by VTK's vtkOpenGLProjectedTetrahedraMapper (vobench-vtk render): a "
              "pixel differs when any 8-bit channel differs from the image of the reference orderer.")
    for st in statuses:
        if st.get("state") != "done":
            text = STATE_TEXT.get(st.get("state"), str(st.get("state")))
            page.para(f"Suite {st.get('suite')}: {text} ({st.get('reason') or 'no reason recorded'}).")
    for path in runs:
        run = json.load(open(path))
        rel = os.path.relpath(os.path.dirname(path), out)
        page.heading(3, f"{scene_name(run['scene'])}: {run['tetrahedra']} tetrahedra, {run['size'][0]}x{run['size'][1]}")
        page.para(f"{run['gl_renderer']}; {run['load']}; reference: {run['reference'] or 'none'}; "
                  f"command: {run['command']}")
        rows = []
        for s in run["summary"]:
            d = s.get("difference_from_reference", {})
            rows.append([s["sorter"], str(d.get("views_differing", "-")), str(d.get("pixels", "-")),
                         str(d.get("max", "-")), f"{1e3 * s['median_frame_seconds']:.1f}",
                         f"{1e3 * s['median_sort_seconds']:.2f}", f"{s['median_frame_ratio_to_vtk_default']:.2f}"])
        page.table(["sorter", "views differing", "pixels", "max", "frame ms", "sort ms", "frame / VTK's"], rows)
        if run["reference"]:
            def vtk_off(v):
                return next(x["difference"]["pixels"] for x in v["results"] if x["sorter"] == "vtk-default")
            worst = max(run["views"], key=vtk_off)
            res = {x["sorter"]: x for x in worst["results"]}
            page.image_row([(f"{rel}/{res[run['reference']]['image']}", f"{run['reference']} (reference)"),
                            (f"{rel}/{res['vtk-default']['image']}", "VTK's sort"),
                            (f"{rel}/{res['vtk-default']['difference']['image']}", "differing pixels")],
                           caption=f"View {worst['view_index']}: VTK's sort differs in {vtk_off(worst)} pixels.")
        page.link_list([("all views side by side", f"{rel}/render.html", "")])
