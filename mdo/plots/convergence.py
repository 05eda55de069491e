"""IPOPT convergence history: parsed from ``ipopt.log`` (so that it exists even for an
interrupted or failed solve), written as ``convergence.csv`` and plotted as objective,
primal and dual infeasibility.

The log is the one source: ``convergence.csv`` holds exactly the numbers of the log's
iteration lines (the intermediate callback's ``inf_pr`` differs from the printed one in
the first iterations, which is why the table is not taken from it).
"""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np

__all__ = ["parse_ipopt_log", "plot_convergence", "convergence_csv", "write_convergence_csv", "COLUMNS"]

_NUM = r"[-+]?(?:\d+\.?\d*(?:[eE][-+]?\d+)?|nan|inf)"
# iter  objective  inf_pr  inf_du  lg(mu)  ||d||  lg(rg)  alpha_du  alpha_pr[tag]  ls
_ROW = re.compile(rf"^\s*(\d+)(r?)\s+({_NUM})\s+({_NUM})\s+({_NUM})\s+({_NUM})\s+({_NUM})\s+(-|{_NUM})\s+"
                  rf"({_NUM})\s+({_NUM})([a-zA-Z]?)\s+(\d+)\s*$")

COLUMNS = ("iter", "objective", "inf_pr", "inf_du", "lg_mu", "d_norm", "lg_rg", "alpha_du", "alpha_pr", "ls")


def parse_ipopt_log(path) -> dict:
    """Iteration rows of an IPOPT log: dict of arrays ``iter, objective, inf_pr, inf_du,
    lg_mu, d_norm, lg_rg`` (nan for '-'), ``alpha_du, alpha_pr, ls``, a boolean
    ``restoration`` (rows IPOPT marks with 'r') and ``step_tag`` (the letter after alpha_pr)."""
    rows = []
    for line in Path(path).read_text(errors="replace").splitlines():
        m = _ROW.match(line)
        if m:
            g = m.groups()
            rows.append((int(g[0]), g[1] == "r", float(g[2]), float(g[3]), float(g[4]), float(g[5]), float(g[6]),
                         float("nan") if g[7] == "-" else float(g[7]), float(g[8]), float(g[9]), g[10], int(g[11])))
    keys = ("iter", "restoration", "objective", "inf_pr", "inf_du", "lg_mu", "d_norm", "lg_rg", "alpha_du",
            "alpha_pr", "step_tag", "ls")
    if not rows:
        return {k: np.array([]) for k in keys}
    cols = list(zip(*rows))
    out = {k: np.array(c) for k, c in zip(keys, cols)}
    out["restoration"] = out["restoration"].astype(bool)
    out["step_tag"] = list(cols[10])
    return out


def convergence_csv(log_path) -> str:
    """The text of ``convergence.csv``: the log's iteration lines, the numbers as printed."""
    h = parse_ipopt_log(log_path)
    lines = [",".join(COLUMNS) + ",restoration"]
    for i in range(h["iter"].size):
        vals = [f"{int(h['iter'][i])}"] + [f"{h[k][i]:.10g}" for k in COLUMNS[1:-1]] + \
               [f"{int(h['ls'][i])}", "1" if h["restoration"][i] else "0"]
        lines.append(",".join(vals))
    return "\n".join(lines) + "\n"


def write_convergence_csv(log_path, csv_path) -> int:
    """Write :func:`convergence_csv` to ``csv_path``; returns the number of iteration rows."""
    text = convergence_csv(log_path)
    Path(csv_path).write_text(text)
    return text.count("\n") - 1


def plot_convergence(log_path, out_png, title: str | None = None):
    """Objective (scaled, as IPOPT sees it), primal and dual infeasibility vs iteration."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator

    from .figures import run_title

    h = parse_ipopt_log(log_path)
    if h["iter"].size == 0:
        raise ValueError(f"{log_path}: no IPOPT iteration rows found")
    n = np.arange(h["iter"].size)  # restoration phases restart nothing, keep row order
    fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax[0].plot(n, h["objective"], "k.-", ms=3)
    ax[0].set_ylabel("objective, as scaled for IPOPT (-)")
    ax[0].grid(True, alpha=0.3)
    ax[1].semilogy(n, np.maximum(h["inf_pr"], 1e-20), ".-", ms=3, label="primal infeasibility inf_pr")
    ax[1].semilogy(n, np.maximum(h["inf_du"], 1e-20), ".-", ms=3, label="dual infeasibility inf_du")
    ax[1].semilogy(n, 10.0 ** h["lg_mu"], ":", label="barrier parameter mu")
    if h["restoration"].any():
        ax[1].plot(n[h["restoration"]], h["inf_pr"][h["restoration"]], "rx", label="restoration")
    ax[1].set_xlabel("IPOPT iteration")
    ax[1].set_ylabel("scaled infeasibility, mu (-)")
    ax[1].xaxis.set_major_locator(MaxNLocator(integer=True))
    ax[1].legend(fontsize=8)
    ax[1].grid(True, alpha=0.3)
    fig.suptitle(title or run_title(Path(log_path).parent, "IPOPT convergence"))
    fig.tight_layout()
    fig.savefig(out_png, dpi=110)
    plt.close(fig)
    return out_png
