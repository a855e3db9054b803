#!/usr/bin/env python3
"""The critical path of a finished Ninja build (docs/build.md#build-time).

Usage: tools/build_critical_path.py <build folder> [target ...]   (default target: all)

Reads the step times of the last build from <build folder>/.ninja_log and the dependency graph
from `ninja -t graph <target>`, and prints the chain of build steps, each waiting for the one
before it, whose times add up to the most: no number of cores builds the target faster than that
sum. Also prints the sum of every step's time (the CPU time the build needs) and that sum over
two, the wall time of a perfect -j2 build, so that the two bounds can be compared with the wall
time measured. Step times are those of the logged build (under -j2 they include the slowdown of
sharing the machine); steps not in the log (phony targets, up-to-date outputs) count as zero.
"""
import re
import subprocess
import sys
from functools import lru_cache


def step_times(build):
    """Output path → seconds of the step that last built it (.ninja_log v5: start end mtime out hash)."""
    times = {}
    with open(f"{build}/.ninja_log") as log:
        for line in log:
            if line.startswith("#"):
                continue
            start, end, _mtime, output, _hash = line.rstrip("\n").split("\t")
            times[output] = (int(end) - int(start)) / 1000.0
    return times


def graph(build, target):
    """(label of each node, inputs of each node) from ninja's graphviz output: file nodes are
    boxes; a build edge with several inputs or outputs is an ellipse node between them."""
    dot = subprocess.run(["ninja", "-C", build, "-t", "graph", target], check=True,
                         capture_output=True, text=True).stdout
    labels, inputs = {}, {}
    for line in dot.splitlines():
        node = re.match(r'"(0x[0-9a-f]+)" \[label="([^"]*)"', line)
        if node:
            labels[node.group(1)] = node.group(2)
            continue
        edge = re.match(r'"(0x[0-9a-f]+)" -> "(0x[0-9a-f]+)"', line)
        if edge:
            inputs.setdefault(edge.group(2), []).append(edge.group(1))
    return labels, inputs


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    build = sys.argv[1]
    targets = sys.argv[2:] or ["all"]
    times = step_times(build)
    for target in targets:
        labels, inputs = graph(build, target)
        sys.setrecursionlimit(100000)

        @lru_cache(maxsize=None)
        def longest(node):
            """(seconds, chain) of the slowest chain of steps ending with node's."""
            before = max((longest(i) for i in inputs.get(node, [])), default=(0.0, ()))
            seconds = times.get(labels.get(node, ""), 0.0)
            chain = before[1] + ((labels[node], seconds),) if seconds > 0 else before[1]
            return before[0] + seconds, chain

        roots = [n for n, label in labels.items() if label == target]
        if not roots:
            sys.exit(f"{target}: not in the graph of {build}")
        total, chain = longest(roots[0])
        steps = {labels[n] for n in labels if labels[n] in times}
        cpu = sum(times[s] for s in steps)
        print(f"{target}: critical path {total:.1f} s in {len(chain)} steps; "
              f"{len(steps)} steps take {cpu:.1f} s in all ({cpu / 2:.1f} s on 2 cores)")
        for output, seconds in chain:
            print(f"  {seconds:6.1f} s  {output}")


if __name__ == "__main__":
    main()
