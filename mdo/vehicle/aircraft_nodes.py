"""What an :class:`~mdo.vehicle.aircraft.Aircraft` states at its nodes, apart from its
physics: the operating limits (named constraint groups, issue 16: motor power, torque,
speed and throttle per rotor group, helical tip Mach, cell current and voltage, charging,
the strips' stall margin, the rudder's hold of a failed motor's yaw) and the outputs that become
the columns of ``mission.csv``.
Both read the node's rotor, powertrain and aerodynamic results that ``Aircraft.evaluate``
computed; nothing here adds a variable.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..core import units as u
from .balance import surface_lift_N
from .base import G0, Output, ResidualGroup
from .engine_out import engine_out_moments_once, engine_out_rows
from .stall import stall_margin_rows

__all__ = ["operating_limits", "node_outputs", "wing_design_lift_rows"]


def _row(x, K=None) -> ca.DM:
    a = np.asarray(x, dtype=float).reshape(1, -1)
    if K is not None and a.size == 1:
        a = np.repeat(a, K, axis=1)
    return ca.DM(a)


def _num(x) -> np.ndarray:
    return np.asarray(ca.DM(x), dtype=float)


def _stall_margin(ac, nodes, K) -> np.ndarray:
    """Each node's stall margin (cl): the segment's ``stall_margin_cl`` or the vehicle's;
    negative where the segment is not wing-borne (a tilt-wing's transitions)."""
    return _num(nodes.parameters.get("stall_margin_cl", _row(ac.stall_margin_cl, K))).ravel() * np.ones(K)


def operating_limits(ac, nodes, rot, po, aero, env) -> list:
    """Operating limits at every node, named groups (``mdo.vehicle.aircraft`` docstring, item 8)."""
    K = env["K"]
    tip_nodes = ac.tip_mach_limit == "nodes" and ac.design_point_constraints
    out = []
    for gm in ac.groups:
        o = rot[gm.name]
        lims = gm.limits(nodes, o["omega"], o["Q"], po["groups"][gm.name], env["V"], env["a_s"],
                         tip_mach_at_nodes=tip_nodes)
        on = o["on"]
        for lim in lims:
            if on.size < K:
                lim.expr, lim.columns = lim.expr[:, list(on)], on
            out.append(lim)
    pk = ac.pack
    out.append(ResidualGroup("cell current", po["cell_current_A"] - pk.max_cell_current_A, kind="<=",
                             scale=pk.max_cell_current_A, unit="A", row_labels=["cell current - max"]))
    out.append(ResidualGroup("cell voltage", po["cell_voltage_V"] - pk.min_cell_voltage_V, kind=">=",
                             scale=1.0, unit="V", row_labels=["cell voltage - cut-off"]))
    if not ac.allow_regeneration:
        out.append(ResidualGroup("no battery charging", po["cell_current_A"], kind=">=",
                                 scale=pk.max_cell_current_A, unit="A", row_labels=["cell current >= 0"]))
    else:   # windmilling may charge the pack, at most at the cell's charge rating
        out.append(ResidualGroup("cell charge current", po["cell_current_A"] + pk.max_charge_current_A,
                                 kind=">=", scale=pk.max_charge_current_A, unit="A",
                                 row_labels=["cell current + max charge current"]))
    margin = _stall_margin(ac, nodes, K)
    cols = np.flatnonzero(margin >= 0.0)
    if not ac.design_point_constraints:
        # a frozen design cannot change its span loading: its analysis holds the strips
        # below cl_max itself (margin 0) and reports the margin it has (as the tip Mach)
        margin = np.where(margin >= 0.0, 0.0, margin)
    # the lifting wings and the all-moving trim surfaces (a stabilator must not stall either)
    checked = ac.lifting_wings + ac.trim_surfaces
    expr, labels = stall_margin_rows(ac.vlm, aero["vlm"], checked, ac.strip_eta, env["rho"],
                                     env["V"], env["mu"], _row(margin), nodes.parameters.get(
                                         "flap_deflection", _row(0.0, K)), cols, exposed=ac.strip_exposed)
    if expr is not None:
        out.append(ResidualGroup("stall margin", expr, kind="<=", scale=0.1, unit="-", row_labels=labels,
                                 columns=cols))
    # the wing-borne nodes: where the rudder and not the rotors fly it.  A property of the design, as
    # the design-point tip Mach: the analysis of a frozen design reports it (mission.csv's
    # rudder_yaw_moment_Nm and <group>.engine_out_yaw_moment_Nm) and flies the mission as defined
    if ac.engine_out == "rudder" and ac.design_point_constraints:
        out += engine_out_rows(ac, nodes, rot, env, _stall_margin(ac, nodes, K) >= 0.0)
    return out


def wing_design_lift_rows(ac, nodes, aero, env) -> list:
    """Sizing of each wing's structure (a ``WingStructure``): at every wing-borne node (its
    stall margin on) the wing's lift is at most its design lift, which the bending material
    carries ``n_ult`` times; at the other nodes (the tilt-wing's transitions, whose maneuver
    envelope is not modelled) at most the limit load, ``n_ult / 1.5`` times it."""
    K = env["K"]
    margin = _stall_margin(ac, nodes, K)
    borne, other = np.flatnonzero(margin >= 0.0), np.flatnonzero(margin < 0.0)
    n_limit = ac.config.ultimate_load_factor / 1.5
    names = [s_.name for s_ in ac.vlm.surfaces]
    scale = ac.togw_baseline_kg * G0
    out = []
    for name, F in getattr(ac, "wing_design_lift", {}).items():
        L = surface_lift_N(ac.vlm, aero["vlm"], names.index(name), env["rho"], env["V"])
        if borne.size:
            out.append(ResidualGroup(f"{name} design lift", L[:, list(borne)] - F, kind="<=", scale=scale,
                                     unit="N", row_labels=[f"{name} lift - design lift"], columns=borne))
        if other.size:
            out.append(ResidualGroup(f"{name} limit load", L[:, list(other)] - n_limit * F, kind="<=",
                                     scale=scale, unit="N", row_labels=[f"{name} lift - limit load"],
                                     columns=other))
    return out


DRAG_TERM_DOC = {
    "profile": "section profile drag of every lattice strip (local q and Re; post-stall strips)",
    "fuselage": "fuselage skin friction x form factor (Raymer build-up)",
    "nacelles": "nacelles at their slipstream's dynamic pressure (Raymer build-up)",
    "fins": "fins: skin friction x form factor x wetted area",
    "folded": "stopped/folded rotors' drag area",
    "leakage": "leakage and protuberances (fraction of the component drag, Raymer 12.5.9)",
    "cooling": "cooling air of the motors and inverters (momentum deficit, Eq. B3)",
    "fuselage_crossflow": "fuselage at angle of attack: the viscous crossflow's drag (Allen & Perkins)",
}


def node_outputs(ac, nodes, rot, aero, po, env) -> dict:
    """The per-node outputs (``mission.csv`` columns), whole-aircraft then per rotor group."""
    V, alpha = env["V"], env["alpha"]
    r, q = aero["vlm"], aero["q"]
    T_tot = sum(gm.config.count * rot[gm.name]["T"] for gm in ac.groups)
    P_shaft = sum(gm.config.count * rot[gm.name]["Q"] * rot[gm.name]["omega"] for gm in ac.groups)
    P_thrust = sum(gm.config.count * (rot[gm.name]["T"] * rot[gm.name]["cos"] - rot[gm.name]["H"]
                                      * rot[gm.name]["sin"]) for gm in ac.groups) * V
    P_axial = sum(gm.config.count * rot[gm.name]["T"] * rot[gm.name]["v_ax"] for gm in ac.groups)
    out = {
        "CL": Output(r["CL"], "-", "lift coefficient on S_ref"),
        "CD": Output(aero["D"] / (q * ac.S_ref + 1e-9), "-", "drag coefficient on S_ref"),
        "CDi": Output(aero["D_i"] / (q * ac.S_ref + 1e-9), "-", "induced drag coefficient (swirl credit bounded)"),
        "lift_N": Output(aero["L"], "N"), "drag_N": Output(aero["D"], "N"),
        "induced_drag_N": Output(aero["D_i"], "N"), "parasite_drag_N": Output(aero["D_parasite"], "N"),
        "drag_device_drag_N": Output(aero["D_device"], "N", "gear/flap drag deployed on approach (in parasite)"),
        "drag_device_deployment": Output(aero["deploy"], "-", "fraction of the segment's drag_device_area_m2"),
        "CDp": Output(aero["D_parasite"] / (q * ac.S_ref + 1e-9), "-",
                      "parasite drag coefficient on S_ref (the build-up's terms, drag device included)"),
        **{f"drag_{name}_N": Output(term * _row(1.0, env["K"]), "N", DRAG_TERM_DOC[name])
           for name, term in aero["drag_terms"].items()},
        "swirl_recovered_power_W": Output(aero["swirl_recovered_W"], "W",
                                          "near-field thrust power of the wing in the slipstreams' swirl"),
        "swirl_available_power_W": Output(aero["swirl_available_W"], "W",
                                          "rotational kinetic-energy flux of all slipstreams"),
        "swirl_credited_power_W": Output(aero["swirl_credit_W"], "W", "swirl power credited (bounded)"),
        "angle_of_attack_deg": Output(alpha / u.DEG, "deg"),
        "wing_mounted_angle_deg": Output(env["wma"] * _row(1.0, env["K"]) / u.DEG, "deg",
                                         "wing-mounted angle flown (the schedule, or the tilt control)"),
        "thrust_N": Output(T_tot, "N", "total thrust"),
        "thrust_power_W": Output(P_thrust, "W", "rotor force along the path times speed (useful propulsive power)"),
        "shaft_power_W": Output(P_shaft, "W", "total shaft power"),
        "propulsive_efficiency": Output(P_axial / (P_shaft + 1e-9), "-"),
        "battery_power_W": Output(po["chemical_power_W"], "W", "chemical power drawn from the cells"),
        "terminal_power_W": Output(po["battery_power_W"], "W"),
        "state_of_charge": Output(nodes.states["state_of_charge"], "-"),
        "cell_current_A": Output(po["cell_current_A"], "A"),
        "cell_voltage_V": Output(po["cell_voltage_V"], "V"),
    }
    names = [s_.name for s_ in ac.vlm.surfaces]
    for w in ac.trim_surfaces:
        delta = aero["trim_incidence"][w.name]
        out[f"{w.name}.trim_incidence_deg"] = Output(delta * _row(1.0, env["K"]) / u.DEG, "deg",
                                                      f"{w.name}: incidence added for pitch trim")
        out[f"{w.name}.lift_N"] = Output(surface_lift_N(ac.vlm, r, names.index(w.name), env["rho"], V), "N",
                                         f"{w.name}: lift of the surface (negative: a download)")
    if ac.fins:   # the engine-out limit's two sides (mdo.vehicle.engine_out), at every node
        N_rudder, demand = engine_out_moments_once(ac, env)
        out["rudder_yaw_moment_Nm"] = Output(N_rudder, "N m", "the fins' largest rudder yawing moment")
        for gm in ac.groups:
            worst = demand[gm.name][0]
            for d in demand[gm.name][1:]:   # (an output: the largest of the positions, not smooth)
                worst = ca.fmax(worst, d)
            out[f"{gm.name}.engine_out_yaw_moment_Nm"] = Output(
                worst, "N m", f"{gm.name}: yawing moment with its outermost motor failed and its mirror at "
                              "take-off power (momentum theory)")
    for i, gm in enumerate(ac.groups):
        o, mo, g = rot[gm.name], po["groups"][gm.name], gm.config
        tip = ca.sqrt((o["omega"] * gm.design["R"]) ** 2 + V * V) / env["a_s"]
        eff = o["Q"] * o["omega"] / (mo["motor_power_in_W"] + 1e-9)
        per = {"thrust_N": Output(g.count * o["T"], "N", f"{g.name}: thrust of the group"),
               "rotor_speed_rpm": Output(o["omega"] / u.RPM, "rpm"), "tip_mach": Output(tip, "-"),
               "collective_pitch_deg": Output(o["pitch"] / u.DEG, "deg",
                                              "collective pitch added to the blade twist (control or schedule)"),
               "shaft_power_W": Output(g.count * o["Q"] * o["omega"], "W"),
               "motor_power_fraction": Output(o["Q"] * o["omega"] / gm.design["P_rated"], "-",
                                              "shaft power / continuous rating"),
               "throttle": Output(mo["throttle"], "-"), "motor_efficiency": Output(eff, "-"),
               "drive_efficiency": Output(o["Q"] * o["omega"] / (mo["esc_power_in_W"] + 1e-9), "-",
                                          "shaft power / bus power of one motor with its inverter (or ESC)"),
               "induced_axial_velocity_mps": Output(o["bemt"]["va_mean_mps"], "m/s",
                                                    "mean axial induced velocity at the disk (wake pitch)")}
        for k, v in per.items():
            out[f"{g.name}.{k}"] = v
        if i == 0:   # the first group under the plain names (single-group reports)
            for k in ("rotor_speed_rpm", "tip_mach", "throttle", "motor_efficiency", "motor_power_fraction"):
                out[k] = per[k]
    return out
