"""The conditions a table was measured under, from its records and the paper's numbers file:
our machine beside the paper's, threads, repeats and warm-up of the timed frames, and which
of our data sets stands for which of the paper's (and why). build_tables.py puts this on
every document (Doc.conditions)."""



def paper_machine(paper):
    if isinstance(paper.get("machine"), str):
        return paper["machine"]
    machines = paper.get("machines") or {}
    return "; ".join(f"{k}: {v}" for k, v in machines.items()) or "not stated"


def our_machine(records):
    c = next((r.get("context") for r in records if r.get("context")), {}) or {}
    return (f"{c.get('cpu', '?')}, {c.get('num_cpus', '?')} CPUs, {c.get('compiler', '?')} "
            f"{c.get('build_type', '')} build, commit {c.get('git_sha', '?')}, {c.get('date', '?')}")


def timing(records):
    """'median of R frames after W warm-up, T threads (N records)' for each distinct setting, and
    whether the orderers took turns frame by frame (suite "interleave")."""
    combos = {}
    for r in records:
        key = (r.get("repeats"), r.get("warmup"), r.get("threads"), "probe" if r.get("probe") else "orderer",
               bool(r.get("interleaved")))
        combos[key] = combos.get(key, 0) + 1
    parts = []
    for (reps, warm, threads, kind, turns), n in sorted(combos.items(), key=lambda kv: str(kv[0])):
        parts.append(f"{kind} records ({n}): median of {reps} timed run(s) after {warm} warm-up run(s), "
                     f"{threads} thread(s)" + (", the dataset's orderers taking turns frame by frame" if turns else ""))
    return "; ".join(parts)


def stand_ins(records, paper):
    """The paper's 'stand_ins' entries whose key begins one of our rows or dataset names."""
    table = paper.get("stand_ins") or {}
    names = {str(r.get("row") or "") for r in records} | {str(r.get("dataset") or "") for r in records}
    out, why = [], table.get("why") or table.get("note") or table.get("comment") or ""
    for key, val in table.items():
        if key in ("note", "comment", "why"):
            continue
        if any(n.startswith(key) for n in names):
            out.append(f"{key} for {val}")
    if not out:
        return ""
    return "Stand-ins (ours for the paper's): " + "; ".join(out) + (f". {why}" if why else ".")


def shared_host_warning(records):
    """A warning when timed records came from farm ranks that shared a host (the records'
    ranks_on_host, issue 17), else ''."""
    shared = [r for r in records if (r.get("ranks_on_host") or 1) > 1 and (r.get("repeats") or 0) > 0]
    if not shared:
        return ""
    hosts = sorted({str(r.get("host", "?")) for r in shared})
    most = max(r["ranks_on_host"] for r in shared)
    return (f"Warning: {len(shared)} of {len(records)} timed records were measured by ranks that shared their host "
            f"with other ranks (up to {most} per host, on {', '.join(hosts[:5])}{' ...' if len(hosts) > 5 else ''}): "
            "their times compete for cores, caches and memory bandwidth. For timings run one rank per node "
            "(README, \"Sweeps on a cluster\"). ")


def conditions(records, paper):
    text = (f"Ours: {our_machine(records)}. Paper: {paper_machine(paper)}. Timing: {timing(records)}. ")
    text += shared_host_warning(records)
    few = sorted({str(r.get("suite")) for r in records if (r.get("repeats") or 0) < 3})
    if few and scale(records) == "tiny":
        text += "Fewer than 3 timed runs at the tiny scale: it only checks that the tables build. "
    elif few:
        text += (f"Fewer than 3 timed runs in {', '.join(few)}: those records are for the oracle or images, or "
                 "their table's notes say why. ")
    return text + stand_ins(records, paper)


def scale(records):
    return next((r.get("scale") for r in records if r.get("scale")), "default")



