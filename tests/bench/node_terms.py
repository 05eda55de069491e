"""Which term of one node's forces is curved in one variable (issue 20 item 2).

    python tests/bench/node_terms.py ttw results/ttw/analysis/solution.json 48 71 body_angle

Builds PROBLEM's optimization, starts it from BASELINE (a converged analysis' solution.json, as
``mdo run --from-baseline`` does), runs ITERATIONS of IPOPT in this process (0: the start
itself), and prints, at mission node NODE, each term of the aircraft's forces (wing lift and
drag, the drag build-up's parts, the swirl credit, each rotor group's thrust and in-plane
force) with its first and second derivative in VARIABLE's entry at that node (IPOPT's scaled
variable).  A term whose second derivative is orders of magnitude above the others is where
a constraint row's curvature comes from (``group_curvature.py`` finds the row).  Not collected
by pytest.
"""
from __future__ import annotations

import sys
from pathlib import Path

import casadi as ca
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from mdo.nlp.run import _import_file  # noqa: E402
from mdo.vehicle import aircraft as _aircraft  # noqa: E402

_TERMS: dict = {}


def _recording(original):
    def wrapped(self, nodes, unknowns, rot, env, heat_W=None):
        out = original(self, nodes, unknowns, rot, env, heat_W)
        _TERMS.update(aero=out, rot=rot)
        return out
    return wrapped


def terms_of(aero: dict, rot: dict) -> dict:
    t = {"wing lift": aero["L"], "lattice lift": aero["vlm"]["L"], "drag": aero["D"], "induced drag": aero["D_i"],
         "parasite drag": aero["D_parasite"], "body normal force": aero["body_normal_N"],
         "swirl recovered": aero["swirl_recovered_W"], "swirl credit": aero["swirl_credit_W"]}
    t.update({f"drag: {k}": v for k, v in aero["drag_terms"].items()})
    for g, o in rot.items():
        t.update({f"{g}.thrust": o["T"], f"{g}.in-plane force": o["H"],
                  f"{g}.normal component": o["T"] * o["sin"] + o["H"] * o["cos"]})
    return t


def main():
    problem, baseline, iterations, node, var_name = sys.argv[1:6]
    iterations, node = int(iterations), int(node)
    _aircraft.Aircraft._aerodynamics = _recording(_aircraft.Aircraft._aerodynamics)
    p = _import_file(ROOT / "problems" / f"{problem}.py").build(analysis=False)
    p.warm_start(baseline)
    opti = p.opti
    if iterations > 0:
        p.start_from_baseline()
        sol = p.solve(verbose=False, max_iter=iterations, threads=1)
        print(f"{problem}: {sol.status} after {sol.iterations} iterations")
        x = np.asarray(opti.debug.value(opti.x), float).ravel()
    else:
        x = np.asarray(opti.value(opti.x, opti.initial()), float).ravel()
    par = np.asarray(opti.value(opti.p, opti.value_parameters()), float).ravel() if opti.np else np.zeros(0)
    var = p.variables[var_name]
    X = var.scaled
    col = (lambda e: e[0, node] if e.shape[1] > node else e[0, 0])  # noqa: E731
    value = ca.Function("v", [opti.x, opti.p], [ca.densify(col(ca.MX(var.expr)))])(x, par)
    print(f"{var_name} at node {node}: {float(value):.6g} {var.unit} (scale {float(var.scale.ravel()[node]):g})")
    print(f"{'term':32s} {'value':>12s} {'d/dX':>12s} {'d2/dX2':>12s}")
    k = node if X.numel() > node else 0     # a design variable has one entry
    for name, e in terms_of(_TERMS["aero"], _TERMS["rot"]).items():
        s = col(ca.MX(e))
        d1 = ca.jacobian(s, X)[0, k]
        d2 = ca.jacobian(d1, X)[0, k]
        v = ca.Function("t", [opti.x, opti.p], [ca.densify(s), ca.densify(d1), ca.densify(d2)])(x, par)
        print(f"{name:32s} {float(v[0]):12.4g} {float(v[1]):12.4g} {float(v[2]):12.4g}")


if __name__ == "__main__":
    main()
