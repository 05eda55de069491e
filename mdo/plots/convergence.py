"""IPOPT convergence history: parsed from ``ipopt.log`` (so that it exists even for an
interrupted or failed solve), plotted as objective, primal and dual infeasibility."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np

__all__ = ["parse_ipopt_log", "plot_convergence"]

# iter  objective  inf_pr  inf_du  lg(mu)  ||d||  lg(rg)  alpha_du  alpha_pr  ls
_ROW = re.compile(r"^\s*(\d+)(r?)\s+([-+]?\d\.\d+e[-+]\d+)\s+(\d\.\d+e[-+]\d+)\s+(\d\.\d+e[-+]\d+)\s+"
                  r"([-+]?\d+\.\d)\s")


def parse_ipopt_log(path) -> dict:
    """Iteration rows of an IPOPT log: dict of arrays iter, objective, inf_pr, inf_du,
    lg_mu and a boolean ``restoration`` (rows IPOPT marks with 'r')."""
    rows = []
    for line in Path(path).read_text(errors="replace").splitlines():
        m = _ROW.match(line)
        if m:
            rows.append((int(m.group(1)), m.group(2) == "r", float(m.group(3)), float(m.group(4)),
                         float(m.group(5)), float(m.group(6))))
    if not rows:
        return {k: np.array([]) for k in ("iter", "restoration", "objective", "inf_pr", "inf_du", "lg_mu")}
    a = list(zip(*rows))
    return {"iter": np.array(a[0]), "restoration": np.array(a[1], bool), "objective": np.array(a[2]),
            "inf_pr": np.array(a[3]), "inf_du": np.array(a[4]), "lg_mu": np.array(a[5])}


def plot_convergence(log_path, out_png, title: str | None = None):
    """Objective (scaled, as IPOPT sees it), primal and dual infeasibility vs iteration."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    h = parse_ipopt_log(log_path)
    if h["iter"].size == 0:
        raise ValueError(f"{log_path}: no IPOPT iteration rows found")
    n = np.arange(h["iter"].size)  # restoration phases restart nothing, keep row order
    fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax[0].plot(n, h["objective"], "k.-", ms=3)
    ax[0].set_ylabel("objective (scaled)")
    ax[0].grid(True, alpha=0.3)
    ax[1].semilogy(n, np.maximum(h["inf_pr"], 1e-20), ".-", ms=3, label="primal infeasibility")
    ax[1].semilogy(n, np.maximum(h["inf_du"], 1e-20), ".-", ms=3, label="dual infeasibility")
    ax[1].semilogy(n, 10.0 ** h["lg_mu"], ":", label="barrier parameter mu")
    if h["restoration"].any():
        ax[1].plot(n[h["restoration"]], h["inf_pr"][h["restoration"]], "rx", label="restoration")
    ax[1].set_xlabel("IPOPT iteration")
    ax[1].legend(fontsize=8)
    ax[1].grid(True, alpha=0.3)
    fig.suptitle(title or f"IPOPT convergence ({Path(log_path).parent.name})")
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png
