#!/usr/bin/env python3
"""Bit-identity check of σ (pendepth::minimum_depth, issue 16).

Runs BUILD/bin/sigma_identity (bench/sigma_identity.cpp: every Depth3 field in hex floats over
fixed sets of placements — 9 000 on the real game hulls, integer boxes with quarter turns at
integer offsets, integer prisms and bipyramids, slivers flattened to 1e-9) and prints one
SHA-256 per set, with its number of placements.

  scripts/sigma_identity.py BUILD/bin/sigma_identity > hashes.txt                 # record
  scripts/sigma_identity.py BUILD/bin/sigma_identity --check scripts/sigma_identity.sha256

The recorded file scripts/sigma_identity.sha256 is main 951d3af's output: a change of one bit
of one field (the work counter `candidates` included) of one placement changes its set's hash.
A change of the engine meant to keep the answers (speed) must keep every hash.
"""
import hashlib, subprocess, sys


def hashes(exe):
    out = subprocess.run([exe], check=True, capture_output=True, text=True).stdout
    sets, name, lines = [], None, []
    for line in out.splitlines() + ["# set END"]:
        if line.startswith("# set "):
            if name is not None:
                sets.append((name, hashlib.sha256("\n".join(lines).encode()).hexdigest(), len(lines)))
            name, lines = line[6:], []
        else:
            lines.append(line)
    return sets


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
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
