"""How many threads mdo's numeric work uses: ``MDO_THREADS`` if set, else 2 on a machine
with two or more cores (the exact Hessian's two parts, :mod:`mdo.nlp.threads`; the
numeric BEMT's operating points, :func:`mdo.rotor.analysis.solve_phi`).  ``mdo run
--threads`` sets it for the whole run; a sweep's Dask workers keep one each."""
from __future__ import annotations

import contextlib
import os

from .errors import InputError

__all__ = ["check_threads", "default_threads", "threads_set_to"]


def default_threads() -> int:
    """``MDO_THREADS`` if set, else 2 on a machine with two or more cores, else 1.  Only 1
    and 2 mean something: the Hessian has two parts."""
    env = os.environ.get("MDO_THREADS")
    if env is not None and env.strip():
        return check_threads(env, "MDO_THREADS")
    return 2 if (os.cpu_count() or 1) >= 2 else 1


def check_threads(value, field: str = "threads") -> int:
    """``value`` as 1 or 2, else ``InputError`` naming ``field``."""
    try:
        n = int(value)
    except (TypeError, ValueError):
        n = None
    if n not in (1, 2) or str(value).strip() not in ("1", "2"):
        raise InputError(field, f"1 or 2 (threads for the Hessian and the numeric BEMT), got {value!r}")
    return n


@contextlib.contextmanager
def threads_set_to(n: int | None):
    """``MDO_THREADS`` set to ``n`` inside the block (nothing changed for None), restored after."""
    if n is None:
        yield
        return
    before = os.environ.get("MDO_THREADS")
    os.environ["MDO_THREADS"] = str(check_threads(n))
    try:
        yield
    finally:
        if before is None:
            os.environ.pop("MDO_THREADS", None)
        else:
            os.environ["MDO_THREADS"] = before
