"""Shared pass/fail bookkeeping for the validation cases (validation/<case>/check.py).

Each check compares one measured figure against a reference taken from the case README
(a closed form, a standard, a paper, or a converged run) with a stated tolerance, and
prints one row. `finish()` prints the table, writes it to results/checks.md and ends with
one line `<case>: PASS (n checks)` or `<case>: FAIL (k of n: names)`; the exit status is
0 only on PASS. `info()` rows are reported figures that are not pass criteria (known
deviations, documented in the README); they never change the outcome.

Usage in a case:
    from vcheck import Checks
    c = Checks("hertz")
    c.rel("p0, equal discs", measured, reference, 0.015, "Johnson 1985 §4.3")
    sys.exit(c.finish())
"""
import math
import os
import sys


def _fmt(v):
    if isinstance(v, str):
        return v
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "missing"
    if isinstance(v, bool):
        return str(v)
    if isinstance(v, int):
        return str(v)
    return f"{v:.6g}"


class Checks:
    def __init__(self, case, out_dir=None):
        self.case = case
        self.rows = []  # (status, name, measured, reference, tolerance, source)
        self.out_dir = out_dir

    def _add(self, ok, name, measured, reference, tolerance, source):
        if measured is None or (isinstance(measured, float) and math.isnan(measured)):
            ok = False
        self.rows.append(("PASS" if ok else "FAIL", name, _fmt(measured), _fmt(reference), tolerance, source))
        return ok

    def rel(self, name, measured, reference, tol, source, unit=""):
        """|measured/reference - 1| <= tol."""
        ok = measured is not None and reference != 0 and abs(measured / reference - 1) <= tol
        dev = f" ({(measured / reference - 1) * 100:+.3g} %)" if measured is not None and reference else ""
        return self._add(ok, name, (_fmt(measured) + unit + dev) if measured is not None else None,
                         _fmt(reference) + unit, f"±{tol * 100:g} %", source)

    def abs(self, name, measured, reference, tol, source, unit=""):
        """|measured - reference| <= tol."""
        ok = measured is not None and abs(measured - reference) <= tol
        return self._add(ok, name, (_fmt(measured) + unit) if measured is not None else None,
                         _fmt(reference) + unit, f"±{_fmt(tol)}{unit}", source)

    def at_most(self, name, measured, limit, source, unit=""):
        ok = measured is not None and measured <= limit
        return self._add(ok, name, (_fmt(measured) + unit) if measured is not None else None,
                         "—", f"≤ {_fmt(limit)}{unit}", source)

    def at_least(self, name, measured, limit, source, unit=""):
        ok = measured is not None and measured >= limit
        return self._add(ok, name, (_fmt(measured) + unit) if measured is not None else None,
                         "—", f"≥ {_fmt(limit)}{unit}", source)

    def within(self, name, measured, lo, hi, source, unit=""):
        ok = measured is not None and lo <= measured <= hi
        return self._add(ok, name, (_fmt(measured) + unit) if measured is not None else None,
                         "—", f"in [{_fmt(lo)}, {_fmt(hi)}]{unit}", source)

    def true(self, name, ok, measured, reference, source):
        """A qualitative check stated in the reference (e.g. 'contact loss', 'exit 0')."""
        return self._add(bool(ok), name, measured, reference, "exact", source)

    def info(self, name, measured, reference, note):
        """Reported, not a pass criterion (a known deviation explained in the README)."""
        self.rows.append(("info", name, _fmt(measured), _fmt(reference), "—", note))

    def table(self):
        lines = ["| check | measured | reference | tolerance | source | status |",
                 "|---|---|---|---|---|---|"]
        for status, name, m, r, t, s in self.rows:
            cells = [name, m, r, t, s, status]
            lines.append("| " + " | ".join(str(x).replace("|", "\\|") for x in cells) + " |")
        return "\n".join(lines)

    def finish(self):
        """Print the table and the PASS/FAIL line; return the exit status."""
        text = self.table()
        print(text)
        if self.out_dir:
            os.makedirs(self.out_dir, exist_ok=True)
            with open(os.path.join(self.out_dir, "checks.md"), "w") as f:
                f.write(text + "\n")
        n = sum(1 for r in self.rows if r[0] != "info")
        fails = [r[1] for r in self.rows if r[0] == "FAIL"]
        if n == 0:
            print(f"{self.case}: FAIL (no checks ran)")
            return 1
        if fails:
            shown = "; ".join(fails[:6]) + (f"; ... {len(fails) - 6} more" if len(fails) > 6 else "")
            print(f"{self.case}: FAIL ({len(fails)} of {n} checks: {shown})")
            return 1
        print(f"{self.case}: PASS ({n} checks)")
        return 0


def read_md_tables(path):
    """All markdown tables of a file: a list of (header cells, rows of cells)."""
    tables, head, rows = [], None, []
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("|"):
                cells = [c.strip() for c in line.strip().strip("|").split("|")]
                if head is None:
                    head = cells
                elif set("".join(cells)) <= set("-: "):
                    continue
                else:
                    rows.append(cells)
            elif head is not None:
                tables.append((head, rows))
                head, rows = None, []
    if head is not None:
        tables.append((head, rows))
    return tables


def read_csv(path):
    """A CSV file with a header line as a list of dicts; the header names lose their
    ' [unit]' suffix; values are floats where they parse."""
    import csv
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = [h.split(" [")[0].strip() for h in rows[0]]
    out = []
    for r in rows[1:]:
        if not r:
            continue
        d = {}
        for h, v in zip(head, r):
            try:
                d[h] = float(v)
            except ValueError:
                d[h] = v
        out.append(d)
    return out


def num(text):
    """The leading number of a table cell ('1.2 %' -> 1.2); None if there is none."""
    import re
    m = re.match(r"\s*([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)", text)
    return float(m.group(1)) if m else None


def strip_columns(lines, drop=lambda h: h.startswith("time")):
    """Markdown table lines without the columns whose header matches `drop` (timings),
    so that a tracked table changes only when a number changes. Non-table lines pass."""
    out, keep = [], None
    for line in lines:
        if not line.startswith("|"):
            out.append(line)
            keep = None
            continue
        cells = line.strip().strip("|").split("|")
        if keep is None:  # a header line
            keep = [i for i, c in enumerate(cells) if not drop(c.strip())]
        if len(cells) < max(keep, default=-1) + 1:
            out.append(line)
            continue
        out.append("|" + "|".join(cells[i] for i in keep) + "|")
    return out


def write_if_changed(path, text):
    """Write a tracked file only when its content changes (no churn of unchanged files)."""
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == text:
                return False
    tmp = path + ".tmp.write"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)
    return True


def load_shares(rows, tkey, torque, position, kappa=None):
    """Load share per (pinion tooth, gear tooth) at one torque (column `tkey`) and position:
    gearfem's pairs.csv rows when kappa is None, else the CalculiX rows of that penalty factor."""
    out = {}
    for r in rows:
        if int(r["position"]) != position or r[tkey] != torque or (kappa is not None and r["kappa"] != kappa):
            continue
        if kappa is None:
            out[(int(r["pinion tooth"]), int(r["gear tooth"]))] = r["load share"]
        else:
            out[(int(r["pinion_tooth"]), int(r["gear_tooth"]))] = r["share"]
    return out


def read_prm(path):
    """The entries of a parameter file as 'Section/Sub/Entry' -> value (later entries win)."""
    out, stack = {}, []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                stack.append(line[len("subsection "):].strip())
            elif line == "end":
                stack.pop()
            elif line.startswith("set "):
                k, v = line[4:].split("=", 1)
                out["/".join(stack + [k.strip()])] = v.strip()
    return out


def save_figure(fig, path, dpi=100):
    """Lay out `fig` and write it to `path` through a temporary name (never a half-written PNG)."""
    fig.tight_layout()
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=dpi)
    os.replace(tmp, path)
