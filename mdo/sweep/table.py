"""The tidy table of a sweep: one row per point, one column per quantity.

Columns, in order: ``point`` (run-folder name), the grid inputs, ``status``,
``success``, ``returncode``, ``iterations`` (the optimization stage),
``iterations_baseline`` (the baseline analysis stage, empty when warm-started),
``wall_time_s`` (the whole point, both stages and start-up), ``solve_time_s`` (IPOPT
wall time of the stages), ``warm_start_from``, ``git_commit`` (the model version), ``objective`` with ``objective_name`` and
``objective_unit``, every scalar summary output of the problem (``battery_energy_kWh``,
``togw_kg``, ...), every design variable (a vector as ``name[i]``; values in the
variable's unit, which the name or ``summary.md`` gives), and ``active`` (the active
constraints, ``;``-separated) when ``summary.json`` has an ``"active"`` entry.

Written as ``sweep.csv`` (always; atomically) and ``sweep.parquet`` when ``pyarrow`` is
installed (the optional extra ``mdo[parquet]``).
"""
from __future__ import annotations

import csv
import io
import os
from pathlib import Path

from .grid import point_name
from .point import point_status, read_json, record_path

__all__ = ["point_row", "write_table", "read_table"]

_SKIP = {"problem", "mode", "status", "success", "objective", "iterations", "wall_time_s", "nlp_size",
         "worst_violations", "timing", "active"}


def _scalar(v):
    if isinstance(v, bool) or isinstance(v, (int, float, str)):
        return v
    return None


def _design_columns(solution: dict) -> dict:
    cols = {}
    for v in (solution or {}).get("variables", []):
        if not v.get("design"):
            continue
        val = v["value"]
        if isinstance(val, list):
            flat = _flatten(val)
            for i, x in enumerate(flat):
                cols[f"{v['name']}[{i}]"] = x
        else:
            cols[v["name"]] = val
    return cols


def _flatten(x):
    if isinstance(x, list):
        return [y for e in x for y in _flatten(e)]
    return [x]


def point_row(run_dir, point: dict) -> dict:
    """The table row of one point from its run folder (any state: finished, failed, not run)."""
    run_dir = Path(run_dir)
    s = read_json(run_dir / "summary.json") or {}
    base = read_json(run_dir / "analysis" / "summary.json") or {}
    rec = read_json(record_path(run_dir)) or {}
    row = {"point": point_name(point), **point, "status": point_status(run_dir),
           "success": s.get("success", False), "returncode": rec.get("returncode")}
    staged = bool(base) and not rec.get("warm_start_used")
    row["iterations"] = s.get("iterations")
    row["iterations_baseline"] = base.get("iterations") if staged else None
    row["wall_time_s"] = rec.get("wall_time_s")
    stage_times = [x.get("wall_time_s") for x in ((s, base) if staged else (s,)) if x.get("wall_time_s") is not None]
    row["solve_time_s"] = round(sum(stage_times), 3) if stage_times else None
    ws = rec.get("warm_start_used")
    row["warm_start_from"] = Path(ws).parent.name if ws else ""
    row["git_commit"] = rec.get("git_commit", "")
    obj = s.get("objective") or {}
    row.update({"objective": obj.get("value"), "objective_name": obj.get("name"), "objective_unit": obj.get("unit")})
    for k, v in s.items():
        if k not in _SKIP and _scalar(v) is not None:
            row[k] = v
    if s:
        row.update(_design_columns(read_json(run_dir / "solution.json")))
    if "active" in s:
        act = s["active"]
        row["active"] = ";".join(str(a.get("name", a) if isinstance(a, dict) else a) for a in act) \
            if isinstance(act, (list, tuple)) else str(act)
    return row


def _columns(rows: list) -> list:
    cols = []
    for r in rows:
        for k in r:
            if k not in cols:
                cols.append(k)
    return cols


def write_table(out, points: list) -> list:
    """Rows of every point of ``points`` (run folders under ``out``); writes sweep.csv (and .parquet)."""
    out = Path(out)
    rows = [point_row(out / point_name(p), p) for p in points]
    cols = _columns(rows)
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=cols, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: ("" if r.get(k) is None else r.get(k)) for k in cols})
    tmp = out / f".sweep.csv.{os.getpid()}.tmp"
    tmp.write_text(buf.getvalue())
    os.replace(tmp, out / "sweep.csv")
    _write_parquet(out, rows, cols)
    return rows


def _write_parquet(out: Path, rows: list, cols: list) -> None:
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        return  # optional: mdo[parquet]
    data = {}
    for c in cols:
        vals = [r.get(c) for r in rows]
        kinds = {type(v) for v in vals if v is not None}
        if kinds and kinds <= {int, float} and kinds != {int}:
            vals = [None if v is None else float(v) for v in vals]
        elif len(kinds) > 1:
            vals = [None if v is None else str(v) for v in vals]
        data[c] = vals
    tmp = out / f".sweep.parquet.{os.getpid()}.tmp"
    pq.write_table(pa.table(data), tmp)
    os.replace(tmp, out / "sweep.parquet")


def read_table(path) -> list:
    """Rows of a ``sweep.csv`` with numbers parsed (empty cells as None)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            r[k] = _parse_cell(v)
    return rows


def _parse_cell(v: str):
    if v == "":
        return None
    if v in ("True", "False"):
        return v == "True"
    try:
        return int(v)
    except ValueError:
        pass
    try:
        return float(v)
    except ValueError:
        return v
