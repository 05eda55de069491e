"""A problem builder over ``casadi.Opti``: named, scaled variables and constraint
groups, an objective with a unit, one IPOPT solve that leaves everything in files.

Conventions
-----------
* A variable is stored in Opti *scaled*: the optimizer sees ``X``, the model sees
  ``x = scale * X``.  Bounds are given in model units and handed to IPOPT as true
  variable bounds (``detect_simple_bounds``), not as general constraints.
* A constraint group is ``(expr - rhs) / scale`` compared with 0, where ``scale`` is
  the size of a typical residual (a force in N, a power in W).  Each group keeps
  its name, its elements' labels (``"segment CR node 3"``) and its scale, so that a
  failed solve can say which physics is violated and where.
* The objective is divided by its ``scale``.

The ``Opti`` instance is public (``problem.opti``) so that a user can mix mdo
blocks with their own variables and constraints.
"""
from __future__ import annotations

import contextlib
import json
import math
import os
import signal
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterable, Sequence

import casadi as ca
import numpy as np

from ..core.errors import InputError

__all__ = ["Problem", "Variable", "ConstraintGroup", "Solution", "SolveError"]


class SolveError(RuntimeError):
    """A solve that did not converge; ``.solution`` holds the last iterate and report."""

    def __init__(self, message: str, solution: "Solution"):
        super().__init__(message)
        self.solution = solution


@dataclass
class Variable:
    name: str
    shape: tuple
    unit: str
    scale: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    init: np.ndarray
    scaled: ca.MX          # the Opti decision variable (what IPOPT sees)
    expr: ca.MX            # scale * scaled (what models see)
    design: bool = False
    frozen: bool = False
    description: str = ""
    labels: list | None = None

    @property
    def size(self) -> int:
        return int(np.prod(self.shape))


@dataclass
class ConstraintGroup:
    name: str
    kind: str               # '==', '<=', '>='
    residual: ca.MX         # (expr - rhs) / scale, flattened
    scale: float
    unit: str
    labels: list
    size: int


@dataclass
class Output:
    name: str
    expr: object
    unit: str
    summary: bool


def _broadcast(value, shape, what, name):
    a = np.asarray(value, dtype=float)
    if a.ndim == 1 and shape[1] == 1 and a.size == shape[0]:
        a = a.reshape(shape)  # a 1-D array is a column
    try:
        return np.broadcast_to(a, shape).astype(float).copy()
    except ValueError as exc:
        raise InputError(name, f"{what} has shape {a.shape}, cannot broadcast to {shape}") from exc


def _shape(shape) -> tuple:
    if isinstance(shape, int):
        return (shape, 1)
    shape = tuple(int(s) for s in shape)
    if len(shape) == 1:
        return (shape[0], 1)
    if len(shape) != 2:
        raise ValueError("variables are vectors or matrices (CasADi is 2-D)")
    return shape


class Problem:
    """An NLP under construction.

    >>> p = Problem("demo")
    >>> x = p.variable("x", unit="m", scale=10, lower=0, upper=100, init=5)
    >>> p.constrain("floor", x - 2, kind=">=", scale=1, unit="m")
    >>> p.minimize((x - 20) ** 2, unit="m^2", scale=100)
    >>> sol = p.solve(verbose=False)
    """

    def __init__(self, name: str, description: str = ""):
        if not name or any(c in name for c in "/\\ "):
            raise InputError("problem name", f"must be a non-empty word without spaces or slashes, got {name!r}")
        self.name = name
        self.description = description
        self.opti = ca.Opti()
        self.variables: dict[str, Variable] = {}
        self.groups: dict[str, ConstraintGroup] = {}
        self.outputs: dict[str, Output] = {}
        self.objective = None
        self.objective_unit = "-"
        self.objective_scale = 1.0
        self.objective_name = "objective"
        self.reports: list[Callable] = []
        self.meta: dict = {}
        self.ipopt_options: dict = {
            "tol": 1e-6,
            "acceptable_tol": 1e-4,
            "max_iter": 3000,
            "mu_strategy": "adaptive",
            "nlp_scaling_method": "gradient-based",
        }
        self._analysis = False

    # ------------------------------------------------------------------ build
    def variable(self, name: str, shape=1, *, unit: str = "-", scale=1.0, lower=-np.inf,
                 upper=np.inf, init=0.0, design: bool = False, description: str = "",
                 labels: Sequence[str] | None = None):
        """Add a decision variable; returns the expression in model units (``scale * X``).

        ``design=True`` marks a design variable: ``freeze_design()`` (the CLI's
        ``--analysis``) fixes those at their initial values.
        """
        if name in self.variables:
            raise InputError("variable name", f"{name!r} is already defined in problem {self.name!r}")
        shp = _shape(shape)
        scale = _broadcast(scale, shp, "scale", name)
        if np.any(scale <= 0) or not np.all(np.isfinite(scale)):
            raise InputError(f"{name}.scale", "must be finite and > 0")
        lower = _broadcast(lower, shp, "lower bound", name)
        upper = _broadcast(upper, shp, "upper bound", name)
        init = _broadcast(init, shp, "initial guess", name)
        if np.any(lower > upper):
            i = int(np.argmax(lower > upper))
            raise InputError(f"{name}.bounds", f"lower {lower.flat[i]:g} > upper {upper.flat[i]:g} {unit}")
        init = np.clip(init, lower, upper)
        X = self.opti.variable(*shp)
        expr = X * ca.DM(scale) if shp != (1, 1) else X * float(scale[0, 0])
        lo_s, up_s = lower / scale, upper / scale
        if np.any(np.isfinite(lo_s)) or np.any(np.isfinite(up_s)):
            lo_s = np.where(np.isfinite(lo_s), lo_s, -np.inf)
            up_s = np.where(np.isfinite(up_s), up_s, np.inf)
            self.opti.subject_to(self.opti.bounded(ca.DM(lo_s), X, ca.DM(up_s)))
        self.opti.set_initial(X, ca.DM(init / scale))
        var = Variable(name, shp, unit, scale, lower, upper, init, X, expr, design=design,
                       description=description, labels=list(labels) if labels else None)
        self.variables[name] = var
        return expr

    def parameter(self, name: str, value, *, unit: str = "-"):
        """A fixed number that can be changed between solves without rebuilding."""
        a = np.atleast_2d(np.asarray(value, dtype=float))
        P = self.opti.parameter(*a.shape)
        self.opti.set_value(P, ca.DM(a))
        self.meta.setdefault("parameters", {})[name] = {"unit": unit}
        return P

    def constrain(self, name: str, expr, *, kind: str = "==", rhs=0.0, scale=1.0,
                  unit: str = "-", labels: Sequence[str] | None = None):
        """Add a named group ``expr (kind) rhs``, scaled by ``scale`` (a typical residual)."""
        if kind not in ("==", "<=", ">="):
            raise InputError(f"constraint {name!r} kind", f"must be '==', '<=' or '>=', got {kind!r}")
        if name in self.groups:
            raise InputError("constraint group name", f"{name!r} is already defined")
        if not (np.isfinite(scale) and scale > 0):
            raise InputError(f"constraint {name!r} scale", "must be finite and > 0")
        r = ca.vec((expr - rhs) / float(scale))
        n = int(r.numel())
        if n == 0:
            return
        if kind == "==":
            self.opti.subject_to(r == 0)
        elif kind == "<=":
            self.opti.subject_to(r <= 0)
        else:
            self.opti.subject_to(r >= 0)
        if labels is None:
            labels = [f"{name}[{i}]" for i in range(n)]
        labels = list(labels)
        if len(labels) != n:
            raise InputError(f"constraint {name!r} labels", f"{len(labels)} labels for {n} elements")
        self.groups[name] = ConstraintGroup(name, kind, r, float(scale), unit, labels, n)

    def minimize(self, expr, *, unit: str = "-", scale: float = 1.0, name: str = "objective"):
        self.objective = expr
        self.objective_unit = unit
        self.objective_scale = float(scale)
        self.objective_name = name
        self.opti.minimize(expr / float(scale))

    def output(self, name: str, expr, *, unit: str = "-", summary: bool = False):
        """A named quantity to evaluate at the solution (``summary=True`` puts it in summary.json)."""
        self.outputs[name] = Output(name, expr, unit, summary)

    def add_report(self, fn: Callable):
        """``fn(solution, out_dir)`` writes extra files after a solve (figures, tables)."""
        self.reports.append(fn)

    def freeze_design(self):
        """Fix every design variable at its initial value (analysis mode)."""
        for v in self.variables.values():
            if v.design and not v.frozen:
                if np.all(v.lower == v.upper):
                    v.frozen = True   # fixed by its bounds already; a second equality would overconstrain
                    continue
                self.opti.subject_to(v.scaled == ca.DM(v.init / v.scale))
                v.frozen = True
        self._analysis = True

    def set_initial(self, name: str, value):
        v = self.variables[name]
        val = np.clip(_broadcast(value, v.shape, "initial guess", name), v.lower, v.upper)
        v.init = val
        self.opti.set_initial(v.scaled, ca.DM(val / v.scale))

    def warm_start(self, solution: "Solution | dict | str | os.PathLike"):
        """Initial guess from an earlier solution (object, dict or ``solution.json``)."""
        if isinstance(solution, (str, os.PathLike)):
            with open(solution) as f:
                data = json.load(f)
        elif isinstance(solution, Solution):
            data = solution.to_dict()
        else:
            data = solution
        used = []
        for item in data.get("variables", []):
            v = self.variables.get(item["name"])
            if v is None:
                continue
            if np.size(item["value"]) != v.size:
                continue
            val = np.asarray(item["value"], dtype=float).reshape(v.shape)
            if v.frozen:
                continue
            self.set_initial(v.name, val)
            used.append(v.name)
        return used

    def initial_violations(self, top: int | None = None) -> list:
        """Each constraint group's worst scaled violation at the initial guess
        (name, kind, scaled, value in group units, where), worst first: what a
        continuation stage must fix before IPOPT starts."""
        init = self.opti.initial()
        out = []
        for grp in self.groups.values():
            r = np.asarray(self.opti.debug.value(grp.residual, init), float).ravel()
            viol = np.abs(r) if grp.kind == "==" else (np.maximum(r, 0) if grp.kind == "<=" else np.maximum(-r, 0))
            viol = np.where(np.isfinite(viol), viol, np.inf)
            i = int(np.argmax(viol))
            out.append({"group": grp.name, "kind": grp.kind, "scaled": float(viol[i]),
                        "max_violation": float(viol[i] * grp.scale), "unit": grp.unit, "where": grp.labels[i]})
        out.sort(key=lambda d: -d["scaled"])
        return out[:top] if top else out

    # ------------------------------------------------------------------ size
    def size(self) -> dict:
        nx = sum(v.size for v in self.variables.values())
        ng = sum(g.size for g in self.groups.values())
        return {"variables": nx, "constraints": ng}

    # ------------------------------------------------------------------ solve
    def solve(self, *, log_path: str | os.PathLike | None = None, max_iter: int | None = None,
              verbose: bool = True, options: dict | None = None, raise_on_failure: bool = False,
              hessian: str = "exact") -> "Solution":
        """Solve with IPOPT; stream the log to the terminal and to ``log_path``.

        Returns a ``Solution`` whatever the outcome (check ``.success``); with
        ``raise_on_failure`` a failed solve raises ``SolveError`` carrying it.
        """
        if self.objective is None:
            self.opti.minimize(0)
        ipopt = dict(self.ipopt_options)
        if max_iter is not None:
            ipopt["max_iter"] = int(max_iter)
        if hessian == "limited-memory":
            ipopt["hessian_approximation"] = "limited-memory"
        ipopt["print_level"] = 5 if verbose else 0
        if not verbose:
            ipopt["sb"] = "yes"  # no banner
        if log_path is not None:
            log_path = Path(log_path)
            log_path.parent.mkdir(parents=True, exist_ok=True)
            ipopt["output_file"] = str(log_path)
            ipopt["file_print_level"] = 5
        if options:
            ipopt.update(options)
        plugin = {"detect_simple_bounds": True, "print_time": verbose,
                  "error_on_fail": False, "expand": False}
        self.opti.solver("ipopt", plugin, ipopt)

        history = {"iter": [], "objective": [], "inf_pr": [], "inf_du": []}
        interrupted = []

        def on_sigint(signum, frame):
            # CasADi notices the pending KeyboardInterrupt inside IPOPT's callback and
            # stops with NonIpopt_Exception_Thrown; remember that it was the user.
            interrupted.append(True)
            signal.default_int_handler(signum, frame)

        previous = None
        with contextlib.suppress(ValueError):  # not in the main thread: leave handlers alone
            previous = signal.signal(signal.SIGINT, on_sigint)
        t0 = time.perf_counter()
        try:
            sol = self.opti.solve()
            debug = sol
        except KeyboardInterrupt:
            interrupted.append(True)
            debug = self.opti.debug
        except RuntimeError:
            debug = self.opti.debug
        finally:
            if previous is not None:
                signal.signal(signal.SIGINT, previous)
        wall = time.perf_counter() - t0
        stats = {}
        with contextlib.suppress(Exception):
            stats = dict(self.opti.stats())
        it = stats.get("iterations", {})
        if it:
            history["objective"] = [float(v) for v in it.get("obj", [])]
            history["inf_pr"] = [float(v) for v in it.get("inf_pr", [])]
            history["inf_du"] = [float(v) for v in it.get("inf_du", [])]
            history["iter"] = list(range(len(history["objective"])))
        status = "Interrupted_By_User" if interrupted else stats.get("return_status", "unknown")
        success = bool(stats.get("success", False)) and not interrupted
        n_iter = int(stats.get("iter_count", 0))
        if not (0 <= n_iter <= int(ipopt["max_iter"])):
            # IPOPT aborted (interrupt, exception): its counter is not set; use what was logged
            n_iter = max(len(history["objective"]) - 1, 0)
        solution = Solution._from_debug(self, debug, status=status, success=success,
                                        iterations=n_iter, wall_time_s=wall,
                                        stats=stats, history=history)
        if raise_on_failure and not success:
            raise SolveError(f"{self.name}: IPOPT ended with {status}\n" + solution.violation_report(), solution)
        return solution

    def nlp_size(self) -> dict:
        """Variables, constraints and derivative nonzeros of the NLP IPOPT sees.

        Counts after simple-bound detection (bounds are not constraints).
        """
        size = self.size()
        try:
            solver = self.opti.debug.casadi_solver
            jac = solver.get_function("nlp_jac_g")
            hes = solver.get_function("nlp_hess_l")
            size["constraints_ipopt"] = int(jac.sparsity_out(1).size1())
            size["jacobian_nnz"] = int(jac.sparsity_out(1).nnz())
            size["hessian_nnz"] = int(hes.sparsity_out(0).nnz())
        except Exception:  # solver not built yet or limited-memory Hessian
            pass
        return size


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

        values = {}
        variables = []
        for v in problem.variables.values():
            x = np.reshape(val(v.scaled), v.shape) * v.scale
            values[v.name] = x
            variables.append({"name": v.name, "unit": v.unit, "value": _jsonable(x),
                              "design": v.design, "description": v.description})
        outputs = {}
        for o in problem.outputs.values():
            outputs[o.name] = {"value": _jsonable(val(o.expr)), "unit": o.unit, "summary": o.summary}
        violations = []
        for g in problem.groups.values():
            r = val(g.residual).ravel()
            if g.kind == "==":
                viol = np.abs(r)
            elif g.kind == "<=":
                viol = np.maximum(r, 0.0)
            else:
                viol = np.maximum(-r, 0.0)
            bad = ~np.isfinite(r)
            viol = np.where(bad, np.inf, viol)
            i = int(np.argmax(viol)) if viol.size else 0
            violations.append({"group": g.name, "kind": g.kind, "nonfinite": int(bad.sum()),
                               "max_violation": float(viol[i] * g.scale) if viol.size else 0.0,
                               "scaled": float(viol[i]) if viol.size else 0.0,
                               "where": g.labels[i] if viol.size else "", "unit": g.unit,
                               "size": g.size})
        violations.sort(key=lambda d: -d["scaled"])
        obj = float(val(problem.objective)) if problem.objective is not None else float("nan")
        timing = {k: float(v) for k, v in stats.items() if k.startswith("t_wall_") or k.startswith("n_call_")}
        sol = cls(problem.name, status, success, iterations, wall_time_s, obj, problem.objective_unit,
                  problem.objective_name, variables, outputs, violations, history,
                  problem.nlp_size(), timing, analysis=problem._analysis)
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
        return "\n".join(lines)

    def to_dict(self) -> dict:
        return {"problem": self.problem_name, "status": self.status, "success": self.success,
                "objective": {"name": self.objective_name, "value": self.objective,
                              "unit": self.objective_unit},
                "variables": self.variables, "outputs": self.outputs}

    def summary(self) -> dict:
        d = {"problem": self.problem_name, "mode": "analysis" if self.analysis else "optimization",
             "status": self.status, "success": self.success,
             "objective": {"name": self.objective_name, "value": self.objective, "unit": self.objective_unit},
             "iterations": self.iterations, "wall_time_s": round(self.wall_time_s, 3),
             "nlp_size": self.nlp_size}
        d.update(self.summary_values())
        d["worst_violations"] = [v for v in self.violations[:5]]
        d["timing"] = self.timing
        return d

    # -------------------------------------------------------------- files
    def save(self, out_dir: str | os.PathLike) -> Path:
        """Write solution.json, summary.json, summary.md, convergence.csv into ``out_dir``."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        with open(out / "solution.json", "w") as f:
            json.dump(self.to_dict(), f, indent=1, default=_json_default)
        with open(out / "summary.json", "w") as f:
            json.dump(self.summary(), f, indent=1, default=_json_default)
        (out / "summary.md").write_text(self.summary_markdown())
        if (out / "ipopt.log").exists():   # one source: the iteration lines the log shows
            from ..plots.convergence import write_convergence_csv
            write_convergence_csv(out / "ipopt.log", out / "convergence.csv")
            return out
        with open(out / "convergence.csv", "w") as f:   # no log: the intermediate callback's history
            f.write("iter,objective,inf_pr,inf_du\n")
            h = self.history
            for i in range(len(h.get("objective", []))):
                f.write(f"{i},{h['objective'][i]:.10g},{h['inf_pr'][i]:.6g},{h['inf_du'][i]:.6g}\n")
        return out

    def summary_markdown(self) -> str:
        lines = [f"# {self.problem_name}: {'analysis' if self.analysis else 'optimization'}", "",
                 f"- status: **{self.status}** ({'converged' if self.success else 'NOT converged'})",
                 f"- {self.objective_name}: {self.objective:.6g} {self.objective_unit}",
                 f"- IPOPT iterations: {self.iterations}; wall time {self.wall_time_s:.2f} s",
                 f"- NLP: " + ", ".join(f"{k} {v}" for k, v in self.nlp_size.items()), ""]
        sv = self.summary_values()
        if sv:
            lines += ["## Results", "", "| quantity | value | unit |", "|---|---|---|"]
            for k, val in sv.items():
                lines.append(f"| {k} | {_fmt(val)} | {self.outputs[k]['unit']} |")
            lines.append("")
        design = [v for v in self.variables if v["design"]]
        if design:
            lines += ["## Design variables", "", "| name | value | unit | description |", "|---|---|---|---|"]
            for v in design:
                lines.append(f"| {v['name']} | {_fmt(v['value'])} | {v['unit']} | {v['description']} |")
            lines.append("")
        lines += ["## Constraint groups (worst scaled violation)", "", self.violation_report(top=10), ""]
        return "\n".join(lines)


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
