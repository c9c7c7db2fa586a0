"""Shared helpers of bench/tables_<name>.py: read a Google Benchmark JSON file, format times and
ratios for the markdown tables of docs/benchmarks.md, write the tables.

Each table script is run as  tables_<name>.py JSON CSV MD BUILD_TYPE  (see bench/run_common.sh).
"""
import json

SCALE = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


class Results:
    """The runs of one benchmark JSON file, one record per benchmark name: the median aggregate
    when repeated, else the single run."""

    def __init__(self, path):
        with open(path) as f:
            self.data = json.load(f)
        self.runs = {}
        for b in self.data["benchmarks"]:
            name = b.get("run_name", b["name"])
            if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
                continue
            if name in self.runs and self.runs[name].get("aggregate_name") == "median":
                continue
            self.runs[name] = b

    def ok(self, name):
        b = self.runs.get(name)
        return b is not None and not b.get("error_occurred")

    def ns(self, name):
        """CPU time in ns, None if the benchmark is missing or failed."""
        b = self.runs[name] if self.ok(name) else None
        return None if b is None else b["cpu_time"] * SCALE[b["time_unit"]]

    def real_ns(self, name):
        b = self.runs[name] if self.ok(name) else None
        return None if b is None else b["real_time"] * SCALE[b["time_unit"]]

    def counter(self, name, key):
        return self.runs[name].get(key) if self.ok(name) else None

    def errors(self):
        return [f"{n}: {b.get('error_message')}" for n, b in self.runs.items()
                if b.get("error_occurred")]

    def run_line(self):
        """Start of the closing "Run: ..." line (date, CPUs, load); the caller appends the rest."""
        ctx = self.data.get("context", {})
        return (f"Run: {ctx.get('date', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
                f"{ctx.get('mhz_per_cpu', '?')} MHz, load {ctx.get('load_avg', '?')}")

    def library_build(self):
        return self.data.get("context", {}).get("library_build_type", "?")


def fmt_t(x):
    if x is None:
        return "—"
    for unit, div in (("s", 1e9), ("ms", 1e6), ("µs", 1e3)):
        if x >= div:
            return f"{x / div:.3g} {unit}"
    return f"{x:.3g} ns"


def fmt_r(num, den):
    if num is None or den is None or den == 0:
        return "—"
    r = num / den
    return f"{r:,.0f}×" if r >= 100 else f"{r:.3g}×"


def fmt_i(x):
    return "—" if x is None else f"{int(x):,}"


def finish(md_path, lines, errors, run_line):
    """Appends the errors (if any) and the "Run: ..." line, writes md_path and prints it."""
    if errors:
        lines.append("")
        lines.append("Errors: " + "; ".join(errors))
    lines.append("")
    lines.append(run_line)
    text = "\n".join(lines) + "\n"
    with open(md_path, "w") as f:
        f.write(text)
    print()
    print(text, end="")
