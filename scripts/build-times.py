#!/usr/bin/env python3
"""Where the build time goes: the slowest steps of a Ninja build, from its log.

    scripts/build-times.py [BUILD_DIR] [--top N]

Reads BUILD_DIR/.ninja_log (default build/; written by every build) and prints
the N slowest steps (default 10), each with its seconds and the object or file
it made, then the sum over every step (CPU-seconds spent in the compiler and
linker; with -j 2 the wall time is about half of it). A step's time is its
wall time, so numbers from a build that shared the machine with other work
run high. For the numbers of docs/explanation/build-time.md "Build time", start from an empty build
folder: Ninja keeps only the last run of each step.
"""
import argparse
import os
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", nargs="?", default="build")
    parser.add_argument("--top", type=int, default=10)
    args = parser.parse_args()
    log = os.path.join(args.build, ".ninja_log")
    try:
        lines = open(log, encoding="utf-8").read().splitlines()
    except OSError as error:
        print(f"build-times.py: cannot read {log} ({error.strerror}): build first", file=sys.stderr)
        return 2
    steps = {}
    for line in lines[1:]:  # the first line is the log's version
        fields = line.split("\t")
        if len(fields) < 4:
            continue
        start, end, output = int(fields[0]), int(fields[1]), fields[3]
        steps[output] = (end - start) / 1000.0  # the last run of each output
    if not steps:
        print(f"build-times.py: {log} records no step", file=sys.stderr)
        return 2
    for output, seconds in sorted(steps.items(), key=lambda item: -item[1])[: args.top]:
        print(f"{seconds:7.1f} s  {output}")
    print(f"{sum(steps.values()):7.0f} s  in all, {len(steps)} steps")
    return 0


if __name__ == "__main__":
    sys.exit(main())
