"""A model that evaluates to NaN at the solver's points (log of a negative number)."""
import casadi as ca

from mdo.nlp import Problem


def build():
    p = Problem("nan_model")
    x = p.variable("x", 2, lower=-5, upper=5, init=[-1.0, 2.0])
    p.constrain("rotor model", ca.log(x[0]) - 1.0, scale=1.0, labels=["CR node 3"])
    p.constrain("fine", x[1] - 1.0, scale=1.0)
    p.minimize(ca.sumsqr(x))
    return p
