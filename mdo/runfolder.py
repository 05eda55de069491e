"""Read a run folder in Python: values by name with units, the mission table, the design.

``mdo run`` writes a folder (``summary.json``, ``solution.json``, ``mission.csv``,
``design.json`` ...); :func:`read_run` turns it back into numbers without re-solving::

    from mdo.runfolder import read_run
    run = read_run("results/ga2p")
    run.status, run.objective                    # 'Solve_Succeeded', (51.6, 'kWh')
    run.value("togw_kg")                         # (2062.4, 'kg')  an output or a variable
    run.mission["speed_mps"]                     # numpy column of mission.csv, SI
    run.segment("CR")["shaft_power_W"]           # the rows of one segment
    run.design                                   # design.json (aircraft runs), a dict
    run.baseline                                 # the analysis/ stage of an optimization, or None

Files that are missing give ``None`` (a polar-vehicle run has no ``design.json``); a
folder without ``summary.json`` is not a run and raises ``InputError``.
"""
from __future__ import annotations

import csv
import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .core.errors import InputError

__all__ = ["RunFolder", "read_run"]


def _json(path: Path):
    if not path.is_file():
        return None
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError) as exc:
        raise InputError(str(path), f"is not a readable JSON file ({exc})") from exc


def _mission(path: Path) -> dict | None:
    if not path.is_file():
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return {}
    out = {}
    for key in rows[0]:
        col = [r[key] for r in rows]
        try:
            out[key] = np.array([float(x) if x not in ("", None) else np.nan for x in col])
        except ValueError:
            out[key] = np.array(col, dtype=object)
    return out


@dataclass
class RunFolder:
    """One run folder's results (see the module docstring)."""

    path: Path
    summary: dict
    solution: dict | None
    mission: dict | None
    design: dict | None
    _values: dict = field(default_factory=dict, repr=False)

    @property
    def status(self) -> str:
        return self.summary.get("status", "")

    @property
    def success(self) -> bool:
        return bool(self.summary.get("success", False))

    @property
    def objective(self) -> tuple:
        o = self.summary.get("objective", {})
        return o.get("value"), o.get("unit", "-")

    def value(self, name: str) -> tuple:
        """(value, unit) of an output or a variable by name (arrays as numpy)."""
        if not self._values and self.solution:
            for k, o in (self.solution.get("outputs") or {}).items():
                self._values[k] = (o.get("value"), o.get("unit", "-"))
            for v in self.solution.get("variables") or []:
                self._values.setdefault(v["name"], (v.get("value"), v.get("unit", "-")))
        if name not in self._values:
            known = sorted(self._values)
            raise InputError("name", f"{name!r} is not an output or variable of {self.path}; known: "
                             f"{', '.join(known[:20])}{' ...' if len(known) > 20 else ''}")
        v, unit = self._values[name]
        return (np.asarray(v, float) if isinstance(v, list) else v), unit

    def segment(self, name: str) -> dict:
        """The mission rows of segment ``name``."""
        if not self.mission or "segment" not in self.mission:
            raise InputError("segment", f"{self.path} has no mission table")
        sel = self.mission["segment"] == name
        if not np.any(sel):
            raise InputError("segment", f"no segment {name!r}; have {sorted(set(self.mission['segment']))}")
        return {k: v[sel] for k, v in self.mission.items()}

    @property
    def baseline(self) -> "RunFolder | None":
        p = self.path / "analysis"
        return read_run(p) if (p / "summary.json").is_file() else None


def read_run(path) -> RunFolder:
    """Read the run folder at ``path`` (see the module docstring)."""
    p = Path(path)
    summary = _json(p / "summary.json")
    if summary is None:
        raise InputError(str(p), "is not a run folder (no summary.json)")
    return RunFolder(p, summary, _json(p / "solution.json"), _mission(p / "mission.csv"), _json(p / "design.json"))
