"""The :class:`~mdo.vehicle.aircraft.Aircraft`'s parasite drag build-up and its flaps and
drag device, as a mixin: everything but the lattice's induced drag, for a lattice solution
at the nodes (or a numeric one, for the initial guess and the reports).  Every term has
its source in the method's docstring; ``mdo.wing.buildup`` is the same physics for a
whole airframe without a lattice.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.smooth import smooth_max
from ..wing import body_drag, crossflow_normal_force, profile_drag
from ..wing.buildup import CP_AIR
from ..wing.drag import form_factor_wing, skin_friction
from .aircraft_nodes import _num, _row, _stall_margin
from .stall import stall_correction

__all__ = ["AirframeDragMixin"]


class AirframeDragMixin:
    """Drag terms of an ``Aircraft`` (uses its ``config``, ``groups``, ``bodies``, ``fins``,
    ``nacelles``, ``vlm``, ``lifting_wings``, ``strip_eta`` and ``wing_stall``)."""

    def drag_buildup(self, vlm, r, rho, mu, V, mach, stopped=None, thrust=None, heat_W=None,
                     alpha_body=None, post_stall_nodes=None, r_profile=None, fin_area_scale=None) -> dict:
        """Everything but the induced drag and the approach drag device, for a lattice
        solution ``r`` of ``vlm`` (rows 1 x K, numbers or CasADi), each term in N:

        * ``profile``: section profile drag of every strip at its local dynamic pressure and
          Reynolds number (:func:`~mdo.wing.profile_drag`; the airfoil name carries the
          transition setting, e.g. tripped at 10 % chord), plus the post-stall strips of a
          tilt-wing (:func:`stall_correction`);
        * ``fuselage``: Raymer's component build-up (:func:`~mdo.wing.body_drag`);
        * ``nacelles``: the same, scrubbed by the group's slipstream (:meth:`_nacelle_drag`;
          ``thrust`` {group: thrust per rotor, 1 x K}; freestream without it);
        * ``fins``: flat-plate skin friction x form factor x wetted area 2.04 S (times
          ``fin_area_scale[fin]`` for a sized fin, its chords by the square root: the guess
          flies the configured fins);
        * ``folded``: the drag area of each stopped/folded group times ``stopped[group]``;
        * ``leakage``: ``config.drag.leakage_protuberance_fraction`` of the terms above;
        * ``cooling``: the motor and inverter heat ``heat_W`` (1 x K, W) carried off by
          ram air, Eq. B3 of :mod:`mdo.wing.buildup`: ``D = zeta V P_heat / (cp dT)``;
        * ``fuselage_crossflow``: the fuselage at the body's angle of attack ``alpha_body``
          (1 x K, rad; none without it): the viscous crossflow's normal force ``N``
          (:func:`~mdo.wing.crossflow_normal_force`, ``FuselageConfig``'s eta, c_dc and
          planform area), whose drag ``N sin(alpha)`` is this term and whose lift
          ``N cos(alpha)`` is ``L_body``.  Neither leakage nor anything else scales it.

        ``r_profile``: the lattice result whose strips' local velocity and cl the profile drag
        uses (``Aircraft(blown_profile_drag=True)``: the slipstream's axial part included); a
        strip past stall trades that drag for the full-circle section's at ``r``'s local q.
        ``post_stall_nodes`` (K booleans): the nodes where the post-stall strips apply (a
        tilt-wing flying the viscous correction in its wing-borne segments); all nodes if None.

        The model and the initial guess both use it.  Returns ``pd`` (profile drag
        terms), ``L_stall``, ``L_body``, ``N_body``, ``D_folded``, ``D_parasite`` (N) and
        ``terms`` {name: N}."""
        cfg = self.config.drag
        q = 0.5 * rho * V * V
        pd_lattice = profile_drag(vlm, r, rho, mu, mach)
        pd = pd_lattice if r_profile is None else profile_drag(vlm, r_profile, rho, mu, mach)
        counted = None if r_profile is None else (r_profile, pd)   # what a stalled strip trades away
        L_stall, D_stall = (stall_correction(vlm, r, pd_lattice, rho, V, counted=counted)
                            if self.wing_stall else (0.0, 0.0))
        if self.wing_stall and post_stall_nodes is not None:
            on = ca.DM(np.asarray(post_stall_nodes, float).reshape(1, -1))
            L_stall, D_stall = on * L_stall, on * D_stall
        D_bodies, _ = body_drag(self.bodies, V, rho, mu, mach)
        D_fin = 0.0
        for f in self.fins:   # a sized fin: area x s, chords x sqrt(s) (aspect ratio held)
            s = (fin_area_scale or {}).get(f.name, 1.0)
            re = rho * V * f.mean_aerodynamic_chord_m * ca.sqrt(s) / mu
            cf = skin_friction(ca.sqrt(re * re + 1e8), mach)
            ff = form_factor_wing(f.thickness_to_chord, mach=ca.sqrt(mach * mach + 1e-4),
                                  sweep_max_thickness=math.radians(f.sweep_quarter_chord_deg))
            D_fin = D_fin + q * cf * ff * 2.04 * f.area_m2 * s
        D_folded = 0.0
        for gm in self.groups:
            A = gm.config.folded_drag_area_m2
            if A and stopped is not None and gm.name in stopped:
                D_folded = D_folded + q * stopped[gm.name] * gm.config.count * A
        terms = {"profile": pd["D_p"] + D_stall, "fuselage": D_bodies,
                 "nacelles": self._nacelle_drag(V, rho, mu, mach, thrust), "fins": D_fin, "folded": D_folded}
        components = sum(terms.values())
        terms["leakage"] = cfg.leakage_protuberance_fraction * components
        # Eq. B3: the cooling air's momentum deficit (mdo.wing.buildup, CP_AIR)
        terms["cooling"] = 0.0 if heat_W is None else \
            cfg.cooling_momentum_loss * V * heat_W / (CP_AIR * cfg.cooling_delta_T_K)
        f = self.config.fuselage
        N_body = 0.0 if alpha_body is None else crossflow_normal_force(
            alpha_body, q, f.planform_area, f.crossflow_eta, f.crossflow_drag_coefficient)
        lib = ca if isinstance(N_body, (ca.MX, ca.SX, ca.DM)) else np
        terms["fuselage_crossflow"] = N_body * lib.sin(alpha_body) if alpha_body is not None else 0.0
        L_body = N_body * lib.cos(alpha_body) if alpha_body is not None else 0.0
        D_parasite = components + terms["leakage"] + terms["cooling"] + terms["fuselage_crossflow"]
        return {"pd": pd, "L_stall": L_stall, "L_body": L_body, "N_body": N_body, "D_folded": D_folded,
                "D_parasite": D_parasite, "terms": terms}

    def _nacelle_drag(self, V, rho, mu, mach, thrust=None):
        """Nacelle drag (N, 1 x K): Raymer's build-up ``q_s Cf(Re_s) FF Q S_wet`` at the
        slipstream's dynamic pressure.  Actuator disk (far wake): ``q_s = q + T/A`` for a
        rotor of thrust T and disk area A; where the rotor windmills (T < 0) the wake is
        slower than the freestream, floored smoothly at ``q/4`` (half the speed; width
        ``0.02 q + 1`` Pa).  In hover ``q_s = T/A`` is the download of the nacelle in the
        downwash.  Without ``thrust`` (or ``drag.nacelles_in_slipstream`` off): freestream."""
        q = 0.5 * rho * V * V
        D = 0.0
        for name, b in self.nacelles.items():
            gm = next(g for g in self.groups if g.name == name)
            if thrust is None or not self.config.drag.nacelles_in_slipstream:
                qs = q
            else:
                qs = smooth_max(q + thrust[name] / (math.pi * gm.design["R"] ** 2), 0.25 * q, 0.02 * q + 1.0)
            D = D + body_drag([b], ca.sqrt(2.0 * qs / rho), rho, mu, mach)[0]
        return D

    def _flap_upwash(self, nodes, v_cp, V):
        """Deflected flaps as an incidence increment of the flapped strips in the flow
        tangency: ``d_alpha = delta dcl_max / (2 pi)`` - the section lift curve moves up
        by about the flap's cl_max increment (Raymer 6th ed. Sec. 12.4, plain and
        slotted flaps), an upwash ``V d_alpha`` at those control points; the forces keep
        the freestream, so the flap adds circulation (lift, and its induced drag)."""
        K = nodes.size
        vz = self.flap_upwash(_num(nodes.parameters.get("flap_deflection", _row(0.0, K))).ravel() * np.ones(K), V)
        return v_cp if vz is None else (v_cp[0], v_cp[1], v_cp[2] + vz)

    def flap_upwash(self, flap, V, vlm=None):
        """Upwash (N x K, m/s) of the deflected flaps at the control points of ``vlm``
        (default the vehicle's lattice) for flap deflections ``flap`` (K numbers) and
        speeds ``V`` (1 x K); None when no flap is deflected."""
        vlm = vlm or self.vlm
        dalpha = self._flap_strip_dalpha()
        flap = np.asarray(flap, float).ravel()
        if not np.any(flap) or not np.any(dalpha):
            return None
        panel = ca.mtimes(ca.DM(vlm.strip_sum).T, ca.DM(dalpha.reshape(-1, 1)))   # N x 1
        return ca.mtimes(panel, V * _row(flap))

    def _flap_strip_dalpha(self) -> np.ndarray:
        """Incidence increment (rad) of each strip at full flap deflection (0 where no flap)."""
        names = [s_.name for s_ in self.vlm.surfaces]
        by = {w.name: w for w in self.lifting_wings}
        out = np.zeros(len(self.vlm.strip_surface))
        for i, si in enumerate(self.vlm.strip_surface):
            w = by.get(names[si])
            if w is not None and w.flap_clmax_increment > 0:
                lo, hi = w.flap_span_eta
                if lo <= self.strip_eta[i] <= hi:
                    out[i] = w.flap_clmax_increment / (2 * math.pi)
        return out


    def _drag_device(self, nodes, unknowns, q):
        """Gear/flap drag where the segment allows it (``drag_device_area_m2`` > 0):
        ``D = q A_max delta`` with the deployment ``delta`` in [0, 1] the unknown
        ``drag_device_deployment`` (a variable of those nodes only, zero elsewhere; the
        mission creates it, see :meth:`unknowns`).  Its lift change is neglected.
        Returns (drag row, deployment row)."""
        K = nodes.size
        area = _num(nodes.parameters.get("drag_device_area_m2", _row(0.0, K))).ravel() * np.ones(K)
        deploy = unknowns.get("drag_device_deployment", ca.DM.zeros(1, K))
        return q * _row(area) * deploy, deploy

    def post_stall_nodes(self, nodes, K):
        """With both the viscous correction and the post-stall strips: the nodes of segments that
        are not wing-borne (negative ``stall_margin_cl``), where the post-stall strips apply and the
        shifts are held at zero (K booleans); None otherwise (each model at every node)."""
        if not (self.wing_viscous and self.wing_stall):
            return None
        return _stall_margin(self, nodes, K) < 0.0

    def _blown_strips(self, r, v_axial, v_rest, V, alpha):
        """The lattice result with each strip's local velocity and cl on the whole wake at its
        control points (the slipstream's axial part included): what its profile drag sees
        (``blown_profile_drag``)."""
        vlm = self.vlm
        ones_N = ca.DM.ones(vlm.n_panels, 1)
        vx, vy, vz = (a + b for a, b in zip(v_axial, v_rest))
        U = (ca.mtimes(ones_N, V * ca.cos(alpha)) + vx, vy, ca.mtimes(ones_N, V * ca.sin(alpha)) + vz)
        out = dict(r)
        out["V_local"], out["cl_local"] = vlm.strip_local(U, r["cl"], V)
        return out
