"""Physics-based initial guesses of the :class:`~mdo.vehicle.aircraft.Aircraft` at its
baseline design (DESIGN rule 7): the lattice's lift for the angle of attack, the drag
build-up for the thrust, the BEMT rotor speed for that thrust, the pack current from
the power balance.  Numbers only; nothing here enters the NLP's graph.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core.atmosphere import atmosphere
from ..rotor import PHI_MAX_RAD, PHI_MIN_RAD, analyze_inputs
from ..wing import VLM
from .base import G0

__all__ = ["initial_guess", "bemt_numeric", "omega_for_thrust"]


def initial_guess(ac, nodes) -> dict:
    """Physics-based guesses at the baseline design: lattice lift for the angle of
    attack, drag build-up for the thrust, BEMT rotor speed for that thrust."""
    cfg = ac.config
    K = nodes.size
    h = np.asarray(nodes.altitude_m, float).ravel()
    V = np.maximum(np.asarray(nodes.speed_mps, float).ravel(), 0.5)
    gam = np.asarray(nodes.flight_path_angle_rad, float).ravel()
    acc = np.asarray(nodes.acceleration_mps2, float).ravel()
    gdot = np.asarray(nodes.flight_path_angle_rate_radps, float).ravel()
    wma = np.asarray(nodes.parameters.get("wing_mounted_angle_rad", np.zeros(K)), float).ravel() * np.ones(K)
    pitch = np.asarray(nodes.parameters.get("pitch_command_rad", np.zeros(K)), float).ravel() * np.ones(K)
    flap = np.asarray(nodes.parameters.get("flap_deflection", np.zeros(K)), float).ravel() * np.ones(K)
    atm = atmosphere(h)
    rho, mu, a_s = atm["density_kgpm3"], atm["dynamic_viscosity_Pas"], atm["speed_of_sound_mps"]
    m = ac.togw_baseline_kg
    surfaces, _ = ac.wing_surfaces(ac.numeric_design())
    vlm = VLM(surfaces, S_ref=ac.S_ref if hasattr(ac, "S_ref") else sum(w.area_m2 for w in ac.lifting_wings),
              mach_ref=0.2)
    S = float(vlm.geometry["S_ref"]) if not isinstance(vlm.geometry["S_ref"], ca.MX) else ac.S_ref
    r0 = vlm.solve(ca.DM([[0.0, 0.1]]), 1.0)
    CL0, CL1 = (float(x) for x in np.asarray(r0["CL"]).ravel())
    CLa = (CL1 - CL0) / 0.1
    q = 0.5 * rho * V ** 2
    tilting = cfg.kind == "tilt_wing"
    # lift needed (thrust's normal share ignored); clip the angle of attack to the linear range
    vz1 = ac.flap_upwash(flap, ca.DM.ones(1, K), vlm)
    if vz1 is not None:   # the flaps' lift at zero angle of attack, per node
        z = ca.DM.zeros(vlm.n_panels, K)
        CL0 = np.asarray(vlm.solve(ca.DM.zeros(1, K), 1.0, v_ext=(z, z, vz1), v_ext_bound=(z, z, z))["CL"],
                         float).ravel()
    CL_req = m * (G0 * np.cos(gam) + V * gdot) / (q * S)
    alpha = np.clip((CL_req - CL0) / CLa - (wma if tilting else 0.0), np.radians(-8), np.radians(12))
    theta_in = np.asarray(nodes.body_angle_rad, float).ravel()
    free = np.isnan(theta_in)
    theta = np.where(free, alpha + gam, theta_in)
    DM = lambda x: ca.DM(np.asarray(x, float).reshape(1, -1))  # noqa: E731
    active = {gm.name: np.asarray(nodes.parameters.get(f"{gm.name}.active", np.ones(K)), float).ravel()
              * np.ones(K) for gm in ac.groups}
    vectored = tilting & (np.abs(wma) > np.radians(5.0))

    def forces(th, sel):
        """Lift, drag, and the force the thrust must supply (path frame) at attitudes th."""
        a_ = th - gam[sel]
        wa = a_ + wma[sel] if tilting else a_
        vz = ac.flap_upwash(flap[sel], DM(V[sel]), vlm)
        zero = ca.DM.zeros(vlm.n_panels, int(np.sum(sel)) if sel.dtype == bool else len(sel))
        r = vlm.solve(DM(wa), DM(V[sel]), rho=DM(rho[sel]), mach=DM(V[sel] / a_s[sel]),
                      v_ext=None if vz is None else (zero, zero, vz), v_ext_bound=None if vz is None else
                      (zero, zero, zero))
        idx = np.flatnonzero(sel) if sel.dtype == bool else np.asarray(sel)
        stopped = {gm.name: DM(1.0 - active[gm.name][idx]) for gm in ac.groups}
        b = ac.drag_buildup(vlm, r, DM(rho[sel]), DM(mu[sel]), DM(V[sel]), DM(V[sel] / a_s[sel]), stopped,
                            alpha_body=DM(a_))
        Dn = np.asarray(r["D_i"]).ravel() + np.asarray(b["D_parasite"], float).ravel()   # the model's build-up
        Ln = np.asarray(r["L"]).ravel() + np.asarray(b["L_stall"] + b["L_body"], float).ravel()
        nt = Dn + m * (G0 * np.sin(gam[sel]) + acc[sel])
        nn = m * (G0 * np.cos(gam[sel]) + V[sel] * gdot[sel]) - Ln
        return nt, nn

    allsel = np.ones(K, bool)
    need_t, need_n = forces(theta, allsel)
    fv = vectored & free
    if fv.any():
        # tilted rotors carry the weight: choose the attitude at which the thrust axis
        # points along the force the rotors must supply, with the least thrust
        idx = np.flatnonzero(fv)
        grid = np.radians(np.arange(-40.0, 81.0, 2.0))
        G = grid.size
        sel = np.repeat(idx, G)
        th_g = np.tile(grid, idx.size)
        nt, nn = forces(th_g, sel)
        a_g = th_g - gam[sel] + wma[sel]
        cross = (-nt * np.sin(a_g) + nn * np.cos(a_g)).reshape(idx.size, G)
        thrust = (nt * np.cos(a_g) + nn * np.sin(a_g)).reshape(idx.size, G)
        for j, k in enumerate(idx):
            c, t = cross[j], thrust[j]
            roots = [i for i in range(G - 1) if c[i] == 0 or c[i] * c[i + 1] < 0]
            good = [i for i in roots if t[i] > 0]
            if good:
                i = min(good, key=lambda i: t[i])
                f = c[i] / (c[i] - c[i + 1]) if c[i] != c[i + 1] else 0.0
                theta[k] = grid[i] + f * (grid[i + 1] - grid[i])
            else:
                theta[k] = grid[np.argmin(np.abs(c) / (np.abs(t) + 1.0))]
        nt, nn = forces(theta, allsel)
        need_t, need_n = nt, nn
    alpha = theta - gam
    return _rotor_guesses(ac, nodes, theta, alpha, vectored, need_t, need_n, V, h, wma, pitch, m)


def _rotor_guesses(ac, nodes, theta, alpha, vectored, need_t, need_n, V, h, wma, pitch, m) -> dict:
    """Split the force the rotors must supply among the running groups (by disk area),
    find each group's rotor speed for its share, and the pack current."""
    K = theta.size
    out = {"body_angle_rad": theta}
    shares, acts = {}, {}
    for gm in ac.groups:
        act = np.asarray(nodes.parameters.get(f"{gm.name}.active", np.ones(K)), float).ravel() * np.ones(K)
        acts[gm.name] = act > 0.5
        shares[gm.name] = acts[gm.name] * gm.config.count * gm.config.radius_m ** 2
    total = sum(shares.values())
    total = np.where(total > 0, total, 1.0)
    torques, omegas = [], []
    for gm in ac.groups:
        g = gm.config
        a_rot = alpha + (wma if gm.tilting else 0.0)
        T_total = np.where(vectored & gm.tilting, np.hypot(need_t, need_n), need_t / np.maximum(np.cos(a_rot), 0.3))
        frac = shares[gm.name] / total
        T1 = np.maximum(T_total * frac / g.count, 0.03 * m * G0 / max(1, sum(x.config.count for x in ac.groups)))
        mask = gm.transition_nodes(wma)
        n, mm_ = ac.n_stations, gm.n_azimuth
        omega, phi, Q1 = np.zeros(K), np.zeros((n * mm_, K)), np.zeros(K)
        for sel, mm in ((mask, mm_), (~mask, 1)):
            if not sel.any():
                continue
            args = (V[sel] * np.cos(a_rot[sel]), V[sel] * np.sin(a_rot[sel]), h[sel], pitch[sel])
            om = omega_for_thrust(gm, T1[sel], *args, n_azimuth=mm)
            om = np.where(acts[gm.name][sel], om, gm.omega_design)
            omega[sel] = om
            res = bemt_numeric(gm, om, *args, n_azimuth=mm)
            ph = np.asarray(res["phi_rad"], float).reshape(n * mm, int(sel.sum()))
            phi[:, sel] = ph if mm == mm_ else np.tile(ph, (mm_, 1))
            Q1[sel] = np.asarray(res["torque_Nm"], float).ravel()
        out[f"{g.name}.omega"] = omega
        if gm.pitch_control:   # the collective starts at the segments' schedule
            lo, hi = np.radians(g.collective_range_deg)
            out[f"{g.name}.collective_pitch"] = np.clip(pitch, lo, hi)
        out[f"{g.name}.phi"] = np.clip(phi, PHI_MIN_RAD, PHI_MAX_RAD)
        _size_motor_guess(ac, gm, nodes, np.where(acts[gm.name], Q1, 0.0), omega, acts[gm.name])
        torques.append(np.where(acts[gm.name], Q1, 0.0))
        omegas.append(omega)
    soc = np.asarray(nodes.states.get("state_of_charge", np.ones(K)), float).ravel() * np.ones(K)
    # a node whose guessed drag needs more than the pack can give (a slow node guessed without
    # the slipstreams' lift, its strips past stall) starts at the pack's maximum power
    po = ac.config.bus().analyze(torques, omegas, np.clip(soc, 0.05, 1.0), within_pack=True)
    out["battery_current_A"] = np.asarray(po["battery_current_A"], float).ravel()
    return out


def _size_motor_guess(ac, gm, nodes, Q1, omega, active):
    """Initial motor rating of a sized group: the least that meets the power, torque and
    speed limits at the guessed operating points (+5 %), so the limits start satisfied."""
    if not gm.config.motor.sized or not active.any():
        return
    from .rotor_group import least_motor_rating
    f = gm.short_time_row(nodes)
    # throttle and speed limits met with margin
    P_r, w_r = least_motor_rating(Q1[active], omega[active], f[active], speed_margin=1.02, power_margin=1.05)
    ac.guess_motor_rating(gm, P_r, w_r)


def bemt_numeric(gm, omega, v_ax, v_ip, h, pitch, n_azimuth=1):
    """Numeric BEMT of rotor group ``gm`` (a RotorGroupModel) at its baseline blade, with the
    sections placed at the stations as in the group's NLP Functions (``rotor_group.py``)."""
    g = gm.config
    blade = gm.baseline_blade()
    atm = atmosphere(h)
    K = omega.size
    inputs = {"radius_m": g.radius_m, "hub_fraction": g.hub_fraction, "blades": g.blades,
              "chord_m": np.asarray(blade["chord_m"], float).ravel(),
              "twist_rad": np.asarray(blade["twist_rad"], float).ravel(),
              "pitch_rad": pitch, "omega_radps": omega, "v_axial_mps": v_ax,
              "v_inplane_mps": v_ip if n_azimuth > 1 else np.zeros(K),
              "rho_kgpm3": atm["density_kgpm3"], "mu_Pas": atm["dynamic_viscosity_Pas"],
              "a_mps": atm["speed_of_sound_mps"], "spin": np.ones(K)}
    return analyze_inputs(gm.section, inputs, gm.n_stations, n_azimuth, hub_fraction=g.hub_fraction)

# ``mdo run`` builds a problem twice (the baseline with its design frozen, then the
# optimization): the same rotor-speed guesses, 2-3 s of numeric BEMT per build, are kept
# here for the second build.  The key holds the section object itself (the airfoil cache
# shares it between builds) and every number the result depends on.
_OMEGA_CACHE: dict = {}
_OMEGA_CACHE_SIZE = 32


def _omega_key(gm, arrays, scalars):
    g, blade = gm.config, gm.baseline_blade()
    nums = [np.asarray(a, float).tobytes() for a in
            (*arrays, blade["chord_m"], blade["twist_rad"])]
    return (gm.section, gm.n_stations, g.radius_m, g.hub_fraction, g.blades, float(gm.omega_design),
            *scalars, *nums)


def omega_for_thrust(gm, T1, v_ax, v_ip, h, pitch, iterations=40, n_azimuth=1, rtol=1e-10):
    """Rotor speed giving thrust ``T1`` per rotor at each node (see ``_omega_for_thrust``;
    a repeated call with the same rotor and conditions returns the stored result)."""
    key = _omega_key(gm, (T1, v_ax, v_ip, h, pitch), (iterations, n_azimuth, rtol))
    hit = _OMEGA_CACHE.get(key)
    if hit is None:
        hit = _omega_for_thrust(gm, T1, v_ax, v_ip, h, pitch, iterations, n_azimuth, rtol)
        if len(_OMEGA_CACHE) >= _OMEGA_CACHE_SIZE:
            _OMEGA_CACHE.pop(next(iter(_OMEGA_CACHE)))
        _OMEGA_CACHE[key] = hit
    return hit.copy()


def speed_grid(gm) -> np.ndarray:
    """The rotor speeds [rad/s] the rotor-speed search climbs: 0.05-2.5 x the design speed."""
    return gm.omega_design * np.linspace(0.05, 2.5, 25)


def _omega_for_thrust(gm, T1, v_ax, v_ip, h, pitch, iterations=40, n_azimuth=1, rtol=1e-10):
    """Rotor speed giving thrust ``T1`` per rotor at each node: a scan for the
    lowest speed whose thrust reaches T1 (thrust need not be monotonic in speed
    for a blade far from its design inflow), then the Illinois variant of regula
    falsi in that interval (Dowell & Jarratt, BIT 11, 1971: superlinear, and it keeps
    the bracket), to ``|T - T1| <= rtol T1`` at every node (about 6-8 BEMT solves
    where 22 bisection steps were needed for the same rotor speed)."""
    grid = speed_grid(gm)
    K = T1.size
    # the scan climbs the grid and stops at each node once its thrust reaches T1: the
    # same bracket as the whole grid's, with the speeds above it never evaluated (GA-2P:
    # about 10 of 25 grid speeds per node)
    Tg = np.full((grid.size, K), np.nan)
    climbing = np.ones(K, bool)
    for i, om in enumerate(grid):
        idx = np.flatnonzero(climbing)
        if not idx.size:
            break
        Tg[i, idx] = np.asarray(bemt_numeric(gm, np.full(idx.size, om), *_at(idx, K, v_ax, v_ip, h, pitch),
                                             n_azimuth)["thrust_N"], float).ravel()
        climbing[idx] = ~(Tg[i, idx] >= T1[idx])
    reach = Tg >= T1[None, :]
    j = np.where(reach.any(axis=0), np.argmax(reach, axis=0), grid.size - 1)
    cols = np.arange(K)
    hi, f_hi = grid[j], Tg[j, cols] - T1
    lo, f_lo = grid[np.maximum(j - 1, 0)], Tg[np.maximum(j - 1, 0), cols] - T1
    # no sign change (T1 below the first or above the last grid speed): the bracket's end
    out = np.where(f_hi < 0, hi, lo)
    live = (f_lo < 0) & (f_hi >= 0) & (j > 0)
    side = np.zeros(K, int)             # which end was kept last (Illinois halves its value)
    tol = rtol * np.maximum(np.abs(T1), 1e-9)
    for _ in range(iterations):
        if not live.any():
            break
        idx = np.flatnonzero(live)
        a, b, fa, fb = lo[idx], hi[idx], f_lo[idx], f_hi[idx]
        x = b - fb * (b - a) / (fb - fa)
        x = np.where((x > a) & (x < b), x, 0.5 * (a + b))
        fx = np.asarray(bemt_numeric(gm, x, *_at(idx, K, v_ax, v_ip, h, pitch), n_azimuth)["thrust_N"],
                        float).ravel() - T1[idx]
        out[idx] = x
        done = np.abs(fx) <= tol[idx]
        left = fx < 0                    # the root lies in (x, b]: x replaces lo
        lo[idx] = np.where(left, x, a)
        f_lo[idx] = np.where(left, fx, np.where(side[idx] == -1, 0.5 * fa, fa))
        hi[idx] = np.where(left, b, x)
        f_hi[idx] = np.where(left, np.where(side[idx] == 1, 0.5 * fb, fb), fx)
        side[idx] = np.where(left, 1, -1)
        live[idx] = ~done
    return out


def _at(idx, K, *rows):
    """The ``idx`` entries of each row (numbers broadcast to K first)."""
    return tuple((np.asarray(r, float) * np.ones(K))[idx] for r in rows)
