"""Render every figure a run folder has data for, then its ``report.html``, from
whatever of the folder is readable.

Everything is drawn from the folder's files (``ipopt.log``, ``mission.csv``,
``loading.csv``, ``blade.csv``, ``geometry.json`` ...), so ``mdo plot RUN_DIR`` redoes
what the run wrote, in either unit system (``units="si"|"aviation"``).

A run folder may be damaged (a killed run, a full disk, a hand edit): files empty,
binary, truncated, missing columns, or not files at all (a FIFO named
``ipopt.log`` would block a plain ``open``).  ``render_run`` therefore checks each
input before any figure code opens it — a regular file (``stat.S_ISREG``; a FIFO,
device or folder is never opened), at most ``MAX_INPUT_BYTES``, text without NUL
bytes — and runs each figure maker on its own: a figure whose input is unusable is
skipped with one warning line naming the file and what is wrong, and the others
are still drawn.
"""
from __future__ import annotations

import inspect
import os
import stat
import sys
from pathlib import Path

from .convergence import plot_convergence, write_convergence_csv
from .figures import plot_loading, plot_mission, plot_rotor, run_title
from .units import unit_system

__all__ = ["render_run", "RENDERERS", "usable_input", "MAX_INPUT_BYTES", "register_renderer", "figure_report"]

MAX_INPUT_BYTES = 64 * 2 ** 20   # a GA-2P ipopt.log is ~0.1 MB, its mission.csv ~50 kB
_SNIFF_BYTES = 64 * 1024


class SkipFigure(Exception):
    """An input of a figure is missing or unusable (the message says which and why)."""


def usable_input(path) -> str | None:
    """``None`` if ``path`` is a readable, bounded text file; else why not (one phrase).

    Never blocks: the type is checked with ``lstat``/``stat`` before the file is opened,
    and the open itself is non-blocking (a FIFO swapped in after the check returns at
    once and is refused by ``fstat``)."""
    p = Path(path)
    try:
        st = os.stat(p)
    except FileNotFoundError:
        return "missing"
    except OSError as exc:
        return f"cannot be read ({exc.strerror or exc})"
    if not stat.S_ISREG(st.st_mode):
        return "not a regular file (a FIFO, device or folder is not read)"
    if st.st_size == 0:
        return "empty"
    if st.st_size > MAX_INPUT_BYTES:
        return f"{st.st_size / 2 ** 20:.0f} MiB, larger than the {MAX_INPUT_BYTES // 2 ** 20} MiB read limit"
    try:
        fd = os.open(p, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        return f"cannot be read ({exc.strerror or exc})"
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return "not a regular file (a FIFO, device or folder is not read)"
        head = os.read(fd, _SNIFF_BYTES)
    except OSError as exc:
        return f"cannot be read ({exc.strerror or exc})"
    finally:
        os.close(fd)
    if b"\0" in head:
        return "binary (NUL bytes), not text"
    try:
        head.decode("utf-8")
    except UnicodeDecodeError as exc:
        if exc.start < len(head) - 4:   # a multi-byte character cut at the sniff boundary is fine
            return "not UTF-8 text"
    return None


def _need(run: Path, name: str) -> Path | None:
    """``run/name`` if usable; ``None`` if absent (nothing to draw); ``SkipFigure`` if damaged."""
    p = run / name
    if not os.path.lexists(p):
        return None
    why = usable_input(p)
    if why is not None:
        raise SkipFigure(f"{name}: {why}")
    return p


def _optional(run: Path, name: str) -> Path | None:
    """Like ``_need`` but a damaged optional input is left out with a warning."""
    try:
        return _need(run, name)
    except SkipFigure as exc:
        _warn(f"{exc} (drawn without it)")
        return None


def _convergence(run: Path, units="si"):
    log = _need(run, "ipopt.log")
    if not log:
        return []
    write_convergence_csv(log, run / "convergence.csv")   # the table from the same lines as the figure
    return [plot_convergence(log, run / "convergence.png")]


def _mission(run: Path, units="si"):
    m = _need(run, "mission.csv")
    return [plot_mission(m, run / "mission.png", units=units)] if m else []


def _loading(run: Path, units="si"):
    d = _need(run, "loading.csv")
    if not d:
        return []
    base = _optional(run, str(Path("analysis") / "loading.csv"))
    return [plot_loading(d, run / "loading.png", baseline=base, units=units)]


def _rotor(run: Path, units="si"):
    if not _need(run, "blade.csv"):
        return []
    if os.path.lexists(run / "mission.csv") and usable_input(run / "mission.csv") is not None:
        raise SkipFigure(f"mission.csv: {usable_input(run / 'mission.csv')}")
    return [plot_rotor(run, run / "rotor.png", units=units)]


def _geometry(run: Path, units="si"):
    g = _need(run, "geometry.json")
    if not g:
        return []
    from .geometry import plot_geometry, plot_planform, read_geometry
    name = read_geometry(g).get("name", "")
    base = _optional(run, str(Path("analysis") / "geometry.json"))
    return [plot_geometry(g, run / "geometry.png", title=run_title(run, f"{name} geometry"), units=units),
            plot_planform(g, run / "planform.png", baseline=base, units=units,
                          title=run_title(run, f"{name} three-view" + (", baseline dashed" if base else "")))]


def _checks(run: Path, units="si"):
    if _need(run, "summary.json"):
        from .checks import write_design_checks
        write_design_checks(run)
    return []


RENDERERS = [_convergence, _mission, _loading, _rotor, _geometry, _checks]


def figure_report(solution, out_dir):
    """A problem report (``problem.add_report(figure_report)``) that renders every figure."""
    return render_run(out_dir)


def register_renderer(fn):
    """Disciplines add figure makers ``fn(run_dir) -> [png paths]`` (empty if no data);
    a ``units`` keyword, if ``fn`` has one, receives the unit system's name."""
    RENDERERS.append(fn)
    return fn


def _warn(text: str) -> None:
    print(f"mdo: warning: {text}", file=sys.stderr)


def _reason(exc: Exception) -> str:
    """One line for a figure maker's failure on readable but malformed data."""
    if isinstance(exc, KeyError):
        return f"column {exc.args[0]!r} missing"
    text = " ".join(str(exc).split()) or type(exc).__name__
    return text if len(text) <= 200 else text[:197] + "..."


def _label(fn) -> str:
    return getattr(fn, "__name__", str(fn)).lstrip("_")


def render_run(run_dir, units: str = "si", html: bool = True, warn=_warn) -> list:
    """Every figure the folder has usable data for (paths), then ``report.html`` (with ``html``).

    Each figure maker runs on its own: an unusable input or a failure inside one
    (missing column, no rows, text where numbers belong) is one ``warn`` line naming
    the figure and the reason, and the next figure is still drawn."""
    import warnings

    run = Path(run_dir)
    us = unit_system(units)
    made = []
    for fn in list(RENDERERS) + ([_html] if html else []):
        if fn is _html and not made:
            break
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")   # NumPy/matplotlib chatter on odd data: the warn line says it
                takes_units = "units" in inspect.signature(fn).parameters
                made += fn(run, units=us.name) if takes_units else fn(run)
        except SkipFigure as exc:
            warn(f"{_label(fn)} figure skipped: {exc}")
        except MemoryError:
            warn(f"{_label(fn)} figure skipped: out of memory")
        except Exception as exc:  # damaged data: skip this figure, keep the others
            warn(f"{_label(fn)} figure skipped: {_reason(exc)}")
    return made


def _html(run: Path):
    from .report_html import write_report_html
    return [write_report_html(run)]
