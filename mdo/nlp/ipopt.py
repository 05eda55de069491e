"""How mdo runs IPOPT: the solve options, statuses and signal handling of
:meth:`mdo.nlp.problem.Problem.solve` (kept apart from the problem's building side)."""
from __future__ import annotations

import contextlib
import math
import os
import signal
from dataclasses import dataclass

from ..core.parallel import check_threads, default_threads  # noqa: F401 (re-exported)
from ..core.signals import SignalInterrupt

__all__ = ["DivergenceWatch", "HESSIAN_CHOICES", "check_threads", "default_threads", "INTERRUPT_STATUS",
           "CRASH_ON_EXIT_STATUS", "FRAGILE", "FROM_BASELINE_OPTIONS",
           "WARM_START_OPTIONS"]

#: ``Problem.solve(hessian=...)``: exact (split by structure), exact (one colouring), quasi-Newton
HESSIAN_CHOICES = ("exact", "full", "limited-memory")


# status of a solve stopped by a signal -> (signal name, conventional exit code 128 + signum)
INTERRUPT_STATUS = {"Interrupted_By_User": ("SIGINT", 130), "Terminated_By_Signal": ("SIGTERM", 143)}

# IPOPT statuses after which CasADi 3.6-3.8 crashes (SIGSEGV) when the solver is destroyed
# at interpreter exit; the CLI then leaves with os._exit once its files are flushed
CRASH_ON_EXIT_STATUS = {"Invalid_Option"}
FRAGILE = []   # Opti objects whose solve ended so: kept alive until os._exit


# The optimization started from its converged baseline (mdo run's stage 2): a monotone
# barrier instead of IPOPT's adaptive mu.  Measured 2026-12-02 on the GA
# family: the adaptive rule's free mode dropped mu to 1e-9.5 with the iterate still
# 0.1 infeasible and took steps of |d| 20-30 that left the feasible region for good
# (GA-8P's layout and the 12-propeller member: "local infeasibility" / diverged), while
# the monotone barrier converged in 48 and 38 iterations; on GA-2P 42 iterations to
# 51.402 kWh against 69 to 51.434 kWh.  A problem that sets its own mu_strategy keeps it.
# Started at mu = 1e-4 since 2026-12-05 (tests/bench/barrier_start.py, results/benchmark.md):
# at 1e-2 the barrier terms of ~2700 bounded unknowns weigh as much as the objective, and
# the GA iterates climbed from 74 to 85 kWh before coming back; from 1e-4 GA-8P needs 23
# iterations instead of 51 to the same optimum, GA-2P 26 instead of 43.
FROM_BASELINE_OPTIONS = {"mu_strategy": "monotone", "mu_init": 1e-4}
BARRIERS = ("monotone", "adaptive")   # Problem.barrier_order: monotone = FROM_BASELINE_OPTIONS



class Diverging(RuntimeError):
    """Raised in IPOPT's iteration callback by :class:`DivergenceWatch` (IPOPT then ends
    ``User_Requested_Stop`` with the last iterate)."""


@dataclass
class DivergenceWatch:
    """Give up a solve that has left for good, read from the IPOPT log file as written so far
    (IPOPT writes it in blocks, so the watch may see the last iterations late; measured: the
    previous line on a small problem, up to 4 kB, about 40 iterations, on the TTW).  For the
    first attempt from the baseline, which has a fallback (``mdo run``).  Two signs:

    * **the duals run away**: after iteration ``after_iter``, ``run`` consecutive iterations
      with IPOPT's (scaled) ``inf_du`` above ``inf_du_max``.  GA-2P at 170 mph spent 500
      iterations and 675 s wandering with inf_du up to 1e6 before the fallback converged in
      14; the TTW met its constraints at iteration 168 and then wandered 130 iterations with
      inf_du 1e4-1e13.  The committed converged runs stay below it (largest inf_du after
      iteration 50: 3.9e3, GA-2P's block-time free trajectory, 281 iterations);
    * **the barrier stalls at its start**: after iteration ``mu_after_iter``, ``mu_run``
      consecutive iterations with lg(mu) at or above ``lg_mu_stall`` (an adaptive barrier still
      at IPOPT's initial mu 0.1: its free mode never took hold).  The TTW from a design drawn
      within +-15 % (2026-12-06, robustness start 0) held lg(mu) = -1.0 from iteration 5 to 126
      with inf_du growing from 1e2 to 1e6; the committed adaptive runs leave it within a few
      iterations (largest lg(mu) after iteration 30: -3.3, and -1.6 to 1.1 for at most 10
      iterations in a row in the untrimmed TTW's 260-iteration fallback).  A monotone attempt
      (mu 1e-4) never meets it;
    * **the Hessian stays far from convex**: ``rg_run`` consecutive iterations whose inertia
      correction is at least ``10**lg_rg_stuck`` (IPOPT's lg(rg)): each step is then a tiny
      gradient step, and each iteration costs several factorizations (a minute on the TTW).
      Three TTW attempts that ended by a timeout or by hand held it at 1e7-1e10 for 8-9
      iterations in a row (robustness start 1 on 2026-12-06, sixteenth session, from iteration 14
      to its 1500 s timeout at 22; the same study's start 2 with a pole-free BEMT residual,
      seventeenth; ``results/ttw/drag_pmsm_attempt``, stopped by hand at 69); the committed
      converged runs hold it at most 5 iterations (the untrimmed TTW's analysis).

    Replayed on every ``ipopt.log`` under ``results/`` on 2026-12-06 (49): none of the signs would
    have stopped any of the 44 converged runs; each of the five attempts that did not converge
    meets one of them (the new sign: ``drag_pmsm_attempt`` at iteration 67)."""

    after_iter: int = 100
    inf_du_max: float = 1e4
    run: int = 10
    mu_after_iter: int = 20
    lg_mu_stall: float = -1.2
    mu_run: int = 20
    lg_rg_stuck: float = 7.0
    rg_run: int = 7
    reason: str | None = None

    def check(self, log_path, iteration: int) -> None:
        if iteration < min(self.after_iter, self.mu_after_iter, self.rg_run - 1):
            return
        rows = _last_iterations(log_path, max(self.run, self.mu_run, self.rg_run))
        du_rows, mu_rows, rg_rows = rows[-self.run:], rows[-self.mu_run:], rows[-self.rg_run:]
        if len(rg_rows) == self.rg_run and min(r[3] for r in rg_rows) >= self.lg_rg_stuck:
            it, du, _, rg = rg_rows[-1]
            self.reason = (f"inertia correction at lg(rg) >= {self.lg_rg_stuck:g} for {self.rg_run} iterations "
                           f"(lg(rg) {rg:g}, dual infeasibility {du:.1e} at iteration {it})")
            raise Diverging(self.reason)
        if iteration > self.after_iter and len(du_rows) == self.run and min(r[1] for r in du_rows) > self.inf_du_max:
            it, du, _, _ = du_rows[-1]
            self.reason = (f"dual infeasibility above {self.inf_du_max:g} for {self.run} iterations "
                           f"after iteration {self.after_iter} (last {du:.1e} at iteration {it})")
            raise Diverging(self.reason)
        if (iteration > self.mu_after_iter and len(mu_rows) == self.mu_run
                and min(r[2] for r in mu_rows) >= self.lg_mu_stall and mu_rows[0][0] > self.mu_after_iter):
            it, du, mu, _ = mu_rows[-1]
            self.reason = (f"barrier parameter at lg(mu) >= {self.lg_mu_stall:g} for {self.mu_run} iterations "
                           f"after iteration {self.mu_after_iter} (lg(mu) {mu:g}, dual infeasibility {du:.1e} "
                           f"at iteration {it})")
            raise Diverging(self.reason)


def _last_iterations(log_path, n: int) -> list:
    """(iteration, inf_du, lg(mu), lg(rg)) of the last ``n`` iteration lines of an IPOPT log (fewer
    if not yet written); lg(rg) is -inf where IPOPT made no inertia correction ("-")."""
    try:
        with open(log_path, "rb") as f:
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - 200 * (n + 20)))
            lines = f.read().decode("ascii", "replace").splitlines()[1:]
    except OSError:
        return []
    out = []
    for line in lines:
        tok = line.split()
        if len(tok) >= 7 and tok[0].rstrip("r").isdigit():
            with contextlib.suppress(ValueError):
                rg = -math.inf if tok[6] == "-" else float(tok[6])
                out.append((int(tok[0].rstrip("r")), float(tok[3]), float(tok[4]), rg))
    return out[-n:]


WARM_START_OPTIONS = {
    "warm_start_init_point": "yes",
    "warm_start_bound_push": 1e-9,
    "warm_start_bound_frac": 1e-9,
    "warm_start_slack_bound_push": 1e-9,
    "warm_start_slack_bound_frac": 1e-9,
    "warm_start_mult_bound_push": 1e-9,
    "mu_init": 1e-9,
}


def _outcome(stats: dict, max_iter: int, signum):
    """(history, status, success, iterations) from IPOPT's stats and the signal caught."""
    history = {"iter": [], "objective": [], "inf_pr": [], "inf_du": []}
    it = stats.get("iterations", {})
    if it:
        history["objective"] = [float(v) for v in it.get("obj", [])]
        history["inf_pr"] = [float(v) for v in it.get("inf_pr", [])]
        history["inf_du"] = [float(v) for v in it.get("inf_du", [])]
        history["iter"] = list(range(len(history["objective"])))
    if signum is None:
        status = stats.get("return_status", "unknown")
    else:
        status = "Terminated_By_Signal" if signum == signal.SIGTERM else "Interrupted_By_User"
    success = bool(stats.get("success", False)) and signum is None
    n_iter = int(stats.get("iter_count", 0))
    if not (0 <= n_iter <= max_iter):
        # IPOPT aborted (interrupt, exception): its counter is not set; use what was logged
        n_iter = max(len(history["objective"]) - 1, 0)
    return history, status, success, n_iter


@contextlib.contextmanager
def _signals_as_interrupts():
    """SIGINT and SIGTERM raise KeyboardInterrupt while IPOPT runs (CasADi checks for a
    pending Python exception in its iteration callback and stops with the last iterate);
    yields a dict whose ``"signal"`` says which one came."""
    caught: dict = {}

    def handler(signum, frame):
        caught.setdefault("signal", int(signum))
        raise SignalInterrupt(signum)

    previous = {}
    for sig in (signal.SIGINT, signal.SIGTERM):
        with contextlib.suppress(ValueError, OSError):  # not in the main thread: leave handlers alone
            previous[sig] = signal.signal(sig, handler)
    try:
        yield caught
    finally:
        for sig, h in previous.items():
            signal.signal(sig, h)
