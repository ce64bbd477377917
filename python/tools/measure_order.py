"""Times vobench.order and vobench.check against `vobench check`'s seconds for the same view.

    PYTHONPATH=build/python /usr/bin/python3 python/tools/measure_order.py build/harness/cli/vobench \
        helix cells=100000 sxmpvo [VIEW]

Prints one JSON line: the orderer's own seconds (its phases) and the wall time of the
Python call, on the first call (prepare included) and on a second one; the program's
seconds for that view; check's wall time; whether the counts equal the program's; and how
many iterations a Python thread made while a check ran (the GIL is released).
"""
import json
import subprocess
import sys
import threading
import time

import vobench


def main():
    binary, dataset, sets, algorithm = sys.argv[1:5]
    view = int(sys.argv[5]) if len(sys.argv) > 5 else 0
    params = dict(kv.split("=") for kv in sets.split(",") if kv)
    scene = vobench.generate(dataset, **params)
    cam = vobench.views(scene, 14, 512, 512)[view]
    out = {"scene": repr(scene), "algorithm": algorithm, "view": view}

    t = time.perf_counter()
    ids, first = vobench.order(scene, cam, algorithm, details=True)
    out["first_call_wall"] = time.perf_counter() - t
    out["prepare_seconds"] = first["prepare_seconds"]
    out["first_order_seconds"] = first["seconds"]
    t = time.perf_counter()
    ids, second = vobench.order(scene, cam, algorithm, details=True)
    out["second_call_wall"] = time.perf_counter() - t
    out["second_order_seconds"] = second["seconds"]

    args = [binary, "check", "-a", algorithm, "--dataset", dataset, "--views", "14",
            "--view-index", str(view), "--size", "512x512", "--json"]
    for kv in params.items():
        args += ["--set", "=".join(kv)]
    t = time.perf_counter()
    cli = json.loads(subprocess.run(args, capture_output=True, text=True).stdout)["views"][0]
    out["program_wall"] = time.perf_counter() - t
    out["program_seconds"] = cli["seconds"]

    t = time.perf_counter()
    counts = vobench.check(scene, cam, ids)
    out["check_wall"] = time.perf_counter() - t
    out["counts_equal_program"] = all(counts[k] == cli[k] for k in counts)
    out["violating_pixels"] = counts["violating_pixels"]

    spins, stop = [0], []

    def spin():
        while not stop:
            spins[0] += 1

    th = threading.Thread(target=spin)
    th.start()
    time.sleep(0.05)
    before = spins[0]
    vobench.check(scene, cam, ids)
    out["python_iterations_during_check"] = spins[0] - before
    stop.append(1)
    th.join()
    print(json.dumps(out))


if __name__ == "__main__":
    main()
