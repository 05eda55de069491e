"""Assembly of the vortex lattice's geometry (a mixin of :class:`mdo.wing.vlm.VLM`).

The lattice's geometry is built once in named steps: ``_build_halves`` (each surface's
right half and, in symmetric mode, its mirror image) -> ``_add_filaments`` /
``_add_horseshoes`` / ``_add_trefftz_traces`` / ``_add_unknown_panels`` -> ``_assemble_geometry``
(the incidence matrices as numbers and one CasADi Function of the design parameters for
the rest).  The panel geometry itself is in ``lattice.py``; the influence matrices, the
solve and the loads stay in ``vlm.py``.
"""
from __future__ import annotations

import collections

import casadi as ca
import numpy as np

from ..core.errors import InputError
from ..core.smooth import is_symbolic
from .geometry import Params
from .lattice import surface_half

__all__ = ["LatticeAssemblyMixin"]

_MIRROR = np.diag([1.0, -1.0, 1.0])   # reflection y -> -y


def _hmean(a, b):
    return a * b / (a + b)


class LatticeAssemblyMixin:
    """The geometry-assembly steps of :class:`~mdo.wing.vlm.VLM` (module docstring)."""

    # --- lattice assembly ------------------------------------------------------------------
    def _build_halves(self, p: Params):
        halves = []
        for si, s in enumerate(self.surfaces):
            h = surface_half(s, p, flat=self.flat_lattice)
            in_plane = not s.mirrored
            if self.symmetric and in_plane:
                if not s.vertical:
                    raise InputError(f"{s.name}.mirrored",
                                     "symmetric=True needs every unmirrored surface to be a fin in the "
                                     "symmetry plane; use symmetric=False")
                origin_y = s.origin[1]
                if is_symbolic(origin_y) or abs(float(origin_y)) > 1e-12:
                    raise InputError(f"{s.name}.origin", "an unmirrored fin must sit at y = 0 for symmetric=True")
                continue   # zero load in symmetric flow
            halves.append(dict(h, surface=si, image=False, unknown=True))
            if s.mirrored:
                img = dict(h)
                Mi = ca.DM(_MIRROR)
                img["nodes"] = [ca.mtimes(Mi, X) for X in h["nodes"]]
                img["cp"] = ca.mtimes(Mi, h["cp"])
                img["tangent"] = ca.mtimes(Mi, h["tangent"])
                img["tangent0"] = ca.mtimes(Mi, h["tangent0"])
                img["le"] = ca.mtimes(Mi, h["le"])
                halves.append(dict(img, surface=si, image=True, unknown=not self.symmetric))
        self.halves = halves
        # unknown-panel bookkeeping
        offs, n = [], 0
        for h in halves:
            if h["unknown"]:
                offs.append(n)
                n += h["S"] * h["nc"]
            else:
                offs.append(None)
        self.n_panels = n
        for h, o in zip(halves, offs):
            h["offset"] = o
        # images in symmetric mode share the unknowns of their original
        for k, h in enumerate(halves):
            if h["image"] and not h["unknown"]:
                h["offset"] = halves[k - 1]["offset"]

    def _build_geometry_function(self, ref):
        """One SX Function: design parameters -> every geometric array the VLM needs.

        Per half-surface, in order: its vortex filaments (:meth:`_add_filaments`), the
        horseshoes that combine them (:meth:`_add_horseshoes`), its Trefftz-plane traces
        (:meth:`_add_trefftz_traces`) and, for the halves whose circulation is unknown,
        control points, normals and strips (:meth:`_add_unknown_panels`); then the
        incidence matrices and the Function (:meth:`_assemble_geometry`)."""
        acc = collections.defaultdict(list)
        acc["counts"] = {"finite": 0, "semi": 0, "tz_edges": 0, "tz_strips": 0}
        self.surface_slices = {}
        for h in self.halves:
            s = self.surfaces[h["surface"]]
            S = h["S"]
            qc = h["nodes"][0]
            width = [ca.norm_2(qc[1:, si + 1] - qc[1:, si]) for si in range(S)]
            # the width an edge's filaments belong to (for their vortex cores)
            edge_width = [width[min(e, S - 1)] if e in (0, h["E"] - 1) else 0.5 * (width[e - 1] + width[e])
                          for e in range(h["E"])]
            bound_idx, leg_idx, semi_idx = self._add_filaments(h, s, width, edge_width, acc)
            self._add_horseshoes(h, bound_idx, leg_idx, semi_idx, acc)
            self._add_trefftz_traces(h, s, edge_width, acc)
            if h["unknown"]:
                first_strip = len(acc["st_chord"])
                self._add_unknown_panels(h, width, acc)
                self.surface_slices[s.name + (" (left)" if h["image"] else "")] = (first_strip, len(acc["st_chord"]))
        self._assemble_geometry(acc, ref)

    @staticmethod
    def _strip_edges(h, si):
        """(left, right) edge indices of strip ``si`` (mirrored on an image half)."""
        return (si + 1, si) if h["image"] else (si, si + 1)

    def _add_filaments(self, h, s, width, edge_width, acc):
        """Bound segments on the quarter-chord lines, chordwise legs along the camber line,
        semi-infinite legs from the trailing edge; returns their indices."""
        E, S, nc, nodes, cnt = h["E"], h["S"], h["nc"], h["nodes"], acc["counts"]
        pchord_e = [h["edge_chord"][e] / nc for e in range(E)]
        bound_idx, leg_idx, semi_idx = {}, {}, {}
        for si in range(S):
            for r in range(nc):
                a, b = (nodes[r][:, si + 1], nodes[r][:, si]) if h["image"] else (nodes[r][:, si], nodes[r][:, si + 1])
                acc["fA"].append(a)
                acc["fB"].append(b)
                acc["fcore"].append(s.core * _hmean(width[si], 0.5 * (pchord_e[si] + pchord_e[si + 1])))
                bound_idx[(si, r)] = cnt["finite"]
                cnt["finite"] += 1
        for e in range(E):
            for r in range(nc):
                acc["fA"].append(nodes[r][:, e])
                acc["fB"].append(nodes[r + 1][:, e])
                acc["fcore"].append(s.core * _hmean(edge_width[e], pchord_e[e]))
                leg_idx[(e, r)] = cnt["finite"]
                cnt["finite"] += 1
        for e in range(E):
            acc["sA"].append(nodes[nc][:, e])
            acc["score"].append(s.core * _hmean(edge_width[e], pchord_e[e]))
            semi_idx[e] = cnt["semi"]
            cnt["semi"] += 1
        return bound_idx, leg_idx, semi_idx

    def _add_horseshoes(self, h, bound_idx, leg_idx, semi_idx, acc):
        """Each panel's horseshoe: its bound segment, the legs from it to the trailing edge
        on both sides, and the two semi-infinite legs (rows of MF and MS)."""
        nc, off = h["nc"], h["offset"]
        for si in range(h["S"]):
            left, right = self._strip_edges(h, si)
            for r in range(nc):
                j = off + si * nc + r
                acc["MF"].append((j, bound_idx[(si, r)], 1.0))
                for k in range(r, nc):
                    acc["MF"] += [(j, leg_idx[(left, k)], -1.0), (j, leg_idx[(right, k)], 1.0)]
                acc["MS"] += [(j, semi_idx[left], -1.0), (j, semi_idx[right], 1.0)]

    def _add_trefftz_traces(self, h, s, edge_width, acc):
        """The half's trailing-edge traces in the Trefftz plane (y, z): edges, strip
        midpoints and normals, and which panels and edges each strip's circulation sums."""
        E, S, nc, off, cnt = h["E"], h["S"], h["nc"], h["offset"], acc["counts"]
        te = h["nodes"][nc]
        h["tz_strip0"] = cnt["tz_strips"]
        h["te_yz"] = [te[1:, e] for e in range(E)]
        e0 = cnt["tz_edges"]
        for e in range(E):
            acc["tz_edge"].append(te[1:, e])
            acc["tz_core"].append(s.core * edge_width[e])
        for si in range(S):
            left, right = self._strip_edges(h, si)
            L, Rr = te[1:, left], te[1:, right]
            acc["tz_mid"].append(0.5 * (L + Rr))
            acc["tz_nds"].append(ca.vertcat(-(Rr[1] - L[1]), Rr[0] - L[0]))   # x_hat x (R - L)
            srow = cnt["tz_strips"] + si
            acc["TS"] += [(srow, off + si * nc + r) for r in range(nc)]
            # edge strength: +Gamma at the edge its right leg leaves, -Gamma at its left leg
            acc["TE"] += [(e0 + right, srow, 1.0), (e0 + left, srow, -1.0)]
        cnt["tz_edges"] += E
        cnt["tz_strips"] += S

    def _add_unknown_panels(self, h, width, acc):
        """Control points, normals (cambered and flat), bound-segment midpoints and vectors,
        panel areas, and the strips (chord, width, normal, midpoint, span ends, section)."""
        nc, off, nodes = h["nc"], h["offset"], h["nodes"]
        qc = nodes[0]
        for si in range(h["S"]):
            left, right = self._strip_edges(h, si)
            cols = []
            for r in range(nc):
                j = off + si * nc + r
                a, b = nodes[r][:, left], nodes[r][:, right]
                lvec = b - a
                n_ = ca.cross(h["tangent"][:, si * nc + r], lvec)
                acc["nrm"].append(n_ / ca.norm_2(n_))
                n0 = ca.cross(h["tangent0"][:, si * nc + r], lvec)
                acc["nrm0"].append(n0 / ca.norm_2(n0))
                acc["cp"].append(h["cp"][:, si * nc + r])
                acc["rb"].append(0.5 * (a + b))
                acc["lb"].append(lvec)
                acc["area"].append(0.5 * (h["edge_chord"][left] + h["edge_chord"][right]) * width[si] / nc)
                cols.append(j)
                acc["panel_surface"].append(h["surface"])
            acc["strip_panels"].append(cols)
            a, b = qc[:, left], qc[:, right]
            dyz = b[1:] - a[1:]
            acc["st_chord"].append(0.5 * (h["edge_chord"][left] + h["edge_chord"][right]))
            acc["st_width"].append(width[si])
            acc["st_nrm"].append(ca.vertcat(0, -dyz[1], dyz[0]) / ca.norm_2(dyz))
            acc["st_mid"].append(0.5 * (a + b))
            acc["st_y"].append(ca.vertcat(a[1], b[1]))
            acc["strip_surface"].append(h["surface"])
            acc["strip_airfoil"].append(h["strip_airfoil"][si])

    def _assemble_geometry(self, acc, ref):
        """The incidence matrices (numbers) and the geometry Function (symbolic in the design)."""
        def triplet(entries, n_rows, n_cols):
            rows, cols, vals = zip(*entries) if entries else ((), (), ())
            return ca.DM.triplet(list(rows), list(cols), ca.DM(list(vals)), n_rows, n_cols)

        cnt = acc["counts"]
        tzc_a, tzc_b, TC_rows, TC_cols, TC_vals = self._trefftz_chains()
        N = self.n_panels
        self.n_finite, self.n_semi = cnt["finite"], cnt["semi"]
        self.MF = triplet(acc["MF"], N, cnt["finite"])
        self.MS = triplet(acc["MS"], N, cnt["semi"])
        self.n_strips = n_strips = len(acc["st_chord"])
        self.strip_panels = acc["strip_panels"]
        self.strip_surface = acc["strip_surface"]
        self.strip_airfoil = acc["strip_airfoil"]
        self.panel_surface = acc["panel_surface"]
        self.strip_sum = triplet([(i, j, 1.0) for i, cols in enumerate(self.strip_panels) for j in cols], n_strips, N)
        self.TS = triplet([(i, j, 1.0) for i, j in acc["TS"]], cnt["tz_strips"], N)
        self.TE = triplet(acc["TE"], cnt["tz_edges"], cnt["tz_strips"])
        self.n_tz_edges, self.n_tz_strips = cnt["tz_edges"], cnt["tz_strips"]
        self.n_tz_segments = len(tzc_a)
        self.TC = ca.DM.triplet(TC_rows, TC_cols, ca.DM(TC_vals), len(tzc_a), cnt["tz_strips"])
        cat = {"cp": "cp", "normal": "nrm", "normal_lattice": "nrm0", "fA": "fA", "fB": "fB", "fcore": "fcore",
               "sA": "sA", "score": "score", "rb": "rb", "lb": "lb", "area": "area", "strip_chord": "st_chord",
               "strip_width": "st_width", "strip_normal": "st_nrm", "strip_mid": "st_mid", "strip_y": "st_y",
               "tz_edge": "tz_edge", "tz_core": "tz_core", "tz_mid": "tz_mid", "tz_nds": "tz_nds"}
        outs = {k: ca.horzcat(*acc[key]) for k, key in cat.items()}
        outs.update({"tz_seg_a": ca.horzcat(*tzc_a), "tz_seg_b": ca.horzcat(*tzc_b),
                     "S_ref": ref[0], "c_ref": ref[1], "b_ref": ref[2], "r_ref": ca.vertcat(*ref[3:])})
        outs = {k: (v if isinstance(v, ca.SX) else ca.SX(v)) for k, v in outs.items()}
        self.geometry_function = ca.Function("vlm_geometry", [self.params.sx], list(outs.values()),
                                             ["p"], list(outs.keys()))

