#!/usr/bin/python3
"""The fuzz suite: bad input given to vobench must give exactly one error line and exit 2.

Usage: /usr/bin/python3 tests/fuzz/run_fuzz.py VOBENCH_BINARY WORKDIR [--only MODULE]

Every module cases/*.py (sorted by name) defines READER (a short label such as "vtu" or
"suite"; a case may override it with a "reader" key) and cases(work), where work is an empty
folder for that module. cases() returns dicts:
  {"name": "short-unique-name", "files": {"relative/name.ext": bytes},
   "argv": ["check", "--input", "{dir}/bad.vtu", ...], "names": "bad.vtu",
   optional "reader", "stdin" (bytes), "exit" (expected code, default 2)}
"{dir}" in argv is the case's own folder WORKDIR/<module>/<name>/, where its files are
written. A case passes when vobench exits with the expected code within 60 s, writes
nothing to stdout, and writes exactly one non-empty line to stderr that contains "names",
has no control byte and is at most 1000 characters long.
"""
import argparse
import collections
import importlib.util
import pathlib
import shutil
import subprocess
import sys

TIMEOUT_S = 60
MAX_LINE = 1000


# The case modules import their shared helpers from fuzz_helpers.py next to this file.
sys.path.insert(0, str(pathlib.Path(__file__).parent))


def load_module(path):
    spec = importlib.util.spec_from_file_location(f"fuzz_cases_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def problems_of(case, proc):
    """What is wrong with one finished run (empty list: it passed)."""
    out = []
    expected = case.get("exit", 2)
    if proc.returncode != expected:
        out.append(f"exit code {proc.returncode}, expected {expected}")
    if proc.stdout:
        out.append(f"wrote to stdout: {proc.stdout[:80]!r}")
    err = proc.stderr
    if not err.endswith(b"\n") or err.count(b"\n") != 1 or not err.strip():
        out.append(f"stderr is not exactly one line: {err[:300]!r}")
        return out
    line = err[:-1]
    if case["names"].encode() not in line:
        out.append(f"stderr line does not contain {case['names']!r}: {line[:300]!r}")
    if any(b < 0x20 or b == 0x7F for b in line):
        out.append(f"stderr line has a control byte: {line[:300]!r}")
    if len(line.decode("utf-8", "replace")) > MAX_LINE:
        out.append(f"stderr line has {len(line)} bytes (at most {MAX_LINE} characters)")
    return out


def run_case(binary, case, case_dir):
    case_dir.mkdir(parents=True, exist_ok=True)
    for rel, data in case.get("files", {}).items():
        path = case_dir / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
    argv = [a.replace("{dir}", str(case_dir)) for a in case["argv"]]
    try:
        proc = subprocess.run([binary] + argv, input=case.get("stdin", b""),
                              capture_output=True, timeout=TIMEOUT_S, cwd=case_dir)
    except subprocess.TimeoutExpired:
        return [f"timed out after {TIMEOUT_S} s"]
    if proc.returncode < 0:
        return [f"killed by signal {-proc.returncode}; stderr {proc.stderr[-300:]!r}"]
    problems = problems_of(case, proc)
    if not problems and case.get("show"):
        print(f"ok   {case['show']}: {proc.stderr.decode('utf-8', 'replace').rstrip()}")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("binary")
    ap.add_argument("workdir")
    ap.add_argument("--only", help="run only this module of cases/ (e.g. suite)")
    ap.add_argument("--show", action="store_true", help="also print the error line of every passing case")
    a = ap.parse_args()
    binary = str(pathlib.Path(a.binary).resolve())
    workdir = pathlib.Path(a.workdir).resolve()
    modules = sorted((pathlib.Path(__file__).parent / "cases").glob("*.py"))
    modules = [m for m in modules if not m.stem.startswith("_")]
    if a.only:
        modules = [m for m in modules if m.stem == a.only]
        if not modules:
            sys.exit(f"run_fuzz: no module cases/{a.only}.py")
    passed = failed = 0
    per_reader = collections.OrderedDict()
    for path in modules:
        mod_dir = workdir / path.stem
        shutil.rmtree(mod_dir, ignore_errors=True)
        mod_dir.mkdir(parents=True)
        try:
            module = load_module(path)
            cases = module.cases(mod_dir)
        except Exception as e:  # a broken module is a failure, not a crash of the runner
            print(f"FAIL {path.stem}: cannot load its cases: {type(e).__name__}: {e}")
            failed += 1
            continue
        seen = set()
        for case in cases:
            name = case.get("name", "")
            reader = case.get("reader", getattr(module, "READER", path.stem))
            counts = per_reader.setdefault(reader, [0, 0])
            counts[0] += 1
            if not name or name in seen or "/" in name:
                problems = [f"case name {name!r} is empty, repeated or has a '/'"]
            else:
                seen.add(name)
                if a.show:
                    case = dict(case, show=f"{path.stem}/{name}")
                problems = run_case(binary, case, mod_dir / name)
            if problems:
                failed += 1
                counts[1] += 1
                for p in problems:
                    print(f"FAIL {path.stem}/{name}: {p}")
            else:
                passed += 1
    for reader, (n, bad) in per_reader.items():
        print(f"{reader}: {n} cases, {bad} failed")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or passed == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
