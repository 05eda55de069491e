"""``report.html``: one self-contained page per run folder, for a designer's browser.

Made from the folder's files only (so ``mdo plot RUN_DIR`` regenerates it): status and
objective (``summary.json``), the baseline's objective when ``analysis/`` is there, the
active constraints with their multipliers (``summary.json["active"]``, a list of
``{"name", "kind", "where", "multiplier", "unit"}``; "not available" when absent), the
design checks, the design variables (``solution.json``), the summary outputs, the
energy and mass tables (``energy.md``, ``mass.md``) and every figure, embedded as
base64 PNG so that the page needs no other file and no network.  No script runs in it.
"""
from __future__ import annotations

import base64
import html
import json
import math
import re
from pathlib import Path

from ..core.units import as_read

__all__ = ["write_report_html", "report_html", "markdown_to_html", "FIGURES"]

# figure file -> caption, in the order a designer reads them
FIGURES = {
    "planform.png": "Three-view of the design (optimum solid, baseline dashed when analysis/ is present)",
    "geometry.png": "Geometry: lifting surfaces, fuselage, rotor disks and fixed wakes at mid-cruise",
    "mission.png": "Mission profile: altitude, airspeed, power and state of charge",
    "loading.png": "Spanwise loading c·cl/c_ref at mid-cruise, propeller disks shaded",
    "rotor.png": "Rotor: blade geometry and performance along the mission",
    "convergence.png": "IPOPT convergence (from ipopt.log)",
}

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:24px auto;max-width:1180px;
color:#222;line-height:1.4}
h1{font-size:1.6em;margin-bottom:.2em} h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:1.6em}
table{border-collapse:collapse;margin:.6em 0;font-size:.92em} th,td{border:1px solid #ccc;padding:3px 8px}
th{background:#f2f2f2;text-align:left} td.num{text-align:right;font-variant-numeric:tabular-nums}
.ok{color:#176e17;font-weight:600} .bad{color:#b00020;font-weight:600} .warn{background:#fff4e5}
figure{margin:1em 0} figure img{max-width:100%;border:1px solid #ddd} figcaption{font-size:.9em;color:#555}
.muted{color:#777}
"""


def _json(path: Path):
    try:
        return json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None


def _e(x) -> str:
    return html.escape(str(x))


def _num(v) -> str:
    if isinstance(v, bool) or v is None:
        return _e(v)
    if isinstance(v, (int, float)):
        return "—" if not math.isfinite(v) else f"{v:.6g}"
    if isinstance(v, list):
        import numpy as np
        flat = np.asarray(v, float).ravel().tolist()
        return "[" + ", ".join(f"{x:.4g}" for x in flat) + "]" if len(flat) <= 12 else f"[{len(flat)} values]"
    return _e(v)


def _inline(text: str) -> str:
    t = html.escape(text)
    t = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", t)
    return re.sub(r"`(.+?)`", r"<code>\1</code>", t)


def markdown_to_html(md: str, shift: int = 1) -> str:
    """The Markdown the run writes (headings, pipe tables, bullets, paragraphs) as HTML;
    headings move down by ``shift`` levels so that they sit under the page's own."""
    out, table, para = [], [], []

    def flush():
        if table:
            rows = [r for r in table if not re.fullmatch(r"\|?[\s:|-]+\|?", r)]
            cells = [[c.strip() for c in r.strip().strip("|").split("|")] for r in rows]
            out.append("<table><tr>" + "".join(f"<th>{_inline(c)}</th>" for c in cells[0]) + "</tr>")
            for r in cells[1:]:
                out.append("<tr>" + "".join(f"<td class='num'>{_inline(c)}</td>" if re.match(r"^[-+*\d.—]", c)
                                            else f"<td>{_inline(c)}</td>" for c in r) + "</tr>")
            out.append("</table>")
            table.clear()
        if para:
            out.append("<p>" + _inline(" ".join(para)) + "</p>")
            para.clear()

    for line in md.splitlines():
        s = line.strip()
        if s.startswith("|"):
            if para:
                flush()
            table.append(s)
            continue
        if table:
            flush()
        if not s:
            flush()
        elif s.startswith("#"):
            flush()
            level = min(len(s) - len(s.lstrip("#")) + shift, 6)
            out.append(f"<h{level}>{_inline(s.lstrip('#').strip())}</h{level}>")
        elif s.startswith("- "):
            flush()
            out.append(f"<ul><li>{_inline(s[2:])}</li></ul>")
        else:
            para.append(s)
    flush()
    return "\n".join(out)


def _head(run: Path, s: dict) -> list[str]:
    obj = s.get("objective", {})
    ok = s.get("success")
    parts = [f"<h1>{_e(s.get('problem', run.name))}: {_e(s.get('mode', 'run'))}</h1>",
             "<table>",
             f"<tr><th>status</th><td class='{'ok' if ok else 'bad'}'>{_e(s.get('status'))} "
             f"({'converged' if ok else 'NOT converged'})</td></tr>",
             f"<tr><th>objective: {_e(obj.get('name', ''))}</th><td class='num'>{_num(obj.get('value'))} "
             f"{_e(obj.get('unit', ''))}</td></tr>",
             f"<tr><th>IPOPT iterations</th><td class='num'>{_num(s.get('iterations'))}</td></tr>",
             f"<tr><th>wall time</th><td class='num'>{_num(s.get('wall_time_s'))} s</td></tr>"]
    base = _json(run / "analysis" / "summary.json")
    if base and obj.get("value") is not None:
        bv = base.get("objective", {}).get("value")
        if isinstance(bv, (int, float)) and bv:
            parts.append(f"<tr><th>baseline (analysis/)</th><td class='num'>{_num(bv)} {_e(obj.get('unit', ''))}"
                         f" &rarr; {100 * (obj['value'] - bv) / abs(bv):+.2f} %</td></tr>")
    size = s.get("nlp_size") or {}
    if size:
        parts.append("<tr><th>NLP size</th><td>" + ", ".join(f"{_e(k)} {_num(v)}" for k, v in size.items())
                     + "</td></tr>")
    parts.append("</table>")
    return parts


def _active(s: dict) -> list[str]:
    act = s.get("active")
    out = ["<h2>Active constraints</h2>"]
    if not isinstance(act, list):
        return out + ["<p class='muted'>not available (this run's summary.json has no \"active\" list)</p>"]
    if not act:
        return out + ["<p>no active inequality or bound</p>"]
    out.append("<table><tr><th>constraint</th><th>kind</th><th>where</th><th>multiplier</th><th>unit</th></tr>")
    for a in act:
        out.append(f"<tr><td>{_e(a.get('name', ''))}</td><td>{_e(a.get('kind', ''))}</td>"
                   f"<td>{_e(a.get('where', ''))}</td><td class='num'>{_num(a.get('multiplier'))}</td>"
                   f"<td>{_e(a.get('unit', ''))}</td></tr>")
    return out + ["</table>"]


def _checks(s: dict) -> list[str]:
    checks = s.get("design_checks")
    if not checks:
        return []
    out = ["<h2>Design checks (usual practice)</h2>",
           "<table><tr><th>quantity</th><th>value</th><th>usual range</th><th>unit</th><th>basis</th></tr>"]
    for c in checks:
        cls = "" if c.get("ok") else " class='warn'"
        flag = "" if c.get("ok") else " <span class='bad'>outside</span>"
        out.append(f"<tr{cls}><td>{_e(c['quantity'])}</td><td class='num'>{_num(c['value'])}{flag}</td>"
                   f"<td>{_num(c['low'])} – {_num(c['high'])}</td><td>{_e(c['unit'])}</td>"
                   f"<td>{_e(c['basis'])}</td></tr>")
    return out + ["</table>"]


def _design(run: Path, s: dict) -> list[str]:
    out = []
    sol = _json(run / "solution.json")
    design = [v for v in (sol or {}).get("variables", []) if v.get("design")]
    if design:
        out += ["<h2>Design variables</h2>",
                "<table><tr><th>name</th><th>value</th><th>unit</th><th>description</th></tr>"]
        for v in design:
            value, unit = as_read(v["value"], v["unit"])
            value = value.tolist()
            out.append(f"<tr><td>{_e(v['name'])}</td><td class='num'>{_num(value)}</td><td>{_e(unit)}</td>"
                       f"<td>{_e(v.get('description', ''))}</td></tr>")
        out.append("</table>")
    res = {k: o for k, o in (sol or {}).get("outputs", {}).items() if o.get("summary")}
    if res:
        out += ["<h2>Results</h2>", "<table><tr><th>quantity</th><th>value</th><th>unit</th></tr>"]
        out += [f"<tr><td>{_e(k)}</td><td class='num'>{_num(o['value'])}</td><td>{_e(o.get('unit', ''))}</td></tr>"
                for k, o in res.items()]
        out.append("</table>")
    return out


def _figures(run: Path) -> list[str]:
    names = [n for n in FIGURES if (run / n).exists()]
    names += sorted(p.name for p in run.glob("*.png") if p.name not in FIGURES)
    if not names:
        return []
    out = ["<h2>Figures</h2>"]
    for n in names:
        data = base64.b64encode((run / n).read_bytes()).decode("ascii")
        out.append(f"<figure id='{_e(n[:-4])}'><img alt='{_e(n)}' src='data:image/png;base64,{data}'>"
                   f"<figcaption>{_e(n)}: {_e(FIGURES.get(n, ''))}</figcaption></figure>")
    return out


def report_html(run_dir) -> str:
    """The page as a string (see the module docstring for what it holds)."""
    run = Path(run_dir)
    s = _json(run / "summary.json") or {"problem": run.name, "status": "no summary.json", "success": False}
    body = _head(run, s) + _active(s) + _checks(s) + _design(run, s)
    for md, title in (("energy.md", "Energy breakdown"), ("mass.md", "Mass build-up")):
        if (run / md).exists():
            text = (run / md).read_text(errors="replace")
            text = re.sub(r"^# .*\n", "", text, count=1)   # the page's own heading replaces the file's
            body += [f"<h2>{title}</h2>", markdown_to_html(text, shift=2)]
    body += _figures(run)
    title = f"{s.get('problem', run.name)}: {s.get('mode', 'run')} report"
    return ("<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'>"
            f"<title>{_e(title)}</title><style>{_CSS}</style></head><body>\n" + "\n".join(body)
            + "\n<p class='muted'>Written by mdo from the files of this run folder; "
              "<code>mdo plot RUN_DIR</code> regenerates it.</p>\n</body></html>\n")


def write_report_html(run_dir) -> Path:
    """Write ``report.html`` into ``run_dir``; returns its path."""
    path = Path(run_dir) / "report.html"
    path.write_text(report_html(run_dir), encoding="utf-8")
    return path
