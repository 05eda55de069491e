"""Chebyshev-Gauss-Lobatto (CGL) collocation: nodes, differentiation and integration.

With ``n`` nodes the interpolating polynomial has degree ``n - 1``; the matrices
below are exact (to round-off) for every polynomial up to that degree and converge
spectrally on smooth functions.  This is the pseudospectral transcription the
paper's mission solver uses (Clarke et al., section VI; SUAVE's
``chebyshev_data``), written here from the textbook formulas:

* nodes   ``tau_j = -cos(pi j / (n-1))``, j = 0..n-1, on [-1, 1], mapped to [t0, tf];
* differentiation by the barycentric formula (Berrut & Trefethen, SIAM Rev. 2004,
  Eq. 9.4): ``D_ij = (w_j / w_i) / (tau_i - tau_j)``, ``D_ii = -sum_{j!=i} D_ij``,
  with CGL weights ``w_j = (-1)^j delta_j`` (delta = 1/2 at the ends);
* integration ``I_ij``: the integral from t0 to t_i of the j-th Lagrange
  polynomial, obtained through the Chebyshev basis; the last row is the
  Clenshaw-Curtis quadrature.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.polynomial import chebyshev as C

__all__ = ["cgl_nodes", "differentiation_matrix", "integration_matrix", "Collocation"]


def cgl_nodes(n: int, t0: float = -1.0, tf: float = 1.0) -> np.ndarray:
    """The ``n`` CGL nodes on [t0, tf], increasing, ends included."""
    if n < 2:
        raise ValueError(f"CGL collocation needs n >= 2 nodes, got n = {n}")
    tau = -np.cos(np.pi * np.arange(n) / (n - 1))
    return t0 + 0.5 * (tau + 1.0) * (tf - t0)


@lru_cache(maxsize=64)
def _lagrange_chebyshev(n: int) -> np.ndarray:
    """Column j: the Chebyshev coefficients of the j-th Lagrange polynomial of the n CGL nodes."""
    V = C.chebvander(cgl_nodes(n), n - 1)               # V[i, k] = T_k(tau_i)
    return np.linalg.solve(V, np.eye(n))


@lru_cache(maxsize=64)
def _unit(n: int):
    tau = cgl_nodes(n)
    w = (-1.0) ** np.arange(n)
    w[0] *= 0.5
    w[-1] *= 0.5
    diff = tau[:, None] - tau[None, :]
    np.fill_diagonal(diff, 1.0)
    D = (w[None, :] / w[:, None]) / diff
    np.fill_diagonal(D, 0.0)
    np.fill_diagonal(D, -D.sum(axis=1))
    # Integration: Lagrange basis -> Chebyshev coefficients -> antiderivative.
    coef = _lagrange_chebyshev(n)
    I = np.empty((n, n))
    for j in range(n):
        anti = C.chebint(coef[:, j], lbnd=-1.0)
        I[:, j] = C.chebval(tau, anti)
    return tau, D, I


def differentiation_matrix(n: int, t0: float = -1.0, tf: float = 1.0) -> np.ndarray:
    """``D`` with ``(D f)(t_i) = f'(t_i)`` for the degree n-1 interpolant of f on [t0, tf]."""
    return _unit(n)[1] * (2.0 / (tf - t0))


def integration_matrix(n: int, t0: float = -1.0, tf: float = 1.0) -> np.ndarray:
    """``I`` with ``(I f)_i = integral from t0 to t_i`` of the interpolant of f."""
    return _unit(n)[2] * (0.5 * (tf - t0))


@dataclass(frozen=True)
class Collocation:
    """The CGL data of one segment on the unit interval [0, 1].

    A segment of duration ``T`` maps as ``t = t0 + T*s``; then ``d/dt = D/T`` and the
    running integral is ``T*I``.  Keeping the unit-interval matrices lets the
    duration be a symbolic variable.
    """

    n: int

    @property
    def s(self) -> np.ndarray:
        return cgl_nodes(self.n, 0.0, 1.0)

    @property
    def D(self) -> np.ndarray:
        return differentiation_matrix(self.n, 0.0, 1.0)

    @property
    def I(self) -> np.ndarray:  # noqa: E743 - the integration matrix is conventionally I
        return integration_matrix(self.n, 0.0, 1.0)

    def derivative_at(self, s_eval) -> np.ndarray:
        """``E`` with ``(E f)_k = f'(s_k)``, the derivative on [0, 1] of the degree n-1 interpolant
        of the node values f at the points ``s_eval`` (anywhere in [0, 1]; ``E = D`` at the nodes)."""
        n = self.n
        coef = _lagrange_chebyshev(n)
        tau = 2.0 * np.asarray(s_eval, float) - 1.0
        return 2.0 * np.column_stack([C.chebval(tau, C.chebder(coef[:, j])) for j in range(n)])

    def between_nodes(self, per_interval: int = 3) -> np.ndarray:
        """The nodes and ``per_interval`` evenly spaced points inside each interval between two
        nodes, increasing (node j at index ``j * (per_interval + 1)``): where a rate limit is held,
        since the interpolant's derivative between the nodes can exceed its values at them (by 72 %
        in the TTW's approach transition, 2026-12-07)."""
        s = self.s
        inner = [a + (b - a) * (k + 1) / (per_interval + 1) for a, b in zip(s[:-1], s[1:])
                 for k in range(per_interval)]
        return np.sort(np.concatenate([s, inner]))

    @property
    def weights(self) -> np.ndarray:
        """Clenshaw-Curtis quadrature weights on [0, 1] (sum to 1)."""
        return self.I[-1].copy()
