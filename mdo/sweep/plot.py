"""Figures of a sweep from its ``sweep.csv``: line plots and carpet plots.

* **Line plot** ``--x KEY [--y COLUMN]``: the column (default ``objective``) against one
  input, one line per combination of the other inputs.
* **Carpet plot** ``--x KEY --carpet KEY2``: two inputs on one chart.  The
  horizontal position of a point is ``i + stagger * j`` (``i``, ``j`` the indices of its
  values of KEY and KEY2; the "cheater axis" of carpet plots, which has no scale of its
  own); lines of constant KEY and of constant KEY2 form the carpet and are labelled
  at their ends, the vertical axis is the output.  The other inputs must have one
  value (a carpet of a sub-grid: sweep it alone).

Only converged points are drawn; the title says how many others there were.
"""
from __future__ import annotations

import json
from pathlib import Path

from ..core.errors import InputError
from .table import read_table

__all__ = ["line_plot", "carpet_plot", "plot_sweep"]

_STAGGER = 0.35


def _load(sweep_dir):
    d = Path(sweep_dir)
    if not (d / "sweep.csv").exists():
        raise InputError("DIR", f"{d}: no sweep.csv (not a sweep folder, or no point finished yet)")
    meta = json.loads((d / "sweep.json").read_text()) if (d / "sweep.json").exists() else {}
    return read_table(d / "sweep.csv"), meta.get("grid", {}), meta


def _check(rows, grid, keys, y):
    cols = set().union(*(r.keys() for r in rows)) if rows else set()
    for k in keys:
        if k not in grid:
            raise InputError("--x" if k == keys[0] else "--carpet",
                             f"{k!r} is not a grid key of this sweep; keys: {', '.join(grid)}")
    if y not in cols:
        numeric = sorted(c for c in cols if any(isinstance(r.get(c), (int, float)) and not isinstance(r.get(c), bool)
                                                for r in rows))
        raise InputError("--y", f"no column {y!r} in sweep.csv; numeric columns: {', '.join(numeric)}")


def _title(meta, rows, ok, y):
    prob = Path(meta.get("problem", "sweep")).stem
    bad = len(rows) - len(ok)
    commit = meta.get("git_commit", "")[:12]
    extra = f"; {bad} point(s) not converged, not drawn" if bad else ""
    return f"{prob}: {y}{extra}" + (f"\nmodel {commit}" if commit else "")


def _ylabel(rows, y):
    if y == "objective" and rows:
        return f"{rows[0].get('objective_name')} [{rows[0].get('objective_unit')}]"
    return y


def line_plot(sweep_dir, x: str, y: str = "objective", out=None) -> Path:
    """``y`` against grid key ``x``, one line per combination of the other keys; returns the PNG path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows, grid, meta = _load(sweep_dir)
    _check(rows, grid, [x], y)
    ok = [r for r in rows if r.get("success") and isinstance(r.get(y), (int, float))]
    others = [k for k in grid if k != x and len(grid[k]) > 1]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    groups = {}
    for r in ok:
        groups.setdefault(tuple(r[k] for k in others), []).append(r)
    for key, rs in groups.items():
        rs.sort(key=lambda r: grid[x].index(r[x]) if r[x] in grid[x] else 0)
        label = ", ".join(f"{k}={v}" for k, v in zip(others, key)) or None
        ax.plot([r[x] for r in rs], [r[y] for r in rs], "o-", label=label)
    ax.set_xlabel(x)
    ax.set_ylabel(_ylabel(rows, y))
    ax.set_title(_title(meta, rows, ok, y), fontsize=9)
    ax.grid(True, alpha=0.3)
    if others:
        ax.legend(fontsize=8)
    path = Path(out) if out else Path(sweep_dir) / f"{y}_vs_{x}.png"
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def carpet_plot(sweep_dir, x: str, carpet: str, y: str = "objective", out=None) -> Path:
    """Carpet of ``y`` over grid keys ``x`` and ``carpet`` (see module docstring); returns the PNG path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows, grid, meta = _load(sweep_dir)
    _check(rows, grid, [x, carpet], y)
    if x == carpet:
        raise InputError("--carpet", "must differ from --x")
    varying = [k for k in grid if k not in (x, carpet) and len(grid[k]) > 1]
    if varying:
        raise InputError("--carpet", f"the other grid keys must have one value for a carpet; "
                                     f"{', '.join(varying)} vary (sweep a sub-grid into its own folder)")
    ok = {(r[x], r[carpet]): r[y] for r in rows if r.get("success") and isinstance(r.get(y), (int, float))}
    xi = {v: i for i, v in enumerate(grid[x])}
    cj = {v: j for j, v in enumerate(grid[carpet])}
    fig, ax = plt.subplots(figsize=(6.8, 4.6))
    def draw(pairs, label, style, at_end):
        pts = [(xi[a] + _STAGGER * cj[c], ok[(a, c)]) for a, c in pairs if (a, c) in ok]
        if pts:
            h, v = zip(*pts)
            ax.plot(h, v, style, marker="o", ms=3)
            # blue labels at the lines' ends, orange at their starts: the last of each meet in a corner
            k, off, ha = (-1, (4, 2), "left") if at_end else (0, (-4, -8), "right")
            ax.annotate(label, (h[k], v[k]), textcoords="offset points", xytext=off, fontsize=7,
                        color=style[:2], ha=ha)

    for c in grid[carpet]:   # lines of constant KEY2, along KEY
        draw([(a, c) for a in grid[x]], f"{carpet}={c}", "C0-", True)
    for a in grid[x]:        # lines of constant KEY, along KEY2
        draw([(a, c) for c in grid[carpet]], f"{x}={a}", "C1-", False)
    missing = [f"{x}={a}, {carpet}={c}" for a in grid[x] for c in grid[carpet] if (a, c) not in ok]
    ax.set_xticks([])
    ax.margins(x=0.12)
    ax.set_xlabel(f"carpet: {x} (orange lines of constant {x})\nx {carpet} (blue lines of constant {carpet})"
                  + (f"\nnot converged, not drawn: {'; '.join(missing)}" if missing else ""), fontsize=8)
    ax.set_ylabel(_ylabel(rows, y))
    ax.set_title(_title(meta, rows, [r for r in rows if (r.get(x), r.get(carpet)) in ok], y), fontsize=9)
    ax.grid(True, axis="y", alpha=0.3)
    path = Path(out) if out else Path(sweep_dir) / f"carpet_{y}_{x}_{carpet}.png"
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def plot_sweep(sweep_dir, x: str, y: str | None = None, carpet: str | None = None, out=None) -> Path:
    y = y or "objective"
    if carpet:
        return carpet_plot(sweep_dir, x, carpet, y, out)
    return line_plot(sweep_dir, x, y, out)
