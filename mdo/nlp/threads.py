"""The NLP's derivatives on two cores (issue 20): the same matrices, two threads.

IPOPT evaluates the constraint Jacobian and the Hessian of the Lagrangian once per
iteration, one after the other, and together they are 70-80 % of a whole-mission
solve.  Each is a sum of independent parts:

* the Hessian's node block ``H_yy`` (the global variables held fixed) and the rows of
  the global variables ``[H_dy, H_dd]`` (:mod:`mdo.nlp.hessian`);
* the Jacobian's node columns (globals held fixed) and global columns.

Each part is a CasADi function that writes its entries into the nonzeros of the whole
matrix (zeros elsewhere); a ``Switch`` over the two parts, mapped over two threads
(``Function.map(2, "thread", 2)``), evaluates both at once and their sum is the
matrix.  The Hessian's parts are the split's own expressions, so it is the same matrix to
the bit and IPOPT takes the same path; ``Problem.solve`` uses it by default.  The
Jacobian's column blocks are seeded differently from CasADi's whole Jacobian and agree
only to round-off (5e-18 on GA-2P), which is enough to move the TTW's sensitive path to
another optimum (``results/benchmark.md``), so the solve keeps CasADi's own; the two-part
Jacobian is here, tested, for problems whose path is not so sensitive.  CPU time grows a
little: each part evaluates the nominal graph it needs.

Rule for symmetric parts: a part that computes whole rows of the Hessian keeps an entry
``(r, c)`` (in solver order) with ``r <= c`` when its mirror is computed as a row too,
and maps it to ``(min, max)`` when the mirror is in a block no part computes as a row.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

__all__ = ["nonzero_index", "scatter", "two_thread_sum", "upper_entries"]


def upper_entries(block: ca.MX, row_index, col_index, mirror_in_rows) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The upper-triangle positions of ``block``'s nonzeros in the solver's ``x`` order.

    ``row_index`` / ``col_index``: the solver index of each of the block's rows and
    columns.  ``mirror_in_rows(c_block)``: boolean per block column, True where the
    mirrored entry is computed by some part as a row (keep ``r <= c`` only); False where
    it is not (map to ``(min, max)``).  Returns ``(selected nonzeros of block, rows,
    cols)``."""
    i, j = block.sparsity().get_triplet()
    i, j = np.asarray(i, int), np.asarray(j, int)
    r, c = np.asarray(row_index, int)[i], np.asarray(col_index, int)[j]
    mirrored = np.asarray(mirror_in_rows, bool)[j]
    keep = ~mirrored | (r <= c)
    sel = np.flatnonzero(keep)
    lo, hi = np.minimum(r[sel], c[sel]), np.maximum(r[sel], c[sel])
    return sel, lo, hi


def two_thread_sum(name: str, inputs: list, parts: list, length: int) -> list:
    """``parts[0] + parts[1]`` (dense vectors of ``length``, functions of ``inputs``),
    each evaluated in its own thread.  Returns the new input symbols and the sum."""
    fa = ca.Function(f"{name}_part_a", inputs, [parts[0]])
    fb = ca.Function(f"{name}_part_b", inputs, [parts[1]])
    both = ca.Function.conditional(f"{name}_parts", [fa], fb).map(2, "thread", 2)
    syms = [ca.MX.sym(f"in{k}", s.sparsity()) for k, s in enumerate(inputs)]
    out = both(ca.DM([[0, 1]]), *[ca.repmat(s, 1, 2) for s in syms])
    if out.size1() != length:
        raise ValueError(f"{name}: parts of length {out.size1()}, expected {length}")
    return syms, out[:, 0] + out[:, 1]


def scatter(values: ca.MX, positions, length: int) -> ca.MX:
    """A dense ``length`` vector, ``values`` at ``positions`` and zeros elsewhere."""
    v = ca.MX.zeros(length, 1)
    if len(positions):
        v[[int(k) for k in positions]] = values
    return v


def nonzero_index(sparsity: ca.Sparsity, rows, cols) -> np.ndarray:
    """The nonzero index of each entry ``(rows[k], cols[k])`` of ``sparsity``; -1 where it
    is not a structural nonzero."""
    r, c = (np.asarray(a, np.int64) for a in sparsity.get_triplet())
    n1 = np.int64(sparsity.size1())
    keys = c * n1 + r                      # column-major: the nonzeros' own order
    want = np.asarray(cols, np.int64) * n1 + np.asarray(rows, np.int64)
    at = np.searchsorted(keys, want)
    at = np.minimum(at, keys.size - 1) if keys.size else at
    ok = keys.size > 0 and True
    found = (keys[at] == want) if ok else np.zeros(want.shape, bool)
    return np.where(found, at, -1)
