#!/usr/bin/python3
"""`vobench run SUITE --mpi` under mpirun (issue 17), 3 ranks on this machine (oversubscribed):

1. the farm gives exactly the keys of the serial run, each once, with the same oracle
   verdicts record by record; records name their rank (1 or 2 of 3), host and ranks_on_host
   (2 workers here), and each worker's context line comes before its records;
2. run again, it writes nothing (every key is in the file: resumed like any run);
3. a dataset whose file is malformed makes its jobs fail on the worker: the farm goes on,
   exits 2 naming RESULTS.failed.jsonl, where each failed job has the file's reason, and
   every other record is written, with the serial run's verdicts.

usage: check_farm.py MPIEXEC VOBENCH WORKDIR
"""
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "cli"))
from farm_common import by_key, fail, run, same_records, write_suite  # noqa: E402

MPIEXEC, VOBENCH, WORK = sys.argv[1:4]
WHO = "check_farm"
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
out = lambda name: os.path.join(WORK, name + ".jsonl")  # noqa: E731
MPIRUN = [MPIEXEC, "-np", "3", "--oversubscribe", "--allow-run-as-root", "--mca", "btl", "self,vader"]

suite = write_suite(WORK, "farm")
run([VOBENCH, "run", suite, "-o", out("serial")], WHO)
serial = by_key(WHO, out("serial"))
run(MPIRUN + [VOBENCH, "run", suite, "--mpi", "-o", out("farm")], WHO)
farm = by_key(WHO, out("farm"))
same_records(WHO, serial, farm, "3-rank farm")
for k, r in farm.items():
    if r.get("rank") not in (1, 2) or r.get("ranks") != 3 or r.get("ranks_on_host") != 2 or not r.get("host"):
        fail(WHO, f"{k}: placement {[r.get(f) for f in ('rank', 'ranks', 'ranks_on_host', 'host')]}, "
                  "want rank 1 or 2 of 3, 2 ranks on the host")
p = run(MPIRUN + [VOBENCH, "run", suite, "--mpi", "-o", out("farm")], WHO)
if " 0 records written" not in p.stderr or len(by_key(WHO, out("farm"))) != len(serial):
    fail(WHO, f"the farm run again wrote records or lost some:\n{p.stderr[-1500:]}")

# A malformed mesh file: its dataset's jobs fail on whichever worker gets them.
bad = os.path.join(WORK, "broken.node")
with open(bad, "w") as f:
    f.write("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n")
with open(os.path.join(WORK, "broken.ele"), "w") as f:
    f.write("1 4 0\n1 1 2 3 99\n")
suite = write_suite(WORK, "farm-broken", [{"input": bad}])
p = run(MPIRUN + [VOBENCH, "run", suite, "--mpi", "-o", out("broken")], WHO, codes=(2,))
failed_path = os.path.join(WORK, "broken.failed.jsonl")
if failed_path not in p.stderr or not os.path.exists(failed_path):
    fail(WHO, f"the failed jobs' file is not named or not written:\n{p.stderr[-2000:]}")
failed = [json.loads(ln) for ln in open(failed_path) if ln.strip()]
if len(failed) != 5 or any("broken" not in f["job_key"] or "broken.ele" not in f["reason"] for f in failed):
    fail(WHO, f"want the 5 jobs of the broken dataset (2 orderers x 2 views, the probe), each with the file's reason: "
              f"{failed}")
same_records(WHO, serial, by_key(WHO, out("broken")), "farm with a failing dataset")
print("check_farm: ok")
