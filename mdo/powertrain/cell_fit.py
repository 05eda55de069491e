"""Fit of the cell model (``cell.py``, Eqs. C1-C4) to the measured discharge curves.

Run ``python -m mdo.powertrain.cell_fit`` to regenerate ``data/nmc18650_fit.json``
(``--check`` compares with the committed file instead of writing it).

Procedure (deterministic, no starting guesses):

1. Usable capacity ``Q_u(T)`` (Eq. C4): the median over the four currents of the
   capacity at the 2.5 V cut-off at each ambient temperature; least squares of
   ``ln(Q/Q_nom)`` on ``[1, tau, tau^2]``.  The measured cut-off capacity depends on
   the temperature (3.07..3.40 Ah) and hardly on the current, so the knee of
   ``U(s)`` sits at ``s = 0`` for every temperature.
2. With ``s = 1 - q/Q_u(T)`` fixed, the voltage of Eq. C1 is *linear* in all other
   coefficients (8 Chebyshev, 12 ohmic, 12 kinetic).  They minimize the
   sum of squared voltage errors over all 24 curves (2, 4, 6, 8 A x 0..50 deg C)
   subject to linear physical constraints on a grid (s in [-0.05, 1] by 0.025,
   T in [0, 50] deg C by 5 K): ``R(s, T) >= 5 mOhm``, ``A(s, T) >= 0`` (so the voltage
   falls with current everywhere, and equals U at zero current), and the loaded
   voltage ``V(s, I, T)`` increasing in s (slope >= 0.1 V) on s in [-0.05, 1] for
   I = 0..12 A (no spurious rise of the voltage past the knee; U increasing is the
   I = 0 case).  A dense convex quadratic program, solved by qpOASES (active set,
   through CasADi) in a fraction of a second.

The zero-current voltage is not measured (the lowest current is 2 A); the
constraints and the asinh form fix it.  The fitted ``U(1) = 4.20 V`` agrees with a
cell charged to 4.2 V, which is a check, not an input.
"""
from __future__ import annotations

import argparse
import contextlib
import hashlib
import json
import os
import sys
from pathlib import Path

import casadi as ca
import numpy as np
from numpy.polynomial import chebyshev as C

from .cell import (CURRENT_REF_A, FIT_FILE, OCV_DEGREE, RAW_FILE, TEMP_REF_C,
                   TEMP_SPAN_C, CellModel, load_discharge_data, soc_basis, temperature_basis)

CELL_SPEC = {
    "capacity_nominal_Ah": 3.55,   # rating of the paper's cell (SUAVE Lithium_Ion_LiNiMnCoO2_18650)
    "voltage_nominal_V": 3.6,
    "voltage_max_V": 4.2,
    "voltage_cutoff_V": 2.5,       # end of the measured curves
    "mass_kg": 0.048,
}
R_MIN_OHM = 0.005
GRID_SOC = np.linspace(-0.05, 1.0, 43)
MIN_DVDS = 0.1      # V per unit state of charge: strictly increasing between grid points
GRID_I_A = (0.0, 1.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0)
GRID_T_C = np.linspace(0.0, 50.0, 11)


def _surface_columns(soc, tau):
    phi = np.stack([np.broadcast_to(p, np.shape(soc)) for p in soc_basis(np.asarray(soc, float))], 1)
    psi = np.stack([np.broadcast_to(p, np.shape(tau)) for p in temperature_basis(np.asarray(tau, float))], 1)
    return (phi[:, :, None] * psi[:, None, :]).reshape(len(soc), -1)


def _ocv_columns(soc):
    return C.chebvander(2 * np.asarray(soc, float) - 1, OCV_DEGREE)


@contextlib.contextmanager
def _quiet_stdout():
    """Silence the C-level stdout (file descriptor 1) for the duration."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 1)
            yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)


def fit_capacity(curves):
    temps = sorted({c["ambient_C"] for c in curves})
    q_end = np.array([np.median([c["capacity_Ah"].max() for c in curves if c["ambient_C"] == T])
                      for T in temps])
    tau = (np.asarray(temps) - TEMP_REF_C) / TEMP_SPAN_C
    M = np.stack([np.ones_like(tau), tau, tau ** 2], 1)
    coeffs, *_ = np.linalg.lstsq(M, np.log(q_end / CELL_SPEC["capacity_nominal_Ah"]), rcond=None)
    return coeffs, dict(zip(temps, q_end))


def fit(curves=None) -> CellModel:
    """Fit the model to ``curves`` (default: the measured data) and return it."""
    curves = curves if curves is not None else load_discharge_data()
    cap_coeffs, q_end = fit_capacity(curves)
    I = np.concatenate([np.full(len(c["capacity_Ah"]), c["current_A"]) for c in curves])
    T = np.concatenate([np.full(len(c["capacity_Ah"]), c["ambient_C"]) for c in curves])
    q = np.concatenate([c["capacity_Ah"] for c in curves])
    V = np.concatenate([c["voltage_V"] for c in curves])
    tau = (T - TEMP_REF_C) / TEMP_SPAN_C
    Qu = CELL_SPEC["capacity_nominal_Ah"] * np.exp(cap_coeffs[0] + cap_coeffs[1] * tau + cap_coeffs[2] * tau ** 2)
    soc = 1.0 - q / Qu
    S = _surface_columns(soc, tau)
    A = np.hstack([_ocv_columns(soc), -I[:, None] * S, -np.arcsinh(I / CURRENT_REF_A)[:, None] * S])
    nU = OCV_DEGREE + 1
    nS = S.shape[1]

    sg, tg = np.meshgrid(GRID_SOC, (GRID_T_C - TEMP_REF_C) / TEMP_SPAN_C)
    Sg = _surface_columns(sg.ravel(), tg.ravel())
    z = np.zeros_like(Sg)
    zU = np.zeros((Sg.shape[0], nU))
    # V increasing in s at every current of interest (0..12 A) and temperature on
    # s in [-0.05, 1]: differences of the design rows between neighbouring s
    s_fine = np.linspace(-0.05, 1.0, 106)
    rows = []
    for t in (GRID_T_C - TEMP_REF_C) / TEMP_SPAN_C:
        St = _surface_columns(s_fine, np.full(s_fine.shape, t))
        for i in GRID_I_A:
            Ai = np.hstack([_ocv_columns(s_fine), -i * St, -np.arcsinh(i / CURRENT_REF_A) * St])
            rows.append(np.diff(Ai, axis=0))
    G = np.vstack([np.hstack([zU, Sg, z]),          # R >= R_min
                   np.hstack([zU, z, Sg]),          # A >= 0
                   np.vstack(rows)])                # dV/ds >= 0.1 V (U too: i = 0)
    lbg = np.concatenate([np.full(Sg.shape[0], R_MIN_OHM), np.zeros(Sg.shape[0]),
                          np.full(G.shape[0] - 2 * Sg.shape[0], MIN_DVDS * (s_fine[1] - s_fine[0]))])
    # min |A x - V|^2 = x'(A'A)x - 2 (A'V)'x + const: a dense convex QP (qpOASES, active set)
    H = ca.DM(2.0 * A.T @ A)
    with _quiet_stdout():   # qpOASES prints its licence banner on first use
        qp = ca.conic("cell_fit", "qpoases", {"h": H.sparsity(), "a": ca.DM(G).sparsity()},
                      {"printLevel": "none", "error_on_fail": False})
        sol = qp(h=H, g=-2.0 * A.T @ V, a=ca.DM(G), lba=lbg, uba=np.inf)
    if not qp.stats()["success"]:
        raise RuntimeError(f"cell fit QP failed: {qp.stats()['return_status']}")
    xv = np.asarray(sol["x"]).ravel()
    u = xv[:nU]
    rc = xv[nU:nU + nS].reshape(4, 3)
    kc = xv[nU + nS:].reshape(4, 3)
    model = CellModel(
        name="nmc18650", **CELL_SPEC,
        capacity_log_coeffs=tuple(float(c) for c in cap_coeffs),
        ocv_chebyshev=tuple(float(c) for c in u),
        resistance_coeffs=tuple(tuple(float(c) for c in row) for row in rc),
        kinetic_coeffs=tuple(tuple(float(c) for c in row) for row in kc),
        temperature_range_C=(0.0, 50.0), current_range_A=(2.0, 8.0),
        fit={"measured_cutoff_capacity_Ah": {f"{k:g}": float(v) for k, v in q_end.items()}})
    return model


def error_table(model: CellModel, curves=None) -> dict:
    """Voltage errors of ``model`` against the measured curves.

    RMS and max |error| per current over all points and over the points with
    s >= 0.2 (the knee below is steep: a few mAh of capacity shift are tens of mV),
    per (current, temperature), and the capacity at the cut-off voltage
    (model vs measured) per curve.
    """
    curves = curves if curves is not None else load_discharge_data()
    per_curve = []
    for c in curves:
        soc = model.soc_from_charge(c["capacity_Ah"], c["ambient_C"])
        err = model.voltage(soc, c["current_A"], c["ambient_C"]) - c["voltage_V"]
        # capacity at which the model reaches the last measured voltage (bisection in s
        # on [-0.05, 1], where U is constrained monotone; -0.05 means "not reached")
        v_end = c["voltage_V"][-1]
        lo, hi = -0.05, 1.0
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            if model.voltage(mid, c["current_A"], c["ambient_C"]) > v_end:
                hi = mid
            else:
                lo = mid
        q_model = (1.0 - 0.5 * (lo + hi)) * model.usable_capacity_Ah(c["ambient_C"])
        per_curve.append({"current_A": c["current_A"], "ambient_C": c["ambient_C"], "soc": soc,
                          "err": err, "q_end_measured": float(c["capacity_Ah"][-1]), "q_end_model": float(q_model)})

    def stats(errs):
        e = np.concatenate(errs) if errs else np.zeros(0)
        return {"rms_mV": float(1e3 * np.sqrt(np.mean(e ** 2))), "max_mV": float(1e3 * np.abs(e).max()),
                "points": int(e.size)}

    out = {"per_current": {}, "per_current_soc_ge_0.2": {}, "per_curve": [], "all": None}
    for I in sorted({p["current_A"] for p in per_curve}):
        sel = [p for p in per_curve if p["current_A"] == I]
        out["per_current"][f"{I:g}"] = stats([p["err"] for p in sel])
        out["per_current_soc_ge_0.2"][f"{I:g}"] = stats([p["err"][p["soc"] >= 0.2] for p in sel])
    out["all"] = stats([p["err"] for p in per_curve])
    out["all_soc_ge_0.2"] = stats([p["err"][p["soc"] >= 0.2] for p in per_curve])
    for p in per_curve:
        out["per_curve"].append({"current_A": p["current_A"], "ambient_C": p["ambient_C"],
                                 **stats([p["err"]]),
                                 "cutoff_capacity_measured_Ah": round(p["q_end_measured"], 4),
                                 "cutoff_capacity_model_Ah": round(p["q_end_model"], 4)})
    return out


def model_to_json(model: CellModel, errors: dict) -> dict:
    raw_sha = hashlib.sha256(Path(RAW_FILE).read_bytes()).hexdigest()
    return {
        "name": model.name,
        "description": ("18650 NMC cell (Panasonic NCR18650G data via SUAVE): V = U(s) - I R(s,T) "
                        "- A(s,T) asinh(I/1A), s = 1 - q/Q_u(T); see mdo/powertrain/cell.py"),
        "source_data": {"file": RAW_FILE.name, "sha256": raw_sha},
        "model": {
            "capacity_nominal_Ah": model.capacity_nominal_Ah, "voltage_nominal_V": model.voltage_nominal_V,
            "voltage_max_V": model.voltage_max_V, "voltage_cutoff_V": model.voltage_cutoff_V,
            "mass_kg": model.mass_kg, "capacity_log_coeffs": list(model.capacity_log_coeffs),
            "ocv_chebyshev": list(model.ocv_chebyshev),
            "resistance_coeffs": [list(r) for r in model.resistance_coeffs],
            "kinetic_coeffs": [list(r) for r in model.kinetic_coeffs],
            "temperature_range_C": list(model.temperature_range_C),
            "current_range_A": list(model.current_range_A),
        },
        "fit": {**model.fit, "errors": errors},
    }


def _print_table(errors):
    print("current   RMS all   max all   RMS s>=0.2   max s>=0.2   (mV)")
    for I, e in errors["per_current"].items():
        e2 = errors["per_current_soc_ge_0.2"][I]
        print(f"{I:>5} A  {e['rms_mV']:8.1f}  {e['max_mV']:8.1f}  {e2['rms_mV']:11.1f}  {e2['max_mV']:11.1f}")
    print(f"  all    {errors['all']['rms_mV']:8.1f}  {errors['all']['max_mV']:8.1f}  "
          f"{errors['all_soc_ge_0.2']['rms_mV']:11.1f}  {errors['all_soc_ge_0.2']['max_mV']:11.1f}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m mdo.powertrain.cell_fit", description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="compare with the committed fit instead of writing")
    ap.add_argument("--out", default=str(FIT_FILE))
    args = ap.parse_args(argv)
    model = fit()
    errors = error_table(model)
    _print_table(errors)
    data = model_to_json(model, errors)
    if args.check:
        old = json.loads(Path(args.out).read_text())
        a = np.concatenate([np.ravel(np.asarray(v, float)) for k, v in old["model"].items()
                            if isinstance(v, list)])
        b = np.concatenate([np.ravel(np.asarray(v, float)) for k, v in data["model"].items()
                            if isinstance(v, list)])
        diff = float(np.max(np.abs(a - b)))
        print(f"max coefficient difference to {args.out}: {diff:.3g}")
        return 0 if diff < 1e-6 else 1
    Path(args.out).write_text(json.dumps(data, indent=1) + "\n")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
