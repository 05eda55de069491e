"""A solved problem: ``Solution`` (values by name, the constraint groups' values and
multipliers, what limits the design) and the files a run folder keeps (``solution.json``,
``summary.json``, ``summary.md``), written atomically.  ``mdo.nlp.problem.Problem.solve``
makes one; ``read_solution`` and ``mdo check`` read its files back.
"""
from __future__ import annotations

import contextlib
import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..core.units import as_read

if TYPE_CHECKING:
    from .problem import Problem

__all__ = ["Solution", "write_atomic", "active_limits", "limiting_constraints", "pinned_variables", "element_label",
           "group_values", "group_residual", "ACTIVE_SLACK", "DESIGN_BOUND_FRACTION"]

# an inequality element whose scaled slack is at most this is "active" (IPOPT ends with
# slacks of order mu ~ tol = 1e-6 on the scaled problem, so 1e-5 separates at-the-limit
# from clear of it)
ACTIVE_SLACK = 1e-5
# ... or whose scaled multiplier is at least ACTIVE_RATIO x its scaled slack and at least
# ACTIVE_PUSH: a solve ended at a looser tolerance (the TTW's 1e-4) leaves the barrier
# parameter mu near 1e-5 and an active element's slack s ~ mu / lambda of order 1e-2, while
# an inactive one has lambda ~ mu / s << s.  lambda >= 0.1 s means s <= sqrt(10 mu).
ACTIVE_RATIO = 0.1
ACTIVE_PUSH = 1e-4
# a design variable within this fraction of its bound is reported as bound-limited (#16 item 5)
DESIGN_BOUND_FRACTION = 0.01


@dataclass
class Solution:
    """The outcome of a solve: values by name with units, status, report."""

    problem_name: str
    status: str
    success: bool
    iterations: int
    wall_time_s: float
    objective: float
    objective_unit: str
    objective_name: str
    variables: list                 # [{name, unit, value, design, description}]
    outputs: dict                   # name -> {value, unit, summary}
    violations: list                # [{group, kind, max_violation, scaled, where, unit}]
    history: dict
    nlp_size: dict
    timing: dict
    analysis: bool = False
    constraints: list = field(default_factory=list)   # per group: kind, unit, scale, labels, lhs, rhs, multiplier
    objective_scale: float = 1.0
    active: list = field(default_factory=list)        # what limits the design (active_limits)
    pinned: list = field(default_factory=list)        # variables at a bound (pinned_variables)
    barrier: dict = field(default_factory=dict)       # IPOPT's barrier strategy; "fallback_from" if retried
    stopped_because: str | None = None                # why mdo stopped IPOPT early (DivergenceWatch)
    _values: dict = field(default_factory=dict, repr=False)
    _problem: object = field(default=None, repr=False)
    _debug: object = field(default=None, repr=False)

    @classmethod
    def _from_debug(cls, problem: Problem, debug, *, status, success, iterations, wall_time_s,
                    stats, history):
        def val(e):
            try:
                return np.asarray(debug.value(e), dtype=float)
            except Exception:
                return np.full(np.shape(e) if hasattr(e, "shape") else (1,), np.nan)

        fs = problem.objective_scale
        lam = val(problem.opti.lam_g).ravel() if problem.opti.ng else np.zeros(0)
        if lam.size != int(problem.opti.ng):
            lam = np.full(int(problem.opti.ng), np.nan)   # IPOPT stopped before its first iterate
        index = problem._dual_index()
        values = {}
        variables = []
        for v in problem.variables.values():
            x = np.reshape(val(v.scaled), v.shape) * v.scale
            values[v.name] = x
            i = index.get(("x", v.name))
            mult = None
            if i is not None:   # objective units per model unit of the variable
                m = np.where(i >= 0, lam[np.maximum(i, 0)], 0.0) * fs / np.ravel(v.scale, order="F")
                mult = _jsonable(m.reshape(v.shape, order="F"))
            variables.append({"name": v.name, "unit": v.unit, "value": _jsonable(x),
                              "design": v.design, "description": v.description,
                              "scale": _jsonable(v.scale), "lower": _bound_json(v.lower),
                              "upper": _bound_json(v.upper), "frozen": v.frozen,
                              "labels": v.labels, "multiplier": mult})
        outputs = {}
        for o in problem.outputs.values():
            outputs[o.name] = {"value": _jsonable(val(o.expr)), "unit": o.unit, "summary": o.summary}
        constraints = []
        for g in problem.groups.values():
            m = lam[index[("g", g.name)]] * fs / g.scale
            constraints.append({"name": g.name, "kind": g.kind, "unit": g.unit, "scale": g.scale,
                                "labels": g.labels, "lhs": _flat(val(g.lhs), g.size).tolist(),
                                "rhs": _compact(_flat(val(g.rhs), g.size)), "multiplier": m.tolist()})
        violations = [_worst_violation(c) for c in constraints]
        violations.sort(key=lambda d: -d["scaled"])
        obj = float(np.ravel(val(problem.objective))[0]) if problem.objective is not None else float("nan")
        timing = {k: float(v) for k, v in stats.items() if k.startswith(("t_wall_", "t_proc_", "n_call_"))}
        sol = cls(problem.name, status, success, iterations, wall_time_s, obj, problem.objective_unit,
                  problem.objective_name, variables, outputs, violations, history,
                  problem.nlp_size(), timing, analysis=problem.is_analysis)
        sol.constraints = constraints
        sol.objective_scale = fs
        sol.active = active_limits(sol)
        sol.pinned = pinned_variables(sol)
        sol._values = values
        sol._problem = problem
        sol._debug = debug
        return sol

    # -------------------------------------------------------------- access
    def __getitem__(self, name: str) -> np.ndarray:
        """Value of a variable (model units), as an array of its shape (scalars as float)."""
        if name in self._values:
            x = self._values[name]
            return float(x.ravel()[0]) if x.size == 1 else x
        if name in self.outputs:
            return np.asarray(self.outputs[name]["value"]) if np.ndim(self.outputs[name]["value"]) else \
                float(self.outputs[name]["value"])
        raise KeyError(f"no variable or output named {name!r} in {self.problem_name}")

    def value(self, expr):
        """Evaluate any expression of the problem's variables at this solution."""
        return np.asarray(self._debug.value(expr), dtype=float) if np.ndim(self._debug.value(expr)) \
            else float(self._debug.value(expr))

    def summary_values(self) -> dict:
        return {k: o["value"] for k, o in self.outputs.items() if o["summary"]}

    def violation_report(self, top: int = 5, tol: float = 1e-6) -> str:
        """The worst-violated groups and, when any is violated, the variables pinned at a
        bound: a too-small battery shows as its state pinned, not only as a force residual."""
        bad = [v for v in self.violations if v["scaled"] > tol]
        if not bad:
            return "all constraint groups satisfied (scaled violation <= %g)" % tol
        lines = ["worst-violated constraint groups (scaled violation, value in group units, where):"]
        for v in bad[:top]:
            if v.get("nonfinite"):
                lines.append(f"  {v['group']:<32s} {v['kind']:>2s}  NaN/Inf in {v['nonfinite']} element(s), "
                             f"first at {v['where']} (the block of this group produced it)")
                continue
            lines.append(f"  {v['group']:<32s} {v['kind']:>2s}  {v['scaled']:10.3e}  "
                         f"{v['max_violation']:10.3e} {v['unit']:<6s} at {v['where']}")
        if self.pinned:
            lines.append("variables pinned at a bound (possible causes, most pushed first):")
            for p in self.pinned:
                lines.append("  " + describe_pinned(p))
        limits = limiting_constraints(self)
        if limits:
            # a cause that is a constraint, not a bound: the battery's state-of-charge reserve
            lines.append("inequality constraints at their limit (possible causes, most pushed first):")
            for c in limits:
                lines.append(f"  {c['name']} at {c['where']} (multiplier {c['multiplier']:.4g} {c['unit']})")
        return "\n".join(lines)

    def to_dict(self) -> dict:
        """solution.json: every variable (value, bounds, scale, multiplier), every
        constraint group (kind, unit, scale, labels, lhs, rhs, multiplier), outputs.

        Multipliers are in objective units per unit of the variable / group, signed as
        IPOPT's (L = f + lam g: positive pushes at an upper limit, negative at a lower)."""
        return {"problem": self.problem_name, "mode": "analysis" if self.analysis else "optimization",
                "status": self.status, "success": self.success,
                "objective": {"name": self.objective_name, "value": self.objective,
                              "unit": self.objective_unit, "scale": self.objective_scale},
                "variables": self.variables, "constraints": self.constraints, "outputs": self.outputs}

    def summary(self) -> dict:
        d = {"problem": self.problem_name, "mode": "analysis" if self.analysis else "optimization",
             "status": self.status, "success": self.success,
             "objective": {"name": self.objective_name, "value": self.objective, "unit": self.objective_unit},
             "iterations": self.iterations, "wall_time_s": round(self.wall_time_s, 3),
             "nlp_size": self.nlp_size}
        options = getattr(self._problem, "build_options", None)
        if options is not None:
            d["options"] = options
        d.update(self.summary_values())
        d["active"] = [{k: a[k] for k in ("name", "kind", "where", "multiplier", "unit")} for a in self.active]
        d["worst_violations"] = [v for v in self.violations[:5]]
        d["pinned_at_bounds"] = self.pinned
        d["timing"] = self.timing
        if self.barrier:
            d["barrier"] = self.barrier
        if self.stopped_because:
            d["stopped_because"] = self.stopped_because
        return d

    # -------------------------------------------------------------- files
    def save(self, out_dir: str | os.PathLike) -> Path:
        """Write solution.json, summary.json, summary.md, convergence.csv into ``out_dir``,
        each through a temporary name and an atomic rename (a reader never sees half a file)."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        # solution.json is for programs (warm start, mdo check, plots): one line, no indent
        write_atomic(out / "solution.json", json.dumps(self.to_dict(), default=_json_default))
        write_atomic(out / "summary.json", json.dumps(self.summary(), indent=1, default=_json_default))
        write_atomic(out / "summary.md", self.summary_markdown())
        if (out / "ipopt.log").exists():   # one source: the iteration lines the log shows
            from ..plots.convergence import convergence_csv
            write_atomic(out / "convergence.csv", convergence_csv(out / "ipopt.log"))
        else:                              # no log: the intermediate callback's history
            h = self.history
            rows = ["iter,objective,inf_pr,inf_du\n"] + [
                f"{i},{h['objective'][i]:.10g},{h['inf_pr'][i]:.6g},{h['inf_du'][i]:.6g}\n"
                for i in range(len(h.get("objective", [])))]
            write_atomic(out / "convergence.csv", "".join(rows))
        return out

    def summary_markdown(self) -> str:
        lines = [f"# {self.problem_name}: {'analysis' if self.analysis else 'optimization'}", "",
                 f"- status: **{self.status}** ({'converged' if self.success else 'NOT converged'})",
                 f"- {self.objective_name}: {self.objective:.6g} {self.objective_unit}",
                 f"- IPOPT iterations: {self.iterations}; wall time {self.wall_time_s:.2f} s",
                 f"- NLP: " + ", ".join(f"{k} {v}" for k, v in self.nlp_size.items())]
        if self.barrier:
            b = self.barrier
            lines.append(f"- barrier: {b['mu_strategy']}, mu_init {b['mu_init']:g}" + (
                f" (after the {b['fallback_from']['mu_strategy']} barrier ended "
                f"{b['fallback_from']['status']} in {b['fallback_from']['iterations']} iterations"
                + (f", {b['fallback_from']['stopped_because']}" if "stopped_because" in b["fallback_from"] else "")
                + "; "
                f"its files in {b['fallback_from']['folder']}/)" if "fallback_from" in b else ""))
        lines.append("")
        sv = self.summary_values()
        if sv:
            lines += ["## Results", "", "| quantity | value | unit |", "|---|---|---|"]
            for k, val in sv.items():
                lines.append(f"| {k} | {_fmt(val)} | {self.outputs[k]['unit']} |")
            lines.append("")
        design = [v for v in self.variables if v["design"]]
        if design:
            lines += ["## Design variables", "", "| name | value | unit | bounds | description |",
                      "|---|---|---|---|---|"]
            for v in design:
                val, unit = _readable(v["value"], v["unit"])
                lo, _ = _readable(v["lower"], v["unit"]) if v.get("lower") is not None else ("-inf", unit)
                up, _ = _readable(v["upper"], v["unit"]) if v.get("upper") is not None else ("inf", unit)
                lines.append(f"| {v['name']} | {val} | {unit} | {lo} to {up} | {v['description']} |")
            lines.append("")
        lines += _active_markdown(self.active)
        lines += ["## Constraint groups (worst scaled violation)", "", self.violation_report(top=10), ""]
        return "\n".join(lines)


def describe_pinned(p: dict) -> str:
    """'energy_drawn at its upper bound 3.6e+07 J from element [0, 12] (13 of 40 elements)'."""
    val, unit = _readable(p["bound"], p["unit"])
    text = f"{p['name']} at its {p['side']} bound {val} {unit}"
    if p["size"] > 1:
        text += f" from {p['first']} ({p['count']} of {p['size']} elements)"
    return text


def _active_markdown(active: list, top: int = 30) -> list:
    """The 'what limits the design' table: one row per (name, side of limit), the
    largest multiplier of its elements, where the first one is."""
    lines = ["## What limits the design (active bounds and constraints)", ""]
    if not active:
        return lines + ["no design bound within 1 % and no inequality constraint active", ""]
    rows: dict = {}
    for a in active:
        key = (a["name"], a["kind"], a["where"].split(": ")[-1] if a["kind"] == "bound" else "")
        r = rows.setdefault(key, {**a, "count": 0})
        r["count"] += 1
        r["multiplier"] = max(r["multiplier"], a["multiplier"])
    ranked = sorted(rows.values(), key=lambda r: -r["multiplier"])
    lines += ["| name | kind | where | multiplier | unit |", "|---|---|---|---|---|"]
    for r in ranked[:top]:
        where = r["where"] + (f" (+{r['count'] - 1} more)" if r["count"] > 1 else "")
        lines.append(f"| {r['name']} | {r['kind']} | {where} | {r['multiplier']:.4g} | {r['unit']} |")
    if len(ranked) > top:
        lines.append(f"| ... | | {len(ranked) - top} more rows in summary.json | | |")
    return lines + [""]


def _readable(v, unit: str):
    """A value as people read it: angles in degrees, 4 significant digits."""
    a, unit = as_read(v, unit)
    if a.size == 1:
        return f"{float(a.ravel()[0]):.4g}", unit
    return "[" + ", ".join(f"{x:.4g}" for x in a.ravel()) + "]", unit


def write_atomic(path, text: str) -> None:
    """Write ``text`` to ``path`` through ``path.tmp-<pid>`` and ``os.replace`` (atomic on
    POSIX); a symbolic link at ``path`` is refused rather than followed."""
    path = Path(path)
    if path.is_symlink():
        raise OSError(40, "is a symbolic link; mdo does not write through links", str(path))
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    try:
        with open(tmp, "w") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise


def _flat(a, n: int) -> np.ndarray:
    """Values of an expression flattened column-major (CasADi's ``vec``), a scalar broadcast to n."""
    a = np.asarray(a, dtype=float)
    if a.size == 1 and n != 1:
        return np.full(n, float(a.ravel()[0]))
    return a.ravel(order="F") if a.size == n else np.full(n, np.nan)


def _bound_json(b):
    """A bound array for JSON: infinite entries as None (JSON has no infinity)."""
    a = np.asarray(b, dtype=float)
    if np.all(np.isfinite(a)):
        return _jsonable(a)
    if a.size == 1 or not np.any(np.isfinite(a)):
        return None
    obj = a.astype(object)
    obj[~np.isfinite(a)] = None
    return obj.tolist()


def _bound_array(b, shape, fill: float) -> np.ndarray:
    """Inverse of ``_bound_json``: None -> ``fill`` (+-inf), column-major flat."""
    n = int(np.prod(shape))
    if b is None:
        return np.full(n, fill)
    a = np.array(b, dtype=object)
    a = np.where(np.equal(a, None), fill, a).astype(float)
    return np.broadcast_to(a, shape).ravel(order="F") if a.size > 1 else np.full(n, float(a))


def element_label(var: dict, i: int) -> str:
    """Label of element ``i`` (column-major) of a variable entry of solution.json."""
    shape = np.shape(var["value"]) or (1,)
    n = int(np.prod(shape))
    labels = var.get("labels")
    if labels and len(labels) == n:
        return labels[i]
    if labels and len(shape) == 2 and len(labels) == shape[1]:   # one label per column (node)
        return labels[i // shape[0]] + (f" row {i % shape[0]}" if shape[0] > 1 else "")
    if n == 1:
        return ""
    if len(shape) == 1 or shape[1] == 1:
        return f"element {i}"
    return f"element [{i % shape[0]}, {i // shape[0]}]"


def _compact(a: np.ndarray):
    """A list, or one number when every element is the same (most right-hand sides)."""
    return float(a[0]) if a.size and np.all(a == a[0]) else a.tolist()


def group_values(c: dict):
    """(lhs, rhs) arrays of a constraint entry of solution.json (None -> NaN, rhs broadcast)."""
    lhs = np.array([np.nan if x is None else x for x in c["lhs"]], dtype=float)
    rhs = c["rhs"]
    rhs = np.full(lhs.size, np.nan if rhs is None else float(rhs)) if not isinstance(rhs, list) else \
        np.array([np.nan if x is None else x for x in rhs], dtype=float)
    return lhs, rhs


def group_residual(c: dict) -> np.ndarray:
    """Scaled residual (lhs - rhs) / scale of a constraint entry of solution.json."""
    lhs, rhs = group_values(c)
    return (lhs - rhs) / float(c["scale"])


def _worst_violation(c: dict) -> dict:
    """A group's worst element: the violation in scaled and group units and where."""
    r = group_residual(c)
    kind = c["kind"]
    viol = np.abs(r) if kind == "==" else (np.maximum(r, 0.0) if kind == "<=" else np.maximum(-r, 0.0))
    bad = ~np.isfinite(r)
    viol = np.where(bad, np.inf, viol)
    i = int(np.argmax(viol)) if viol.size else 0
    return {"group": c["name"], "kind": kind, "nonfinite": int(bad.sum()),
            "max_violation": float(viol[i] * c["scale"]) if viol.size else 0.0,
            "scaled": float(viol[i]) if viol.size else 0.0,
            "where": c["labels"][i] if viol.size else "", "unit": c["unit"], "size": len(r)}


def _variable_arrays(v: dict):
    """(value, lower, upper, scale, multiplier) of a variable entry, column-major flat."""
    x = np.asarray(v["value"], dtype=float)
    shape = x.shape or (1,)
    flat = lambda a: np.broadcast_to(np.asarray(a, float), shape).ravel(order="F")  # noqa: E731
    lo = _bound_array(v.get("lower"), shape, -np.inf)
    up = _bound_array(v.get("upper"), shape, np.inf)
    m = flat(v["multiplier"]) if v.get("multiplier") is not None else np.zeros(x.size)
    return flat(x), lo, up, flat(v.get("scale", 1.0)), m


def active_limits(sol: "Solution") -> list:
    """What limits the design (#16 item 5): every design-variable bound within
    ``DESIGN_BOUND_FRACTION`` of the value, every other variable at a bound that pushes
    (multiplier of the scaled problem > 1e-6), every active inequality element (scaled
    slack <= ``ACTIVE_SLACK``, or a scaled multiplier >= ``ACTIVE_RATIO`` x the slack and
    >= ``ACTIVE_PUSH``: what a solve at a looser tolerance leaves at its limits).

    ``multiplier`` is |d objective / d limit| in objective units per unit of the
    limit: what relaxing it by one unit would gain (first order)."""
    fu, out = sol.objective_unit, []
    for v in sol.variables:
        if v.get("frozen") or v.get("multiplier") is None:
            continue
        x, lo, up, sc, m = _variable_arrays(v)
        for side, b, d in (("lower", lo, x - lo), ("upper", up, up - x)):
            fin = np.isfinite(b) & (lo != up)
            if v["design"]:
                ref = np.where(b != 0, np.abs(b), np.where(np.isfinite(up - lo), up - lo, 1.0))
                near = fin & (d <= DESIGN_BOUND_FRACTION * ref)
            else:
                near = fin & (d / sc <= ACTIVE_SLACK) & (np.abs(m) * sc / sol.objective_scale > 1e-6)
            for i in np.flatnonzero(near):
                lab = element_label(v, int(i))
                out.append({"name": v["name"], "kind": "bound",
                            "where": (f"{lab}: " if lab else "") + f"{side} bound {b[i]:.6g} {v['unit']}",
                            "multiplier": float(abs(m[i])), "unit": f"{fu} per {v['unit']}",
                            "value": float(x[i]), "limit": float(b[i]), "design": bool(v["design"])})
    for c in sol.constraints:
        if c["kind"] == "==":
            continue
        r = group_residual(c)
        lhs, rhs = group_values(c)
        slack = -r if c["kind"] == "<=" else r
        m = np.asarray([np.nan if x is None else x for x in c["multiplier"]], float)
        lam = np.abs(m) * np.abs(np.broadcast_to(np.asarray(c["scale"], float), m.shape)) / sol.objective_scale
        # the multiplier rule only where the solve converged (mid-way, mu is large and every
        # element near its limit carries a multiplier of mu / slack)
        converged = bool(getattr(sol, "success", True))
        pushed = converged & (np.nan_to_num(lam) >= np.maximum(ACTIVE_RATIO * slack, ACTIVE_PUSH))
        for i in np.flatnonzero(np.isfinite(slack) & ((slack <= ACTIVE_SLACK) | pushed)):
            out.append({"name": c["name"], "kind": "constraint", "where": c["labels"][i],
                        "multiplier": float(abs(m[i])), "unit": f"{fu} per {c['unit']}",
                        "value": float(lhs[i]), "limit": float(rhs[i]), "design": False})
    return out


def limiting_constraints(sol: "Solution", top: int = 4) -> list:
    """Inequality groups at their limit, one entry per group (its most pushed element),
    ranked by the push on the scaled problem (|multiplier| x group scale / objective
    scale): beside the pinned variables, the likely causes of an infeasible solve."""
    best = {}
    for a in active_limits(sol):
        if a["kind"] != "constraint" or not np.isfinite(a["multiplier"]):
            continue
        c = next(c for c in sol.constraints if c["name"] == a["name"])
        push = a["multiplier"] * float(np.max(np.abs(np.asarray(c.get("scale", 1.0), float)))) / sol.objective_scale
        if push > 1e-6 and push > best.get(a["name"], ({}, -1.0))[1]:
            best[a["name"]] = (a, push)
    ranked = sorted(best.values(), key=lambda t: -t[1])
    return [a for a, _ in ranked[:top]]


def pinned_variables(sol: "Solution", top: int = 6) -> list:
    """Variables sitting at a bound, one entry per (variable, side): the likely causes
    of an infeasible solve (#19 item 5), those IPOPT pushes hardest first."""
    out = []
    for v in sol.variables:
        if v.get("frozen"):
            continue
        x, lo, up, sc, m = _variable_arrays(v)
        for side, b, d in (("lower", lo, x - lo), ("upper", up, up - x)):
            at = np.isfinite(b) & (lo != up) & (d <= 1e-6 * np.maximum(np.abs(b), sc))
            if not at.any():
                continue
            idx = np.flatnonzero(at)
            push = np.abs(m[idx]) * sc[idx] / sol.objective_scale
            out.append({"name": v["name"], "side": side, "bound": float(b[idx[0]]), "unit": v["unit"],
                        "first": element_label(v, int(idx[0])), "count": int(idx.size), "size": int(x.size),
                        "push": float(np.nanmax(push)) if np.any(np.isfinite(push)) else 0.0})
    out.sort(key=lambda d: -d["push"])
    return out[:top]


def _fmt(v):
    a = np.asarray(v, dtype=float)
    if a.size == 1:
        return f"{float(a):.6g}"
    return "[" + ", ".join(f"{x:.4g}" for x in a.ravel()) + "]"


def _jsonable(x):
    a = np.asarray(x, dtype=float)
    if a.size == 1:
        return float(a.ravel()[0])
    return a.tolist()


def _json_default(o):
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    if isinstance(o, np.ndarray):
        return o.tolist()
    return str(o)
