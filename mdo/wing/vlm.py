"""Multi-surface vortex lattice, symbolic in the geometry, one solve for K operating points.

Method (paper section III.A; Katz & Plotkin 2001 ch. 12; Drela & Youngren, AVL):
horseshoe vortices with the bound segment on the quarter-chord line of each
panel and legs that follow the camber line to the trailing edge and then run to
infinity along +x; control points at the three-quarter chord; Biot-Savart
filaments of paper Eq. 2 with a smooth vortex core (:mod:`mdo.wing.kernels`).

Flow tangency at control point i for operating point k::

    sum_j A_ij Gamma_jk = -(V_inf,k + v_ext,ik) . n_i         (A depends on the design only)

so ``A(d) [Gamma_1 ... Gamma_K] = [b_1 ... b_K]`` is one dense linear solve (one
MX ``solve`` node) for all K mission nodes.  ``v_ext`` is any external induced
velocity at the control points (the propeller wake).

Compressibility: Prandtl-Glauert/Goethert.  The influence matrix is built for the
x-coordinates stretched by 1/beta_ref (beta = sqrt(1 - M^2)), with the x
component of induced velocity scaled by 1/beta_ref; Gamma is unchanged by the
transformation (AVL does the same).  Because A may not depend on the node, each
node's Mach M_k enters as the 2-D correction factor beta_ref / beta(M_k) on Gamma;
it is exact at M_k = mach_ref (build one VLM per segment at the segment Mach if the
Mach number varies a lot; at M = 0.25 with mach_ref = 0 the factor over-predicts
CL_alpha of an AR-8 wing by 0.8 %, see README).

Forces: Kutta-Joukowski on every bound segment, F_j = rho Gamma_j (V_inf + v_ext,j) x l_j
(``lift_velocity='local'``, default: a blown strip sees the slipstream's axial
velocity, i.e. its higher dynamic pressure, and the slipstream swirl tilts its
force, which is the thrust/drag of swirl recovery), or F_j = rho Gamma_j V_inf x l_j
(``'freestream'``: the paper's SUAVE implementation, forces with the freestream
dynamic pressure).  The wing's own induced velocity is left out of the
Kutta-Joukowski velocity (it changes the lift by a second-order amount); the
induced drag of the wing's own vorticity comes instead from the Trefftz plane:
the trailing legs' traces at the trailing-edge (y, z) points, body axes, as 2-D
point vortices; D_i = -(rho/2) sum_s Gamma_s (v_s . n_s) ds_s at the strip
midpoints (Katz & Plotkin Eq. 8.150; AVL's CDff).  With ``'local'`` the
near-field x-force of the external velocity (CD_ext) is reported separately and
added to CDi.

Reference quantities: ``S_ref, c_ref, b_ref`` (default: area, MAC and span of
the first surface, symbolic if the design is), ``r_ref`` the moment reference.

Layout of ``VLM``: the lattice's geometry is built once in named steps
(``_build_halves`` -> ``_add_filaments``/``_add_horseshoes``/``_add_trefftz_traces``/
``_add_unknown_panels`` -> ``_assemble_geometry``, in ``vlm_assembly.py``), then the matrices that depend on the
design only (``_influence_matrix``, ``_trefftz_matrix``, ``_bound_velocity_matrices``), then
the per-operating-point public API (``solve`` -> ``loads``) and small broadcasting helpers.
The panel geometry itself is in ``lattice.py``, the filament kernels in ``kernels.py``.
"""
from __future__ import annotations

import math

import casadi as ca
import numpy as np

from ..core.errors import InputError, check_range
from .geometry import Params, Surface, mean_aerodynamic_chord, planform_area
from .kernels import (log_point_column, log_segment_column, segment_column, semi_column,
                      trefftz_column, velocity_columns)
from .vlm_assembly import LatticeAssemblyMixin

__all__ = ["VLM"]

class VLM(LatticeAssemblyMixin):
    """Vortex lattice of a set of surfaces (see module doc).

    Parameters
    ----------
    surfaces : list of :class:`~mdo.wing.geometry.Surface` (numbers or CasADi expressions).
    symmetric : solve only the right halves of mirrored surfaces, with their mirror
        images in the influence matrix (flow and external velocity symmetric about
        y = 0; halves the influence cost and cuts the solve 8-fold).  Surfaces that
        are not mirrored must then lie in the symmetry plane (a fin: its load is
        zero in symmetric flow) and are left out.  Default: True if every surface
        is mirrored.
    mach_ref : Mach number of the Prandtl-Glauert stretch of the influence matrix.
    lift_velocity : 'local' (V_inf + v_ext in Kutta-Joukowski) or 'freestream'.
    S_ref, c_ref, b_ref : reference area (m^2), chord and span (m); may be expressions.
    r_ref : moment reference point (m, body axes).
    """

    def __init__(self, surfaces, *, symmetric: bool | None = None, mach_ref: float = 0.0,
                 lift_velocity: str = "local", S_ref=None, c_ref=None, b_ref=None,
                 r_ref=(0.0, 0.0, 0.0), trefftz: str = "linear", near_field: bool = False,
                 flat_lattice: bool = False):
        if isinstance(surfaces, Surface):
            surfaces = [surfaces]
        self.surfaces = list(surfaces)
        if not self.surfaces:
            raise InputError("surfaces", "need at least one surface")
        names = [s.name for s in self.surfaces]
        if len(set(names)) != len(names):
            raise InputError("surfaces", f"names must be unique, got {names}")
        check_range("mach_ref", mach_ref, 0.0, 0.95, inclusive=True)
        self.mach_ref = float(mach_ref)
        self.beta_ref = math.sqrt(1.0 - self.mach_ref**2)
        if lift_velocity not in ("local", "freestream"):
            raise InputError("lift_velocity", f"'local' or 'freestream', got {lift_velocity!r}")
        self.lift_velocity = lift_velocity
        if trefftz not in ("linear", "midpoint"):
            raise InputError("trefftz", f"'linear' or 'midpoint', got {trefftz!r}")
        self.trefftz = trefftz
        self.trefftz_band = 6
        self.near_field = bool(near_field)
        self.flat_lattice = bool(flat_lattice)
        if symmetric is None:
            symmetric = all(s.mirrored for s in self.surfaces)
        self.symmetric = bool(symmetric)

        p = Params()
        self.params = p
        self._build_halves(p)
        s0 = self.surfaces[0]
        S_ref = planform_area(s0) if S_ref is None else S_ref
        c_ref = mean_aerodynamic_chord(s0) if c_ref is None else c_ref
        b_ref = s0.span if b_ref is None else b_ref
        ref = [p(S_ref, "S_ref"), p(c_ref, "c_ref"), p(b_ref, "b_ref")] + \
              [p(v, f"r_ref[{i}]") for i, v in enumerate(r_ref)]
        self._build_geometry_function(ref)
        self._geo = dict(zip(self.geometry_function.name_out(),
                             self.geometry_function.call([p.value_vector()])))
        self.A = self._influence_matrix()
        self.V_ind = self._bound_velocity_matrices() if self.near_field else None

    # --- influence -------------------------------------------------------------------------
    def _influence_matrix(self):
        g = self._geo
        b = self.beta_ref
        stretch = ca.DM(np.diag([1.0 / b, 1.0, 1.0]))
        P = ca.mtimes(stretch, g["cp"])
        # n . (v'_x / beta, v'_y, v'_z); a flat lattice uses its own (untwisted) normals here and
        # the twisted/cambered ones only in the right-hand side (linearized boundary condition)
        Nn = ca.mtimes(stretch, g["normal_lattice"] if self.flat_lattice else g["normal"])
        N = self.n_panels
        seg = segment_column(N).map("seg_map", "serial", self.n_finite, [0, 1], [])
        semi = semi_column(N).map("semi_map", "serial", self.n_semi, [0, 1], [])
        WF = seg(P, Nn, ca.mtimes(stretch, g["fA"]), ca.mtimes(stretch, g["fB"]), g["fcore"])
        WS = semi(P, Nn, ca.mtimes(stretch, g["sA"]), g["score"])
        A = ca.mtimes(WF, self.MF.T) + ca.mtimes(WS, self.MS.T)
        return A

    def _trefftz_chains(self):
        """Sheet segments of the Trefftz plane with circulation linear along each surface.

        Each surface's wake trace is a chain tip -> ... -> tip (a mirrored surface
        runs through its root; an unmirrored one starts at its root) through the
        strip midpoints and strip edges.  Gamma is the strip's value at its midpoint,
        the mean of the neighbours at an interior edge and 0 at a free end.  Segment
        k carries the jump g_k = Gamma(end) - Gamma(start) (a constant matrix TC of
        the strip circulations), spread uniformly along it.
        """
        seg_a, seg_b, rows, cols, vals = [], [], [], [], []
        chain_of = []
        by_surface = {}
        for h in self.halves:
            by_surface.setdefault(h["surface"], []).append(h)
        for si, hs in by_surface.items():
            orig = [h for h in hs if not h["image"]][0]
            img = [h for h in hs if h["image"]]
            nodes = []     # (point, {tz strip: weight})

            def half_nodes(h):
                out = []
                S = h["S"]
                s0 = h["tz_strip0"]
                for e in range(S + 1):
                    if 0 < e < S:
                        out.append((h["te_yz"][e], {s0 + e - 1: 0.5, s0 + e: 0.5}))
                    elif e == S:
                        out.append((h["te_yz"][e], {}))
                    else:
                        out.append((h["te_yz"][e], None))    # root: filled below
                    if e < S:
                        out.append((0.5 * (h["te_yz"][e] + h["te_yz"][e + 1]), {s0 + e: 1.0}))
                return out

            right = half_nodes(orig)
            if img:
                left = half_nodes(img[0])
                root_w = {orig["tz_strip0"]: 0.5, img[0]["tz_strip0"]: 0.5}
                nodes = left[::-1][:-1] + [(right[0][0], root_w)] + right[1:]
            else:
                nodes = [(right[0][0], {})] + right[1:]
            for k in range(len(nodes) - 1):
                (pa, wa), (pb, wb) = nodes[k], nodes[k + 1]
                j = len(seg_a)
                seg_a.append(pa)
                seg_b.append(pb)
                chain_of.append(si)
                acc = dict(wb)
                for st, wt in wa.items():
                    acc[st] = acc.get(st, 0.0) - wt
                for st, wt in acc.items():   # (DM.triplet does not sum duplicates)
                    if wt != 0.0:
                        rows.append(j); cols.append(st); vals.append(wt)
        band = self.trefftz_band
        self._tz_near_pairs = [(k, m) for k in range(len(seg_a)) for m in range(len(seg_a))
                               if k != m and chain_of[k] == chain_of[m] and abs(k - m) <= band]
        return seg_a, seg_b, rows, cols, vals

    def _bound_velocity_matrices(self):
        """(Vx, Vy, Vz), each N x N: velocity at the bound midpoints per unit circulation (stretched x)."""
        g = self._geo
        b = self.beta_ref
        stretch = ca.DM(np.diag([1.0 / b, 1.0, 1.0]))
        P = ca.mtimes(stretch, g["rb"])
        N = self.n_panels
        seg = velocity_columns(N, False).map("segv_map", "serial", self.n_finite, [0], [])
        semi = velocity_columns(N, True).map("semiv_map", "serial", self.n_semi, [0], [])
        out = []
        WF = seg(P, ca.mtimes(stretch, g["fA"]), ca.mtimes(stretch, g["fB"]), g["fcore"])
        WS = semi(P, ca.mtimes(stretch, g["sA"]), g["score"])
        for i in range(3):
            Vi = ca.mtimes(WF[i], self.MF.T) + ca.mtimes(WS[i], self.MS.T)
            out.append(Vi / b if i == 0 else Vi)
        return out

    def trefftz_matrix(self, scheme: str | None = None):
        """Q (strips x strips, all halves) with D_i = rho * Gs^T Q Gs.

        'linear' (default): circulation piecewise linear along each wake trace
        (Trefftz-plane kinetic energy D = -(rho/4 pi) sum g_k g_m <ln|r - r'|>_km,
        Katz & Plotkin Eq. 8.150 written as the 2-D vortex-sheet energy; the
        log-kernel averages are closed-form in one segment and 4-point
        Gauss-Legendre in the other, the self term exact: ln L - 3/2).  Error
        O(1/n^2): elliptic wing e = 1.004 at 16 strips per semispan.
        'midpoint': strip-constant circulation, point vortices at the strip
        edges, velocity at strip midpoints (AVL's CDff); error O(1/n), it
        underestimates D_i by about 0.6/n (e = 1.019 at 32 strips).
        """
        scheme = scheme or self.trefftz
        cache = self.__dict__.setdefault("_trefftz_cache", {})
        if scheme not in cache:   # one graph per instance, however often solve() is called
            cache[scheme] = self._trefftz_matrix(scheme)
        return cache[scheme]

    def _trefftz_matrix(self, scheme):
        g = self._geo
        if scheme == "midpoint":
            col = trefftz_column(self.n_tz_strips).map("tz_map", "serial", self.n_tz_edges, [0, 1], [])
            K = col(g["tz_mid"], g["tz_nds"], g["tz_edge"], g["tz_core"])   # strips x edges
            return -0.5 * ca.mtimes(K, self.TE)
        M = self.n_tz_segments
        a, b = g["tz_seg_a"], g["tz_seg_b"]
        mid = 0.5 * (a + b)
        # far pairs: ln|mid_k - mid_m| (error ~ (L_k^2 + L_m^2)/(24 d^2), d > 3 segment lengths)
        J = log_point_column(M).map("tz_far_map", "serial", M, [0], [])(mid, mid)
        # near pairs (same chain, |k - m| <= band, k != m): 4-point Gauss x closed-form segment mean
        pairs = self._tz_near_pairs
        if pairs:
            kk = [k for k, _ in pairs]
            mm = [m for _, m in pairs]
            nb = len(pairs)
            xg, wg = np.polynomial.legendre.leggauss(4)
            xg, wg = 0.5 * (xg + 1), 0.5 * wg
            ak, bk = a[:, kk], b[:, kk]
            am, bm = a[:, mm], b[:, mm]
            near = 0
            fcol = log_segment_column(1).map(nb, "serial")
            pfar = log_point_column(1).map(nb, "serial")
            for x, wq in zip(xg, wg):
                near = near + float(wq) * fcol(ak + float(x) * (bk - ak), am, bm)
            far = pfar(0.5 * (ak + bk), 0.5 * (am + bm))
            Rk = ca.DM.triplet(kk, list(range(nb)), ca.DM.ones(nb), M, nb)
            Cm = ca.DM.triplet(list(range(nb)), mm, ca.DM.ones(nb), nb, M)
            J = J + ca.mtimes(Rk, ca.mtimes(ca.diag((near - far).T), Cm))
        L = ca.sqrt(ca.sum1((b - a) ** 2))
        J = J - ca.diag(ca.diag(J)) + ca.diag(ca.log(L) - 1.5)
        J = 0.5 * (J + J.T)
        return (-0.25 / math.pi) * ca.mtimes(ca.mtimes(self.TC.T, J), self.TC)

    # --- public ------------------------------------------------------------------------------
    def outline(self) -> list[dict]:
        """Leading- and trailing-edge points (3 x E each) of every surface half, for plots.

        One dict per half (images included): ``surface`` (name), ``image`` (bool),
        ``le``, ``te`` (DM for numeric designs, MX otherwise) and ``nodes`` (the
        bound-vortex rows, list of 3 x E).
        """
        if not hasattr(self, "_outline_fn"):
            outs = []
            for h in self.halves:
                outs += [h["le"], h["nodes"][-1]] + list(h["nodes"][:-1])
            self._outline_fn = ca.Function("vlm_outline", [self.params.sx], outs)
        vals = self._outline_fn.call([self.params.value_vector()])
        res, k = [], 0
        for h in self.halves:
            nc = h["nc"]
            res.append({"surface": self.surfaces[h["surface"]].name, "image": h["image"],
                        "le": vals[k], "te": vals[k + 1], "nodes": vals[k + 2:k + 2 + nc]})
            k += 2 + nc
        return res

    @property
    def geometry(self) -> dict:
        """Geometric arrays (DM for numeric designs, MX otherwise): cp, normal, strip data, refs."""
        return dict(self._geo)

    def solve(self, alpha, V=1.0, *, beta=0.0, rho=1.225, mach=None, v_ext=None,
              v_ext_bound=None, linear_solver: str | None = None) -> dict:
        """Circulation and loads at K operating points (row vectors 1 x K or scalars).

        alpha, beta : rad (body axes; sideslip must be 0 in symmetric mode).
        V : freestream speed (m/s); rho : density (kg/m^3); mach : per node (default mach_ref).
        v_ext : external velocity at the control points, (vx, vy, vz) each N x K, m/s.
        v_ext_bound : the same at the bound-vortex midpoints for Kutta-Joukowski
            (default: v_ext at the control points of the same panel).
        Returns a dict of DM (numeric) or MX: Gamma (N x K, m^2/s), F and M (3 x K,
        body axes, N and N m about r_ref), L, D_i, Y (N), CL, CDi, CDi_ff, CD_ext,
        CY, Cm, Cl_roll, Cn_yaw, e, and strip quantities (n_strips x K): cl, ccl_cref,
        cl_local, V_local, and dCp (N x K).
        """
        g = self._geo
        N = self.n_panels
        alpha, beta, V, rho = (_row(x) for x in (alpha, beta, V, rho))
        mach = _row(self.mach_ref if mach is None else mach)
        Kn = max(x.shape[1] for x in (alpha, beta, V, rho, mach))
        alpha, beta, V, rho, mach = (_bcast(x, Kn) for x in (alpha, beta, V, rho, mach))
        if self.symmetric and not isinstance(beta, (ca.MX, ca.SX)) and float(ca.mmax(ca.fabs(beta))) != 0.0:
            raise InputError("beta", "sideslip must be 0 in symmetric mode (use symmetric=False)")
        ca_, sa_ = ca.cos(alpha), ca.sin(alpha)
        cb_, sb_ = ca.cos(beta), ca.sin(beta)
        xw = [ca_ * cb_, -sb_, sa_ * cb_]                 # unit freestream / drag direction
        zw = [-sa_, 0 * alpha, ca_]                         # lift direction
        yw = [ca_ * sb_, cb_, sa_ * sb_]                    # side-force direction
        Vinf = [V * c for c in xw]
        ones_N = ca.DM.ones(N, 1)
        if v_ext is None:
            vx = vy = vz = ca.DM.zeros(N, Kn)
        else:
            vx, vy, vz = (_mat(v, N, Kn) for v in v_ext)
        if v_ext_bound is None:
            bx, by, bz = vx, vy, vz
        else:
            bx, by, bz = (_mat(v, N, Kn) for v in v_ext_bound)
        n = g["normal"]
        nx, ny, nz = (n[i, :].T for i in range(3))
        Ux = ca.mtimes(ones_N, Vinf[0]) + vx
        Uy = ca.mtimes(ones_N, Vinf[1]) + vy
        Uz = ca.mtimes(ones_N, Vinf[2]) + vz
        rhs = -(_cs(nx, Ux) + _cs(ny, Uy) + _cs(nz, Uz))
        # Prandtl-Glauert of each node relative to the matrix's reference Mach
        pg = self.beta_ref / ca.sqrt(1 - mach * mach)
        rhs = _rs(rhs, pg)
        A = self.A
        if isinstance(A, ca.MX) or isinstance(rhs, ca.MX):
            # one dense LU for all K right-hand sides ('lapacklu' measured fastest, see bench)
            Gam = ca.solve(A, rhs, linear_solver or "lapacklu")
        else:
            Gam = ca.DM(np.linalg.solve(np.array(A), np.array(rhs)))
        out = self.loads(Gam, alpha=alpha, beta=beta, V=V, rho=rho, vb=(bx, by, bz),
                         axes=(xw, yw, zw))
        out.update(alpha=alpha, beta=beta, V=V, rho=rho, mach=mach)
        return out

    def strip_local(self, U, cl, V):
        """Each strip's local speed (the rms over its panels of ``U`` = (Ux, Uy, Uz), N x K,
        m/s) and its cl on that speed's dynamic pressure from ``cl`` on the freestream's
        (V, 1 x K): (V_local, cl_local), n_strips x K."""
        Ux, Uy, Uz = U
        K = cl.shape[1]
        U2 = ca.mtimes(self.strip_sum, Ux * Ux + Uy * Uy + Uz * Uz) / \
            ca.mtimes(self.strip_sum, ca.DM.ones(self.n_panels, K))
        return ca.sqrt(U2), cl * ca.repmat(V * V, self.n_strips, 1) / U2

    def loads(self, Gam, *, alpha, beta, V, rho, vb, axes) -> dict:
        g = self._geo
        N = self.n_panels
        Kn = Gam.shape[1]
        xw, yw, zw = axes
        ones_N = ca.DM.ones(N, 1)
        bx, by, bz = vb
        if self.lift_velocity == "freestream":
            bx = by = bz = ca.DM.zeros(N, Kn)
        Vinf = [V * c for c in xw]
        Ux = ca.mtimes(ones_N, Vinf[0]) + bx
        Uy = ca.mtimes(ones_N, Vinf[1]) + by
        Uz = ca.mtimes(ones_N, Vinf[2]) + bz
        U_ext = (Ux, Uy, Uz)
        if self.near_field:   # the wing's own induced velocity at the bound midpoints (AVL)
            Ux = Ux + ca.mtimes(self.V_ind[0], Gam)
            Uy = Uy + ca.mtimes(self.V_ind[1], Gam)
            Uz = Uz + ca.mtimes(self.V_ind[2], Gam)
        l = g["lb"]
        lx, ly, lz = (l[i, :].T for i in range(3))
        rG = _rs(Gam, rho)
        Fx = rG * (_cs(lz, Uy) - _cs(ly, Uz))
        Fy = rG * (_cs(lx, Uz) - _cs(lz, Ux))
        Fz = rG * (_cs(ly, Ux) - _cs(lx, Uy))
        r = g["rb"] - ca.mtimes(g["r_ref"], ca.DM.ones(1, N))
        rx, ry, rz = (r[i, :].T for i in range(3))
        sum_N = ca.DM.ones(1, N)
        F = [ca.mtimes(sum_N, Fx), ca.mtimes(sum_N, Fy), ca.mtimes(sum_N, Fz)]
        M = [ca.mtimes(sum_N, _cs(ry, Fz) - _cs(rz, Fy)),
             ca.mtimes(sum_N, _cs(rz, Fx) - _cs(rx, Fz)),
             ca.mtimes(sum_N, _cs(rx, Fy) - _cs(ry, Fx))]
        if self.symmetric:   # add the mirror half
            F = [2 * F[0], 0 * F[1], 2 * F[2]]
            M = [0 * M[0], 2 * M[1], 0 * M[2]]
        # induced drag of the wing's own trailing vorticity (Trefftz plane)
        Q = self.trefftz_matrix()
        Gs = ca.mtimes(self.TS, Gam)
        Di_ff = rho * ca.sum1(Gs * ca.mtimes(Q, Gs))
        D_near = sum(F[i] * xw[i] for i in range(3))   # near-field drag: external (and, near_field, own) velocity
        if not self.near_field:
            F = [F[i] + Di_ff * xw[i] for i in range(3)]
        L = sum(F[i] * zw[i] for i in range(3))
        Y = sum(F[i] * yw[i] for i in range(3))
        Di = D_near if self.near_field else Di_ff + D_near
        q = 0.5 * rho * V * V
        S, c, b = g["S_ref"], g["c_ref"], g["b_ref"]
        qS = q * S
        out = {
            "Gamma": Gam,
            "F": ca.vertcat(*F), "M": ca.vertcat(*M),
            "L": L, "D_i": Di, "Y": Y,
            "CL": L / qS, "CDi": Di / qS, "CDi_ff": Di_ff / qS,
            "CD_ext": (0 * D_near if self.near_field else D_near) / qS, "CDi_near": D_near / qS,
            "CY": Y / qS, "Cm": M[1] / (qS * c), "Cl_roll": M[0] / (qS * b), "Cn_yaw": M[2] / (qS * b),
        }
        AR = b * b / S
        out["e"] = out["CL"] ** 2 / (math.pi * AR * out["CDi"])
        # strips: section lift per unit span, the force normal to the freestream in the strip's
        # section plane (normal to its span axis s = n x x_body): along e = x_w x s, which is n at
        # zero incidence.  Not n minus its freestream component: that vanishes, and flips, when the
        # strip stands normal to the flow (a tilt-wing's transition past 90 deg), where its cl
        # had a kink and a 1/cos(alpha) derivative.
        Fs = [ca.mtimes(self.strip_sum, Fi) for Fi in (Fx, Fy, Fz)]
        ns = g["strip_normal"]
        nsy, nsz = (ns[i, :].T for i in (1, 2))
        ones_S = ca.DM.ones(self.n_strips, 1)
        xs = [ca.mtimes(ones_S, xw[i]) for i in range(3)]
        ex = -_cs(nsy, xs[1]) - _cs(nsz, xs[2])     # s = (0, n_z, -n_y): the strips' normals lie in y-z
        ey = _cs(nsy, xs[0])
        ez = _cs(nsz, xs[0])
        enorm = ca.sqrt(ex * ex + ey * ey + ez * ez)   # |x_w x s| >= cos(dihedral) without sideslip
        lift_s = (Fs[0] * ex + Fs[1] * ey + Fs[2] * ez) / enorm
        cw = (g["strip_chord"] * g["strip_width"]).T
        qcw = _rs(ca.mtimes(cw, ca.DM.ones(1, Kn)), q)
        out["cl"] = lift_s / qcw
        out["ccl_cref"] = _cs(g["strip_chord"].T / c, out["cl"])
        out["V_local"], out["cl_local"] = self.strip_local(U_ext, out["cl"], V)
        Fn = Fx * _cs(g["normal"][0, :].T, ca.DM.ones(N, Kn)) + Fy * _cs(g["normal"][1, :].T, ca.DM.ones(N, Kn)) \
            + Fz * _cs(g["normal"][2, :].T, ca.DM.ones(N, Kn))
        out["dCp"] = Fn / _rs(ca.mtimes(g["area"].T, ca.DM.ones(1, Kn)), q)
        return out


# --- small broadcasting helpers (CasADi does not broadcast) ---------------------------------
def _row(x):
    if isinstance(x, (ca.MX, ca.SX)):
        return x if x.shape[0] == 1 else x.T
    a = np.atleast_1d(np.asarray(x, dtype=float)).ravel()
    return ca.DM(a).T


def _bcast(x, K):
    if x.shape[1] == K:
        return x
    if x.shape[1] == 1:
        return ca.repmat(x, 1, K)
    raise InputError("operating point", f"inputs must have 1 or {K} columns, got {x.shape[1]}")


def _mat(v, N, K):
    if isinstance(v, (ca.MX, ca.SX, ca.DM)):
        m = v
    else:
        m = ca.DM(np.asarray(v, dtype=float).reshape(N, -1) if np.ndim(v) else np.full((N, K), float(v)))
    if m.shape == (N, 1) and K > 1:
        m = ca.repmat(m, 1, K)
    if m.shape != (N, K):
        raise InputError("v_ext", f"each component must be {N} x {K}, got {m.shape}")
    return m


def _cs(col, M):
    """Scale the rows of M (N x K) by the column vector ``col`` (N x 1)."""
    return ca.repmat(col, 1, M.shape[1]) * M


def _rs(M, row):
    """Scale the columns of M (N x K) by the row vector ``row`` (1 x K)."""
    return M * ca.repmat(row, M.shape[0], 1)
