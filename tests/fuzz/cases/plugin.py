"""`vobench --plugin PATH.so SUBCOMMAND`: files that are not vobench plugins (missing, empty,
text, a truncated ELF header, a folder, a real shared library without the entry point) and
misplaced options. Each is refused with one line naming the path or the option, before the
subcommand runs.
"""
import glob

READER = "plugin"


def cases(work):
    elf = b"\x7fELF\x02\x01\x01" + b"\x00" * 57  # a 64-bit ELF header cut short
    out = [
        dict(name="missing", argv=["--plugin", "{dir}/missing.so", "list"], names="missing.so"),
        dict(name="empty", files={"empty.so": b""}, argv=["--plugin", "{dir}/empty.so", "list"],
             names="empty.so"),
        dict(name="text", files={"text.so": b"not a library\n"},
             argv=["--plugin", "{dir}/text.so", "check", "--algorithm", "mpvo", "--dataset", "gap"],
             names="text.so"),
        dict(name="truncated-elf", files={"cut.so": elf}, argv=["--plugin={dir}/cut.so", "list"],
             names="cut.so"),
        dict(name="folder", files={"sub/x": b""}, argv=["--plugin", "{dir}/sub", "list"],
             names="is a folder"),
        dict(name="no-path", argv=["--plugin"], names="--plugin"),
        dict(name="after-subcommand", files={"text.so": b"x"},
             argv=["list", "--plugin", "{dir}/text.so"], names="before the subcommand"),
        dict(name="second-bad", files={"text.so": b"x"},
             argv=["--plugin", "{dir}/missing.so", "--plugin", "{dir}/text.so", "list"],
             names="missing.so"),
    ]
    # A real shared library that is no vobench plugin.
    libm = sorted(glob.glob("/usr/lib/*/libm.so.6") + glob.glob("/lib/*/libm.so.6"))
    if libm:
        out.append(dict(name="no-entry-point", argv=["--plugin", libm[0], "list"],
                        names="no entry point vobench_register_orderers"))
    return out
