"""Minimum-time brachistochrone on one CGL segment: a small genuine NLP with a known answer.

A bead slides without friction from (0, 10) m to (10, 5) m under g = 9.80665 m/s^2;
the minimum time is 1.8016 s (the classic cycloid; Dymos' brachistochrone example uses
the same data).  States x, y, v; control theta (angle from the downward vertical):
x' = v sin(theta), y' = -v cos(theta), v' = g cos(theta).
"""
import numpy as np

from mdo.core import Collocation
from mdo.nlp import Problem

G = 9.80665


def build(nodes: int = 20, analysis: bool = False, final_y: float = 5.0):
    p = Problem("brachistochrone", "minimum-time bead on a wire, CGL collocation")
    c = Collocation(int(nodes))
    tf = p.variable("final_time", unit="s", scale=1.0, lower=0.1, upper=10.0, init=2.0, design=True,
                    description="time of flight")
    s = c.s
    x = p.variable("x", nodes, unit="m", scale=10.0, lower=0, upper=10, init=10 * s)
    y = p.variable("y", nodes, unit="m", scale=10.0, lower=0, upper=10, init=10 - (10 - final_y) * s)
    v = p.variable("v", nodes, unit="m/s", scale=10.0, lower=0, upper=100, init=9.9 * s)
    th = p.variable("theta", nodes, unit="rad", scale=1.0, lower=0.0, upper=np.pi, init=np.full(nodes, 1.5))
    import casadi as ca
    D = ca.DM(c.D)
    labels = [f"node {i}" for i in range(nodes)]
    p.constrain("x_dynamics", ca.mtimes(D, x) - tf * v * ca.sin(th), scale=10.0, unit="m", labels=labels)
    p.constrain("y_dynamics", ca.mtimes(D, y) + tf * v * ca.cos(th), scale=10.0, unit="m", labels=labels)
    p.constrain("v_dynamics", ca.mtimes(D, v) - tf * G * ca.cos(th), scale=10.0, unit="m/s", labels=labels)
    p.constrain("start", ca.vertcat(x[0], y[0] - 10.0, v[0]), scale=1.0, unit="m",
                labels=["x(0)", "y(0)", "v(0)"])
    p.constrain("end", ca.vertcat(x[-1] - 10.0, y[-1] - final_y), scale=1.0, unit="m",
                labels=["x(tf)", "y(tf)"])
    p.minimize(tf, unit="s")
    p.output("final_time_s", tf, unit="s", summary=True)
    return p
