#!/usr/bin/env python3
"""Runs an evaluation or benchmark program and checks the figures it prints against floors.

    check_figures.py [--min KEY=FLOOR]... [--max KEY=CEILING]... -- PROGRAM [ARGS...]

The program's output passes through unchanged. For each KEY the value is taken from the last
output line that holds `KEY=<number>` (a figure line such as `doors_laser: precision=0.812
recall=0.734`; text after the number, e.g. `0.0123±0.004`, is ignored). The check fails when the
program fails, when a KEY is not printed, or when a value is below its --min or above its --max;
a last line `figures: ok` or `figures: FAILED ...` says which. Quality figures get a --min, errors
a --max; run times are never checked (the machine may be shared).
"""
import argparse
import math
import re
import subprocess
import sys


def parse_bound(text):
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=NUMBER, got '{text}'")
    try:
        return key, float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{value}' in '{text}' is not a number") from None


def last_value(lines, key):
    pattern = re.compile(r"(?:^|[\s,;(])" + re.escape(key) + r"=([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf)")
    for line in reversed(lines):
        found = pattern.findall(line)
        if found:
            return float(found[-1])
    return None


def check(lines, minimums, maximums):
    """The failed checks as messages; empty when every figure is within its bound."""
    failures = []
    for bounds, below in ((minimums, True), (maximums, False)):
        for key, bound in bounds:
            value = last_value(lines, key)
            if value is None:
                failures.append(f"{key} not printed")
            elif math.isnan(value) or (value < bound if below else value > bound):
                failures.append(f"{key}={value:g} {'below the floor' if below else 'above the ceiling'} {bound:g}")
    return failures


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--min", action="append", default=[], type=parse_bound, metavar="KEY=FLOOR")
    parser.add_argument("--max", action="append", default=[], type=parse_bound, metavar="KEY=CEILING")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args(argv)
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("no program to run")
    if not args.min and not args.max:
        parser.error("no figure to check: give --min or --max")
    process = subprocess.Popen(command, stdout=subprocess.PIPE, text=True, errors="replace")
    lines = []
    for line in process.stdout:
        sys.stdout.write(line)
        sys.stdout.flush()
        lines.append(line.rstrip("\n"))
    status = process.wait()
    failures = check(lines, args.min, args.max)
    if status != 0:
        failures.insert(0, f"the program ended with status {status}")
    if failures:
        print("figures: FAILED " + "; ".join(failures))
        return 1
    print("figures: ok " + " ".join(f"{key}>={bound:g}" for key, bound in args.min) +
          "".join(f" {key}<={bound:g}" for key, bound in args.max))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
