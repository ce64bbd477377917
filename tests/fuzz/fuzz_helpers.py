"""Helpers the case modules in cases/ share (run_fuzz.py puts this folder on sys.path)."""
import copy

DELETE = object()  # as a new value in mutate(): remove the key instead


def mutate(doc, path, value):
    """A deep copy of doc with the entry at path (keys and indices) set to value, or
    removed when value is DELETE."""
    d = copy.deepcopy(doc)
    node = d
    for key in path[:-1]:
        node = node[key]
    if value is DELETE:
        del node[path[-1]]
    else:
        node[path[-1]] = value
    return d


def check_cases(files, ext, algorithm):
    """One `vobench check` case per bad input file {name: bytes}, named by that file."""
    return [{"name": n, "files": {f"{n}.{ext}": d},
             "argv": ["check", "--algorithm", algorithm, "--input", "{dir}/" + f"{n}.{ext}",
                      "--views", "2", "--size", "32x32"],
             "names": f"{n}.{ext}"} for n, d in files.items()]
