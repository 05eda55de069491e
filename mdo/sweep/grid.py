"""Grid of a trade study: parse ``--grid KEY=V1,V2,...``, check the keys, expand the points.

A grid is a dict ``key -> [values]`` over the options of a problem file's
``build(**options)``; its points are the Cartesian product.  Each point has a run
folder named ``key=value,key2=value2`` (keys in the order of ``build()``'s
signature, so the name does not depend on the order of the ``--grid`` flags and a
resumed sweep finds its folders again).
"""
from __future__ import annotations

import importlib.util
import inspect
import itertools
import json
import sys
from pathlib import Path

from ..core.errors import InputError

__all__ = ["parse_grid", "build_parameters", "check_keys", "expand", "point_name", "structural_keys"]

# Characters a value may not carry into a folder name.
_BAD_NAME_CHARS = set('/\\:*?"<>|,= ')


def _parse_value(text: str):
    """A grid value: JSON when it parses (numbers, true/false, null), else the bare string."""
    text = text.strip()
    try:
        return json.loads(text)
    except json.JSONDecodeError:
        return text


def parse_grid(items) -> dict:
    """``["n_props=2,4,6", "mode=a,b"]`` -> ``{"n_props": [2, 4, 6], "mode": ["a", "b"]}``.

    Raises ``InputError`` naming ``--grid`` for a missing ``=``, an empty value list, an
    empty value, a repeated key, a repeated value, or no ``--grid`` at all (an empty grid).
    """
    if not items:
        raise InputError("--grid", "empty grid: give at least one --grid KEY=V1,V2,...")
    grid = {}
    for item in items:
        if "=" not in item:
            raise InputError("--grid", f"expected KEY=V1,V2,..., got {item!r}")
        key, values = item.split("=", 1)
        key = key.strip()
        if not key.isidentifier():
            raise InputError("--grid", f"key {key!r} is not a Python identifier (an option of build())")
        if key in grid:
            raise InputError("--grid", f"key {key!r} given twice; list all its values in one --grid")
        parts = [v for v in values.split(",")]
        if not values.strip() or any(not p.strip() for p in parts):
            raise InputError("--grid", f"{key}: empty value in {values!r}; expected V1,V2,...")
        vals = [_parse_value(p) for p in parts]
        if len({json.dumps(v) for v in vals}) != len(vals):
            raise InputError("--grid", f"{key}: a value is repeated in {values!r}")
        for v in vals:
            if isinstance(v, (dict, list)) or (isinstance(v, str) and _BAD_NAME_CHARS & set(v)):
                raise InputError("--grid", f"{key}: value {v!r} must be a number, true/false or a plain word "
                                           f"(no spaces or any of {''.join(sorted(_BAD_NAME_CHARS))})")
        grid[key] = vals
    return grid


def build_parameters(problem_path) -> list:
    """Names of the options of ``build()`` in a problem file (imports the file, builds nothing).

    Raises ``InputError`` for a missing file or a file without ``build``; a ``**kwargs``
    parameter is returned as ``"**"`` (any key is then accepted).
    """
    path = Path(problem_path)
    if not path.is_file() or path.suffix != ".py":
        raise InputError("PROBLEM", f"{path}: not an existing .py problem file")
    name = "mdo_sweep_problem_" + "".join(c if c.isalnum() else "_" for c in path.stem)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except Exception as exc:  # the user's file: one line, not a traceback
        raise InputError("PROBLEM", f"{path} failed to import: {type(exc).__name__}: {exc}") from exc
    build = getattr(module, "build", None)
    if not callable(build):
        raise InputError("PROBLEM", f"{path} has no function build(**options)")
    params = inspect.signature(build).parameters
    return [("**" if p.kind == p.VAR_KEYWORD else n) for n, p in params.items()
            if p.kind != p.VAR_POSITIONAL]


def check_keys(grid: dict, parameters: list, fixed: dict | None = None) -> None:
    """Every grid (and fixed ``-o``) key must be an option of ``build()``; ``analysis`` is not a grid key."""
    allowed = [p for p in parameters if p not in ("analysis", "**")]
    for source, keys in (("--grid", grid), ("--option", fixed or {})):
        for key in keys:
            if key == "analysis":
                raise InputError(source, "'analysis' is not a sweep option: every point is a full `mdo run`")
            if key not in allowed and "**" not in parameters:
                raise InputError(source, f"unknown key {key!r}: build() takes {', '.join(allowed) or 'no options'}")
    both = set(grid) & set(fixed or {})
    if both:
        raise InputError("--option", f"{sorted(both)[0]!r} is also a --grid key")


def expand(grid: dict, parameters: list) -> list:
    """Cartesian product of the grid as a list of dicts, keys in ``build()`` order."""
    order = [k for k in parameters if k in grid] + sorted(k for k in grid if k not in parameters)
    return [dict(zip(order, combo)) for combo in itertools.product(*(grid[k] for k in order))]


def format_value(v) -> str:
    return v if isinstance(v, str) else json.dumps(v)


def point_name(point: dict) -> str:
    """Run-folder name of a point: ``key=value,key2=value2``."""
    return ",".join(f"{k}={format_value(v)}" for k, v in point.items())


def structural_keys(grid: dict) -> list:
    """Keys whose values are not floats (ints, booleans, words): they may change the NLP's
    size or structure (node counts, propeller counts, model switches), so a point only
    warm-starts from a neighbour that has the same values of these."""
    return [k for k, vals in grid.items() if not all(isinstance(v, float) for v in vals)]
