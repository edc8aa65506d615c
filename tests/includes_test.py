#!/usr/bin/env python3
"""Every source file of the program (core/, app/) includes what it uses. The test command compiles
in unity batches, which hide a missing include behind an earlier file of the same batch; this
compiles each program source of each batch on its own, syntax only, with its batch's own compile
command from compile_commands.json; a batch's first source is left out, since nothing precedes it
in the batch. The test sources (tests/) are left out: each parses GoogleTest
and most of the program's headers, about 5 s a file, which doubled the check's time in CI.
The C++ standard library comes precompiled (every standard header the program includes, once per
compile command), which takes 40 % off the check's time: it proves the program's own headers and
the libraries' (GLM, nlohmann::json, ImGui, OpenImageIO…), not the standard ones.

usage: includes_test.py BUILD_DIR"""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def standalone_jobs(build):
    """(directory, flags, source) for every program source of every unity batch: its batch's
    compile command without the batch and its output."""
    program = tuple(os.path.join(ROOT, folder) + os.sep for folder in ("core", "app"))
    for entry in json.load(open(os.path.join(build, "compile_commands.json"))):
        batch = entry["file"]
        if "/Unity/unity_" not in batch:
            continue  # compiled on its own already
        sources = re.findall(r'^#include "(.+)"$', open(batch).read(), re.M)
        flags, skip_next = [], False
        for arg in shlex.split(entry["command"]):
            if skip_next:
                skip_next = False
            elif arg in ("-o", "-c"):
                skip_next = True  # the batch's object file and the batch itself
            else:
                flags.append(arg)
        for source in sources[1:]:  # the first one is compiled alone by the batch itself
            if os.path.abspath(source).startswith(program):
                yield entry["directory"], tuple(flags), source


def standard_headers():
    """One #include line for each standard header (<name>, no extension) the program includes."""
    names = set()
    for folder in ("core", "app"):
        for directory, _, files in os.walk(os.path.join(ROOT, folder)):
            for name in files:
                with open(os.path.join(directory, name), errors="replace") as text:
                    names.update(re.findall(r"^#include <([a-z_0-9]+)>", text.read(), re.M))
    return "".join(f"#include <{name}>\n" for name in sorted(names))


def compile_alone(job):
    directory, command, source = job
    result = subprocess.run(command, cwd=directory, capture_output=True, text=True)
    return source, result.returncode, result.stderr


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    jobs = list(standalone_jobs(sys.argv[1]))
    if not jobs:
        sys.exit("includes_test: no unity batches in compile_commands.json (is this a unity build?)")
    with tempfile.TemporaryDirectory() as scratch, ThreadPoolExecutor(os.cpu_count()) as pool:
        # The standard library precompiled once per distinct compile command (a precompiled header
        # is used only with the flags it was made with): `-include` finds it beside the header.
        standard, headers, builds = standard_headers(), {}, []
        for i, (directory, flags) in enumerate(dict.fromkeys((directory, flags) for directory, flags, _ in jobs)):
            headers[flags] = os.path.join(scratch, str(i), "standard.h")
            os.mkdir(os.path.dirname(headers[flags]))
            with open(headers[flags], "w") as out:
                out.write(standard)
            suffix = ".pch" if "clang" in os.path.basename(flags[0]) else ".gch"
            builds.append((directory, [*flags, "-x", "c++-header", headers[flags], "-o", headers[flags] + suffix],
                           "the precompiled standard library"))
        for what, code, errors in pool.map(compile_alone, builds):
            if code != 0:
                sys.exit(f"includes_test: {what} did not compile\n{errors}")
        commands = [(directory, [*flags, "-include", headers[flags], "-fsyntax-only", source], source)
                    for directory, flags, source in jobs]
        failed = 0
        for source, code, errors in pool.map(compile_alone, commands):
            if code != 0:
                failed += 1
                print(f"{source}: does not compile on its own\n{errors}")
    print(f"includes_test: {len(jobs)} program sources compiled one by one, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
