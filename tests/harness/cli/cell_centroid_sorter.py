#!/usr/bin/python3
"""A Python sorter of cells speaking vobench's protocol, imitating the built-in `centroid`
(key=eye): the scene read by docs/examples/vtu_cells.py, centroids summed vertex by vertex
as vobench sums them, float keys, a stable sort. Argument: the folder of vtu_cells.py."""
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, sys.argv[1])
from vtu_cells import read_vtu  # noqa: E402

assert os.environ["VOBENCH_KIND"] == "cells"
points, conn, offsets, _ = read_vtu(os.environ["VOBENCH_SCENE"])
starts = np.concatenate(([0], offsets[:-1]))
sizes = offsets - starts
total = np.zeros((len(offsets), 3))
for k in range(int(sizes.max())):
    has = sizes > k
    total[has] += points[conn[starts[has] + k]]
centroids = total / sizes[:, None]

for line in sys.stdin:
    camera = json.loads(line)["camera"]
    t0 = time.perf_counter()
    d = centroids - np.array(camera["eye"])
    dist = np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1] + d[:, 2] * d[:, 2])
    order = np.argsort(-dist.astype(np.float32), kind="stable")
    print(json.dumps({"order": order.tolist(), "phases": {"sort": time.perf_counter() - t0}}), flush=True)
