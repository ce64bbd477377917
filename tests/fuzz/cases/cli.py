"""Command-line cases: every subcommand's options with bad numbers, values out of range,
huge and negative values, missing values, unknown names and options that cannot apply
together. Each must be refused with one line naming the option, before any dataset is made.
"""
READER = "cli"

# A tiny scene: if an option were not checked before the scene is made, the run would go on
# and print results (stdout) or progress, and the case would fail.
GAP = ["--dataset", "gap", "--set", "nx=2", "--set", "ny=2", "--set", "nz=2"]
CHECK = ["check", "--algorithm", "mpvo"] + GAP
ORDER = ["order", "--algorithm", "mpvo"] + GAP + ["-o", "{dir}/order.json"]
GENERATE = ["generate"] + GAP
CAMERA = ["--eye", "3,0,1", "--target", "0,0,0"]

BAD_INTEGERS = ["0", "-1", "10001", "4294967298", "2147483648", "-4294967295", "abc", "1.5",
                "1e3", "0x10", "", "99999999999999999999999"]


def case(name, argv, names, **extra):
    return dict(name=name, argv=argv, names=names, **extra)


def cases(work):
    out = []
    for i, v in enumerate(BAD_INTEGERS):
        out.append(case(f"views-{i}", CHECK + ["--views", v], "--views"))
    for i, v in enumerate(["-1", "-5", "4294967296", "10000", "x", "1.0"]):
        out.append(case(f"view-index-{i}", CHECK + ["--view-index", v], "--view-index"))
    out.append(case("view-index-past-views", CHECK + ["--views", "4", "--view-index", "4"], "--view-index"))
    out.append(case("view-index-past-orbit", CHECK + ["--orbit", "3", "--view-index", "3"], "--view-index"))
    for i, v in enumerate(["0", "-3", "10001", "2147483648", "many"]):
        out.append(case(f"orbit-{i}", CHECK + ["--orbit", v], "--orbit"))
    for i, v in enumerate(["0", "-10", "180", "1e9", "nan", "inf", "wide"]):
        out.append(case(f"fov-{i}", CHECK + CAMERA + ["--fov", v], "--fov"))
    for i, v in enumerate(["0", "-1", "nan", "1e6", "-inf"]):
        out.append(case(f"zoom-{i}", CHECK + ["--zoom", v], "--zoom"))
    for i, v in enumerate(["0", "-2", "nan"]):
        out.append(case(f"ortho-{i}", CHECK + CAMERA + ["--ortho", v], "--ortho"))
    for i, v in enumerate(["0x10", "10x0", "x", "100", "99999x10", "-5x5", "5x5x5",
                           "4294967297x5", "1e2x5", "+5x5", " 5x5", "abc"]):
        out.append(case(f"size-{i}", CHECK + ["--size", v], "--size"))
    for i, v in enumerate(["0", "17", "-1", "4294967297"]):
        out.append(case(f"supersample-{i}", CHECK + ["--supersample", v], "--supersample"))
    for i, (opt, v) in enumerate([("--eye", "1,2"), ("--eye", "a,b,c"), ("--eye", "nan,0,0"),
                                  ("--target", "1,2,3,4"), ("--up", "0,0,inf")]):
        argv = CHECK + CAMERA + [opt, v] if opt == "--up" else CHECK + [
            "--eye", v if opt == "--eye" else "3,0,1", "--target", v if opt == "--target" else "0,0,0"]
        out.append(case(f"camera-vector-{i}", argv, opt))
    out.append(case("eye-without-target", CHECK + ["--eye", "3,0,1"], "--target"))
    out.append(case("target-without-eye", CHECK + ["--target", "0,0,0"], "--eye"))
    # Options that the chosen kind of view would ignore.
    for opt, v in [("--views", "5"), ("--view-index", "0"), ("--orbit", "4"), ("--zoom", "2")]:
        out.append(case(f"camera-with{opt}", CHECK + CAMERA + [opt, v], opt))
    out.append(case("camera-with--ortho-views", CHECK + CAMERA + ["--ortho-views"], "--ortho-views"))
    out.append(case("fov-and-ortho", CHECK + CAMERA + ["--fov", "30", "--ortho", "2"], "--fov"))
    for opt, v in [("--fov", "30"), ("--ortho", "2"), ("--up", "0,1,0")]:
        out.append(case(f"view-set-with{opt}", CHECK + [opt, v], opt))
    out.append(case("orbit-and-views", CHECK + ["--orbit", "4", "--views", "6"], "--views"))
    out.append(case("own-views-with--views", ["check", "--algorithm", "mpvo", "--dataset", "edge-on",
                                               "--set", "n=1", "--views", "5"], "--views"))
    # Scene options.
    for i, (kv, names) in enumerate([("nx", "--set"), ("=3", "--set"), ("nx=0", "nx"),
                                     ("nx=100000", "nx"), ("nx=4294967298", "nx"),
                                     ("nx=abc", "nx"), ("colour=3", "colour"), ("nx=", "nx"),
                                     ("nx=-1", "nx"), ("gaps=5", "gaps")]):
        out.append(case(f"set-{i}", ["check", "--algorithm", "mpvo", "--dataset", "gap",
                                      "--set", "nz=2", "--set", kv], names))
    out.append(case("set-twice", CHECK + ["--set", "nx=3"], "--set"))
    out.append(case("set-with-input", ["check", "--algorithm", "mpvo", "--input", "{dir}/m.vtu",
                                       "--set", "nx=2"], "--set"))
    out.append(case("dataset-unknown", ["check", "--algorithm", "mpvo", "--dataset", "nope"], "nope"))
    out.append(case("dataset-and-input", CHECK + ["--input", "{dir}/m.vtu"], "--dataset"))
    out.append(case("no-scene", ["check", "--algorithm", "mpvo"], "--dataset"))
    out.append(case("input-missing", ["check", "--algorithm", "mpvo", "--input", "{dir}/missing.vtu"],
                    "missing.vtu"))
    out.append(case("tetrahedralize-dataset", CHECK + ["--tetrahedralize"], "--tetrahedralize"))
    # Orderer names and parameters.
    for i, (spec, names) in enumerate([("nope", "nope"), ("havs:k=99", "k"), ("havs:k=4294967298", "k"),
                                       ("havs:zzz=1", "zzz"), ("centroid:key=bogus", "key"),
                                       ("havs:k", "k"), ("btf", "btf"), ("", "--algorithm")]):
        out.append(case(f"algorithm-{i}", ["check", "--algorithm", spec] + GAP, names))
    # Missing values, unknown options, stray arguments.
    for opt in ["--views", "--algorithm", "--size", "--set"]:
        out.append(case(f"missing-value{opt}", CHECK + [opt], opt))
    out.append(case("unknown-option", CHECK + ["--bogus"], "--bogus"))
    out.append(case("stray-argument", CHECK + ["stray"], "stray"))
    out.append(case("no-subcommand", [], "subcommand"))
    out.append(case("unknown-subcommand", ["frobnicate"], "frobnicate"))
    out.append(case("images-is-a-file", CHECK + ["--images", "{dir}/img"], "--images", files={"img": b"x"}))
    # Other subcommands.
    out.append(case("order-needs-one-view", ORDER, "--view-index"))
    out.append(case("order-view-index-negative", ORDER + ["--view-index", "-2"], "--view-index"))
    out.append(case("order-missing-output", ["order", "--algorithm", "mpvo"] + GAP + ["--view-index", "0"],
                    "--output"))
    out.append(case("generate-missing-output", GENERATE, "--output"))
    out.append(case("generate-bad-extension", GENERATE + ["-o", "{dir}/g.txt"], "--output"))
    out.append(case("generate-wrong-kind", GENERATE + ["-o", "{dir}/g.off"], "--output"))
    out.append(case("generate-bad-set", ["generate", "--dataset", "sphere", "--set", "subdiv=9",
                                         "-o", "{dir}/s.off"], "subdiv"))
    out.append(case("run-missing-suite", ["run", "{dir}/none.json", "-o", "{dir}/r.jsonl"], "none.json"))
    out.append(case("run-suite-is-folder", ["run", "{dir}", "-o", "{dir}/r.jsonl"], "suite"))
    out.append(case("run-missing-output", ["run", "{dir}/none.json"], "--output"))
    out.append(case("run-output-is-a-folder", ["run", "{dir}/s.json", "-o", "{dir}"], "--output",
                    files={"s.json": b'{"datasets": [{"name": "sphere"}], "algorithms": ["triangle-centroid"]}'}))
    out.append(case("reproduce-output-is-a-file", ["reproduce", "quick", "-o", "{dir}/f"], "--output",
                    files={"f": b"x"}))
    out.append(case("report-missing-results", ["report", "{dir}/none.jsonl", "-o", "{dir}/rep"], "none.jsonl"))
    out.append(case("report-no-results", ["report", "-o", "{dir}/rep"], "results"))
    out.append(case("reproduce-unknown", ["reproduce", "nope"], "nope"))
    out.append(case("reproduce-missing-name", ["reproduce"], "name"))
    out.append(case("list-stray-argument", ["list", "extra"], "extra"))
    return out
