"""Warm starts of a :class:`~mdo.nlp.problem.Problem`: read an earlier solution, check it
against the problem (name, variable names and sizes, finite values), set what fits and,
on a full fit from the same mode, IPOPT's multipliers (issue 19: a warm start checks what
it loads).  ``Problem`` inherits :class:`WarmStartMixin`.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass, field

import casadi as ca
import numpy as np

from ..core.errors import InputError
from .solution import Solution

__all__ = ["WarmStart", "WarmStartError", "WarmStartMixin", "read_solution"]


class WarmStartError(InputError):
    """A warm-start file that does not fit the problem (name, variables, sizes, values)."""


@dataclass
class WarmStart:
    """What a warm start used: ``len(ws)`` variables of ``ws.total``."""

    source_problem: object
    problem: str
    total: int
    used: list = field(default_factory=list)
    missing: list = field(default_factory=list)     # problem variables the file lacks
    extra: list = field(default_factory=list)       # file variables the problem lacks
    bad: list = field(default_factory=list)         # "name has 20 values, expected 30", non-finite
    problems: list = field(default_factory=list)    # whole-file mismatches (problem name)
    values: dict = field(default_factory=dict, repr=False)
    same_mode: bool = True
    multipliers: bool = False

    def __len__(self) -> int:
        return len(self.used)

    def __iter__(self):
        return iter(self.used)

    @property
    def complete(self) -> bool:
        return not (self.missing or self.extra or self.bad or self.problems)

    def describe(self) -> str:
        """One line: how much of the file fits and, if not all, why (first reasons)."""
        text = f"{len(self.used)} of {self.total} variables match"
        why = list(self.problems) + self.bad[:3]
        if self.missing:
            why.append(f"{len(self.missing)} variable(s) missing from the file, e.g. {self.missing[0]!r}")
        if self.extra:
            why.append(f"{len(self.extra)} variable(s) not in this problem, e.g. {self.extra[0]!r}")
        return text + (" (" + "; ".join(why) + ")" if why else "")


def read_solution(source) -> dict:
    """A solution dict from a ``Solution``, a dict or a ``solution.json`` path, checked
    for the structure a warm start needs (``WarmStartError`` names the file otherwise)."""
    if isinstance(source, Solution):
        return source.to_dict()
    where = "warm start"
    if isinstance(source, (str, os.PathLike)):
        where = f"warm start {source}"
        try:
            with open(source, "rb") as f:
                raw = f.read(512 * 1024 * 1024 + 1)   # a solution.json is MBs; do not read without bound
            if len(raw) > 512 * 1024 * 1024:
                raise WarmStartError(where, "file larger than 512 MiB, not a solution.json")
            data = json.loads(raw.decode("utf-8"))
        except WarmStartError:
            raise
        except OSError as exc:
            raise WarmStartError(where, f"cannot read ({exc.strerror or exc})") from exc
        except (UnicodeDecodeError, ValueError) as exc:
            raise WarmStartError(where, f"not a solution.json (invalid JSON: {exc})") from exc
    else:
        data = source
    if not isinstance(data, dict) or not isinstance(data.get("variables"), list):
        raise WarmStartError(where, "not a solution.json (no 'variables' list)")
    return data


class WarmStartMixin:
    """``warm_start`` and its helpers (uses the problem's ``variables``, ``groups``,
    ``opti``, ``objective_scale``, ``set_initial`` and ``_analysis``)."""

    def warm_start(self, solution: "Solution | dict | str | os.PathLike", *, partial: bool = False,
                   multipliers: bool = True) -> "WarmStart":
        """Initial guess from an earlier solution (object, dict or ``solution.json``).

        The source is checked first and nothing is set unless it fits: the problem
        name, every (non-frozen) variable's name and size, finite values.  A partial
        fit raises ``WarmStartError`` naming how many variables of how many match,
        unless ``partial=True`` (then the matching variables are set).  On a full fit
        from a solve of the same mode (analysis / optimization) the stored multipliers
        are loaded too and IPOPT's ``warm_start_init_point`` is used, so a converged
        point re-converges in a couple of iterations.  Returns a ``WarmStart`` report.
        """
        data = read_solution(solution)
        ws = self._match_warm_start(data)
        if not ws.complete and not partial:
            raise WarmStartError("warm start", ws.describe() + "; refused (allow a partial warm start to use "
                                 "the matching variables)")
        for name in ws.used:
            self.set_initial(name, ws.values[name])
        self._warm_lam = None
        if multipliers and ws.complete and ws.same_mode:
            lam = self._multipliers_from(data)
            if lam is not None:
                self._warm_lam = lam
                ws.multipliers = True
        return ws

    def _match_warm_start(self, data: dict) -> "WarmStart":
        """Compare a solution dict with this problem (no side effects)."""
        src_name = data.get("problem")
        targets = {n: v for n, v in self.variables.items() if not v.frozen}
        ws = WarmStart(source_problem=src_name, problem=self.name, total=len(targets))
        ws.same_mode = data.get("mode", "optimization" if not data.get("analysis") else "analysis") == \
            ("analysis" if self._analysis else "optimization")
        if src_name != self.name:
            ws.problems.append(f"written by problem {src_name!r}, this is {self.name!r}")
        seen = set()
        for item in data["variables"]:
            name = item.get("name") if isinstance(item, dict) else None
            if not isinstance(name, str) or "value" not in item:
                raise WarmStartError("warm start", f"variables entry {item!r:.60} has no name and value")
            seen.add(name)
            v = self.variables.get(name)
            if v is None:
                ws.extra.append(name)
                continue
            if v.frozen:
                continue
            try:
                val = np.asarray(item["value"], dtype=float)
            except (TypeError, ValueError):
                ws.bad.append(f"{name!r} has non-numeric values")
                continue
            if val.size != v.size:
                ws.bad.append(f"{name!r} has {val.size} values, expected {v.size}")
                continue
            if not np.all(np.isfinite(val)):
                ws.bad.append(f"{name!r} has {int(np.sum(~np.isfinite(val)))} non-finite value(s)")
                continue
            ws.used.append(name)
            ws.values[name] = val.reshape(v.shape)
        ws.missing = [n for n in targets if n not in seen]
        return ws

    def _dual_index(self) -> dict:
        """Where each variable's bounds and each group sit in ``opti.lam_g``.

        Found by evaluating Opti's dual expressions at lam_g = 1..ng (CasADi keeps
        no public index): ``{("x"|"g", name): int array}``, -1 where none.
        """
        ng = int(self.opti.ng)
        cached = getattr(self, "_dual_cache", None)
        if cached is not None and cached[0] == ng:
            return cached[1]
        keys, exprs = [], []
        for v in self.variables.values():
            if v.bound_con is not None:
                keys.append(("x", v.name, v.size))
                exprs.append(ca.vec(self.opti.dual(v.bound_con)))
        for g in self.groups.values():
            keys.append(("g", g.name, g.size))
            exprs.append(ca.vec(self.opti.dual(g.con)))
        index = {}
        if exprs and ng:
            f = ca.Function("dual_index", [self.opti.lam_g], exprs)
            a = np.arange(1, ng + 1, dtype=float)
            pos, neg = f.call([a]), f.call([-a])
            for (kind, name, n), p_, n_ in zip(keys, pos, neg):
                m = np.maximum(np.abs(np.asarray(p_, float).ravel()), np.abs(np.asarray(n_, float).ravel()))
                if m.size == 2 * n:   # a two-sided bound: one block per side, one of them zero
                    m = np.maximum(m[:n], m[n:])
                index[(kind, name)] = m.astype(int) - 1
        self._dual_cache = (ng, index)
        return index

    def _multipliers_from(self, data: dict):
        """Full lam_g vector (IPOPT's scaled NLP) from a solution dict's physical
        multipliers, or None when the file has none or they do not fit."""
        idx = self._dual_index()
        lam = np.zeros(int(self.opti.ng))
        fs = self.objective_scale
        try:
            for item in data["variables"]:
                v = self.variables.get(item["name"])
                if v is None or ("x", v.name) not in idx or item.get("multiplier") is None:
                    continue
                m = np.asarray(item["multiplier"], float).reshape(v.shape)
                i = idx[("x", v.name)]
                lam[i[i >= 0]] = (np.ravel(m * v.scale, order="F") / fs)[i >= 0]
            for item in data.get("constraints", []):
                g = self.groups.get(item["name"])
                if g is None or item.get("multiplier") is None:
                    continue
                m = np.asarray(item["multiplier"], float).ravel()
                if m.size != g.size:
                    return None
                lam[idx[("g", g.name)]] = m * g.scale / fs
        except (KeyError, TypeError, ValueError):
            return None
        if not data.get("constraints") or not np.all(np.isfinite(lam)):
            return None
        return lam
