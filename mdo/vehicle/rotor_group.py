"""One rotor group of an :class:`~mdo.vehicle.aircraft.Aircraft`: its design variables,
blade, motor, per-node BEMT and the limits of its rotors and motors.

A group is identical rotors (``RotorGroupConfig``), identically throttled, on one or
more lifting wings, each with its own motor (``MotorConfig``).  Everything here reads
the group's definition; nothing depends on its name except the variable names.

Design (Eq. 7 of Clarke et al., per group): Adkins-Liebeck design thrust, speed,
tip radius and lift coefficient; the rotor span positions; the motor's continuous
rating (sized: a variable of every stage, so the motors follow the mission).

Per node: rotor speed and BEMT inflow angles are unknowns; thrust, torque and
in-plane force come from the BEMT (azimuth-averaged at tilted-rotor transition
nodes).  A segment may switch the group off (parameter ``<group>.active`` = 0:
stopped or folded; no thrust, no torque, no wake, the folded drag area instead);
at those nodes the rotor speed is held at the design speed so that the (unused)
BEMT unknowns stay determined.

Limits per node (named constraint groups, on by default, see ``limits``):

* motor shaft power <= rating x (short-time factor in the take-off and climb segments);
* motor torque <= rated torque x the same factor (the rated torque is P_r / omega_r; both
  the rated power and the rated speed are sized with the mission, and the motor's
  mass follows its largest torque, NDARC);
* motor speed <= max_speed_factor x rated speed;
* throttle <= 1 (motor voltage <= pack voltage, Eq. E1 of mdo.powertrain);
* helical tip Mach ``sqrt((Omega R)^2 + V^2) / a <= M_max`` (Eq. 7's limit, at every
  node where the design can be changed; the design point only as an option).
"""
from __future__ import annotations

import numpy as np
import casadi as ca

from ..core import units as u
from ..core.atmosphere import atmosphere
from ..powertrain import MotorGroup
from ..rotor import PHI_MAX_RAD, PHI_MIN_RAD, adkins_liebeck, adkins_liebeck_implicit, bemt_function, section
from ..rotor.design import design_cl_stall_rows
from ..rotor.geometry import station_layout
from .base import ResidualGroup, Unknown

__all__ = ["RotorGroupModel"]


def _cols(v, idx, K):
    """Columns ``idx`` of a 1 x K row (or a scalar)."""
    if isinstance(v, (ca.MX, ca.SX, ca.DM)) and v.shape[1] == K and K > 1:
        return v[:, list(idx)]
    return v


def section_name(airfoil: str) -> str:
    """The key of ``mdo.rotor.section`` for a catalog airfoil name ("NACA_4412" -> "naca4412")."""
    return airfoil.lower().replace("_", "")


class RotorGroupModel:
    """The models of one ``RotorGroupConfig`` (see the module docstring)."""

    def __init__(self, group, vehicle_kind: str, tilting: bool, *, n_stations: int, n_azimuth: int,
                 pitch_control: bool = False, lift_loads: bool = True):
        self.config = group
        self.lift_loads = bool(lift_loads)
        self.pitch_control = bool(pitch_control) and group.variable_pitch   # a fixed-pitch group flies the schedule
        self.name = group.name
        self.tilting = bool(tilting)
        self.n_stations = int(n_stations)
        self.n_azimuth = int(n_azimuth) if self.tilting else 1
        self.section = section(section_name(group.airfoil))
        self.omega_design = group.design_rpm * u.RPM
        # the group's hub places a radial distribution of sections at the stations once (bemt_function)
        self.bemt = bemt_function(self.section, self.n_stations, self.n_azimuth, outputs="nlp",
                                  hub_fraction=group.hub_fraction)
        self._axial = bemt_function(self.section, self.n_stations, 1, outputs="nlp",
                                    hub_fraction=group.hub_fraction) if self.n_azimuth > 1 \
            else self.bemt
        self._baseline_blade = None

    # ------------------------------------------------------------------ design
    def baseline_blade(self) -> dict:
        """The numeric Adkins-Liebeck blade at the configured design point."""
        if self._baseline_blade is None:
            g = self.config
            self._baseline_blade = adkins_liebeck(
                blades=g.blades, radius_m=g.radius_m, speed_mps=g.design_speed_mps, airfoil=self.section,
                cl_design=g.design_cl, thrust_N=g.design_thrust_N, omega_radps=self.omega_design,
                hub_fraction=g.hub_fraction, altitude_m=g.design_altitude_m, n_stations=self.n_stations)
        return self._baseline_blade

    def add_design(self, problem, bounds, *, rotor_free: bool, positions_free: bool,
                   design_point_constraint: bool, stall_margin_cl: float | None = None) -> dict:
        """Design variables, the blade (Adkins-Liebeck, solved in the graph), its design
        point below stall (when the blade is designed and ``stall_margin_cl`` >= 0) and the
        motor rating."""
        g, b = self.config, bounds

        def dv(name, init, lo, hi, unit, scale, desc, free=True, shape=1, design=True):
            if not free:
                lo, hi = init, init
            return problem.variable(name, shape, unit=unit, scale=scale, lower=lo, upper=hi, init=init,
                                    design=design, description=desc)

        p = g.name
        d = {"T_design": dv(f"{p}.design_thrust", g.design_thrust_N, b.design_thrust[0] * g.design_thrust_N,
                            b.design_thrust[1] * g.design_thrust_N, "N", g.design_thrust_N,
                            "Adkins-Liebeck design thrust", rotor_free),
             "V_design": dv(f"{p}.design_speed", g.design_speed_mps, b.design_speed[0] * g.design_speed_mps,
                            b.design_speed[1] * g.design_speed_mps, "m/s", max(g.design_speed_mps, 5.0),
                            "Adkins-Liebeck design speed", rotor_free),
             "R": dv(f"{p}.tip_radius", g.radius_m, b.tip_radius[0] * g.radius_m, b.tip_radius[1] * g.radius_m,
                     "m", g.radius_m, "propeller/rotor tip radius", rotor_free),
             "cl_design": dv(f"{p}.design_cl", g.design_cl, b.design_cl[0], b.design_cl[1], "-", 1.0,
                             "Adkins-Liebeck design lift coefficient", rotor_free)}
        eta0 = np.asarray(g.span_eta, float)
        d["eta"] = dv(f"{p}.span_eta", eta0, b.span_eta[0], b.span_eta[1], "-", 1.0,
                      "rotor span positions, fraction of the semispan", positions_free, shape=len(eta0))
        m = g.motor
        w_r = g.motor_rated_rpm * u.RPM
        if m.sized:
            # sized in every stage (not frozen by --analysis): the least rating the mission allows;
            # the rated speed sets the speed constant (Eq. M6), so it is sized with it
            d["P_rated"] = problem.variable(f"{p}.motor_rated_power", 1, unit="W", scale=m.rated_power_W,
                                            lower=0.2 * m.rated_power_W, upper=10.0 * m.rated_power_W,
                                            init=m.rated_power_W, design=False,
                                            description="continuous shaft-power rating of each motor (sized)")
            d["omega_rated"] = problem.variable(f"{p}.motor_rated_speed", 1, unit="rad/s", scale=w_r,
                                                lower=0.4 * w_r, upper=2.5 * w_r, init=w_r, design=False,
                                                description="rated speed of each motor (sized)")
        else:
            d["P_rated"], d["omega_rated"] = m.rated_power_W, w_r
        self.design = d
        atm_d = atmosphere(g.design_altitude_m)
        al_inputs = {"target": d["T_design"], "speed_mps": d["V_design"], "radius_m": d["R"],
                     "omega_radps": self.omega_design, "cl_design": d["cl_design"],
                     "rho_kgpm3": float(atm_d["density_kgpm3"]), "mu_Pas": float(atm_d["dynamic_viscosity_Pas"]),
                     "a_mps": float(atm_d["speed_of_sound_mps"]), "hub_fraction": g.hub_fraction,
                     "blades": g.blades}
        # the blade, solved inside the graph (no blade unknowns: issue 20)
        self.blade = dict(adkins_liebeck_implicit(self.section, self.n_stations,
                                                  hub_fraction=g.hub_fraction)(**al_inputs))
        if rotor_free and stall_margin_cl is not None and stall_margin_cl >= 0.0:
            # the design cl is bounded by stall at each station's Reynolds number, not by a box
            problem.constrain(f"{p} design cl below stall",
                              design_cl_stall_rows(self.section, self.blade, d["cl_design"], g.hub_fraction,
                                                   stall_margin_cl),
                              kind="<=", rhs=0.0, scale=0.1, unit="-",
                              labels=[f"{p} design station {i}" for i in range(self.n_stations)])
        a_d = float(atm_d["speed_of_sound_mps"])
        tip2 = (self.omega_design * d["R"]) ** 2 + d["V_design"] ** 2
        if design_point_constraint:
            problem.constrain(f"{p} tip Mach (design point)", tip2 / (g.tip_mach_max * a_d) ** 2, kind="<=",
                              rhs=1.0, scale=1.0, unit="-", labels=[f"{p} design point"])
        self.tip_mach_design = ca.sqrt(tip2) / a_d
        problem.output(f"{p}.tip_mach_design", self.tip_mach_design, unit="-", summary=True)
        problem.output(f"{p}.motor_rated_power_kW", d["P_rated"] / 1000.0, unit="kW", summary=True)
        problem.output(f"{p}.motor_rated_rpm", d["omega_rated"] / u.RPM, unit="rpm", summary=True)
        return d

    def motor_group(self, pack) -> MotorGroup:
        """The group's motors, sized from the (symbolic) rating at the rated speed
        (``MotorConfig.drive``: PMSM + inverter, or the DC motor of Eq. M6)."""
        g = self.config
        self.rated_speed_radps = self.design["omega_rated"]
        self.motor = g.motor.drive(g.name, g.count, self.design["P_rated"], self.rated_speed_radps, pack)
        return self.motor

    # ------------------------------------------------------------------ nodes
    def unknowns(self) -> list:
        n, m = self.n_stations, self.n_azimuth
        out = [
            Unknown(f"{self.name}.omega", unit="rad/s", scale=self.omega_design, lower=0.05 * self.omega_design,
                    upper=3.0 * self.omega_design, description="rotor speed (all rotors of the group alike)"),
            Unknown(f"{self.name}.phi", unit="rad", scale=0.3, lower=PHI_MIN_RAD, upper=PHI_MAX_RAD, rows=n * m,
                    description="BEMT inflow angles (station fastest, then azimuth)"),
        ]
        if self.lift_loads:
            out += self.load_unknowns()
        if self.pitch_control:   # a variable-pitch hub: the collective is a control where the rotor runs
            lo, hi = (x * u.DEG for x in self.config.collective_range_deg)
            out.append(Unknown(f"{self.name}.collective_pitch", unit="rad", scale=0.2, lower=lo, upper=hi,
                               only_where=f"{self.name}.active", hold_where_uncollocated=True,
                               description="collective pitch added to the blade twist (hub stops "
                                           f"{self.config.collective_range_deg[0]:g} to "
                                           f"{self.config.collective_range_deg[1]:g} deg)"))
        return out

    def _load_specs(self) -> list:
        """(unknown suffix, BEMT output or "swirl", unit, scale, rows, description) of the lifted loads.
        Scales from the baseline blade at its design point."""
        b, n = self.baseline_blade(), self.n_stations
        T0, Q0 = abs(float(b["thrust_N"])), abs(float(b["torque_Nm"]))
        P0 = Q0 * self.omega_design
        specs = [("thrust", "thrust_N", "N", T0, 1, "thrust of one rotor"),
                 ("torque", "torque_Nm", "N m", Q0, 1, "shaft torque of one rotor"),
                 ("circulation", "gamma_m2ps", "m^2/s", float(np.max(np.abs(b["gamma_m2ps"]))), n,
                  "bound circulation of the blade stations (azimuth mean)"),
                 ("induced_velocity", "va_mean_mps", "m/s", max(0.5 * abs(float(b["w_mps"])), 1.0), 1,
                  "area-mean induced axial velocity at the disk"),
                 ("swirl_power", "swirl", "W", max(0.02 * P0, 10.0), 1,
                  "rotational kinetic-energy flux of one rotor's slipstream (swirl_power_W)")]
        if self.n_azimuth > 1:
            specs.insert(2, ("hforce", "hforce_N", "N", 0.1 * T0, 1, "in-plane force of one rotor"))
        return specs

    def load_unknowns(self) -> list:
        """The rotor's node loads as lifted unknowns (issue 20): thrust, torque, in-plane force
        (azimuth-averaged groups), the stations' circulation, the mean induced velocity and
        the slipstream's swirl power, each a variable at every node with an equality to its
        BEMT sum (:meth:`lifted_loads`).  Everything downstream (forces, powertrain, wake,
        lattice, limits) reads the variables, so each inflow angle's second derivatives touch
        only its own station's residual and these sums: a sparser Hessian, in fewer colours."""
        return [Unknown(f"{self.name}.{key}", unit=unit, scale=scale, rows=rows, description=desc + " (lifted)")
                for key, _, unit, scale, rows, desc in self._load_specs()]

    def lifted_loads(self, bm: dict, unknowns: dict, v_ax, rho) -> tuple:
        """The loads downstream blocks read and, when lifted, their defining equalities.

        Returns ({"thrust_N", "torque_Nm", "hforce_N", "gamma_m2ps", "va_mean_mps",
        "swirl_W"} per rotor, rows x K; [ResidualGroup]).  A one-azimuth BEMT has no
        in-plane force (its blade sits at psi = pi, where sin psi is round-off)."""
        swirl = self.swirl_power_W(bm, v_ax, rho)
        exact = {"thrust_N": bm["thrust_N"], "torque_Nm": bm["torque_Nm"],
                 "hforce_N": bm["hforce_N"] if self.n_azimuth > 1 else 0.0 * bm["thrust_N"],
                 "gamma_m2ps": bm["gamma_m2ps"], "va_mean_mps": bm["va_mean_mps"], "swirl_W": swirl}
        if not self.lift_loads:
            return exact, []
        out, groups = dict(exact), []
        for key, src, unit, scale, rows, _ in self._load_specs():
            name = f"{self.name}.{key}"
            dst = "swirl_W" if src == "swirl" else src
            out[dst] = unknowns[name]
            groups.append(ResidualGroup(f"{self.name} {key} (lifted)", unknowns[name] - exact[dst], scale=scale,
                                        unit=unit, defines=name,
                                        row_labels=[f"r{i}" for i in range(rows)] if rows > 1 else None))
        return out, groups

    def transition_nodes(self, wma) -> np.ndarray:
        """Nodes whose tilted rotors see in-plane flow worth azimuth averaging."""
        wma = np.asarray(wma, float).ravel()
        if self.n_azimuth == 1:
            return np.zeros(wma.size, bool)
        tilt_deg = np.degrees(wma)
        return (np.abs(tilt_deg) > 1.0) & (np.abs(tilt_deg - 90.0) > 1.0)

    def bemt_nodes(self, K, wma, pitch, omega, v_ax, v_ip, rho, mu, a_s, phi, azimuth_nodes=None):
        """BEMT outputs at all K nodes and the residual groups (``ResidualGroup`` with
        ``columns``): azimuth-averaged at transition nodes (by the scheduled angle ``wma``,
        numbers, or where ``azimuth_nodes`` is True: a tilt that is a control), axial
        elsewhere (the unused azimuth rows of phi then copy the axial ones, so that every
        unknown has an equation)."""
        g, n, m = self.config, self.n_stations, self.n_azimuth
        d = self.design
        common = dict(radius_m=d["R"], hub_fraction=g.hub_fraction, blades=g.blades,
                      chord_m=self.blade["chord_m"], twist_rad=self.blade["twist_rad"], spin=1.0)
        per = dict(pitch_rad=pitch, omega_radps=omega, v_axial_mps=v_ax, v_inplane_mps=v_ip, rho_kgpm3=rho,
                   mu_Pas=mu, a_mps=a_s)
        rows_m = [f"r{i} psi{j}" for j in range(m) for i in range(n)]
        mask = self.transition_nodes(wma)
        if azimuth_nodes is not None and self.tilting and m > 1:
            mask = mask | np.asarray(azimuth_nodes, bool)
        if m == 1 or mask.all():
            out = self.bemt.map(K)(**common, **per, phi_rad=phi)
            return out, [ResidualGroup(f"{g.name} BEMT", out["residual"], row_labels=rows_m)]
        it, ia = np.flatnonzero(mask), np.flatnonzero(~mask)
        pieces = []
        if it.size:
            pieces.append((it, self.bemt.map(it.size)(**common, **{k: _cols(v, it, K) for k, v in per.items()},
                                                         phi_rad=phi[:, list(it)])))
        pa = phi[:n, list(ia)]
        pieces.append((ia, self._axial.map(ia.size)(**common, **{k: _cols(v, ia, K) for k, v in per.items()},
                                                   phi_rad=pa)))
        order = np.concatenate([p[0] for p in pieces])
        # column j of the stacked blocks is node order[j]: perm[j, order[j]] = 1 puts it back
        perm = ca.DM.triplet(list(range(K)), [int(o) for o in order], ca.DM.ones(K), K, K)
        out = {key: ca.mtimes(ca.horzcat(*[p[1][key] for p in pieces]), perm)
               for key in pieces[0][1].keys() if key != "residual"}
        groups = []
        if it.size:
            groups.append(ResidualGroup(f"{g.name} BEMT (azimuth-averaged)", pieces[0][1]["residual"],
                                        row_labels=rows_m, columns=it))
        groups.append(ResidualGroup(f"{g.name} BEMT (axial)", pieces[-1][1]["residual"], row_labels=rows_m[:n],
                                    columns=ia))
        groups.append(ResidualGroup(f"{g.name} BEMT azimuth copies", phi[n:, list(ia)] - ca.repmat(pa, m - 1, 1),
                                    row_labels=rows_m[n:], columns=ia))
        return out, groups

    def swirl_power_W(self, bm, v_ax, rho):
        """Rotational kinetic-energy flux one rotor's slipstream carries, W (1 x K).

        Momentum theory with Prandtl's factor F (the BEMT's torque balance,
        ``dQ = rho (V + v_a) 2 pi r dr * r * 2 F v_t``): the far wake's annulus-mean
        swirl is ``2 F v_t`` (Glauert's doubling of the induced swirl ``v_t`` at the
        blade), carried by the annulus mass flow ``rho (V + v_a) 2 pi r dr``.  In
        Prandtl's picture a fraction F of the annulus moves with the sheets, at
        ``2 v_t``, the rest with the outer flow, so the mean square swirl is
        ``F (2 v_t)^2``::

            P_swirl = sum_i 1/2 rho (V + v_a,i) 2 pi r_i dr_i 4 F_i v_t,i^2

        This is the upper end of what the same angular momentum can carry (a uniform
        annulus, ``(2 F v_t)^2``, is the lower end), so it bounds what a wing behind
        the rotor can recover.  Without F (before 2026-12-03) the hub and tip stations,
        where F -> 0 makes v_t large, were credited 1/F times their energy (7x at the
        TTW rotors' hub, F = 0.15).
        """
        g = self.config
        s, ds = station_layout(self.n_stations)
        R = self.design["R"]
        r = R * (g.hub_fraction + (1.0 - g.hub_fraction) * ca.DM(s))
        dr = R * (1.0 - g.hub_fraction) * ca.DM(ds)
        va, msq = bm["va_mps"], bm["vt_msq_F_m2ps2"]
        K = va.shape[1]
        w = ca.repmat(2 * np.pi * r * dr, 1, K)
        axial = ca.repmat(v_ax, self.n_stations, 1) + va
        return ca.sum1(0.5 * ca.repmat(rho, self.n_stations, 1) * axial * w * 4.0 * msq)

    # ------------------------------------------------------------------ limits
    def short_time_row(self, nodes) -> np.ndarray:
        """Per node: the power factor the motor may use there (``short_time_factors``)."""
        t = nodes.time_s
        t_num = None if isinstance(t, (ca.MX, ca.SX)) else np.asarray(t, float).ravel()
        return short_time_factors(self.config, nodes.segment, t_num)

    def limits(self, nodes, omega, torque, motor_out, speed, a_s, *, tip_mach_at_nodes: bool) -> list:
        """The group's per-node limits as ``ResidualGroup`` inequalities (see the module docstring)."""
        g, d = self.config, self.design
        m = g.motor
        K = nodes.size
        f = ca.DM(self.short_time_row(nodes).reshape(1, -1))
        P_r = d["P_rated"]
        P0 = m.rated_power_W
        Q_r = P_r / self.rated_speed_radps
        lim = [
            ResidualGroup(f"{g.name} motor power", torque * omega - f * P_r, scale=P0, unit="W", kind="<=",
                          row_labels=["shaft power - rating"]),
            ResidualGroup(f"{g.name} motor torque", torque - f * Q_r, scale=P0 / (g.motor_rated_rpm * u.RPM),
                          unit="N m", kind="<=", row_labels=["torque - rated torque"]),
            ResidualGroup(f"{g.name} motor speed", omega - m.max_speed_factor * self.rated_speed_radps,
                          scale=g.motor_rated_rpm * u.RPM, unit="rad/s", kind="<=", row_labels=["speed - max speed"]),
            ResidualGroup(f"{g.name} throttle", -motor_out["voltage_margin_V"], scale=100.0, unit="V", kind="<=",
                          row_labels=["motor voltage - pack voltage"]),
        ]
        if tip_mach_at_nodes:
            tip2 = ((omega * d["R"]) ** 2 + speed * speed) / (g.tip_mach_max * a_s) ** 2
            lim.append(ResidualGroup(f"{g.name} tip Mach", tip2 - ca.DM.ones(1, K), scale=1.0, unit="-",
                                     kind="<=", row_labels=[f"(M_tip/{g.tip_mach_max:g})^2 - 1"]))
        return lim


def short_time_factors(group, segments, time_s=None) -> np.ndarray:
    """Per node: the power factor the motor of rotor group ``group`` (a ``RotorGroupConfig``)
    may use there: 1, or its short-time factor in the segments its motor configuration names
    (``segments``: each node's segment name).  With ``time_s`` (per node, s), a named segment
    longer than the short-time rating's duration is an ``InputError``."""
    from ..core.errors import InputError
    m = group.motor
    seg = list(segments)
    f = np.ones(len(seg))
    for name in m.short_time_segments:
        idx = [k for k, s in enumerate(seg) if s == name]
        if not idx:
            continue
        if time_s is not None:
            dur = float(time_s[idx[-1]] - time_s[idx[0]])
            if dur > m.short_time_duration_s * (1 + 1e-9):
                raise InputError(f"{group.name}.motor.short_time_segments",
                                 f"segment {name} lasts {dur:.0f} s, longer than the short-time rating's "
                                 f"{m.short_time_duration_s:.0f} s; remove it or raise short_time_duration_s")
        f[idx] = m.short_time_power_factor
    return f


def least_motor_rating(torque_Nm, omega_radps, factors, *, speed_margin: float, power_margin: float):
    """The least continuous rating (W, rad/s) that the motor limits of ``RotorGroupModel.limits``
    allow at the operating points ``torque_Nm``, ``omega_radps`` (per motor, arrays), each with
    its short-time factor ``factors``: rated speed ``speed_margin`` x the highest speed, rated power
    ``power_margin`` x the larger of the highest shaft power and the highest torque x the rated
    speed, each over the point's factor (power <= f P_r, torque <= f P_r / omega_r)."""
    Q, w, f = (np.asarray(a, float).ravel() for a in (torque_Nm, omega_radps, factors))
    w_r = speed_margin * float(np.max(w))
    return power_margin * max(float(np.max(Q * w / f)), float(np.max(Q * w_r / f)), 1.0), w_r


def motor_ratings_from_mission(config, mission: dict, speed_margin: float = 1.1,
                               power_margin: float = 1.05) -> dict:
    """Ratings of the sized motors that a flown mission fits, as initial values.

    ``config``: the ``VehicleConfig``; ``mission``: column name -> per-node array (the
    run folder's ``mission.csv``, e.g. ``mdo.runfolder.read_run(dir).mission``).  For each
    group with ``motor.sized``: the ``least_motor_rating`` of its nodes, with the short-time
    factors of their segments (``short_time_factors``).  Returns ``{"<group>.motor_rated_power": W,
    "<group>.motor_rated_speed": rad/s}``: a start for a solve with the limits on after one
    without them, where the ratings sit on their lower bounds because nothing held them up.
    Until 2026-12-07 the short-time factor was left out: the ratings came out up to that factor
    (1.2 for the TTW's hover and transitions) too high.
    """
    out = {}
    for g in config.rotor_groups:
        if not g.motor.sized:
            continue
        omega = np.asarray(mission[f"{g.name}.rotor_speed_rpm"], float) * u.RPM
        power = np.asarray(mission[f"{g.name}.shaft_power_W"], float) / g.count
        P_r, w_r = least_motor_rating(power / np.maximum(omega, 1e-6), omega, short_time_factors(g, mission["segment"]),
                                      speed_margin=speed_margin, power_margin=power_margin)
        out[f"{g.name}.motor_rated_power"] = P_r
        out[f"{g.name}.motor_rated_speed"] = w_r
    return out
