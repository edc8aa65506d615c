#!/usr/bin/env python3
"""Every source file of the program (core/, app/) includes what it uses. The test command compiles
in unity batches, which hide a missing include behind an earlier file of the same batch; this
compiles each program source of each batch on its own, syntax only, with its batch's own compile
command from compile_commands.json; a batch's first source is left out, since nothing precedes it
in the batch. The test sources (tests/) are left out: each parses GoogleTest
and most of the program's headers, about 5 s a file, which doubled the check's time in CI.

usage: includes_test.py BUILD_DIR"""
import json
import os
import re
import shlex
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def standalone_jobs(build):
    """(directory, command, source) for every program source of every unity batch."""
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
                yield entry["directory"], flags + ["-fsyntax-only", source], source


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
    failed = 0
    with ThreadPoolExecutor(os.cpu_count()) as pool:
        for source, code, errors in pool.map(compile_alone, jobs):
            if code != 0:
                failed += 1
                print(f"{source}: does not compile on its own\n{errors}")
    print(f"includes_test: {len(jobs)} program sources compiled one by one, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
