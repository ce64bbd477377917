#!/usr/bin/python3
"""A sorter speaking vobench's protocol: triangles back to front by centroid distance."""
import json, os, sys, time
import numpy as np

assert os.environ["VOBENCH_KIND"] == "triangles"
words = open(os.environ["VOBENCH_SCENE"]).read().split()  # OFF: counts, points, faces
n_points = int(words[1])
points = np.array(words[4:4 + 3 * n_points], dtype=float).reshape(-1, 3)
tris = np.array(words[4 + 3 * n_points:], dtype=np.int64).reshape(-1, 4)[:, 1:]
centroids = (points[tris[:, 0]] + points[tris[:, 1]] + points[tris[:, 2]]) / 3.0

for line in sys.stdin:  # one view per line; stdin closes after the last
    camera = json.loads(line)["camera"]
    t0 = time.perf_counter()
    d = centroids - np.array(camera["eye"])
    if "ortho_height" in camera:  # orthographic: depth along the view direction
        f = np.array(camera["target"]) - np.array(camera["eye"])
        dist = d @ (f / np.linalg.norm(f))
    else:
        dist = np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1] + d[:, 2] * d[:, 2])
    order = np.argsort(-dist.astype(np.float32), kind="stable")  # farthest first
    phases = {"sort": time.perf_counter() - t0}
    print(json.dumps({"order": order.tolist(), "phases": phases}), flush=True)
