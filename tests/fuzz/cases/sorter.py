"""Orders made elsewhere (issue 15): bad ORDER.json files for `check --order`, broken sorter
programs for `check --command` (each one line naming the view), bad gate options and bad
suite entries {"name", "command"}. Scene: gap 2x2x2 (48 cells), whose identity order
0..47 is a complete permutation.
"""
import json

READER = "sorter"

GAP = ["--dataset", "gap", "--set", "nx=2", "--set", "ny=2", "--set", "nz=2"]
VIEW = ["--views", "2", "--size", "16x16"]
IDS = list(range(48))
CAMERA = {"eye": [5, 1, 1], "target": [0, 0, 0], "up": [0, 0, 1], "width": 16, "height": 16, "fov": 40}


def order_file(**over):
    j = {"algorithm": "mine", "primitive_kind": "cells", "camera": CAMERA, "order": IDS,
         "dataset": {"name": "gap", "set": {"nx": 2, "ny": 2, "nz": 2}}}
    j.update(over)
    return json.dumps({k: v for k, v in j.items() if v is not None}).encode()


def answer(order):
    return "while read x; do echo '" + json.dumps({"order": order}) + "'; done"


def cases(work):
    out = []
    files = {
        "not-json": (b"{\"order\": [", "order.json"),
        "not-object": (b"[1, 2]", "order.json: order file"),
        "no-order": (order_file(order=None), "order.json: order"),
        "order-not-array": (order_file(order=5), "order.json: order"),
        "order-string": (order_file(order=IDS[:-1] + ["47"]), "order.json: order[47]"),
        "order-float": (order_file(order=IDS[:-1] + [47.5]), "order.json: order[47]"),
        "order-huge": (order_file(order=IDS[:-1] + [2 ** 40]), "order.json: order[47]"),
        "dropped": (order_file(order=IDS[:-1]), "47 ids for 48 cells"),
        "repeated": (order_file(order=IDS[:-1] + [3]), "repeats 3"),
        "negative": (order_file(order=IDS[:-1] + [-1]), "holds -1"),
        "extra": (order_file(order=IDS + [48]), "49 ids for 48 cells"),
        "camera-bad": (order_file(camera={"eye": [1, 2]}), "order.json: camera"),
        "camera-eye-is-target": (order_file(camera={**CAMERA, "eye": [0, 0, 0]}), "order.json: camera"),
        "no-camera": (order_file(camera=None), "order.json: camera"),
        "no-dataset": (order_file(dataset=None), "order.json: dataset"),
        "kind-mismatch": (order_file(primitive_kind="triangles"), "primitive_kind"),
    }
    for name, (data, names) in files.items():
        out.append({"name": f"order-{name}", "files": {"order.json": data},
                    "argv": ["check", "--order", "{dir}/order.json"], "names": names})
    out.append({"name": "order-missing-file", "argv": ["check", "--order", "{dir}/none.json"],
                "names": "none.json"})
    sorters = {
        "nonsense": ("while read x; do echo nonsense; done", "view 0: answered malformed JSON"),
        "empty-line": ("while read x; do echo; done", "view 0: answered malformed JSON"),
        "no-order": ("while read x; do echo '{\"phases\": {}}'; done", "view 0: answered no \"order\""),
        "dropped": (answer(IDS[:-1]), "view 0: the order has 47 ids for 48 cells"),
        "repeated": (answer(IDS[:-1] + [0]), "view 0: the order repeats 0"),
        "float-id": (answer(IDS[:-1] + [47.0]), "view 0: order[47] is 47.0"),
        "bad-phase": ("while read x; do echo '{\"order\": " + json.dumps(IDS) + ", \"phases\": {\"a\": -2}}'; done",
                      "view 0: phase 'a' is -2"),
        "exits": ("read x; exit 3", "view 0: exited with status 3"),
        "dies-second-view": ("read x; echo '" + json.dumps({"order": IDS}) + "'; read x; kill -9 $$",
                             "view 1: was killed by signal 9"),
        "not-found": ("{dir}/no-such-sorter", "status 127"),
        "hang": ("sleep 30", "view 0: did not answer within 1 s"),
        "endless-line": ("yes | tr -d '\\n'", "view 0: wrote more than"),
    }
    for name, (cmd, names) in sorters.items():
        # --json: nothing on stdout before the end, even when view 0 was fine
        out.append({"name": f"command-{name}",
                    "argv": ["check", *GAP, *VIEW, "--json", "--command", cmd, "--timeout", "1"], "names": names})
    usage = {
        "two-sources": (["--algorithm", "mpvo", "--command", "cat"], "give exactly one of"),
        "no-source": ([], "give exactly one of"),
        "timeout-without-command": (["--algorithm", "mpvo", "--timeout", "5"], "--timeout"),
        "timeout-zero": (["--command", "cat", "--timeout", "0"], "--timeout"),
        "pixels-over-100": (["--algorithm", "mpvo", "--max-violating-pixels", "101"], "--max-violating-pixels"),
        "pixels-negative": (["--algorithm", "mpvo", "--max-violating-pixels", "-1"], "--max-violating-pixels"),
        "pixels-nan": (["--algorithm", "mpvo", "--max-violating-pixels", "nan"], "--max-violating-pixels"),
        "rmse-negative": (["--algorithm", "mpvo", "--max-rmse", "-0.5"], "--max-rmse"),
        "junit-is-folder": (["--algorithm", "mpvo", "--junit", "{dir}"], "--junit"),
    }
    for name, (args, names) in usage.items():
        out.append({"name": f"usage-{name}", "argv": ["check", *GAP, *VIEW, *args], "names": names})
    suite = {"name": "s", "datasets": [{"name": "gap", "set": {"nx": 2, "ny": 2, "nz": 2}}], "views": 1,
             "sizes": ["16x16"]}
    entries = {
        "empty-command": ({"name": "mine", "command": ""}, "algorithms[0].command"),
        "no-name": ({"command": "cat"}, "algorithms[0].name"),
        "bad-kind": ({"name": "mine", "command": "cat", "kind": "blobs"}, "algorithms[0].kind"),
        "taken-name": ({"name": "centroid", "command": "cat"}, "algorithms[0].name"),
        "bad-name": ({"name": "my sorter", "command": "cat"}, "algorithms[0].name"),
        "bad-timeout": ({"name": "mine", "command": "cat", "timeout": 0}, "algorithms[0].timeout"),
        "unknown-key": ({"name": "mine", "command": "cat", "set": {"k": 1}}, "algorithms[0].set"),
    }
    for name, (entry, names) in entries.items():
        data = json.dumps({**suite, "algorithms": [entry]}).encode()
        out.append({"name": f"suite-{name}", "files": {"suite.json": data},
                    "argv": ["run", "{dir}/suite.json", "-o", "{dir}/results.jsonl"], "names": names})
    mixed = {**suite, "datasets": suite["datasets"] + [{"name": "sphere", "set": {"subdiv": 0}}],
             "algorithms": [{"name": "mine", "command": "cat"}]}
    out.append({"name": "suite-kind-needed", "files": {"suite.json": json.dumps(mixed).encode()},
                "argv": ["run", "{dir}/suite.json", "-o", "{dir}/results.jsonl"], "names": "algorithms[0].kind"})
    return out
