"""A deliberately slow NLP (dense least squares, many iterations) for the Ctrl-C test."""
import casadi as ca
import numpy as np

from mdo.nlp import Problem


def build(n: int = 400):
    p = Problem("slow_dense")
    x = p.variable("x", n, lower=-10, upper=10, init=np.linspace(-1, 1, n))
    A = np.random.default_rng(0).normal(size=(n, n)) / n
    r = ca.mtimes(ca.DM(A), ca.sin(x)) - 1
    p.minimize(ca.sumsqr(r) + ca.sumsqr(ca.mtimes(ca.DM(A), ca.cos(x) * x)) + 1e-3 * ca.sum1(x ** 4))
    p.constrain("sphere", ca.sum1(x ** 2) - n / 3, scale=n, labels=["all"])
    # slow by construction, not by luck: a monotone barrier that shrinks mu by 5 % per
    # step from 100 makes IPOPT take some 550 iterations whatever the machine's load
    p.ipopt_options.update({"max_iter": 100000, "tol": 1e-14, "acceptable_iter": 0, "mu_strategy": "monotone",
                            "mu_init": 100.0, "mu_linear_decrease_factor": 0.95,
                            "mu_superlinear_decrease_power": 1.01, "barrier_tol_factor": 1e-3})
    return p
