"""Validation: APC 10x7 Thin Electric propeller against the UIUC wind-tunnel data.

The paper (Clarke et al., section IV.A, Fig. 3a) compares its BEMT with Brandt &
Selig's UIUC measurements of this propeller and reports under 10 % error up to
J = 0.7.  Here the BEMT of ``mdo.rotor`` is run at every rpm and every measured
advance ratio of ``mdo/rotor/data/apce_10x7_performance.csv`` (7 runs, 4007 to
6531 rpm), plus the static (J = 0) runs of ``apce_10x7_static.csv``, with the
model shared with the 19x12 (``apc_common.py``: E63 -> Clark-Y sections, Du-Selig
stall delay, blade angles referenced to the quoted pitch).

Two ways to run it:

* ``python problems/validation/apc10x7.py`` -- analysis mode (bracketed solve);
  writes ``results/validation/apc10x7.png``, ``apc10x7_errors.csv`` (every data
  point), ``apc10x7_static.csv`` and ``apc10x7_summary.md`` (mean and max |error|
  of CT and CP per run for J <= 0.7 and static, the baseline before issue 18, and
  the sensitivities to the zero-lift angle and Ncrit).
* ``mdo run problems/validation/apc10x7.py --out results/validation/apc10x7_nlp``
  -- the same operating points as ONE NLP: the inflow angles of every station at
  every data point are IPOPT variables and the BEMT residuals its constraints
  (``add_bemt_nodes``), i.e. the mission's NLP mode on the validation case; the
  report compares it with the analysis.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from mdo.rotor import RotorGeometry, add_bemt_nodes, analyze, bemt_function, section
from mdo.rotor.analysis import operating_inputs

sys.path.insert(0, str(Path(__file__).resolve().parent))
import apc_common  # noqa: E402  (the model shared with the 19x12)

PROP = apc_common.Prop("10x7", "APC 10x7 Thin Electric", diameter_in=10.0, pitch_in=7.0)
DIAMETER_M = PROP.diameter_m
BLADES = PROP.blades
AIRFOIL = apc_common.AIRFOIL
N_STATIONS = apc_common.N_STATIONS
J_LIMIT = apc_common.J_LIMIT
OUT_DIR = apc_common.OUT_DIR


def rotor(airfoil: str = AIRFOIL) -> RotorGeometry:
    return PROP.rotor(airfoil)


def performance_data() -> np.ndarray:
    return PROP.data("performance")


def _operating_points(d):
    n = d["rpm"] / 60.0
    return 2 * math.pi * n, d["J"] * n * DIAMETER_M


def write_outputs(out_dir: Path = OUT_DIR) -> dict:
    return apc_common.write_outputs(PROP, out_dir)


# allowed values of the -o options (mdo.nlp.options)
OPTIONS = {"n_stations": (int, 6, 60)}


def build(airfoil: str = AIRFOIL, n_stations: int = N_STATIONS, **_):
    """The validation as one NLP: inflow angles of all stations x data points as
    variables, BEMT residuals as constraints, no objective (a feasibility solve)."""
    from mdo.nlp import Problem

    d = performance_data()
    om, v = _operating_points(d)
    rot = rotor(airfoil)
    sec = section(airfoil)
    inputs, _ = operating_inputs(rot, omega_radps=om, v_axial_mps=v, n_stations=n_stations)
    K = d.size
    ref = analyze(rot, omega_radps=om, v_axial_mps=v, n_stations=n_stations)
    start = np.full((n_stations, K), 0.3)     # a flat start, not the answer: IPOPT must find it
    from mdo.rotor import phi_momentum_guess
    st = rot.stations(n_stations)
    for k in range(K):
        start[:, k] = phi_momentum_guess(st["r_m"], st["chord_m"], st["beta_rad"], v[k], om[k] * st["r_m"], BLADES,
                                         alpha0=math.radians(-4.0))
    p = Problem("apc10x7_nlp", "APC 10x7 validation points as one NLP (BEMT residuals as constraints)")
    row = (lambda x: np.asarray(x, dtype=float).reshape(1, -1))
    nlp_inputs = dict(inputs)
    nlp_inputs["omega_radps"] = row(om)
    nlp_inputs["v_axial_mps"] = row(v)
    out = add_bemt_nodes(p, "apc", bemt_function(sec, n_stations), nlp_inputs, n_nodes=K, phi_init=start)
    n_rev = om / (2 * math.pi)
    rho = float(np.asarray(inputs["rho_kgpm3"]).ravel()[0])
    p.output("CT", out["thrust_N"] / (rho * row(n_rev) ** 2 * DIAMETER_M ** 4))
    p.output("CP", out["power_W"] / (rho * row(n_rev) ** 3 * DIAMETER_M ** 5))

    def report(solution, out_dir):
        ct = np.asarray(solution.outputs["CT"]["value"], dtype=float).ravel()
        cp = np.asarray(solution.outputs["CP"]["value"], dtype=float).ravel()
        lines = ["# APC 10x7 validation points solved as one NLP", "",
                 f"{K} operating points x {n_stations} stations = {K * n_stations} inflow angles.",
                 f"Max |CT_nlp - CT_analysis| = {np.max(np.abs(ct - ref['CT'])):.2e}, "
                 f"max |CP_nlp - CP_analysis| = {np.max(np.abs(cp - ref['CP'])):.2e}.",
                 f"Mean |CT err| vs data (J <= {J_LIMIT}): "
                 f"{100 * np.mean(np.abs(ct / d['CT'] - 1)[d['J'] <= J_LIMIT]):.2f} %, CP: "
                 f"{100 * np.mean(np.abs(cp / d['CP'] - 1)[d['J'] <= J_LIMIT]):.2f} %."]
        Path(out_dir, "apc10x7_nlp_check.md").write_text("\n".join(lines) + "\n")

    p.add_report(report)
    return p


if __name__ == "__main__":
    out = write_outputs(Path(sys.argv[1]) if len(sys.argv) > 1 else OUT_DIR)
    apc_common.print_table(out["table"], out["baseline"])
