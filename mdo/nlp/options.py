"""A problem file's options (``mdo run FILE -o KEY=VALUE``): types, ranges, documentation.

The options of a problem file are the keyword parameters of its ``build()``.  Their
type comes from the annotation (or the type of the default: ``bool``, ``int``,
``float``, ``str``); a problem file may declare the allowed values in a
module-level ``OPTIONS`` dict, one entry per option::

    OPTIONS = {
        "nodes": (int, 3, 40),                       # integer in [3, 40]
        "cruise_distance_nmi": (float, 1.0, 500.0),  # number in [1, 500]
        "mass_model": (str, "buildup", "fixed"),     # one of these strings
        "design_wing_area": (bool,),                 # true or false
    }

The declared type must be the one of the ``build()`` parameter.  An option without
an entry is still checked against its type, numbers within +-1e9 (finite).
``check_options`` turns every bad value into ``InputError`` naming the option and the
allowed values ("nodes: an integer in [3, 40], got 'abc'"); an unknown key lists the
allowed ones.  ``describe_options`` is ``mdo run FILE --options``: each option with
its type, default, allowed values and the text the module docstring gives it.
"""
from __future__ import annotations

import inspect
import re
import textwrap
from pathlib import Path

from ..core.errors import InputError, parse_choice, parse_float, parse_int

__all__ = ["check_options", "option_specs", "describe_options", "UNDECLARED_LIMIT"]

UNDECLARED_LIMIT = 1e9       # |value| bound of a number option the file gives no range
_TYPES = (bool, int, float, str)
_MANAGED = ("analysis",)     # set by ``mdo run --analysis``, not by -o


def _parameters(build) -> dict:
    try:
        sig = inspect.signature(build, eval_str=True)
    except Exception:   # an annotation that does not evaluate: fall back to the raw ones
        sig = inspect.signature(build)
    return {n: p for n, p in sig.parameters.items()
            if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY) and n not in _MANAGED}


def _signature_type(p):
    if p.annotation in _TYPES:
        return p.annotation
    if p.default is not inspect.Parameter.empty and type(p.default) in _TYPES:
        return type(p.default)
    return None


def option_specs(module, build, path) -> dict:
    """``{name: (type or None, spec tuple or None, default)}`` for every option of ``build``;
    a malformed ``OPTIONS`` entry is an ``InputError`` naming the file."""
    from .run import RunError

    params = _parameters(build)
    declared = getattr(module, "OPTIONS", {}) or {}
    if not isinstance(declared, dict):
        raise RunError(f"problem file {path}: OPTIONS must be a dict name -> (type, ...), got "
                       f"{type(declared).__name__}")
    for name, spec in declared.items():
        if name not in params:
            raise RunError(f"problem file {path}: OPTIONS names {name!r}, which build() does not take")
        t = _signature_type(params[name])
        ok = (isinstance(spec, tuple) and spec and spec[0] in _TYPES
              and (t is None or spec[0] is t)
              and ((spec[0] in (int, float) and len(spec) == 3 and spec[1] <= spec[2])
                   or (spec[0] is str and len(spec) >= 2 and all(isinstance(c, str) for c in spec[1:]))
                   or (spec[0] is bool and len(spec) == 1)))
        if not ok:
            raise RunError(f"problem file {path}: OPTIONS[{name!r}] = {spec!r} is not (int|float, lo, hi), "
                           f"(str, choice, ...) or (bool,) matching build()'s {name}: "
                           f"{t.__name__ if t else 'untyped'}")
    out = {}
    for name, p in params.items():
        spec = declared.get(name)
        t = spec[0] if spec else _signature_type(p)
        default = None if p.default is inspect.Parameter.empty else p.default
        out[name] = (t, spec, default)
    return out


def _check_value(name, t, spec, value):
    if t is int:
        lo, hi = (spec[1], spec[2]) if spec else (-int(UNDECLARED_LIMIT), int(UNDECLARED_LIMIT))
        return parse_int(name, value, lo, hi)
    if t is float:
        lo, hi = (spec[1], spec[2]) if spec else (-UNDECLARED_LIMIT, UNDECLARED_LIMIT)
        if isinstance(value, str):   # JSON did not read it as a number
            raise InputError(name, f"a number in [{lo:g}, {hi:g}], got {value!r}")
        return parse_float(name, value, lo, hi)
    if t is bool:
        if not isinstance(value, bool):
            raise InputError(name, f"true or false, got {value!r}")
        return value
    if t is str:
        if spec:
            return parse_choice(name, value, spec[1:])
        if not isinstance(value, str):
            raise InputError(name, f"a string, got {value!r} (quote it as JSON: '\"{value}\"')")
        return value
    return value   # untyped option: the problem file's business


def _allowed(t, spec) -> str:
    if spec and t in (int, float):
        return f"{'an integer' if t is int else 'a number'} in [{spec[1]:g}, {spec[2]:g}]"
    if spec and t is str:
        return "one of " + ", ".join(spec[1:])
    if t in (int, float):
        return (f"{'an integer' if t is int else 'a number'} in [{-UNDECLARED_LIMIT:g}, {UNDECLARED_LIMIT:g}] "
                f"(the file declares no range in OPTIONS)")
    return {bool: "true or false", str: "a string"}.get(t, "any value (untyped)")


def check_options(module, build, options: dict, path) -> dict:
    """The ``-o`` options checked against ``build()``'s parameters and the file's ``OPTIONS``:
    unknown keys refused (listing the allowed ones), each value of its type and range."""
    specs = option_specs(module, build, path)
    takes_kwargs = any(p.kind == p.VAR_KEYWORD for p in inspect.signature(build).parameters.values())
    out = {}
    for key, value in options.items():
        if key in _MANAGED:
            out[key] = value
            continue
        if key not in specs:
            if takes_kwargs:
                out[key] = value
                continue
            raise InputError(key, f"unknown option of {Path(path).name}; allowed: "
                                  f"{', '.join(specs) or 'none'} (see mdo run {path} --options)")
        t, spec, _ = specs[key]
        out[key] = _check_value(key, t, spec, value)
    return out


def _option_docs(doc: str, names) -> dict:
    """The text the module docstring gives each option: from ``name`` to the next option
    mentioned or the end of its paragraph."""
    docs = {}
    for name in names:
        m = re.search(rf"``{re.escape(name)}``", doc)
        if not m:
            continue
        rest = doc[m.end():]
        end = len(rest)
        para = re.search(r"\n\s*\n", rest)
        if para:
            end = para.start()
        for other in names:
            o = re.search(rf"``{re.escape(other)}``", rest)
            if o and other != name and o.start() < end:
                end = o.start()
        text = " ".join(rest[:end].split()).strip(" ,;")
        docs[name] = text
    return docs


def describe_options(path) -> str:
    """``mdo run FILE --options``: the problem's options, their types, defaults, allowed
    values and documentation."""
    from .run import RunError, _import_file

    path = Path(path)
    if not path.is_file() or path.suffix != ".py":
        raise RunError(f"problem file {path}: expected an existing .py file")
    module = _import_file(path)
    build = getattr(module, "build", None)
    if not callable(build):
        raise RunError(f"problem file {path} has no function build(**options) returning an mdo.nlp.Problem")
    specs = option_specs(module, build, path)
    doc = inspect.getdoc(module) or ""
    docs = _option_docs(doc, list(specs))
    lines = [f"{path}: {doc.splitlines()[0] if doc else '(no module docstring)'}", "",
             "options (mdo run FILE -o KEY=VALUE, VALUE as JSON; --analysis sets 'analysis'):"]
    if not specs:
        lines.append("  (none)")
    for name, (t, spec, default) in specs.items():
        tn = t.__name__ if t else "any"
        lines.append(f"  {name} ({tn}, default {default!r}): {_allowed(t, spec)}")
        if docs.get(name):
            lines += textwrap.wrap(docs[name], width=96, initial_indent="      ", subsequent_indent="      ")
    return "\n".join(lines)
