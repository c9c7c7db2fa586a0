#!/usr/bin/env python3
"""Bit-identity check of σ (pendepth::minimum_depth, issue 16).

Runs BUILD/bin/sigma_identity (bench/sigma_identity.cpp: every Depth3 field in hex floats over
fixed sets of placements — 9 000 on the real game hulls, integer boxes with quarter turns at
integer offsets, integer prisms and bipyramids, slivers flattened to 1e-9) and prints one
SHA-256 per set, with its number of placements.

  scripts/sigma_identity.py BUILD/bin/sigma_identity > hashes.txt                 # record
  scripts/sigma_identity.py BUILD/bin/sigma_identity --check scripts/sigma_identity.sha256
  scripts/sigma_identity.py NEW/bin/sigma_identity --answers BASE/bin/sigma_identity  # see below

The recorded file scripts/sigma_identity.sha256 is branch sigstart's output (commit 67a7298, on
main 4f3112a): a change of one bit of one field (the work counter `candidates` included) of one
placement changes its set's hash. A change of the engine meant to keep the answers (speed) must
keep every hash. A change of σ's path (another start, other supports) changes `candidates` only:
--answers runs both dumps and counts, per set, the placements whose fields other than the last
(`candidates`) differ — all must be 0 — and prints the mean `candidates` of each. Recorded anew
at 67a7298 because its first tetrahedron takes GJK's directions towards 0 (fewer supports):
0 differing placements of 38,625 against 4f3112a, whose hashes (951d3af's) it replaces.
Recorded anew (both files) on branch quat16: Pose3::matrix computes R with one division
s = 2/|q|² instead of normalising q (docs/benchmarks.md, σ section, Run 12), which changes the
bits of rotations whose |q|² does not round to a power of two (the quarter turns with
h = fl(√½), most random ones); identity, half-turn and (½, ½, ½, ½) placements keep every bit.
"""
import hashlib, subprocess, sys


def dump(exe):
    """[(set name, [lines])] of the executable's output."""
    out = subprocess.run([exe], check=True, capture_output=True, text=True).stdout
    sets, name, lines = [], None, []
    for line in out.splitlines() + ["# set END"]:
        if line.startswith("# set "):
            if name is not None:
                sets.append((name, lines))
            name, lines = line[6:], []
        else:
            lines.append(line)
    return sets


def hashes(exe):
    return [(name, hashlib.sha256("\n".join(lines).encode()).hexdigest(), len(lines)) for name, lines in dump(exe)]


def same_answers(new_exe, base_exe):
    """Per set: placements whose fields except the last (candidates) differ; 1 if any does."""
    new, base = dump(new_exe), dump(base_exe)
    if [n for n, _ in new] != [n for n, _ in base]:
        print("the sets differ")
        return 1
    bad = 0
    for (name, a), (_, b) in zip(new, base):
        if len(a) != len(b):
            print(f"{name}: {len(a)} placements against {len(b)}")
            bad += 1
            continue
        differ = sum(x.rsplit(" ", 1)[0] != y.rsplit(" ", 1)[0] for x, y in zip(a, b))
        mean = lambda ls: sum(int(x.rsplit(" ", 1)[1]) for x in ls) / max(1, len(ls))
        print(f"{name} {len(a)} differing {differ}, candidates {mean(b):.3f} -> {mean(a):.3f}")
        bad += differ
    return 1 if bad else 0


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    if len(sys.argv) >= 4 and sys.argv[2] == "--answers":
        return same_answers(sys.argv[1], sys.argv[3])
    got = hashes(sys.argv[1])
    if len(sys.argv) >= 4 and sys.argv[2] == "--check":
        want = {}
        with open(sys.argv[3]) as f:
            for line in f:
                name, h, n = line.split()
                want[name] = (h, int(n))
        bad = 0
        for name, h, n in got:
            ok = want.get(name) == (h, n)
            bad += not ok
            print(f"{name} {n} {'same' if ok else 'DIFFERENT'}")
        if set(want) != {g[0] for g in got}:
            print("the sets differ from the recorded ones")
            bad += 1
        return 1 if bad else 0
    for name, h, n in got:
        print(name, h, n)
    return 0


if __name__ == "__main__":
    sys.exit(main())
