"""results/component_figures.py: the cruise figures read from a run folder, the flags against the published
ranges, and the committed table is what the committed run folders give."""
import csv
import importlib.util
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("component_figures", ROOT / "results" / "component_figures.py")
cf = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cf)


def _folder(tmp_path, **cruise):
    row = {"segment": "CR", "CD": 0.030, "CDi": 0.006, "CL": 0.4, "lift_N": 15000.0, "drag_N": 1125.0,
           "propulsive_efficiency": 0.86, "props.motor_efficiency": 0.95, "props.drive_efficiency": 0.93}
    row.update(cruise)
    climb = dict(row, segment="CL", CD=1.0)
    with open(tmp_path / "mission.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(row))
        w.writeheader()
        w.writerows([climb, row])
    (tmp_path / "summary.json").write_text(json.dumps({"battery_mass_kg": 250.0, "togw_kg": 1000.0}))
    return tmp_path


def test_figures_of_a_run_folder(tmp_path):
    f = cf.figures(_folder(tmp_path))
    assert f["CD0"] == pytest.approx(0.024)            # CD - CDi at the cruise segment's first node
    assert f["L/D"] == pytest.approx(15000 / 1125)
    assert f["propulsive efficiency"] == 0.86
    assert f["motor efficiency"] == 0.95 and f["drive efficiency (motor x inverter)"] == 0.93
    assert f["battery mass fraction"] == pytest.approx(0.25)
    assert f["_LDmax"] == pytest.approx(0.5 * (0.4 ** 2 / 0.006 / 0.024) ** 0.5)


def test_outside_the_range_is_flagged():
    assert cf._cell(0.93, "propulsive efficiency").endswith("(above)")
    assert cf._cell(0.70, "propulsive efficiency").endswith("(below)")
    assert "(" not in cf._cell(0.85, "propulsive efficiency")


def test_committed_table_is_current():
    assert (ROOT / "results" / "component_figures.md").read_text() == cf.report()
