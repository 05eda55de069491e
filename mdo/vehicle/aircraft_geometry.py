"""The aircraft's geometry for its analyses: the lattice's surfaces, the rotors' positions and
wakes, the strips' layout, the drag build-up's bodies and the disks' clearance.

A mixin of :class:`mdo.vehicle.aircraft.Aircraft` (it reads the vehicle definition,
``self.config``, and the design variables, ``self.design``): split out of ``aircraft.py``
so that each file holds one part of the model (the node evaluation stays there).
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.smooth import smooth_max, smooth_min
from ..wake import WakeRotor, spin_for, wake_influences
from ..wing import VLM, Body, constant_area, trapezoid
from .config import disks_in_one_plane, fuselage_gaps_m
from .rotor_group import section_name
from .wing_structure import strength_sized_tip_deflection

__all__ = ["AircraftGeometryMixin"]


def disk_plane_x(w, x_ahead_of_le_m, root_chord, taper, eta):
    """Body x (m) of a disk at ``eta`` of wing ``w``'s semispan (numbers or symbols): the unswept
    quarter chord moves the leading edge aft by (c_r - c(y))/4, the disk ``x_ahead_of_le_m`` ahead of it."""
    return w.root_le_x_m + 0.25 * root_chord * (1 - taper) * eta - x_ahead_of_le_m


class AircraftGeometryMixin:
    """Geometry of :class:`~mdo.vehicle.aircraft.Aircraft` (see the module docstring)."""

    # ------------------------------------------------------------------ geometry
    def wing_surfaces(self, d: dict) -> tuple:
        """VLM surfaces and rotor centres per group from a design dict ``d`` (numbers
        or MX): ``d["wings"][name] = {"span", "taper", "twist"}`` and, per group,
        ``d["groups"][name] = {"R", "eta"}``.  Returns (surfaces, {group: [centres]})."""
        surfaces, rotor_pos = [], {gm.name: [] for gm in self.groups}
        for w in self.lifting_wings:
            dw = d["wings"][w.name]
            span, taper, twist = dw["span"], dw["taper"], dw["twist"]
            semispan = span / 2
            breaks, nominal = self._slipstream_breaks(w, d, semispan) if self.slipstream_breaks else ([], [])
            twists = [twist[k] for k in range(len(w.twist_deg))]
            surf = constant_area(w.name, w.area_m2, span, taper, twists, eta=list(w.section_eta),
                                 airfoil=section_name(w.airfoil), nspan=self.wing_strips,
                                 nchord=self.nchord, anchor_sections=False, breaks=breaks,
                                 break_nominal=nominal if nominal else None,
                                 origin=(w.root_le_x_m, 0.0, w.root_z_m), incidence=math.radians(w.incidence_deg),
                                 thickness_to_chord=w.thickness_to_chord)
            surfaces.append(surf)
            c_r = surf.root_chord
            for gm in self.groups:
                g = gm.config
                if w.name not in g.wings:
                    continue
                for i in range(len(g.span_eta)):
                    e = d["groups"][g.name]["eta"][i]
                    rotor_pos[g.name].append((disk_plane_x(w, g.x_ahead_of_le_m, c_r, taper, e), e * semispan,
                                              w.root_z_m - g.z_below_wing_m))
        for t in self.tails:
            surfaces.append(trapezoid(t.name, t.span_m, t.root_chord_m, t.taper, airfoil=section_name(t.airfoil),
                                      nspan=self.tail_strips, nchord=self.nchord, origin=(t.root_le_x_m, 0.0, t.root_z_m),
                                      incidence=math.radians(t.incidence_deg), thickness_to_chord=t.thickness_to_chord))
        return surfaces, rotor_pos

    def _slipstream_breaks(self, w, d, semispan):
        """Strip boundaries at the slipstream edges (option ``slipstream_breaks``)."""
        breaks, nominal = [], []
        for gm in self.groups:
            g = gm.config
            if w.name not in g.wings:
                continue
            R = d["groups"][g.name]["R"]
            for i in range(len(g.span_eta)):
                e = d["groups"][g.name]["eta"][i]
                e0 = float(g.span_eta[i])
                lo0, hi0 = e0 - g.radius_m / (w.span_m / 2), e0 + g.radius_m / (w.span_m / 2)
                if lo0 > 0.02:   # keep the moving edges inside the wing (smooth, width 0.01 semispan)
                    breaks.append(smooth_max((e * semispan - R) / semispan, 0.02, 0.01))
                    nominal.append(lo0)
                if hi0 < 0.98:
                    breaks.append(smooth_min((e * semispan + R) / semispan, 0.98, 0.01))
                    nominal.append(hi0)
        return breaks, nominal

    def numeric_design(self) -> dict:
        """The baseline design as numbers, in the form :meth:`wing_surfaces` takes."""
        d = {"wings": {w.name: {"span": w.span_m, "taper": w.taper,
                                "twist": np.radians(np.asarray(w.twist_deg, float))} for w in self.lifting_wings},
             "groups": {gm.name: {"R": gm.config.radius_m, "eta": np.asarray(gm.config.span_eta, float)}
                        for gm in self.groups}}
        return d

    def _symbolic_design(self) -> dict:
        return {"wings": self.design["wings"],
                "groups": {gm.name: {"R": gm.design["R"], "eta": gm.design["eta"]} for gm in self.groups}}

    def _rotors(self, gm, centres, R):
        g = gm.config
        edges = WakeRotor.from_geometry(gm.baseline_blade()["geometry"], (0.0, 0.0, 0.0),
                                        n_stations=self.n_stations).s_edges
        rotors = []
        for (x, y, z) in centres:
            for s in (1.0, -1.0):   # starboard, port
                ys = s * y
                center = ca.vertcat(x, ys, z) if any(isinstance(c, ca.MX) for c in (x, ys, z)) else (x, ys, z)
                rotors.append(WakeRotor(center, (1.0, 0.0, 0.0), R, edges, g.blades, spin_for(s, g.rotation),
                                        core_rel=self.wake_core_rel))
        return rotors

    def _build_geometry(self, problem):
        cfg = self.config
        main = cfg.main_wing
        S_ref = sum(w.area_m2 for w in self.lifting_wings)
        lift_velocity = "freestream" if self.coupling == "freestream" else "local"
        surfaces, rotor_pos = self.wing_surfaces(self._symbolic_design())
        self.vlm = self._lattice(surfaces, S_ref, lift_velocity)
        self.rotor_centres = rotor_pos
        self.group_rotors = {gm.name: self._rotors(gm, rotor_pos[gm.name], gm.design["R"]) for gm in self.groups}
        self.rotors = [r for gm in self.groups for r in self.group_rotors[gm.name]]
        self.rotor_positions = [p for gm in self.groups for p in rotor_pos[gm.name]]
        self.influences = wake_influences(self.vlm.geometry["cp"], self.rotors, spans=self.vlm.geometry["lb"],
                                          samples=self.wake_samples)
        self.S_ref = S_ref
        self.strip_eta = self._strip_eta()
        # strips of the lifting wings inside the fuselage (baseline semispan) carry no stall limit
        half_width = 0.5 * cfg.fuselage.width_m
        semis = {w.name: w.span_m / 2 for w in self.lifting_wings}
        names = [s_.name for s_ in self.vlm.surfaces]
        # (a tail sits on the narrow tail cone: all its strips are exposed)
        self.strip_exposed = np.array([names[si] not in semis or self.strip_eta[i] * semis[names[si]] > half_width
                                       for i, si in enumerate(self.vlm.strip_surface)])
        self.bodies = self.body_list()
        self.nacelles = self.nacelle_bodies()
        self.fins = cfg.fins
        problem.output("wing_aspect_ratio", self.design["wings"][main.name]["span"] ** 2 / main.area_m2, unit="-",
                       summary=True)
        self._wing_shape_outputs(problem)

    def _wing_shape_outputs(self, problem):
        """Every lifting wing's aspect ratio and, with a ``WingStructure``, the limit-load tip
        deflection its strength-sized caps would have (fraction of the semispan; above the
        structure's ``max_tip_deflection_fraction`` the stiffness sizes the caps, S4)."""
        ws = self.config.wing_structure
        for w in self.lifting_wings:
            dw = self.design["wings"][w.name]
            problem.output(f"{w.name}.aspect_ratio", dw["span"] ** 2 / w.area_m2, unit="-", summary=True)
            if ws is not None:
                problem.output(f"{w.name}.strength_sized_tip_deflection",
                               strength_sized_tip_deflection(ws, w.area_m2, dw["span"], dw["taper"],
                                                             w.thickness_to_chord),
                               unit="of semispan", summary=True)

    def _lattice(self, surfaces, S_ref, lift_velocity="local"):
        """The vehicle's lattice of ``surfaces``: references from the main wing's baseline."""
        main = self.config.main_wing
        return VLM(surfaces, S_ref=S_ref, c_ref=main.mean_aerodynamic_chord_m, b_ref=main.span_m,
                   r_ref=(main.root_le_x_m + 0.25 * main.mean_aerodynamic_chord_m, 0.0, main.root_z_m),
                   mach_ref=0.2, lift_velocity=lift_velocity)

    def _strip_eta(self) -> np.ndarray:
        """Each strip's position as a fraction of its surface's semispan (fixed by the layout)."""
        surfaces, _ = self.wing_surfaces(self.numeric_design())
        vlm = VLM(surfaces, S_ref=self.S_ref, mach_ref=0.2)
        y = np.abs(np.asarray(ca.DM(vlm.geometry["strip_y"]), float).ravel())
        half = {}
        for i, si in enumerate(vlm.strip_surface):
            half[si] = max(half.get(si, 0.0), y[i] + 0.5 * float(np.asarray(ca.DM(vlm.geometry["strip_width"])).ravel()[i]))
        return np.array([y[i] / half[si] for i, si in enumerate(vlm.strip_surface)])

    def body_list(self) -> list:
        """Non-lifting bodies of the drag build-up (Raymer): the fuselage (freestream) and each
        group's nacelles (scrubbed by that group's slipstream, :meth:`drag_buildup`)."""
        f = self.config.fuselage
        bodies = [Body("fuselage", f.length_m, math.sqrt(f.width_m * f.height_m), "fuselage", 1.0,
                       wetted_area=f.wetted_area_m2)]
        return bodies

    def nacelle_bodies(self) -> dict:
        """{group name: Body} for the groups with nacelles: a body of fineness 3 with the
        configured wetted area (pi d l = A, l = 3 d), the group's interference factor."""
        out = {}
        for gm in self.groups:
            a = gm.config.nacelle_wetted_area_m2
            if a:
                dn = math.sqrt(a / (3 * math.pi))
                out[gm.name] = Body(f"nacelle {gm.name}", 3 * dn, dn, "nacelle", gm.config.nacelle_interference,
                                    count=gm.config.count, wetted_area=a)
        return out

    def _no_overlap(self, problem):
        """Disks must not overlap each other (any groups) or cross the symmetry plane (Eq. 7's R_max),
        and the innermost disk of each wing must clear the fuselage's side (``_fuselage_gaps``)."""
        cl = self.bounds.tip_clearance_m
        for w in self.lifting_wings:
            span = self.design["wings"][w.name]["span"]
            disks = []
            for gm in self.groups:
                g = gm.config
                if w.name in g.wings:
                    disks += [(float(g.span_eta[i]), gm.design["eta"][i] * span / 2, gm.design["R"], f"{g.name}[{i}]",
                               g.name, g.x_ahead_of_le_m, g.z_below_wing_m) for i in range(len(g.span_eta))]
            if not disks:
                continue
            disks.sort(key=lambda t: t[0])
            self._fuselage_gaps(problem, w, disks[0])
            gaps = [disks[0][1] - disks[0][2] - 0.5 * cl]
            labels = [f"{w.name} inner disk to symmetry plane"]
            for a, b in zip(disks[:-1], disks[1:]):
                if not disks_in_one_plane(a[4], a[5], b[4], b[5]):
                    continue
                gaps.append(b[1] - a[1] - a[2] - b[2] - cl)
                labels.append(f"{w.name} disks {a[3]}-{b[3]}")
            problem.constrain(f"disk clearance ({w.name})", ca.vertcat(*gaps), kind=">=", scale=0.1, unit="m",
                              labels=labels)

    def _fuselage_gaps(self, problem, w, disk):
        """The wing's innermost disk clears the fuselage's side by ``bounds.fuselage_clearance_m`` (14 CFR
        23.925(d)(1)): its rim against points of the body's elliptical cross-section in the disk's plane
        (``mdo.vehicle.config.fuselage_gaps_m``), with the disk in the wing-borne attitude (its axis
        along the body's x; a tilt-wing's hover attitude is not checked).  The cross-section is the
        one at the baseline disk's plane (the plane moves by centimetres with taper and position)."""
        if self.bounds.fuselage_clearance_m is None:
            return
        eta0, y, R, label, _, x_ahead, z_below = disk
        x0 = disk_plane_x(w, x_ahead, w.root_chord_m, w.taper, eta0)   # in the baseline planform
        a, b = self.config.fuselage.section_half_axes(x0)
        if a <= 0.0:
            return                                                   # the disk's plane misses the body
        gaps = fuselage_gaps_m(a, b, self.config.fuselage_axis_z_m, y, w.root_z_m - z_below, R)
        problem.constrain(f"fuselage clearance ({w.name})",
                          ca.vertcat(*gaps) - self.bounds.fuselage_clearance_m, kind=">=", scale=0.1, unit="m",
                          labels=[f"{label} rim to the fuselage, section point {k}" for k in range(len(gaps))],
                          design_level=True)   # a frozen design flies as given (its checks report the clearance)

