"""Sections for any airfoil: geometry from a NACA code, a coordinate file or
CST/Kulfan parameters, polars from NeuralFoil, surrogate from the shipped fit.

A :class:`SectionSpec` names the geometry and the transition setting (``ncrit``,
or a fixed transition ``xtr_upper``/``xtr_lower`` in x/c).  :func:`generate_polars`
evaluates NeuralFoil (Sharpe & Hansman, "NeuralFoil: an airfoil aerodynamics
analysis tool using physics-informed machine learning", arXiv:2503.16323, 2025;
a network trained on tens of millions of XFOIL runs, so it reproduces XFOIL with
free or forced transition) on the same Reynolds levels and alpha grid the shipped
XFOIL polars use, and keeps the attached range (up to cl_max + 1 deg, as XFOIL's
last converged points).  Those polars go through exactly the same fit
(:func:`mdo.airfoil.fit.fit_tables`) and model (:mod:`mdo.airfoil.model`) as the
shipped sections, so a generated section is the same kind of smooth full-circle
surrogate, usable in any SX/MX graph.

NeuralFoil (and the AeroSandbox it imports) is needed only to *generate*: the
polars are written in XFOIL's format to a cache folder (``MDO_AIRFOIL_CACHE`` or
``~/.cache/mdo/airfoils``) and read from there afterwards, so runs that reuse a
section need neither package.

Geometry (own code, standard definitions):

* NACA 4-digit ``MPTT`` (Abbott & von Doenhoff, *Theory of Wing Sections*, 1959,
  sec. 6.4): thickness ``yt = 5 t (0.2969 sqrt x - 0.1260 x - 0.3516 x^2 + 0.2843 x^3
  - 0.1015 x^4)`` (open trailing edge, as XFOIL's generator), parabolic mean lines.
* NACA 5-digit ``LPQTT`` (ibid. sec. 6.6): design cl = 0.15 L, camber position
  p = P/20, Q = 0 standard or 1 reflexed mean line, with the tabulated m, k1 (k2/k1).
* CST/Kulfan (Kulfan, J. Aircraft 45(1), 2008): ``y = sqrt(x)(1 - x) sum_i A_i
  B_i^n(x) + x dz_te/2`` per surface, plus the leading-edge term
  ``w_le sqrt(x)(1 - x)^(n + 0.5)`` (the parameterisation NeuralFoil takes).
"""
from __future__ import annotations

import hashlib
import json
import os
import re
from dataclasses import dataclass, field
from math import comb
from pathlib import Path

import numpy as np

from ..core.errors import InputError

__all__ = ["SectionSpec", "naca_coordinates", "kulfan_coordinates", "generate_polars",
           "cache_dir", "REYNOLDS_LEVELS", "parse_spec"]

REYNOLDS_LEVELS = (2e4, 5e4, 1e5, 2e5, 5e5, 1e6, 2e6, 5e6, 1e7)   # as the shipped polars
ALPHA_GRID_DEG = np.arange(-14.0, 22.0 + 1e-9, 0.5)
MODEL_SIZE = "xlarge"        # NeuralFoil's most accurate network

# NACA 5-digit mean lines (Abbott & von Doenhoff, Table, design cl 0.3): p -> (m, k1) / (m, k1, k2/k1)
_NACA5_STD = {1: (0.0580, 361.400), 2: (0.1260, 51.640), 3: (0.2025, 15.957), 4: (0.2900, 6.643),
              5: (0.3910, 3.230)}
_NACA5_REFLEX = {2: (0.1300, 51.990, 0.000764), 3: (0.2170, 15.793, 0.00677), 4: (0.3180, 6.520, 0.0303),
                 5: (0.4410, 3.191, 0.1355)}


def _cosine_x(n: int) -> np.ndarray:
    return 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, n)))


def _naca_thickness(x, t):
    return 5.0 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3 - 0.1015 * x ** 4)


def _naca_camber(code: str, x):
    """Mean line z/c and slope of a 4- or 5-digit code."""
    if len(code) == 4:
        m, p = int(code[0]) / 100.0, int(code[1]) / 10.0
        if m == 0.0 or p == 0.0:
            return np.zeros_like(x), np.zeros_like(x)
        fore = x < p
        zc = np.where(fore, m / p ** 2 * (2 * p * x - x ** 2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x ** 2))
        dz = np.where(fore, 2 * m / p ** 2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
        return zc, dz
    L, P, Q = int(code[0]), int(code[1]), int(code[2])
    scale = 0.15 * L / 0.3
    if Q == 0:
        if P not in _NACA5_STD:
            raise InputError("airfoil", f"NACA 5-digit camber position digit must be 1..5, got {code}")
        m, k1 = _NACA5_STD[P]
        fore = x < m
        zc = np.where(fore, k1 / 6 * (x ** 3 - 3 * m * x ** 2 + m ** 2 * (3 - m) * x), k1 * m ** 3 / 6 * (1 - x))
        dz = np.where(fore, k1 / 6 * (3 * x ** 2 - 6 * m * x + m ** 2 * (3 - m)), -k1 * m ** 3 / 6)
    elif Q == 1:
        if P not in _NACA5_REFLEX:
            raise InputError("airfoil", f"NACA 5-digit reflexed camber position digit must be 2..5, got {code}")
        m, k1, r = _NACA5_REFLEX[P]
        fore = x < m
        zc = np.where(fore, k1 / 6 * ((x - m) ** 3 - r * (1 - m) ** 3 * x - m ** 3 * x + m ** 3),
                      k1 / 6 * (r * (x - m) ** 3 - r * (1 - m) ** 3 * x - m ** 3 * x + m ** 3))
        dz = np.where(fore, k1 / 6 * (3 * (x - m) ** 2 - r * (1 - m) ** 3 - m ** 3),
                      k1 / 6 * (3 * r * (x - m) ** 2 - r * (1 - m) ** 3 - m ** 3))
    else:
        raise InputError("airfoil", f"NACA 5-digit third digit must be 0 (standard) or 1 (reflexed), got {code}")
    return scale * zc, scale * dz


def naca_coordinates(code: str, n: int = 121) -> np.ndarray:
    """Selig-ordered (TE -> upper -> LE -> lower -> TE) coordinates of a NACA 4/5-digit section."""
    code = str(code).strip()
    if not re.fullmatch(r"\d{4}|\d{5}", code):
        raise InputError("airfoil", f"a NACA code has 4 or 5 digits, got {code!r}")
    t = int(code[-2:]) / 100.0
    if not (0.01 <= t <= 0.40):
        raise InputError("airfoil", f"NACA thickness must be 1..40 % of chord, got {code!r}")
    x = _cosine_x(n)
    yt = _naca_thickness(x, t)
    zc, dz = _naca_camber(code, x)
    th = np.arctan(dz)
    xu, yu = x - yt * np.sin(th), zc + yt * np.cos(th)
    xl, yl = x + yt * np.sin(th), zc - yt * np.cos(th)
    return np.vstack([np.column_stack([xu[::-1], yu[::-1]]), np.column_stack([xl[1:], yl[1:]])])


def kulfan_coordinates(upper_weights, lower_weights, leading_edge_weight: float = 0.0,
                       te_thickness: float = 0.0, n: int = 121) -> np.ndarray:
    """Selig-ordered coordinates of a CST/Kulfan section (module docstring)."""
    x = _cosine_x(n)

    def surf(w, sign):
        w = np.asarray(w, dtype=float)
        order = w.size - 1
        bern = np.array([comb(order, i) * x ** i * (1 - x) ** (order - i) for i in range(order + 1)])
        y = np.sqrt(x) * (1 - x) * (w @ bern) + sign * x * te_thickness / 2.0
        return y + leading_edge_weight * np.sqrt(x) * (1 - x) ** (order + 1.5)

    yu, yl = surf(upper_weights, 1.0), surf(lower_weights, -1.0)
    if np.any(yu[1:-1] - yl[1:-1] <= 0.0):
        raise InputError("kulfan", "upper and lower surfaces cross (thickness <= 0 somewhere)")
    return np.vstack([np.column_stack([x[::-1], yu[::-1]]), np.column_stack([x[1:], yl[1:]])])


@dataclass(frozen=True)
class SectionSpec:
    """What to generate: geometry (exactly one of ``naca``, ``coordinates``, ``kulfan``)
    and the transition setting: ``ncrit`` (e^N amplification, 9 = XFOIL's default,
    a quiet tunnel; 4-5 a turbulent environment), or a forced transition location
    ``xtr_upper``/``xtr_lower`` in x/c (1.0 = free)."""

    naca: str | None = None
    coordinates: tuple | None = None          # ((x, y), ...) Selig order
    kulfan: dict | None = field(default=None, hash=False)
    ncrit: float = 9.0
    xtr_upper: float = 1.0
    xtr_lower: float = 1.0
    title: str | None = None

    def __post_init__(self):
        given = [v is not None for v in (self.naca, self.coordinates, self.kulfan)]
        if sum(given) != 1:
            raise InputError("airfoil", "give exactly one of a NACA code, coordinates or Kulfan parameters")
        if not (0.5 <= self.ncrit <= 14.0):
            raise InputError("ncrit", f"must lie in [0.5, 14], got {self.ncrit}")
        for nm in ("xtr_upper", "xtr_lower"):
            v = getattr(self, nm)
            if not (0.0 <= v <= 1.0):
                raise InputError(nm, f"forced transition x/c must lie in [0, 1], got {v}")

    def coordinate_array(self) -> np.ndarray:
        if self.naca is not None:
            return naca_coordinates(self.naca)
        if self.coordinates is not None:
            return np.asarray(self.coordinates, dtype=float)
        k = self.kulfan
        return kulfan_coordinates(k["upper_weights"], k["lower_weights"], k.get("leading_edge_weight", 0.0),
                                  k.get("TE_thickness", 0.0))

    @property
    def key(self) -> str:
        """A short, stable name: geometry + transition (hash for coordinates/Kulfan)."""
        if self.naca is not None:
            base = f"naca{self.naca}"
        else:
            payload = json.dumps(self.coordinates if self.coordinates is not None else
                                 {k: np.asarray(v, dtype=float).round(8).tolist() for k, v in self.kulfan.items()})
            base = ("coords" if self.coordinates is not None else "cst") + hashlib.sha1(payload.encode()).hexdigest()[:8]
        tr = f"n{self.ncrit:g}"
        if self.xtr_upper < 1.0 or self.xtr_lower < 1.0:
            tr += f"_xtr{self.xtr_upper:g}_{self.xtr_lower:g}"
        return re.sub(r"[^0-9a-z_]", "", f"{base}_{tr}".replace(".", "p").lower())


def cache_dir() -> Path:
    return Path(os.environ.get("MDO_AIRFOIL_CACHE", Path.home() / ".cache" / "mdo" / "airfoils"))


#: Generated sections the package ships (the reference aircraft's tripped sections), so
#: that a plain install needs no NeuralFoil to fly them; written by ``python -m
#: mdo.airfoil.generate SPEC...`` and read before the cache (``data/generated/SOURCES.md``).
SHIPPED_DIR = Path(__file__).resolve().parent / "data" / "generated"


def _attached_range(alpha, cl):
    """Indices of the attached range: from cl_min - 1 deg to cl_max + 1 deg around alpha 0."""
    i_max = int(np.argmax(np.where(alpha > -2.0, cl, -np.inf)))
    i_min = int(np.argmin(np.where(alpha < 4.0, cl, np.inf)))
    keep = (alpha <= alpha[i_max] + 1.0) & (alpha >= alpha[i_min] - 1.0)
    return keep


def _neuralfoil_eval(spec: SectionSpec, alpha, reynolds):
    try:
        import neuralfoil as nf
    except ImportError as exc:
        raise InputError("airfoil", "generating a section needs the optional package neuralfoil "
                                    "(pip install 'mdo[sections]')") from exc
    kw = dict(alpha=alpha, Re=reynolds, n_crit=spec.ncrit, xtr_upper=spec.xtr_upper,
              xtr_lower=spec.xtr_lower, model_size=MODEL_SIZE)
    if spec.kulfan is not None:
        k = {kk: np.asarray(v, dtype=float) for kk, v in spec.kulfan.items()}
        k.setdefault("leading_edge_weight", 0.0)
        k.setdefault("TE_thickness", 0.0)
        return nf.get_aero_from_kulfan_parameters(k, **kw)
    return nf.get_aero_from_coordinates(spec.coordinate_array(), **kw)


def _write_polar(path: Path, title: str, spec: SectionSpec, re_: float, a, cl, cd, cm):
    lines = [f" generated by mdo.airfoil.generate (NeuralFoil {MODEL_SIZE}, Ncrit {spec.ncrit:g}, "
             f"xtr {spec.xtr_upper:g}/{spec.xtr_lower:g})", "",
             f" Calculated polar for: {title}", "",
             f" Mach =   0.000     Re =     {re_ / 1e6:.3f} e 6     Ncrit =   {spec.ncrit:.3f}", "",
             "  alpha    CL        CD       CDp       CM     Top_Xtr  Bot_Xtr",
             " ------ -------- --------- --------- -------- -------- --------"]
    for row in zip(a, cl, cd, cm):
        lines.append(f" {row[0]:6.2f} {row[1]:8.4f} {row[2]:9.5f} {0.0:9.5f} {row[3]:8.4f} {1.0:8.4f} {1.0:8.4f}")
    path.write_text("\n".join(lines) + "\n")


def generate_polars(spec: SectionSpec, reynolds_levels=REYNOLDS_LEVELS, *, folder: Path | None = None,
                    refresh: bool = False) -> list[Path]:
    """Polar files (XFOIL format, Mach 0) of ``spec`` at ``reynolds_levels``; cached.

    The Reynolds number in a file name is an integer.  Returns the file paths.
    """
    if folder is None and not refresh:
        shipped = _polar_files(SHIPPED_DIR / spec.key, spec.key, reynolds_levels)
        if all(p.exists() for p in shipped) and (SHIPPED_DIR / spec.key / f"{spec.key}_coordinates.txt").exists():
            return shipped
    folder = Path(folder) if folder is not None else cache_dir() / spec.key
    paths = _polar_files(folder, spec.key, reynolds_levels)
    coords_path = folder / f"{spec.key}_coordinates.txt"
    if not refresh and coords_path.exists() and all(p.exists() for p in paths):
        return paths
    folder.mkdir(parents=True, exist_ok=True)
    title = spec.title or spec.key
    xy = spec.coordinate_array()
    coords_path.write_text(title + "\n" + "\n".join(f" {x:.6f} {y:.6f}" for x, y in xy) + "\n")
    a = ALPHA_GRID_DEG
    for re_, path in zip(reynolds_levels, paths):
        out = _neuralfoil_eval(spec, a, float(re_))
        cl, cd, cm = (np.asarray(out[k], dtype=float).ravel() for k in ("CL", "CD", "CM"))
        keep = _attached_range(a, cl) & (cd > 0)
        _write_polar(path, title, spec, float(re_), a[keep], cl[keep], cd[keep], cm[keep])
    return paths


def _polar_files(folder: Path, key: str, reynolds_levels) -> list[Path]:
    return [folder / f"{key}_polar_Re_{int(round(r))}.txt" for r in reynolds_levels]


_SPEC_RE = re.compile(r"^(?P<geom>[^@]+?)\s*(?:@(?P<opts>.*))?$")


def parse_spec(text: str) -> SectionSpec:
    """``"NACA 23012@ncrit=5"``, ``"naca4412@xtr=0.05"``, ``"path/to/file.dat@ncrit=7"``.

    Options after ``@`` (comma-separated): ``ncrit=N``, ``xtr=X`` (both surfaces),
    ``xtr_upper=X``, ``xtr_lower=X``.
    """
    m = _SPEC_RE.match(str(text).strip())
    if m is None:
        raise InputError("airfoil", f"cannot read section spec {text!r}")
    geom, opts = m.group("geom").strip(), m.group("opts")
    kw = {}
    for item in (opts.split(",") if opts else []):
        if "=" not in item:
            raise InputError("airfoil", f"section option must be NAME=VALUE, got {item!r} in {text!r}")
        k, v = (s.strip().lower() for s in item.split("=", 1))
        try:
            val = float(v)
        except ValueError as exc:
            raise InputError("airfoil", f"section option {k} needs a number, got {v!r}") from exc
        if k == "ncrit":
            kw["ncrit"] = val
        elif k == "xtr":
            kw["xtr_upper"] = kw["xtr_lower"] = val
        elif k in ("xtr_upper", "xtr_lower"):
            kw[k] = val
        else:
            raise InputError("airfoil", f"unknown section option {k!r}; use ncrit, xtr, xtr_upper, xtr_lower")
    digits = re.sub(r"[\s_\-]", "", geom.lower())
    if re.fullmatch(r"naca\d{4,5}", digits):
        return SectionSpec(naca=digits[4:], title=f"NACA {digits[4:]}", **kw)
    path = Path(geom).expanduser()
    if path.suffix.lower() in (".dat", ".txt") or path.exists():
        if not path.exists():
            raise InputError("airfoil", f"coordinate file {geom!r} not found")
        from .data_io import read_coordinates
        name, upper, lower = read_coordinates(path)
        xy = np.vstack([upper[::-1], lower[1:]])
        return SectionSpec(coordinates=tuple(map(tuple, xy.round(7))), title=name or path.stem, **kw)
    raise InputError("airfoil", f"{geom!r} is neither a NACA 4/5-digit code nor a coordinate file")


def _ship(specs) -> None:
    """Write the polars of each section spec text into :data:`SHIPPED_DIR` (needs NeuralFoil)."""
    from .airfoil import Airfoil
    for text in specs:
        af = Airfoil.from_name(text)
        spec = af.spec
        generate_polars(spec, folder=SHIPPED_DIR / spec.key, refresh=True)
        print(f"{text}: {SHIPPED_DIR / spec.key}")


if __name__ == "__main__":
    import sys
    _ship(sys.argv[1:])
