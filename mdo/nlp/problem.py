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
import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Sequence

import casadi as ca
import numpy as np

from ..core.errors import InputError
from ..core.signals import interrupt_signal
from .hessian import lagrangian_hessian_functions
from .warm_start import WarmStart, WarmStartError, WarmStartMixin, read_solution  # noqa: F401
from .ipopt import (BARRIERS, CRASH_ON_EXIT_STATUS, FRAGILE, FROM_BASELINE_OPTIONS, HESSIAN_CHOICES,  # noqa: F401
                    DivergenceWatch, check_threads, default_threads,
                    INTERRUPT_STATUS, WARM_START_OPTIONS, _outcome, _signals_as_interrupts)
# re-exported: the solved side lives in mdo.nlp.solution
from .solution import (ACTIVE_SLACK, DESIGN_BOUND_FRACTION, Solution, _readable, _variable_arrays,  # noqa: F401
                       element_label, group_residual, write_atomic)

__all__ = ["Problem", "Variable", "ConstraintGroup", "Solution", "SolveError", "WarmStartError",
           "WarmStart", "INTERRUPT_STATUS"]

class SolveError(RuntimeError):
    """A solve that did not converge; ``.solution`` holds the last iterate and report."""

    def __init__(self, message: str, solution: "Solution"):
        super().__init__(message)
        self.solution = solution


# how far a frozen design's design-level limits are lifted (scaled units: the group's own scale)
DESIGN_LEVEL_LIFT = 1e3


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
    bound_con: object = None   # the Opti ``bounded`` constraint (its dual is IPOPT's lam_x)

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
    lhs: object = None      # expr (model units); values flattened column-major like the residual
    rhs: object = None      # rhs (number, array or expression)
    con: object = None      # the Opti constraint (its dual is IPOPT's lam_g)
    defines: str | None = None   # the variable this equality defines (Problem.constrain)


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


class Problem(WarmStartMixin):
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
        self._design_level_lifts: list = []   # parameters of the design-level groups (constrain)
        # the barriers of an optimization from its converged baseline, in the order tried: the
        # first with the divergence watch, the second if the first ends without an optimum
        # (start_from_baseline, fallback_barrier_after; DESIGN rule 7 in mdo/README.md)
        self.barrier_order: tuple[str, str] = ("monotone", "adaptive")
        self.barrier_fallback_from: dict | None = None   # the failed attempt a retry follows
        self.divergence_watch: DivergenceWatch | None = None   # gives up a wandering solve (has a fallback)

    # ------------------------------------------------------------------ build
    def start_from_baseline(self) -> bool:
        """Use the first barrier of ``barrier_order`` for an optimization that starts from its
        converged baseline ("monotone": ``FROM_BASELINE_OPTIONS``; "adaptive": IPOPT's adaptive
        barrier from its own mu_init), with the divergence watch, unless the problem set its own
        barrier (a ``mu_init`` or a non-adaptive ``mu_strategy`` in its IPOPT options).  True if
        applied (then ``fallback_barrier_after`` may retry with the second)."""
        if self.barrier_order[0] not in BARRIERS or self.barrier_order[1] not in BARRIERS \
                or self.barrier_order[0] == self.barrier_order[1]:
            raise InputError("barrier_order", f"two different barriers of {', '.join(BARRIERS)}, "
                                              f"got {self.barrier_order!r}")
        if self.ipopt_options.get("mu_strategy", "adaptive") == "adaptive" and "mu_init" not in self.ipopt_options:
            self._use_barrier(self.barrier_order[0])
            self.divergence_watch = DivergenceWatch()
            return True
        return False

    def _use_barrier(self, kind: str) -> None:
        for key in FROM_BASELINE_OPTIONS:
            self.ipopt_options.pop(key, None)
        self.ipopt_options.update(FROM_BASELINE_OPTIONS if kind == "monotone" else {"mu_strategy": "adaptive"})

    def fallback_barrier_after(self, failed: "Solution", folder: str) -> None:
        """Switch to the second barrier of ``barrier_order`` after a first attempt from the
        baseline that did not converge; the next solution records the failed attempt (its
        status, iterations, objective and the folder its files were kept in)."""
        self._use_barrier(self.barrier_order[1])
        self.divergence_watch = None
        self.barrier_fallback_from = {"mu_strategy": failed.barrier.get("mu_strategy", "?"),
                                      "status": failed.status, "iterations": failed.iterations,
                                      "objective": failed.objective, "folder": folder}
        if failed.stopped_because:
            self.barrier_fallback_from["stopped_because"] = failed.stopped_because

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
        bound_con = None
        if np.any(np.isfinite(lo_s)) or np.any(np.isfinite(up_s)):
            lo_s = np.where(np.isfinite(lo_s), lo_s, -np.inf)
            up_s = np.where(np.isfinite(up_s), up_s, np.inf)
            bound_con = self.opti.bounded(ca.DM(lo_s), X, ca.DM(up_s))
            self.opti.subject_to(bound_con)
        self.opti.set_initial(X, ca.DM(init / scale))
        var = Variable(name, shp, unit, scale, lower, upper, init, X, expr, design=design,
                       description=description, labels=list(labels) if labels else None,
                       bound_con=bound_con)
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
                  unit: str = "-", labels: Sequence[str] | None = None, defines: str | None = None,
                  design_level: bool = False):
        """Add a named group ``expr (kind) rhs``, scaled by ``scale`` (a typical residual).

        ``defines``: the name of a variable ``v`` this equality defines, ``expr = v -
        f(other variables)`` with ``v`` at coefficient one (a lifted intermediate, e.g. a
        rotor's thrust at the nodes): the solve starts ``v`` at ``f`` of the initial point
        (:meth:`start_defined`), whatever its own guess was.

        ``design_level``: an inequality on the design alone (a geometric limit, e.g. a
        propeller's clearance to the fuselage): enforced while the design is free, lifted by
        :meth:`freeze_design` (a given design is flown as it is; the group still reports its
        value, so a violation shows in the solution's violations)."""
        if kind not in ("==", "<=", ">="):
            raise InputError(f"constraint {name!r} kind", f"must be '==', '<=' or '>=', got {kind!r}")
        if design_level and kind == "==":
            raise InputError(f"constraint {name!r} design_level", "only an inequality can be lifted")
        if name in self.groups:
            raise InputError("constraint group name", f"{name!r} is already defined")
        if not (np.isfinite(scale) and scale > 0):
            raise InputError(f"constraint {name!r} scale", "must be finite and > 0")
        r = ca.vec((expr - rhs) / float(scale))
        n = int(r.numel())
        if n == 0:
            return
        if design_level:
            # r + lift >= 0 (r - lift <= 0): lift 0 while the design is free, DESIGN_LEVEL_LIFT once frozen
            lift = self.opti.parameter(n, 1)
            self.opti.set_value(lift, 0.0)
            self._design_level_lifts.append(lift)
            r_con = r + lift if kind == ">=" else r - lift
        else:
            r_con = r
        con = (r_con == 0) if kind == "==" else (r_con <= 0) if kind == "<=" else (r_con >= 0)
        self.opti.subject_to(con)
        if labels is None:
            labels = [f"{name}[{i}]" for i in range(n)]
        labels = list(labels)
        if len(labels) != n:
            raise InputError(f"constraint {name!r} labels", f"{len(labels)} labels for {n} elements")
        if defines is not None:
            var = self.variables.get(defines)
            if kind != "==" or var is None or var.size != n:
                raise InputError(f"constraint {name!r} defines", f"an equality of the size of an existing variable, "
                                 f"got {kind!r} with {n} elements for {defines!r}")
        self.groups[name] = ConstraintGroup(name, kind, r, float(scale), unit, labels, n,
                                            lhs=expr, rhs=rhs, con=con, defines=defines)

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
        for lift in self._design_level_lifts:   # design-level limits: reported, not enforced
            self.opti.set_value(lift, DESIGN_LEVEL_LIFT)
        self._analysis = True

    @property
    def is_analysis(self) -> bool:
        """No free design variable: frozen (``--analysis``) or a problem without any."""
        return self._analysis or not any(v.design and not v.frozen for v in self.variables.values())

    def set_initial(self, name: str, value):
        v = self.variables[name]
        val = np.clip(_broadcast(value, v.shape, "initial guess", name), v.lower, v.upper)
        v.init = val
        self.opti.set_initial(v.scaled, ca.DM(val / v.scale))

    def start_defined(self) -> None:
        """Start every variable that an equality defines (``constrain(defines=...)``) at its
        definition's value at the current initial point: ``v <- v - (v - f)``, repeated
        while one defined variable feeds another's definition (at most once per group)."""
        groups = [g for g in self.groups.values() if g.defines is not None]
        if not groups:
            return
        opti = self.opti
        f = ca.Function("defined", [opti.x, opti.p], [ca.vec(g.lhs - g.rhs) for g in groups])
        par = opti.debug.value(opti.p, opti.value_parameters()) if opti.np else ca.DM()
        for _ in range(len(groups)):
            x0 = opti.debug.value(opti.x, opti.initial())
            worst = 0.0
            for g, r in zip(groups, f.call([x0, par])):
                v = self.variables[g.defines]
                r = np.asarray(r, float).reshape(v.shape, order="F")
                worst = max(worst, float(np.max(np.abs(r) / v.scale)) if r.size else 0.0)
                self.set_initial(v.name, v.init - r)
            if not worst > 1e-12:   # (NaN: stop too; the solve reports it)
                break

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
              hessian: str = "exact", progress: Callable | None = None,
              threads: int | None = None) -> "Solution":
        """Solve with IPOPT; stream the log to the terminal and to ``log_path``.

        Returns a ``Solution`` whatever the outcome (check ``.success``); with
        ``raise_on_failure`` a failed solve raises ``SolveError`` carrying it.
        ``hessian``: ``"exact"`` (default: the exact Hessian split into its node block
        and global rows, :mod:`mdo.nlp.hessian`), ``"full"`` (the same matrix from
        CasADi's one colouring of all variables, slower) or ``"limited-memory"``.
        SIGINT and SIGTERM stop IPOPT and keep the last iterate (status
        ``Interrupted_By_User`` / ``Terminated_By_Signal``).  ``progress(text)`` is
        told of the silent phases.  ``threads`` (1 or 2; default
        :func:`mdo.nlp.ipopt.default_threads`): the exact Hessian's two parts each in their
        own thread (:mod:`mdo.nlp.threads`; the same matrix, to the bit).
        """
        if self.objective is None:
            self.opti.minimize(0)
        self.start_defined()
        ipopt = dict(self.ipopt_options)
        if max_iter is not None:
            ipopt["max_iter"] = int(max_iter)
        if hessian not in HESSIAN_CHOICES:
            raise InputError("hessian", f"one of {', '.join(HESSIAN_CHOICES)}, got {hessian!r}")
        if hessian == "limited-memory":
            ipopt["hessian_approximation"] = "limited-memory"
        ipopt["print_level"] = 5 if verbose else 0
        if not verbose:
            ipopt["sb"] = "yes"  # no banner
        if log_path is not None:
            log_path = Path(log_path)
            ipopt["output_file"] = str(log_path)
            ipopt["file_print_level"] = 5
        warm_lam = getattr(self, "_warm_lam", None)
        if warm_lam is not None and warm_lam.size == int(self.opti.ng):
            # restart from a converged primal-dual point: keep IPOPT from pushing the point
            # and multipliers off their bounds, and start with a small barrier (Wachter &
            # Biegler 2006, sec. 3.6; IPOPT option docs "Warm Start")
            self.opti.set_initial(self.opti.lam_g, ca.DM(warm_lam))
            ipopt.update(WARM_START_OPTIONS)
        self._warm_lam = None   # used once
        if options:
            ipopt.update(options)
        plugin = {"detect_simple_bounds": True, "print_time": verbose,
                  "error_on_fail": False, "expand": False}
        threads = default_threads() if threads is None else check_threads(threads)
        skip_fixed = ipopt.get("fixed_variable_treatment", "make_parameter") == "make_parameter"
        if hessian == "exact":   # the same matrix, computed by structure (mdo.nlp.hessian)
            plugin["hess_lag"] = lagrangian_hessian_functions(self, "split", skip_fixed=skip_fixed,
                                                              threads=threads)
        # The Jacobian stays CasADi's own: its two-thread form (constraint_jacobian_function)
        # agrees only to round-off, and the TTW's path from its baseline is sensitive to that
        # (116.39 kWh in 151 iterations becomes 119.44 in 197; results/benchmark.md).
        self.opti.solver("ipopt", plugin, ipopt)
        watch = self.divergence_watch if log_path is not None else None
        if watch is not None:
            watch.reason = None
            self.opti.callback(lambda i: watch.check(log_path, i))
        else:
            self.opti.callback()
        if progress is not None:
            progress("building derivative functions (Jacobian, Hessian) and starting IPOPT")

        t0 = time.perf_counter()
        with _signals_as_interrupts() as caught:
            try:
                sol = self.opti.solve()
                debug = sol
            except KeyboardInterrupt as exc:
                caught.setdefault("signal", interrupt_signal(exc))
                debug = self.opti.debug
            except RuntimeError:
                debug = self.opti.debug
        wall = time.perf_counter() - t0
        stats = {}
        with contextlib.suppress(Exception):
            stats = dict(self.opti.stats())
        history, status, success, n_iter = _outcome(stats, int(ipopt["max_iter"]), caught.get("signal"))
        if status in CRASH_ON_EXIT_STATUS:
            FRAGILE.append(self.opti)   # kept alive: destroying it crashes
        solution = Solution._from_debug(self, debug, status=status, success=success,
                                        iterations=n_iter, wall_time_s=wall,
                                        stats=stats, history=history)
        solution.stopped_because = watch.reason if watch is not None else None
        solution.barrier = {"mu_strategy": ipopt.get("mu_strategy", "monotone"),
                            "mu_init": float(ipopt.get("mu_init", 0.1))}   # IPOPT's defaults
        if self.barrier_fallback_from:
            solution.barrier["fallback_from"] = dict(self.barrier_fallback_from)
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
