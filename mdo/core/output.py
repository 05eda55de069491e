"""Files the discipline commands write (``--out``): never over an existing file unasked.

The rule of every writing command (issue 19 item 1, issue 23 item 5): an existing
file is replaced only with ``--force``; a symbolic link is never written through
(its target could be anything, e.g. a committed result); the text goes to a
temporary sibling first and is moved into place with ``os.replace``, so an
interrupted write leaves either the old file or the new one, never half of it.
Errors are ``InputError`` naming the option and the path (one line, exit 2).
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import InputError

__all__ = ["check_new_file", "write_new_file", "check_new_files"]


def check_new_file(path, force: bool, field: str = "--out") -> Path:
    """Raise ``InputError`` unless ``path`` may be written: absent (or a regular file and
    ``force``), not a symlink, in an existing folder."""
    p = Path(path)
    if p.is_symlink():
        raise InputError(field, f"{p} is a symbolic link; refusing to write through it (give a plain file name)")
    if p.exists():
        if not p.is_file():
            raise InputError(field, f"{p} exists and is not a regular file")
        if not force:
            raise InputError(field, f"{p} already exists; pass --force to replace it or choose another name")
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        raise InputError(field, f"cannot write {p}: folder {parent} does not exist")
    return p


def check_new_files(paths, force: bool, field: str = "--out") -> list:
    """``check_new_file`` for every path, before any is written."""
    return [check_new_file(p, force, field) for p in paths]


def write_new_file(path, text: str, force: bool, field: str = "--out") -> Path:
    """Write ``text`` to ``path`` under the rule above (temporary sibling, then ``os.replace``)."""
    p = check_new_file(path, force, field)
    parent = p.parent if str(p.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{p.name}.", suffix=".tmp", dir=parent)
    except OSError as exc:
        raise InputError(field, f"cannot write {p}: {exc.strerror or exc}") from None
    try:
        umask = os.umask(0)
        os.umask(umask)
        os.fchmod(fd, 0o666 & ~umask)   # mkstemp makes 0600; a written result is an ordinary file
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.replace(tmp, p)
    except OSError as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise InputError(field, f"cannot write {p}: {exc.strerror or exc}") from None
    return p
