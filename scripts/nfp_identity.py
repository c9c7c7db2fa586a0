#!/usr/bin/env python3
"""Byte-identity check of the no-fit polygon build (issue 19 item 2).

Runs `pendepth nfp-all` (every ordered pair, every allowed rotation, one thread) on the ESICUP
instances of ../shared/data/nesting and prints one SHA-256 per instance of the WKT output.
Consecutive repeated vertices (gardeyn6 has some) are dropped first, since Shape2 rejects them.

  scripts/nfp_identity.py BUILD/bin/pendepth > hashes.txt          # record
  scripts/nfp_identity.py BUILD/bin/pendepth --check scripts/nfp_identity.sha256   # compare

The recorded file scripts/nfp_identity.sha256 is main 063fb37's output: any change in a single
vertex of a single pair changes the hash. gardeyn2 takes ~1.5 min of CPU.
"""
import hashlib, json, os, subprocess, sys, tempfile

INSTANCES = ["albano", "shirts", "trousers", "baldacci4", "gardeyn2", "gardeyn4", "gardeyn6"]
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "data", "nesting")


def cleaned(path):
    with open(path) as f:
        j = json.load(f)
    for item in j["items"]:
        pts = item["shape"]["data"]
        out = []
        for p in pts:
            if not out or out[-1] != p:
                out.append(p)
        item["shape"]["data"] = out
    return j


def main():
    exe = sys.argv[1]
    check = sys.argv[sys.argv.index("--check") + 1] if "--check" in sys.argv else None
    only = [a for a in sys.argv[2:] if a in INSTANCES] or INSTANCES
    got = {}
    for name in only:
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as t:
            json.dump(cleaned(os.path.join(DATA, name + ".json")), t)
        try:
            out = subprocess.run([exe, "nfp-all", t.name, "--threads", "1"], check=True, capture_output=True).stdout
        finally:
            os.unlink(t.name)
        got[name] = hashlib.sha256(out).hexdigest()
        lines = out.count(b"\n") - 1
        print(f"{name} {got[name]} {lines}", flush=True)
    if check:
        want = {}
        with open(check) as f:
            for line in f:
                if line.strip():
                    k, h, _ = line.split()
                    want[k] = h
        bad = [k for k in got if want.get(k) != got[k]]
        print("IDENTICAL" if not bad else "DIFFERENT: " + " ".join(bad))
        sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
