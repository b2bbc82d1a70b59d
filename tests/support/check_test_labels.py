#!/usr/bin/env python3
"""Checks that every CTest test of a build has exactly one kind label (unit, integration, fault,
eval, bench), also tests added with a bare add_test(), which the configure-time check in
cmake/RgNav.cmake does not see.

    check_test_labels.py <build dir>
"""
import json
import subprocess
import sys

KINDS = {"unit", "integration", "fault", "eval", "bench"}


def unlabelled(tests):
    """Names of the tests without exactly one kind label, with their labels."""
    wrong = []
    for test in tests:
        labels = next((p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"), [])
        if len(KINDS.intersection(labels)) != 1:
            wrong.append(f"{test['name']} (labels: {', '.join(labels) or 'none'})")
    return wrong


def main(build_dir):
    listing = subprocess.run(["ctest", "--test-dir", build_dir, "--show-only=json-v1"], check=True,
                             capture_output=True, text=True).stdout
    tests = json.loads(listing)["tests"]
    wrong = unlabelled(tests)
    for line in wrong:
        print(f"no single kind label: {line}")
    print(f"test_labels: tests={len(tests)} without_one_kind={len(wrong)}")
    return 1 if wrong or not tests else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
