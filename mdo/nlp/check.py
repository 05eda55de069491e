"""``mdo check RUN_DIR``: is a finished run within its limits?

Reads ``RUN_DIR/solution.json`` (and ``RUN_DIR/analysis/solution.json`` when there)
and prints, for every inequality constraint group and every variable-bound group,
the worst element and its margin in the group's unit; equality groups get one line
with their worst residual.  Generic over groups: a new limit added to a problem as
an ordinary named inequality group (motor power, tip Mach, cell current ...) is
checked with no change here.

Margin: ``rhs - lhs`` for ``<=``, ``lhs - rhs`` for ``>=``, ``x - lower`` /
``upper - x`` for bounds; negative means exceeded.  A limit counts as exceeded when
its scaled violation (violation / group scale, the quantity IPOPT drives to zero)
exceeds the tolerance, by default ``1e-4`` = IPOPT's ``constr_viol_tol``.

Exit codes: 0 all within tolerance, 1 a limit exceeded, 2 an unreadable folder.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

from .problem import _readable, _variable_arrays, element_label, group_residual

__all__ = ["check_run", "check_solution", "DEFAULT_TOL"]

DEFAULT_TOL = 1e-4   # IPOPT's default constr_viol_tol (on the scaled problem mdo hands it)


class _Unreadable(Exception):
    pass


def _load(folder: Path) -> dict:
    path = folder / "solution.json"
    try:
        if not folder.is_dir():
            raise _Unreadable(f"{folder}: not a folder" if folder.exists() else f"{folder}: does not exist")
        if not path.is_file():
            raise _Unreadable(f"{path}: missing (not a run folder, or the run was killed)")
        if path.stat().st_size > 1 << 30:
            raise _Unreadable(f"{path}: larger than 1 GiB, not a solution.json")
        data = json.loads(path.read_text())
    except OSError as exc:
        raise _Unreadable(f"{path}: {exc.strerror or exc}") from exc
    except (UnicodeDecodeError, ValueError) as exc:
        raise _Unreadable(f"{path}: not valid JSON ({exc})") from exc
    if not isinstance(data, dict) or not isinstance(data.get("variables"), list) \
            or not isinstance(data.get("constraints"), list):
        raise _Unreadable(f"{path}: no 'variables' and 'constraints' lists (written by an mdo before "
                          f"constraint groups were stored? re-run the problem)")
    return data


def check_solution(data: dict, tol: float = DEFAULT_TOL) -> list:
    """One row per limit group: name, kind, where, margin (group units), scaled
    margin, unit, exceeded.  Worst first."""
    rows = []
    for c in data["constraints"]:
        r = group_residual(c)
        if not len(r):
            continue
        if c["kind"] == "==":
            m = -np.abs(r)
        else:
            m = -r if c["kind"] == "<=" else r
        m = np.where(np.isfinite(m), m, -np.inf)
        i = int(np.argmin(m))
        rows.append({"name": c["name"], "kind": c["kind"], "where": c["labels"][i],
                     "margin": float(m[i] * c["scale"]), "scaled": float(m[i]), "unit": c["unit"],
                     "exceeded": bool(m[i] < -tol)})
    for v in data["variables"]:
        x, lo, up, sc, _ = _variable_arrays(v)
        if not (np.isfinite(lo).any() or np.isfinite(up).any()):
            continue
        fixed = lo == up
        m = np.where(fixed, -np.abs(x - lo), np.minimum(x - lo, up - x))
        m = np.where(np.isfinite(x), m, -np.inf)
        s = m / sc
        # a fixed element (an initial condition) has margin 0 by construction: it is the
        # worst only when it is off its value beyond tolerance or all elements are fixed
        rank = np.where(fixed & (s >= -tol) & ~fixed.all(), np.inf, s)
        i = int(np.argmin(rank))
        lab = element_label(v, i)
        side = "fixed" if fixed[i] else ("lower" if x[i] - lo[i] <= up[i] - x[i] else "upper")
        rows.append({"name": v["name"], "kind": "bound", "where": (f"{lab}, " if lab else "") + f"{side} bound",
                     "margin": float(m[i]), "scaled": float(s[i]), "unit": v["unit"],
                     "exceeded": bool(s[i] < -tol)})
    rows.sort(key=lambda r: (not r["exceeded"], r["scaled"]))
    return rows


def _print_rows(folder: Path, data: dict, rows: list, tol: float, out):
    status = data.get("status", "?")
    print(f"{folder}: problem {data.get('problem', '?')} ({data.get('mode', '?')}), status {status}", file=out)
    print(f"  tolerance: scaled violation <= {tol:g} (violation / group scale); margin < 0 means "
          f"beyond the limit", file=out)
    eq = [r for r in rows if r["kind"] == "=="]
    limits = [r for r in rows if r["kind"] != "=="]
    print(f"  {'group':<40s} {'kind':>5s}  {'margin':>11s} {'unit':<8s} {'scaled':>10s}  worst at", file=out)
    for r in limits:
        margin, unit = _readable(r["margin"], r["unit"]) if np.isfinite(r["margin"]) else ("NaN/Inf", r["unit"])
        flag = "  EXCEEDED" if r["exceeded"] else ""
        print(f"  {r['name']:<40s} {r['kind']:>5s}  {margin:>11s} {unit:<8s} {r['scaled']:10.3g}  "
              f"{r['where']}{flag}", file=out)
    if eq:
        worst = min(eq, key=lambda r: r["scaled"])
        bad = sum(r["exceeded"] for r in eq)
        print(f"  equality groups: {len(eq)}, {bad} beyond tolerance; worst |residual| "
              f"{-worst['margin']:.3g} {worst['unit']} (scaled {-worst['scaled']:.3g}) in {worst['name']} "
              f"at {worst['where']}", file=out)
    if not data.get("success", True):
        print(f"  note: the solve did not converge ({status})", file=out)


def check_run(run_dir, tol: float | None = None, out=None) -> int:
    """Check a run folder (and its ``analysis/`` stage); returns the exit code."""
    out = sys.stdout if out is None else out
    tol = DEFAULT_TOL if tol is None else float(tol)
    if not (np.isfinite(tol) and tol >= 0):
        print(f"mdo: error: --tol: must be finite and >= 0, got {tol}", file=sys.stderr)
        return 2
    folder = Path(run_dir)
    folders = [folder]
    if (folder / "analysis" / "solution.json").exists():
        folders.append(folder / "analysis")
    code = 0
    for f in folders:
        try:
            data = _load(f)
        except _Unreadable as exc:
            print(f"mdo: error: {exc}", file=sys.stderr)
            return 2
        if (f / "INCOMPLETE.txt").exists():
            print(f"warning: {f} says it is incomplete (INCOMPLETE.txt)", file=out)
        rows = check_solution(data, tol)
        _print_rows(f, data, rows, tol, out)
        n_bad = sum(r["exceeded"] for r in rows)
        if n_bad:
            names = ", ".join(r["name"] for r in rows if r["exceeded"])
            print(f"  EXCEEDED: {n_bad} of {len(rows)} groups beyond tolerance ({names})", file=out)
            code = 1
        else:
            print(f"  all {len(rows)} groups within tolerance", file=out)
    return code
