"""Accuracy of the surrogate against the polar points it was fitted to, and plots."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["PolarErrors", "polar_errors", "plot_airfoil"]

CL_TOL = 0.03      # issue 3 acceptance: |dcl| <= 0.03
CD_TOL = 0.05      # |dcd|/cd <= 5 %


@dataclass
class PolarErrors:
    reynolds: float
    n_points: int
    max_dcl: float
    rms_dcl: float
    max_rel_dcd: float
    rms_rel_dcd: float
    n_cl_over: int          # points with |dcl| > CL_TOL
    n_cd_over: int          # points with |dcd|/cd > CD_TOL
    max_dcm: float


def polar_errors(airfoil) -> list[PolarErrors]:
    """Surrogate minus data at every polar point (Mach 0), per Reynolds level."""
    out = []
    for p in airfoil.polars:
        cl, cd, cm = airfoil.coefficients(np.radians(p.alpha_deg), p.reynolds, 0.0)
        dcl = cl - p.cl
        rcd = (cd - p.cd) / p.cd
        out.append(PolarErrors(
            reynolds=p.reynolds, n_points=len(p.cl),
            max_dcl=float(np.abs(dcl).max()), rms_dcl=float(np.sqrt(np.mean(dcl ** 2))),
            max_rel_dcd=float(np.abs(rcd).max()), rms_rel_dcd=float(np.sqrt(np.mean(rcd ** 2))),
            n_cl_over=int(np.sum(np.abs(dcl) > CL_TOL)), n_cd_over=int(np.sum(np.abs(rcd) > CD_TOL)),
            max_dcm=float(np.abs(cm - p.cm).max()),
        ))
    return out


def plot_airfoil(airfoil, path, mach: float = 0.0):
    """cl, cd (and cm) vs alpha at every data Re: data points over the surrogate.

    Left column: the data range (-25..30 deg); right column: the full circle.
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 2, figsize=(13, 12), gridspec_kw={"width_ratios": [1.3, 1]})
    colors = plt.cm.viridis(np.linspace(0.0, 0.9, len(airfoil.polars)))
    a_zoom = np.linspace(-25.0, 30.0, 1101)
    a_full = np.linspace(-180.0, 180.0, 1441)
    for p, c in zip(airfoil.polars, colors):
        lab = f"Re {p.reynolds:.3g}"
        for col, a in ((0, a_zoom), (1, a_full)):
            cl, cd, cm = airfoil.coefficients(np.radians(a), p.reynolds, mach)
            axes[0, col].plot(a, cl, color=c, lw=1.2, label=lab if col == 0 else None)
            axes[1, col].plot(a, cd, color=c, lw=1.2)
            axes[2, col].plot(a, cm, color=c, lw=1.2)
            axes[0, col].plot(p.alpha_deg, p.cl, ".", color=c, ms=3)
            axes[1, col].plot(p.alpha_deg, p.cd, ".", color=c, ms=3)
            axes[2, col].plot(p.alpha_deg, p.cm, ".", color=c, ms=3)
    axes[1, 0].set_yscale("log")
    axes[1, 0].set_ylim(3e-3, 1.0)
    for row, lab in enumerate(("cl", "cd", "cm (c/4)")):
        for col in range(2):
            axes[row, col].set_ylabel(lab)
            axes[row, col].grid(True, alpha=0.3)
        axes[row, 0].set_xlim(-25, 30)
        axes[row, 1].set_xlim(-180, 180)
        axes[row, 1].set_xticks(np.arange(-180, 181, 45))
    axes[2, 0].set_xlabel("alpha [deg]")
    axes[2, 1].set_xlabel("alpha [deg]")
    axes[0, 0].legend(fontsize=8, ncol=2)
    lo, hi = airfoil.reynolds_range
    fig.suptitle(f"{airfoil.title} (t/c {airfoil.thickness_to_chord:.3f}): surrogate (lines) over "
                 f"XFOIL polars (dots), M = {mach:g}; data Re {lo:.3g}-{hi:.3g}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def jump_mask(polar, cl_step: float = 0.06, lncd_step: float = 0.15, within_deg: float = 1.0):
    """Points within ``within_deg`` of an XFOIL discontinuity: two neighbouring points
    whose cl differs by more than ``cl_step`` or ln cd by more than ``lncd_step``."""
    jump = np.zeros(len(polar.cl), bool)
    step = (np.abs(np.diff(polar.cl)) > cl_step) | (np.abs(np.diff(np.log(polar.cd))) > lncd_step)
    jump[:-1] |= step
    jump[1:] |= step
    return np.array([np.any(jump[np.abs(polar.alpha_deg - a) <= within_deg]) for a in polar.alpha_deg])


def summary_markdown(names) -> str:
    """One row per airfoil: points, share within tolerance, worst/RMS errors, misses away from jumps."""
    from . import Airfoil

    rows = ["| airfoil | Re levels | points | within 0.03 cl | within 5 % cd | rms dcl | rms dcd/cd "
            "| max dcl | max dcd/cd | misses >1 deg from an XFOIL jump (cl / cd) |",
            "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for name in names:
        af = Airfoil.from_name(name)
        n = ok_cl = ok_cd = far = far_cl = far_cd = 0
        s_cl = s_cd = 0.0
        m_cl = m_cd = 0.0
        for p in af.polars:
            cl, cd, _ = af.coefficients(np.radians(p.alpha_deg), p.reynolds, 0.0)
            dcl = np.abs(cl - p.cl)
            rcd = np.abs(cd / p.cd - 1.0)
            near = jump_mask(p)
            n += len(dcl)
            ok_cl += int(np.sum(dcl <= CL_TOL))
            ok_cd += int(np.sum(rcd <= CD_TOL))
            s_cl += float(np.sum(dcl ** 2))
            s_cd += float(np.sum(rcd ** 2))
            m_cl = max(m_cl, float(dcl.max()))
            m_cd = max(m_cd, float(rcd.max()))
            far += int(np.sum(~near))
            far_cl += int(np.sum((dcl > CL_TOL) & ~near))
            far_cd += int(np.sum((rcd > CD_TOL) & ~near))
        rows.append(f"| {af.title} | {len(af.polars)} | {n} | {100 * ok_cl / n:.1f} % | {100 * ok_cd / n:.1f} % "
                    f"| {np.sqrt(s_cl / n):.4f} | {np.sqrt(s_cd / n):.3f} | {m_cl:.2f} | {m_cd:.2f} "
                    f"| {far_cl} / {far_cd} of {far} |")
    return "\n".join(rows)
