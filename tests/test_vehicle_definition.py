"""The vehicle definition is the single source of truth (issue 15): any aircraft, any
names, several rotor groups, and numbers that follow the definition consistently."""
import math
import time
from dataclasses import replace

import numpy as np
import pytest

from mdo.core import units as u
from mdo.core.errors import InputError
from mdo.mission import Mission
from mdo.mission.profiles import evtol_segments
from mdo.mission.segments import ConstantSpeedConstantAltitude, LinearSpeedConstantRate
from mdo.nlp import Problem
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import ga2p, ttw
from mdo.vehicle.config import MotorConfig, RotorGroupConfig, WingConfig
from mdo.vehicle.mass import mass_terms, solve_togw

SMALL = dict(n_stations=8, wing_strips=8, tail_strips=3)


def _segments(nodes=3, cruise_parameters=None):
    return [LinearSpeedConstantRate("CL", altitude_start_m=500 * u.FT, altitude_end_m=1500 * u.FT,
                                    speed_start_mps=150 * u.MPH, speed_end_mps=160 * u.MPH,
                                    climb_rate_mps=500 * u.FT_PER_MIN, nodes=nodes),
            ConstantSpeedConstantAltitude("CR", distance_m=10 * u.NMI, nodes=nodes, parameters=cruise_parameters)]


def two_group_vehicle():
    """A GA airframe with a main wing named "wing" and two rotor groups (not in the catalog):
    wing-tip cruise propellers and four inboard propellers that fold in cruise."""
    cfg = ga2p()
    main = replace(cfg.main_wing, name="wing")
    tips = replace(cfg.rotor_groups[0], name="tips", wings=("wing",), span_eta=(1.0,), radius_m=0.8,
                   x_ahead_of_le_m=1.2)
    inboard = RotorGroupConfig("inboard", wings=("wing",), span_eta=(0.3, 0.55), blades=5, radius_m=0.4,
                               design_thrust_N=300.0, design_speed_mps=40.0, design_cl=0.7, design_rpm=3500.0,
                               design_altitude_m=0.0, motor=MotorConfig(15e3), x_ahead_of_le_m=0.5,
                               folded_drag_area_m2=0.005)
    wings = (main,) + tuple(w for w in cfg.wings if w.role != "main")
    return replace(cfg, name="My-Plane", wings=wings, rotor_groups=(tips, inboard))


def _built(cfg, segments, **kw):
    p = Problem("t")
    v = Aircraft(cfg, **{**SMALL, **kw})
    m = Mission(v, segments, nodes=3).build(p)
    p.minimize(m.energy_used_J / u.KWH, unit="kWh")
    return p, v, m


def test_new_vehicle_with_two_groups_and_renamed_wing_builds_fast():
    t0 = time.perf_counter()
    p, v, m = _built(two_group_vehicle(), _segments(cruise_parameters={"inboard.active": 0.0}))
    viol = p.initial_violations()
    elapsed = time.perf_counter() - t0
    assert elapsed < 30.0, f"build + evaluate took {elapsed:.1f} s"
    groups = set(p.groups)
    for g in ("tips", "inboard"):
        assert f"{g} BEMT" in groups and f"{g} motor power" in groups and f"{g} tip Mach" in groups
    assert "inboard stopped" in groups                    # folded in cruise: speed held
    assert "wing.span" in p.variables                     # the renamed main wing is designed
    assert all(np.isfinite(x["max_violation"]) for x in viol)
    # the folded group gives no thrust in cruise
    cr = [k for k, lab in enumerate(m.labels) if lab.startswith("CR")]
    T_in = np.asarray(p.opti.value(m.evaluation.outputs["inboard.thrust_N"].expr, p.opti.initial())).ravel()
    assert np.all(T_in[cr] == 0.0) and np.all(T_in[[k for k in range(len(m.labels)) if k not in cr]] > 0)


def _initial_numbers(cfg):
    p, v, m = _built(cfg, _segments(), free=("rotor", "wing", "positions"))
    return sorted(round(x["max_violation"], 9) for x in p.initial_violations()), float(v.togw_baseline_kg)


def test_renaming_the_vehicle_or_a_wing_changes_no_number():
    base = ga2p()
    renamed = replace(base, name="Somebody's plane")
    w = replace(base.main_wing, name="aile")
    g = replace(base.rotor_groups[0], wings=("aile",))
    renamed_wing = replace(base, wings=(w,) + base.wings[1:], rotor_groups=(g,))
    a = _initial_numbers(base)
    assert _initial_numbers(renamed) == a
    assert _initial_numbers(renamed_wing) == a


def test_battery_parallel_count_changes_energy_and_mass_consistently():
    cfg = ga2p()
    small = replace(cfg, battery=replace(cfg.battery, cells_parallel=64))
    b0, b1 = cfg.battery, small.battery
    assert b1.mass_kg == pytest.approx(0.8 * b0.mass_kg)
    # the electrical pack and the mass build-up read the same battery
    assert Aircraft(small, **SMALL).pack.n_parallel == 64
    assert Aircraft(small, **SMALL).pack.nominal_energy_J == pytest.approx(0.8 * Aircraft(cfg, **SMALL).pack.nominal_energy_J)
    for c in (cfg, small):
        terms = mass_terms(c, solve_togw(c))
        bat = [v for k, v in terms.items() if k.startswith("battery")]
        assert bat == [pytest.approx(c.battery.mass_kg)]
        assert c.battery.mass_kg == pytest.approx(c.battery.cells * 0.048 * 1.42)
    assert solve_togw(small) < solve_togw(cfg)


@pytest.mark.parametrize("change, field", [
    (lambda c: replace(c, wings=(replace(c.main_wing, role="wingy"),) + c.wings[1:]), "main_wing.role"),
    (lambda c: replace(c, wings=c.wings + (replace(c.main_wing, name="second"),)), "wings"),
    (lambda c: replace(c, rotor_groups=(replace(c.rotor_groups[0], wings=("vertical_tail",)),)), "propellers.wings"),
    (lambda c: replace(c, battery=replace(c.battery, cells_parallel=0)), "battery.cells_parallel"),
    (lambda c: replace(c, kind="helicopter"), "kind"),
    (lambda c: replace(c, rotor_groups=(replace(c.rotor_groups[0], motor=52.7e3),)), "propellers.motor"),
])
def test_invalid_definitions_name_the_field(change, field):
    with pytest.raises(InputError) as e:
        change(ga2p())
    assert e.value.args[0].startswith(field) or field in str(e.value)


def test_wing_role_decides_what_is_designed_not_the_name():
    cfg = ga2p()
    # the horizontal tail renamed "main_wing_2" stays a tail; the main wing named "tail" stays the wing
    wings = (replace(cfg.main_wing, name="tail"), replace(cfg.wings[1], name="main_wing_2"), cfg.wings[2])
    cfg2 = replace(cfg, wings=wings, rotor_groups=(replace(cfg.rotor_groups[0], wings=("tail",)),))
    v = Aircraft(cfg2, **SMALL)
    assert [w.name for w in v.lifting_wings] == ["tail"]
    assert [w.name for w in v.tails] == ["main_wing_2"]


def test_tilt_wing_transitions_build_fast():
    """The TTW over the whole eVTOL profile (hover, transitions with azimuth-averaged
    BEMT, cruise) builds and evaluates at its initial guess quickly."""
    t0 = time.perf_counter()
    segs = evtol_segments(nodes=3)
    p = Problem("ttw_small")
    v = Aircraft(ttw(), n_stations=6, n_azimuth=2, wing_strips=6)
    m = Mission(v, segs, nodes=3).build(p)
    p.minimize(m.energy_used_J / u.KWH, unit="kWh")
    viol = p.initial_violations()
    assert time.perf_counter() - t0 < 60.0
    groups = set(p.groups)
    assert "rotors BEMT (azimuth-averaged)" in groups and "rotors BEMT (axial)" in groups
    assert "stall margin" in groups
    # the stall limit covers the wing-borne segments only, not the transitions
    labels = p.groups["stall margin"].labels
    assert any(lab.startswith("CR") for lab in labels) and not any(lab.startswith(("VT", "DT", "AT")) for lab in labels)
    assert all(np.isfinite(x["max_violation"]) for x in viol)


def test_mission_options_set_cruise_altitude_and_speed():
    from mdo.mission.profiles import ga_segments
    segs = ga_segments(cruise_altitude_m=8000 * u.FT, cruise_speed_mps=170 * u.MPH)
    cl = next(s for s in segs if s.name == "CL")
    assert cl.altitude_end_m == pytest.approx(8000 * u.FT) and cl.speed_end_mps == pytest.approx(170 * u.MPH)
    with pytest.raises(InputError, match="cruise_altitude_m"):
        ga_segments(cruise_altitude_m=100.0)
