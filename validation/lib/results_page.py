#!/usr/bin/python3
"""validation/RESULTS.md, generated from the records of the validation cases.

    /usr/bin/python3 validation/lib/results_page.py            rebuild the page from the records
    /usr/bin/python3 validation/lib/results_page.py --check    rebuild in memory; exit 1 if the page on
                                                               disk differs or breaks the page rules
    /usr/bin/python3 validation/lib/results_page.py --from-run results/validate --commit <c> ...
                                                               (scripts/validate, after the cases ran)
                                                               update the records of the cases that ran,
                                                               validation/lib/tier.json, then the page

Records (tracked, one per case): validation/<case>/record.json. Static text, written by hand:
  title, what (1-3 sentences), reference, tolerance, figure (the key figure as text), notes (a few
  lines), tables (tracked files of the case to link), include (one short tracked table to inline),
  fail_note (why a known FAIL fails; shown while the case's result line equals fail_note_result),
  figure_spec (below).
Written by the run (update_record): result (the case's last line without '<case>: '), status
  (PASS/FAIL/SKIP), checks, wall_s, commit, dirty, date, figure_from_log; on SKIP the last compared
  result is kept in last_compared.
validation/lib/tier.json: the last run of ./scripts/validate (commit, date, cases, result, wall_s).
validation/lib/page.json: the order of the cases on the page, benchmarks and studies that
  ./scripts/validate does not run, and the reference checks of the quick tier (text kept by hand).

figure_spec: {"source": "tables" | "checks", "template": "... {name} ...", "fields": {name: field}}.
  "tables": evaluated whenever the page is built, from the tracked tables of the case (the files its
  check.py writes); "checks": evaluated when the case runs, from the check table (vcheck) in its log.
  field: {"table": file (tables only; .md tables or .csv), "col": column or list of columns (a
  repeated header is "name#2"), "where": {column: regex}, "header_has": [columns], "cell": "num" |
  "fraction" | "dev" | "part:<k>" | "text", "ratio_col": column (value / that column's value),
  "offset": x, "scale": x, "agg": "range" | "list" | "max" | "min" | "maxabs" | "first" | "count",
  "fmt": format spec} or {"ratio": [field, field], ...same transforms and agg}.
A field that cannot be evaluated leaves the record's figure text in place (marked † on the page).

Page rules (--check): at most 500 lines, at most 3 commit-like hashes, table cells under 200
characters, no history passages ("clean clone", "before", "was", "earlier", ...).
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vcheck import num, read_md_tables  # noqa: E402

MAX_LINES, MAX_HASHES, MAX_CELL = 500, 3, 200
HISTORY = re.compile(r"clean clone|\bbefore\b|\bwas\b|\bwere\b|\bearlier\b|\bpreviously\b|\bprevious\b|"
                     r"\bno longer\b|\bused to\b|\bsince\b|\bat commit\b|\bnow\b", re.I)
HASH = re.compile(r"(?<![0-9A-Za-z_.\-/])[0-9a-f]{7,40}(?![0-9A-Za-z_])")
RESULT_LINE = re.compile(r"^(\S+): (PASS|FAIL|SKIP)\b(.*)$")
CHECK_HEAD = ["check", "measured", "reference", "tolerance", "source", "status"]


# ---------------------------------------------------------------- records

def lib_dir(root):
    return os.path.join(root, "validation", "lib")


def case_names(root):
    """The validation cases: the folders of validation/ with an executable run.sh."""
    v = os.path.join(root, "validation")
    return sorted(c for c in os.listdir(v)
                  if os.access(os.path.join(v, c, "run.sh"), os.X_OK) and os.path.isfile(os.path.join(v, c, "run.sh")))


def read_json(path, default=None):
    if not os.path.exists(path):
        return default
    with open(path) as f:
        return json.load(f)


def write_atomic(path, text):
    """Write through a temporary file in the same folder, then rename (atomic on POSIX)."""
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def write_json(path, data):
    write_atomic(path, json.dumps(data, indent=2, ensure_ascii=False) + "\n")


def record_path(root, case):
    return os.path.join(root, "validation", case, "record.json")


def load_record(root, case):
    rec = read_json(record_path(root, case))
    if rec is None:
        rec = {"title": case, "what": "", "reference": "see the case README", "tolerance": "see the case README",
               "figure": "", "status": "", "result": "no record"}
    rec["case"] = case
    return rec


# ---------------------------------------------------------------- logs

def last_result_line(case, lines):
    """'PASS (45 checks)' from the case's last '<case>: PASS|FAIL|SKIP ...' line, or None."""
    found = None
    for line in lines:
        m = RESULT_LINE.match(line.rstrip())
        if m and m.group(1) == case:
            found = (m.group(2) + m.group(3)).strip()
    return found


def count_checks(result):
    """(checks, failed) from 'PASS (45 checks)', 'FAIL (1 of 23 checks: ...)', 'PASS (26 cases ...)'."""
    m = re.search(r"\((\d+) of (\d+)\b", result)
    if m:
        return int(m.group(2)), int(m.group(1))
    m = re.search(r"\((\d+) (checks|cases)\b", result)
    if m:
        return int(m.group(1)), 0
    return None, None


def check_rows(lines):
    """Rows of the last vcheck table of a log, as dicts (check, measured, reference, ...)."""
    rows, cur = [], None
    for line in lines:
        line = line.rstrip("\n")
        if not line.startswith("|"):
            cur = None
            continue
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
        if cells == CHECK_HEAD:
            cur, rows = [], []
            continue
        if cur is None or set("".join(cells)) <= set("-: "):
            continue
        if len(cells) == len(CHECK_HEAD):
            rows.append({k: v.replace("\\|", "|") for k, v in zip(CHECK_HEAD, cells)})
    return rows


# ---------------------------------------------------------------- figure specs

def md_rows(path):
    """Every markdown table of a file as lists of dicts; a repeated header gets '#2', '#3'."""
    out = []
    for head, body in read_md_tables(path):
        names, seen = [], {}
        for h in head:
            seen[h] = seen.get(h, 0) + 1
            names.append(h if seen[h] == 1 else f"{h}#{seen[h]}")
        out.append((names, [dict(zip(names, r)) for r in body]))
    return out


def csv_rows(path):
    import csv
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r]
    head = [h.split(" [")[0].strip() for h in rows[0]]
    return [(head, [dict(zip(head, r)) for r in rows[1:]])]


def cell_value(cell, how):
    if cell is None:
        return None
    cell = str(cell).strip().replace("−", "-")
    if how == "text":
        return cell or None
    if how == "fraction":
        m = re.match(r"\s*([0-9.]+)\s*/\s*([0-9.]+)", cell)
        return float(m.group(1)) / float(m.group(2)) if m and float(m.group(2)) else None
    if how == "dev":
        m = re.search(r"\(([-+]?[0-9.]+(?:e[-+]?\d+)?) %\)", cell)
        return float(m.group(1)) if m else None
    if how.startswith("part:"):
        parts = cell.split(" / ")
        k = int(how.split(":")[1])
        return num(parts[k]) if k < len(parts) else None
    return num(cell)


def field_values(f, tables):
    """The values of one field: a list of floats (or strings for cell 'text')."""
    if "ratio" in f:
        a, b = (field_values(g, tables) for g in f["ratio"])
        if not a or not b:
            return []
        b = b * len(a) if len(b) == 1 else b
        vals = [x / y for x, y in zip(a, b) if y]
    else:
        cols = f["col"] if isinstance(f["col"], list) else [f["col"]]
        where = f.get("where", {})
        need = set(cols) | set(where) | set(f.get("header_has", [])) | ({f["ratio_col"]} if "ratio_col" in f else set())
        how = f.get("cell", "num")
        vals = []
        for head, rows in tables(f):
            if not need <= set(head):
                continue
            for r in rows:
                if not all(re.search(p, r.get(c, "")) for c, p in where.items()):
                    continue
                for c in cols:
                    v = cell_value(r.get(c), how)
                    if v is not None and "ratio_col" in f:
                        d = cell_value(r.get(f["ratio_col"]), how)
                        v = v / d if d else None
                    if v is not None:
                        vals.append(v)
    if vals and not isinstance(vals[0], str):
        vals = [(v + f.get("offset", 0.0)) * f.get("scale", 1.0) for v in vals]
    return vals


def fmt_num(v, spec):
    if isinstance(v, str):
        return v
    s = re.sub(r"e([-+])0*(\d)", r"e\1\2", format(v, spec)).replace("e+", "e")
    return "−" + s[1:] if s.startswith("-") else s


def aggregate(vals, f):
    agg, spec = f.get("agg", "first"), f.get("fmt", ".4g")
    if not vals:
        raise ValueError("no values")
    if agg == "count":
        return str(len(vals))
    if agg == "first":
        return fmt_num(vals[0], spec)
    if agg == "list":
        return " / ".join(fmt_num(v, spec) for v in vals)
    if agg == "max":
        return fmt_num(max(vals), spec)
    if agg == "min":
        return fmt_num(min(vals), spec)
    if agg == "maxabs":
        return fmt_num(max(abs(v) for v in vals), spec)
    if agg == "range":
        lo, hi = fmt_num(min(vals), spec), fmt_num(max(vals), spec)
        return lo if lo == hi else f"{lo}{'…' if min(vals) < 0 else '–'}{hi}"
    raise ValueError(f"unknown agg {agg}")


def eval_spec(spec, tables):
    """The figure text of a spec; ValueError (with the field's name) if a field has no value."""
    out = {}
    for name, f in spec["fields"].items():
        try:
            out[name] = aggregate(field_values(f, tables), f)
        except (ValueError, KeyError, IndexError, OSError, ZeroDivisionError) as e:
            raise ValueError(f"field '{name}': {e}") from e
    return spec["template"].format(**out)


def file_tables(case_dir):
    cache = {}

    def tables(f):
        path = os.path.join(case_dir, f["table"])
        if path not in cache:
            cache[path] = csv_rows(path) if path.endswith(".csv") else md_rows(path)
        return cache[path]
    return tables


def log_tables(rows):
    return lambda f: [(CHECK_HEAD, rows)]


def page_figure(root, rec, warn):
    """(figure text, computed?) for the page: a 'tables' spec is evaluated now; a 'checks' spec was
    evaluated by the run that wrote the record."""
    spec = rec.get("figure_spec")
    if spec and spec.get("source", "tables") == "tables":
        try:
            return eval_spec(spec, file_tables(os.path.join(root, "validation", rec["case"]))), True
        except ValueError as e:
            warn(f"{rec['case']}: key figure from its tables: {e}; the record's text is shown")
    if spec and spec.get("source") == "checks" and rec.get("figure_from_log"):
        return rec.get("figure", ""), True
    return rec.get("figure", ""), False


# ---------------------------------------------------------------- update after a run

def update_record(root, case, log_path, status, seconds, commit, dirty=False, date=None, warn=print):
    """Write the run's result into validation/<case>/record.json. status: the verdict of
    scripts/validate (PASS, FAIL or SKIP, from the exit status and the last line)."""
    rec = load_record(root, case)
    rec.pop("case", None)
    lines = []
    if log_path and os.path.exists(log_path):
        with open(log_path, errors="replace") as f:
            lines = f.read().splitlines()
    line = last_result_line(case, lines)
    if status == "SKIP" and rec.get("status") in ("PASS", "FAIL"):
        rec["last_compared"] = {k: rec.get(k) for k in ("result", "status", "checks", "wall_s", "commit", "date")}
    elif status in ("PASS", "FAIL"):
        rec.pop("last_compared", None)
    if line is None:
        line = f"{status} (no '{case}: PASS/FAIL' line; see results/validate/{case}.log)"
    elif not line.startswith(status):
        line = f"{status} (its last line: {line})"  # e.g. a PASS line with a non-zero exit status
    rec["result"] = line
    rec["status"] = status
    n, _ = count_checks(line)
    rec["checks"] = n
    rec["wall_s"] = int(seconds) if seconds is not None else None
    rec["commit"] = commit
    rec["dirty"] = bool(dirty)
    rec["date"] = date or datetime.date.today().isoformat()
    spec = rec.get("figure_spec")
    rec["figure_from_log"] = False
    if spec and spec.get("source") == "checks" and status != "SKIP":
        rows = check_rows(lines)
        try:
            rec["figure"] = eval_spec(spec, log_tables(rows))
            rec["figure_from_log"] = True
        except ValueError as e:
            warn(f"{case}: key figure from its check table: {e}; the record keeps its figure text")
    write_json(record_path(root, case), rec)
    return rec


def update_from_run(root, run_dir, commit, dirty, result, wall, date=None, warn=print):
    """Read <run_dir>/run.tsv (case, verdict, seconds per line, written by scripts/validate) and the
    logs <run_dir>/<case>.log; update each record and validation/lib/tier.json."""
    ran = []
    with open(os.path.join(run_dir, "run.tsv")) as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) < 3 or not parts[0]:
                continue
            case, status, seconds = parts[0], parts[1], parts[2]
            if not os.path.isdir(os.path.join(root, "validation", case)):
                continue
            update_record(root, case, os.path.join(run_dir, f"{case}.log"), status,
                          int(seconds) if seconds.isdigit() else None, commit, dirty, date, warn)
            ran.append(case)
    tier = {"commit": commit, "dirty": bool(dirty), "date": date or datetime.date.today().isoformat(),
            "cases": ran, "all_cases": sorted(ran) == case_names(root), "result": result,
            "wall_s": int(wall) if wall is not None else None}
    write_json(os.path.join(lib_dir(root), "tier.json"), tier)
    return ran


# ---------------------------------------------------------------- page

def heading(rec):
    c = rec["case"]
    return c + (f" — {rec['title']}" if rec.get("title") and rec["title"] != c else "")


def slug(text):
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    return re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")


def esc(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def short(text, n=150):
    text = str(text)
    return text if len(text) <= n else text[:n - 1].rstrip() + "…"


def result_cell(rec):
    wall = rec.get("wall_s")
    out = short(rec.get("result") or "no result recorded", 120) + (f", {wall} s" if wall is not None else "")
    last = rec.get("last_compared") if rec.get("status") == "SKIP" else None
    if last:
        out += f"; last compared: {short(last.get('result'), 60)}" + (f", {last['wall_s']} s" if last.get("wall_s") else "")
    return out


def fail_note_applies(rec):
    """A known FAIL's note, shown while the case fails with the line the note explains."""
    return bool(rec.get("fail_note")) and rec.get("status") == "FAIL" and rec.get("result") == rec.get("fail_note_result")


def run_mark(rec, tier):
    if not rec.get("commit"):
        return "–"
    same = tier and rec.get("commit") == tier.get("commit") and rec["case"] in tier.get("cases", [])
    return "tier" if same else "separate"


def include_table(path, warn, max_lines=22):
    """The table lines of a short tracked file (its heading dropped); [] if too long or hashed."""
    if not os.path.exists(path):
        warn(f"{path}: missing, not included")
        return []
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if not line.startswith("#")]
    while lines and not lines[0].strip():
        lines.pop(0)
    while lines and not lines[-1].strip():
        lines.pop()
    if len(lines) > max_lines or any(HASH.search(x) for x in lines):
        warn(f"{path}: {len(lines)} lines or a commit-like word, linked instead of included")
        return []
    return lines


def render(root, warn=print):
    lib = lib_dir(root)
    tier = read_json(os.path.join(lib, "tier.json"), {})
    extra = read_json(os.path.join(lib, "page.json"), {})
    cases = case_names(root)
    order = extra.get("order", [])
    cases = [c for c in order if c in cases] + [c for c in cases if c not in order]
    recs = [load_record(root, c) for c in cases]
    figs = {r["case"]: page_figure(root, r, warn) for r in recs}
    n_pass = sum(r.get("status") == "PASS" for r in recs)
    n_fail = sum(r.get("status") == "FAIL" for r in recs)
    n_skip = sum(r.get("status") == "SKIP" for r in recs)

    L = ["# Validation results", "",
         "Generated by `./scripts/validate` from the records of the validation cases",
         "(`validation/<case>/record.json`); `/usr/bin/python3 validation/lib/results_page.py` rebuilds it",
         "from the tracked records without running anything. Edit the records, not this page.", "",
         "**The tier.** Each folder `validation/<case>/` with a `run.sh` is one case: it runs gearfem (Release",
         "build in `build/`), compares each figure with a reference named in its README at a stated tolerance",
         "(`check.py`) and ends with `<case>: PASS (n checks)` or `<case>: FAIL (k of n checks: ...)`; a case",
         "whose external tool is missing (`ccx` for the CalculiX cases) ends with `<case>: SKIP (...)` and exit",
         "status 77, neither a failure nor a pass. Known deviations are `info` rows of a case's check table,",
         "never counted as passes. `./scripts/validate` runs every case (parker_ste first: analytical_vs_fe and",
         "parker_dynamics reuse its sweeps) and `./scripts/validate <case> ...` the named ones; it exits 1 if a",
         "case fails, logs to `results/validate/`, then writes the result of each case it ran into its record",
         "and rewrites this page. `ctest -L long` runs the same scripts. Timings: the shared 2-core machine.", "",
         "**Records and commits.** A record holds its case's last result line, check count, wall time and commit.",
         "The page names one commit, in its last line: that of the last run of `./scripts/validate`. A record",
         "from that run is marked `tier` in the summary; `separate` marks a record from a separate run of its",
         "case (its commit is in its record.json). A key figure is computed from the tracked tables the case",
         "writes, or from its check table when it runs; one marked † is text kept in the record, as are the",
         "notes of each section.", "",
         f"{len(recs)} cases: {n_pass} PASS, {n_fail} FAIL, {n_skip} SKIP"
         + (f", {len(recs) - n_pass - n_fail - n_skip} without a result" if len(recs) - n_pass - n_fail - n_skip else "")
         + ". Benchmarks and studies that the tier does not run: [Benchmarks](#benchmarks).", "",
         "## Summary", "",
         "| case | reference | key figure | tolerance | result | run | command |",
         "|---|---|---|---|---|---|---|"]
    for r in recs:
        fig, computed = figs[r["case"]]
        L.append("| " + " | ".join(esc(x) for x in (
            f"[{r['case']}](#{slug(heading(r))})", short(r.get("reference", ""), 190), short(fig, 190) + ("" if computed else " †"),
            short(r.get("tolerance", ""), 190), result_cell(r), run_mark(r, tier),
            f"`./scripts/validate {r['case']}`")) + " |")
    for r in recs:
        fig, computed = figs[r["case"]]
        c = r["case"]
        L += ["", f"## {heading(r)}", ""]
        if r.get("what"):
            L += [r["what"], ""]
        L.append(f"- Reference: {r.get('reference', '')}. Tolerance: {r.get('tolerance', '')}.")
        mark = {"tier": " (tier run)", "separate": " (separate run)"}.get(run_mark(r, tier), "")
        L.append(f"- Key figure: {fig}" + ("" if computed else " †") + f". Result: {result_cell(r)}{mark}."
                 + (f" {r['fail_note']}" if fail_note_applies(r) else ""))
        for n in r.get("notes", []):
            L.append(f"- {n}")
        links = [f"[{t}]({c}/{t})" for t in r.get("tables", [])]
        if os.path.exists(os.path.join(root, "validation", c, "README.md")):
            links.append(f"[README]({c}/README.md)")
        L.append(f"- Reproduce: `./scripts/validate {c}`" + (f"; {r['also']}" if r.get("also") else "")
                 + (". Tracked: " + ", ".join(links) if links else "") + ".")
        if r.get("include"):
            tab = include_table(os.path.join(root, "validation", c, r["include"]), warn)
            if tab:
                L += ["", f"`{r['include']}`:", ""] + tab

    L += ["", "## Benchmarks", "",
          "Measurements the tier does not run and does not judge; each target is the requirement's. Figures",
          "are text kept in `validation/lib/page.json`, each entry with the commit of its measurement.", "",
          "| benchmark | target or reference | figure | met | command |", "|---|---|---|---|---|"]
    for b in extra.get("benchmarks", []):
        L.append("| " + " | ".join(esc(x) for x in (b["name"], short(b.get("target", ""), 120), short(b.get("figure", ""), 190),
                                                    b.get("met", ""), f"`{b['command']}`")) + " |")
    for b in extra.get("benchmarks", []):
        if b.get("notes"):
            L += ["", f"**{b['name']}** (`{b['command']}`)."] + [f"- {n}" for n in b["notes"]]
    if extra.get("quick_tier"):
        L += ["", "## Reference checks in the quick tier", "",
              "Closed forms and published figures that `./scripts/test` (ctest without `-L long`) checks; text kept",
              "in `validation/lib/page.json`.", ""] + [f"- {n}" for n in extra["quick_tier"]]
    L += ["", "## Commit", ""]
    if tier.get("commit"):
        ran = tier.get("cases", [])
        who = "all cases" if tier.get("all_cases") else (", ".join(ran) if len(ran) <= 8 else f"{len(ran)} cases")
        from_it = sum(run_mark(r, tier) == "tier" for r in recs)
        L.append(f"Tier run (commit {tier['commit']}"
                 + (" with uncommitted changes" if tier.get("dirty") else "")
                 + (f", {tier['date']}" if tier.get("date") else "") + f"): `./scripts/validate` of {who}"
                 + (f": `{tier['result']}`" if tier.get("result") else "")
                 + (f", {tier['wall_s']} s" if tier.get("wall_s") is not None else "")
                 + f"; {from_it} of the {len(recs)} records come from it.")
    else:
        L.append("No run of `./scripts/validate` recorded (validation/lib/tier.json).")
    return "\n".join(L) + "\n"


def lint(text):
    """The page rules; a list of problems."""
    problems = []
    lines = text.splitlines()
    if len(lines) > MAX_LINES:
        problems.append(f"{len(lines)} lines (at most {MAX_LINES})")
    hashes = sorted({h for h in HASH.findall(text) if re.search(r"[0-9]", h) and re.search(r"[a-f]", h)})
    if len(hashes) > MAX_HASHES:
        problems.append(f"{len(hashes)} commit-like hashes (at most {MAX_HASHES}): {', '.join(hashes[:10])}")
    for i, line in enumerate(lines, 1):
        m = HISTORY.search(line)
        if m:
            problems.append(f"line {i}: history word '{m.group(0)}': {line[:100]}")
        if line.startswith("|"):
            for cell in re.split(r"(?<!\\)\|", line)[1:-1]:
                if len(cell.strip()) >= MAX_CELL:
                    problems.append(f"line {i}: a cell of {len(cell.strip())} characters")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")),
                    help="repository root (default: this file's)")
    ap.add_argument("--check", action="store_true", help="do not write; exit 1 if the page differs or breaks a rule")
    ap.add_argument("--from-run", metavar="DIR", help="results/validate of a run: update the records first")
    ap.add_argument("--commit", help="commit of the run (default: git rev-parse --short HEAD)")
    ap.add_argument("--dirty", action="store_true", help="the run's tree had uncommitted changes")
    ap.add_argument("--result", help="the run's last line (validate: PASS ...)")
    ap.add_argument("--wall", type=int, help="the run's wall time [s]")
    ap.add_argument("--date", help="the run's date (default: today)")
    ap.add_argument("--out", help="write the page here instead of validation/RESULTS.md")
    a = ap.parse_args()
    root = os.path.abspath(a.root)
    warnings = []

    def warn(msg):
        warnings.append(msg)
        print(f"results_page: {msg}", file=sys.stderr)

    if a.from_run:
        commit = a.commit
        if not commit:
            try:
                commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True,
                                        text=True, check=True).stdout.strip()
            except (OSError, subprocess.CalledProcessError):
                commit = "no-git"
        ran = update_from_run(root, a.from_run, commit, a.dirty, a.result, a.wall, a.date, warn)
        print(f"results_page: records of {len(ran)} cases updated ({', '.join(ran)})")
    text = render(root, warn)
    problems = lint(text)
    for p in problems:
        print(f"results_page: page rule: {p}", file=sys.stderr)
    page = a.out or os.path.join(root, "validation", "RESULTS.md")
    if a.check:
        same = os.path.exists(page) and open(page).read() == text
        if not same:
            print(f"results_page: {page} differs from the records (run results_page.py)", file=sys.stderr)
        return 0 if same and not problems else 1
    write_atomic(page, text)
    print(f"results_page: {os.path.relpath(page, root)}: {len(text.splitlines())} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
