import importlib.util
import sys
from pathlib import Path

import pytest

# let test modules import each other's helpers (e.g. test_nlp_harness.BRACH)
sys.path.insert(0, str(Path(__file__).parent))


def pytest_configure(config):
    """Stop with one line, not one import error per test module, when the
    dependencies are missing (pytest run outside the environment mdo was installed in)."""
    missing = [m for m in ("casadi", "numpy", "scipy", "matplotlib") if importlib.util.find_spec(m) is None]
    if missing:
        raise pytest.UsageError(
            f"{sys.executable} lacks {', '.join(missing)}: install the project first "
            f"(python3 -m venv .venv && . .venv/bin/activate && pip install -e '.[test]'), "
            f"then run python -m pytest inside that environment")
