"""Validation: APC 19x12 Thin Electric propeller against the UIUC wind-tunnel data.

The paper's second validation propeller (Clarke et al., section IV.A, Fig. 3b;
under 10 % error up to J = 0.7 reported).  The BEMT of ``mdo.rotor`` runs at every
measured (rpm, J) of ``mdo/rotor/data/apce_19x12_performance.csv`` (runs at 1500,
2096, 2502, 2508, 2991, 3007 rpm) and every static rpm of ``apce_19x12_static.csv``,
with exactly the model of the 10x7 (``apc_common.py``).

    python problems/validation/apc19x12.py [OUT_DIR]

writes ``results/validation/apc19x12.png``, ``apc19x12_errors.csv``,
``apc19x12_static.csv`` and ``apc19x12_summary.md``.
"""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import apc_common  # noqa: E402

PROP = apc_common.Prop("19x12", "APC 19x12 Thin Electric", diameter_in=19.0, pitch_in=12.0)


def write_outputs(out_dir: Path = apc_common.OUT_DIR) -> dict:
    return apc_common.write_outputs(PROP, out_dir)


if __name__ == "__main__":
    out = write_outputs(Path(sys.argv[1]) if len(sys.argv) > 1 else apc_common.OUT_DIR)
    apc_common.print_table(out["table"], out["baseline"])
