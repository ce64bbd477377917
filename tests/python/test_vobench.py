"""The Python module against the vobench program: same views, orders and oracle counts.

Usage: test_vobench.py VOBENCH_BINARY README.md  (PYTHONPATH holds the built package)
"""
import json
import os
import pickle
import re
import subprocess
import sys
import tempfile
import threading
import unittest

import numpy as np

import vobench

VOBENCH = sys.argv[1] if len(sys.argv) > 1 else "vobench"
README = sys.argv[2] if len(sys.argv) > 2 else None

SCENE_ARGS = ["--dataset", "helix", "--set", "cells=2000"]
VIEW_ARGS = ["--views", "6", "--size", "96x80"]
VIEW = 2
# The oracle's usual keys; check() gives these and more, each as `vobench check --json`
# gives it for the view (which adds its own keys: view_index, camera, cycles, seconds, ...).
USUAL_KEYS = {"covered_pixels", "violating_pixels", "violating_fragments", "violating_pairs", "max_k",
              "fragments", "max_list", "k_histogram", "examples", "supersample", "judged"}


def program_view(got, view):
    """The program's values for the keys check() returned (all of which it must have)."""
    assert USUAL_KEYS <= set(got), sorted(USUAL_KEYS - set(got))
    assert set(got) <= set(view), sorted(set(got) - set(view))
    return {k: view[k] for k in got}


def run(args, expect):
    p = subprocess.run([VOBENCH] + args, capture_output=True, text=True)
    if p.returncode != expect:
        raise AssertionError(f"vobench {' '.join(args)}: exit {p.returncode}\n{p.stdout}\n{p.stderr}")
    return p


class ModuleTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = vobench.generate("helix", cells=2000)
        cls.cams = vobench.views(cls.scene, 6, 96, 80)

    def test_scene(self):
        s = self.scene
        self.assertEqual(s.kind, "cells")
        self.assertGreater(s.num_primitives, 1800)
        lo, hi = s.bounds
        self.assertTrue(all(a < b for a, b in zip(lo, hi)))
        self.assertIn("helix", repr(s))

    def test_views_are_the_programs(self):
        p = run(["check", "-a", "sxmpvo"] + SCENE_ARGS + VIEW_ARGS + ["--json"], 0)
        cli = json.loads(p.stdout)
        self.assertEqual(len(self.cams), len(cli["views"]))
        for cam, v in zip(self.cams, cli["views"]):
            self.assertEqual(cam.to_dict(), v["camera"])
            self.assertEqual(vobench.Camera.from_dict(v["camera"]), cam)
        self.assertEqual((self.cams[0].width, self.cams[0].height), (96, 80))
        self.assertIn("vobench.Camera(", repr(self.cams[0]))
        c = self.cams[3]
        made = vobench.Camera(eye=c.eye, target=c.target, up=c.up, fov=c.fov, width=96, height=80)
        self.assertEqual(made, c)
        self.assertEqual(pickle.loads(pickle.dumps(c)), c)
        with self.assertRaisesRegex(ValueError, "equals the target"):
            vobench.Camera(eye=(1, 2, 3), target=(1, 2, 3))

    def test_exact_order_matches_the_program(self):
        cam = self.cams[VIEW]
        vobench.order(self.scene, self.cams[0], "sxmpvo")  # an earlier view on the same prepared orderer
        ids = vobench.order(self.scene, cam, "sxmpvo")
        self.assertEqual(ids.dtype, np.int32)
        self.assertEqual(sorted(ids.tolist()), list(range(self.scene.num_primitives)))
        got = vobench.check(self.scene, cam, ids)
        self.assertEqual(got["violating_pixels"], 0)
        self.assertGreater(got["covered_pixels"], 0)
        p = run(["check", "-a", "sxmpvo"] + SCENE_ARGS + VIEW_ARGS + ["--view-index", str(VIEW), "--json"], 0)
        view = json.loads(p.stdout)["views"][0]
        self.assertEqual(got, program_view(got, view))
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "ORDER.json")
            run(["order", "-a", "sxmpvo"] + SCENE_ARGS + VIEW_ARGS + ["--view-index", str(VIEW), "-o", out], 0)
            with open(out) as f:
                self.assertEqual(ids.tolist(), json.load(f)["order"])

    def test_reversed_order_violates(self):
        cam = self.cams[VIEW]
        ids = vobench.order(self.scene, cam, "sxmpvo")
        bad = vobench.check(self.scene, cam, ids[::-1])  # a strided view, read in place
        self.assertGreater(bad["violating_pixels"], 0)
        self.assertGreater(bad["violating_fragments"], 0)
        # The same order as a list and as int64: converted, same counts.
        self.assertEqual(vobench.check(self.scene, cam, ids[::-1].tolist()), bad)
        self.assertEqual(vobench.check(self.scene, cam, ids[::-1].astype(np.int64)), bad)
        masked = vobench.check(self.scene, cam, ids[::-1], violation_mask=True)
        mask = masked["violation_mask"]
        self.assertEqual(mask.shape, (80, 96))
        self.assertEqual(int(mask.sum()), bad["violating_pixels"])

    def test_order_is_not_copied(self):
        ids = vobench.order(self.scene, self.cams[0], "sxmpvo")
        # numpy does not own the buffer: the C++ vector does, kept alive by a capsule.
        self.assertFalse(ids.flags.owndata)
        self.assertEqual(type(ids.base).__name__, "PyCapsule")
        self.assertTrue(ids.flags.c_contiguous)
        ids2, info = vobench.order(self.scene, self.cams[0], "sxmpvo", details=True)
        self.assertTrue(np.array_equal(ids, ids2))
        self.assertGreater(info["seconds"], 0)
        self.assertIn("prepare_seconds", info)
        self.assertIn("sxmpvo", self.scene.prepared)
        fresh = vobench.generate("helix", cells=2000)
        vobench.order(fresh, self.cams[0], "centroid")
        self.assertEqual(fresh.prepared, ["centroid"])
        fresh.release_orderers()
        self.assertEqual(fresh.prepared, [])

    def test_errors_are_value_errors(self):
        cam = self.cams[0]
        n = self.scene.num_primitives
        ids = vobench.order(self.scene, cam, "sxmpvo")
        cases = [
            (lambda: vobench.check(self.scene, cam, ids[:-1]), "entries for %d primitives" % n),
            (lambda: vobench.check(self.scene, cam, np.concatenate([ids[:-1], ids[:1]])), "repeats or invents"),
            (lambda: vobench.check(self.scene, cam, ids.astype(np.float64)), "must be integers"),
            (lambda: vobench.check(self.scene, cam, ids.astype(np.int64) + 2**40), "does not fit in int32"),
            (lambda: vobench.check(self.scene, cam, ids.reshape(1, -1)), "1-D"),
            (lambda: vobench.order(self.scene, cam, "nosuch"), "nosuch"),
            (lambda: vobench.order(self.scene, cam, "btf"), "orders voxels"),
            (lambda: vobench.generate("helix", nosuch=1), "nosuch"),
            (lambda: vobench.generate("helix", cells=-5), "cells"),
            (lambda: vobench.generate("nosuch"), "nosuch"),
            (lambda: vobench.load("/nonexistent/mesh.vtu"), "/nonexistent/mesh.vtu"),
            (lambda: vobench.views(self.scene, 0, 64, 64), "n 0"),
            (lambda: vobench.Camera.from_dict({"eye": [0, 0, 1]}), "camera"),
            (lambda: vobench.Camera.from_dict({"eye": [0, 0, 1], "target": [0, 0, 1], "up": [0, 1, 0],
                                               "width": 8, "height": 8}), "camera"),
        ]
        for call, words in cases:
            with self.assertRaises(ValueError) as e:
                call()
            msg = str(e.exception)
            self.assertIsInstance(e.exception, vobench.InputError)
            self.assertIn(words, msg)
            self.assertNotIn("\n", msg)

    def test_same_line_as_the_program(self):
        with self.assertRaises(ValueError) as e:
            vobench.generate("helix", cells=-5)
        p = run(["generate", "--dataset", "helix", "--set", "cells=-5", "-o", "/tmp/never.vtu"], 2)
        self.assertIn(str(e.exception), p.stderr)

    def test_file_round_trip(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "helix.vtu")
            run(["generate"] + SCENE_ARGS + ["-o", path], 0)
            s = vobench.load(path)
            self.assertEqual(s.num_primitives, self.scene.num_primitives)
            cam = vobench.views(s, 6, 96, 80)[VIEW]
            self.assertEqual(vobench.check(s, cam, vobench.order(s, cam, "sxmpvo"))["violating_pixels"], 0)

    def test_every_kind_matches_the_program(self):
        for name, sets, algo in [("block", ["nx=12", "ny=10", "nz=8"], "btf"),
                                 ("spheres", ["subdiv=1"], "triangle-centroid")]:
            s = vobench.generate(name, **dict(kv.split("=") for kv in sets))
            cam = vobench.views(s, 4, 64, 48)[1]
            got = vobench.check(s, cam, vobench.order(s, cam, algo))
            args = ["check", "-a", algo, "--dataset", name, "--views", "4", "--view-index", "1",
                    "--size", "64x48", "--json"]
            for kv in sets:
                args += ["--set", kv]
            p = subprocess.run([VOBENCH] + args, capture_output=True, text=True)
            view = json.loads(p.stdout)["views"][0]
            self.assertEqual(got, program_view(got, view), name)
        # Voxel orders list significant voxel ids, not grid positions 0..n-1.
        s = vobench.generate("block", nx=12, ny=10, nz=8)
        with self.assertRaisesRegex(ValueError, "significant voxels"):
            vobench.check(s, cam, np.arange(s.num_primitives, dtype=np.int32))

    def test_threads_share_a_scene(self):
        # The GIL is released while ordering and checking; a scene's prepared orderers and
        # derived structures are used by one thread at a time.
        s = vobench.generate("helix", cells=2000)
        alone = [vobench.check(s, c, vobench.order(s, c, "mpvonc")) for c in self.cams]
        results = [None] * len(self.cams)

        def work(i):
            results[i] = vobench.check(s, self.cams[i], vobench.order(s, self.cams[i], "mpvonc"))

        threads = [threading.Thread(target=work, args=(i,)) for i in range(len(self.cams))]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(results, alone)

    def test_geometry_views(self):
        s = self.scene
        c = s.centroids
        self.assertEqual(c.shape, (s.num_primitives, 3))
        self.assertFalse(c.flags.writeable or c.flags.owndata)
        self.assertIs(c.base, s)  # the scene's memory, kept alive by the scene
        types, offsets, conn = s.cells
        self.assertEqual(set(types.tolist()), {10})  # tetrahedra
        self.assertEqual(len(offsets), s.num_primitives + 1)
        self.assertEqual(offsets[-1], len(conn))
        mean = s.points[conn[offsets[5]:offsets[6]]].mean(axis=0)
        self.assertTrue(np.allclose(mean, c[5]))
        # A centroid sort in numpy is the built-in centroid orderer.
        cam = self.cams[VIEW]
        mine = np.argsort(-np.linalg.norm(c - cam.eye, axis=1), kind="stable").astype(np.int32)
        self.assertTrue(np.array_equal(mine, vobench.order(s, cam, "centroid")))
        tri = vobench.generate("sphere", subdiv=1)
        self.assertEqual(tri.triangles.shape, (80, 3))
        self.assertTrue(np.allclose(tri.centroids[7], tri.points[tri.triangles[7]].mean(axis=0)))
        vox = vobench.generate("block", nx=12, ny=10, nz=8)
        self.assertEqual(vox.voxel_ids.shape, (vox.num_primitives,))
        self.assertEqual(vox.centroids.shape, (vox.num_primitives, 3))
        with self.assertRaisesRegex(ValueError, "voxels have centroids"):
            vox.points
        with self.assertRaisesRegex(ValueError, "applies to triangles"):
            s.triangles

    def test_scenes_from_arrays(self):
        s = self.scene
        a = vobench.cell_mesh(s.points, *s.cells)
        self.assertEqual((a.kind, a.num_primitives, a.bounds), (s.kind, s.num_primitives, s.bounds))
        cam = vobench.views(a, 6, 96, 80)[VIEW]
        self.assertEqual(cam, self.cams[VIEW])  # the same box, the same view set
        ids = vobench.order(a, cam, "sxmpvo")
        self.assertEqual(vobench.check(a, cam, ids), vobench.check(s, cam, vobench.order(s, cam, "sxmpvo")))
        t = vobench.generate("sphere", subdiv=1)
        b = vobench.triangle_soup(t.points, t.triangles)
        self.assertEqual(b.num_primitives, 80)
        types, offsets, conn = s.cells
        for call, words in [
            (lambda: vobench.cell_mesh(s.points, types, offsets[:-1], conn), "offsets"),
            (lambda: vobench.cell_mesh(s.points, types + 1, offsets, conn), "unsupported cell type 11"),
            (lambda: vobench.cell_mesh(s.points, types, offsets, np.where(conn == 0, 10**6, conn)), "out of range"),
            (lambda: vobench.cell_mesh(s.points * np.nan, types, offsets, conn), "not finite"),
            (lambda: vobench.cell_mesh(s.points[:, :2], types, offsets, conn), "(n, 3)"),
            (lambda: vobench.triangle_soup(t.points, t.triangles[:, :2]), "(n, 3)"),
        ]:
            with self.assertRaisesRegex(ValueError, re.escape(words)):
                call()

    def test_registry_lists(self):
        self.assertIn("sxmpvo", vobench.algorithms("cells"))
        self.assertNotIn("btf", vobench.algorithms("cells"))
        self.assertIn("helix", vobench.datasets())

    @unittest.skipUnless(README, "no README given")
    def test_readme_example(self):
        with open(README) as f:
            text = f.read()
        section = text.split("\n## Python", 1)[1].split("\n## ", 1)[0]
        code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
        exec(compile(code, "README.md (Python)", "exec"), {})


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
