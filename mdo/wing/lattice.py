"""The vortex lattice of one surface half, built as SX expressions of the design.

For a :class:`~mdo.wing.geometry.Surface` this module returns the lattice points
of its original (right, or only) half in vehicle body axes:

* ``nodes[r]`` (3 x E), r = 0..nc-1: the bound-vortex points of chordwise row r
  on each spanwise strip edge, at x/c = (r + 1/4)/nc on the camber line;
  ``nodes[nc]``: the trailing-edge points (where the trailing legs leave along +x);
* ``cp`` (3 x S*nc): control points, x/c = (r + 3/4)/nc at mid-strip on the
  straight legs between the lattice nodes, and ``tangent``: the chordwise
  camber-line tangent at x/c = (r + 3/4)/nc (for the normals);
* edge data: chord, eta and leading-edge points.

Panels are numbered strip-major: panel j = s*nc + r (strip s from the root out,
row r from the leading edge back).  Horseshoe (s, r) of the original half runs
infinity -> TE(s) -> ... -> node(s, r) -> node(s+1, r) -> ... -> TE(s+1) ->
infinity, with the chordwise legs following the camber line to the trailing
edge (as in AVL), so that its bound segment points outboard (+y on the right
wing) and a positive circulation lifts.  The mirror image uses the reflected
points in reversed order (vorticity is a pseudovector: the image of a bound
vortex along +y at +y is a bound vortex along +y at -y).
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from .camber import camber_line
from .geometry import Params, Surface, interpolation_weights

__all__ = ["surface_half", "rotation_matrices"]


def rotation_matrices(incidence, vertical: bool):
    """(R, V): nose-up rotation about y by ``incidence`` and the +90 deg roll of a vertical surface."""
    ci, si = ca.cos(incidence), ca.sin(incidence)
    R = ca.vertcat(ca.horzcat(ci, 0, si), ca.horzcat(0, 1, 0), ca.horzcat(-si, 0, ci))
    V = ca.SX(np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]], dtype=float)) if vertical else ca.SX.eye(3)
    return R, V


def surface_half(s: Surface, p: Params, flat: bool = False) -> dict:
    """SX lattice of the original half of surface ``s`` (see module doc).

    flat: the lattice lies on the untwisted chord surface (no twist rotation, no
    camber offset); twist and camber enter only through the control-point
    tangents (AVL's linearized boundary condition), so that the lattice, and the
    influence matrix, do not depend on the twists.
    """
    sec = _sections(s, p)
    anchors, counts, edges = _edges(s, p)
    pts, tans, le, chord_e = _edge_points(s, sec, edges, flat)
    R, V = rotation_matrices(sec["incidence"], s.vertical)
    RV = ca.mtimes(R, V)
    o = ca.vertcat(*sec["origin"])
    pv = ca.vertcat(*sec["pivot"])

    def to_global(cols):
        P = ca.horzcat(*cols)
        return o + pv + ca.mtimes(R, ca.mtimes(V, P) - pv)   # rotate about the pivot

    nc = s.nchord
    cp_cols, tan_cols = _control_points(pts, tans, nc, len(edges) - 1)
    t0 = ca.DM([1.0, 0.0, 0.0])
    return {
        "nodes": [to_global(pts[r]) for r in range(nc + 1)],
        "cp": to_global(cp_cols),
        "tangent": ca.mtimes(RV, ca.horzcat(*tan_cols)),
        "tangent0": ca.mtimes(RV, ca.repmat(t0, 1, len(tan_cols))),
        "le": to_global(le),
        "edge_chord": ca.horzcat(*chord_e),
        "edge_eta": ca.horzcat(*[ca.SX(e) for e in edges]),
        "E": len(edges), "S": len(edges) - 1, "nc": nc,
        "strip_airfoil": _strip_airfoils(s, [a[0] for a in anchors], counts),
    }


def _sections(s: Surface, p: Params) -> dict:
    """The defining sections as parameters: chords, twists, quarter-chord points
    (local frame: root leading edge at 0, span along +y), and the placement."""
    nm = s.name
    span = p(s.span, f"{nm}.span")
    c_root = p(s.root_chord, f"{nm}.root_chord")
    semispan = span / 2 if s.mirrored else span
    eta_k = np.array([sec.eta for sec in s.sections], dtype=float)
    # the parameters in the order the lattice has always registered them
    chord_k = [c_root * p(sec.chord, f"{nm}.sections[{k}].chord") for k, sec in enumerate(s.sections)]
    twist_k = [p(sec.twist, f"{nm}.sections[{k}].twist") for k, sec in enumerate(s.sections)]
    sweep = [p(v, f"{nm}.sweep[{k}]") for k, v in enumerate(s.sweep)]
    dih = [p(v, f"{nm}.dihedral[{k}]") for k, v in enumerate(s.dihedral)]
    origin = [p(v, f"{nm}.origin[{k}]") for k, v in enumerate(s.origin)]
    pivot = [p(v, f"{nm}.pivot[{k}]") for k, v in enumerate(s.pivot)]
    incidence = p(s.incidence, f"{nm}.incidence") + p(s.tilt, f"{nm}.tilt")
    y_k = [e * semispan for e in eta_k]
    xq_k, z_k = [0.25 * chord_k[0]], [0.0]
    for k in range(len(s.sections) - 1):
        dy = y_k[k + 1] - y_k[k]
        xq_k.append(xq_k[k] + ca.tan(sweep[k]) * dy)
        z_k.append(z_k[k] + ca.tan(dih[k]) * dy)
    return {"semispan": semispan, "eta": eta_k, "chord": chord_k, "twist": twist_k, "xq": xq_k, "z": z_k,
            "origin": origin, "pivot": pivot, "incidence": incidence}


def _edges(s: Surface, p: Params):
    """Strip edges (fractions of the semispan): the anchors (sections and breaks) with
    cosine spacing in between.  Returns (anchors, panel counts, edges)."""
    anchors = [(nom, p(val, f"{s.name}.anchor[{i}]")) for i, (nom, val) in enumerate(s.anchors())]
    counts = s.panel_counts()
    edges = []
    for i, n in enumerate(counts):
        a, b = anchors[i][1], anchors[i + 1][1]
        g = s.spacing_fractions(n, starts_at_root=(i == 0))
        for j, gj in enumerate(g):
            if i > 0 and j == 0:
                continue
            edges.append(a if j == 0 else b if j == n else a + (b - a) * float(gj))
    return anchors, counts, edges


def _edge_points(s: Surface, sec: dict, edges: list, flat: bool):
    """At every strip edge: the lattice's chordwise points (bound-vortex rows and the
    trailing edge), the camber-line tangents at the control rows, the leading edge and
    the chord, in the surface's local frame."""
    nc = s.nchord
    xi_b = (np.arange(nc) + 0.25) / nc      # bound vortices at the panels' quarter chords
    xi_c = (np.arange(nc) + 0.75) / nc      # control points at three quarters
    cambers = [camber_line(k.airfoil if k.airfoil is not None else s.airfoil) for k in s.sections]
    zb_k = np.array([[cl.z(x) for x in xi_b] for cl in cambers])        # K x nc
    sc_k = np.array([[cl.slope(x) for x in xi_c] for cl in cambers])
    t0 = ca.DM([1.0, 0.0, 0.0])
    pts = {r: [] for r in range(nc + 1)}
    tans = {r: [] for r in range(nc)}
    le, chord_e = [], []
    for e in edges:
        w = interpolation_weights(e, sec["eta"], s.eta_smoothing)

        def mix(vals):
            return sum(wk * v for wk, v in zip(w, vals) if not (isinstance(wk, float) and wk == 0.0))

        c = mix(sec["chord"])
        th = mix(sec["twist"])
        q = ca.vertcat(mix(sec["xq"]), e * sec["semispan"], mix(sec["z"]))
        # streamwise (x-z plane) section rotated nose-up by the twist about its quarter chord
        t = ca.vertcat(ca.cos(th), 0, -ca.sin(th))
        u = ca.vertcat(ca.sin(th), 0, ca.cos(th))
        for r in range(nc):
            zb = mix(zb_k[:, r])
            sc = mix(sc_k[:, r])
            if flat:
                pts[r].append(q + (xi_b[r] - 0.25) * c * t0)
            else:
                pts[r].append(q + (xi_b[r] - 0.25) * c * t + c * zb * u)
            tans[r].append(t + sc * u)
        tg = t0 if flat else t
        pts[nc].append(q + 0.75 * c * tg)
        le.append(q - 0.25 * c * tg)
        chord_e.append(c)
    return pts, tans, le, chord_e


def _control_points(pts: dict, tans: dict, nc: int, S: int):
    """Control points on the lattice itself: on the straight chordwise legs between the
    row's bound point and the next node (half way; 2/3 of the way to the trailing edge
    on the last row), so that camber never lifts a control point off the legs of a
    narrow strip (the camber enters through the normals' slope, as in thin-airfoil
    theory); and their tangents (local frame)."""
    frac = [0.5] * (nc - 1) + [2.0 / 3.0]
    cp_cols, tan_cols = [], []
    for si in range(S):
        for r in range(nc):
            a = 0.5 * (pts[r][si] + pts[r][si + 1])
            b = 0.5 * (pts[r + 1][si] + pts[r + 1][si + 1])
            cp_cols.append(a + frac[r] * (b - a))
            tan_cols.append(0.5 * (tans[r][si] + tans[r][si + 1]))
    return cp_cols, tan_cols


def _strip_airfoils(s: Surface, anchor_nominal, counts):
    """Airfoil name of each strip: that of the section at the strip's inboard end (nominal)."""
    names = []
    eta_k = [sec.eta for sec in s.sections]
    for i, n in enumerate(counts):
        a, b = anchor_nominal[i], anchor_nominal[i + 1]
        g = s.spacing_fractions(n, starts_at_root=(i == 0))
        for j in range(n):
            mid = a + (b - a) * 0.5 * (g[j] + g[j + 1])
            k = int(np.clip(np.searchsorted(eta_k, mid, side="right") - 1, 0, len(eta_k) - 2))
            sec = s.sections[k]
            names.append(sec.airfoil if sec.airfoil is not None else s.airfoil)
    return names
