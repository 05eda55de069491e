"""The approach drag device (gear and flap) of the GA airplanes: where the profile allows
it, what it does at the nodes, and the vehicles that cannot use it."""
import numpy as np
import pytest

from mdo.core import units as u
from mdo.core.errors import InputError
from mdo.mission import Mission
from mdo.mission.profiles import ga_segments
from mdo.mission.segments import ConstantAccelerationConstantAltitude
from mdo.nlp import Problem
from mdo.vehicle.aircraft import Aircraft
from mdo.vehicle.catalog import GA_APPROACH_DRAG_AREA_M2, ga2p


def test_profile_gives_the_device_to_base_leg_and_final_approach_only():
    segs = {s.name: s for s in ga_segments(approach_drag_area_m2=0.4)}
    with_device = sorted(k for k, s in segs.items() if s.parameters.get("drag_device_area_m2", 0.0) > 0)
    assert with_device == ["BL", "FA"]
    # default of the profile builder: no device anywhere (flaps only on take-off and approach)
    assert all("drag_device_area_m2" not in s.parameters for s in ga_segments())
    flaps = {k: s.parameters.get("flap_deflection", 0.0) for k, s in segs.items()}
    assert flaps == {"DER": 0.5, "ICA": 0.5, "CL": 0.0, "CR": 0.0, "D": 0.0, "DL": 0.0, "RCL": 0.0, "RCR": 0.0,
                     "RD": 0.0, "BL": 0.5, "FA": 1.0}
    with pytest.raises(InputError, match="approach_drag_area_m2"):
        ga_segments(approach_drag_area_m2=-0.1)


def test_vehicle_without_the_device_rejects_the_parameter():
    from mdo.vehicle import PolarVehicle
    seg = ConstantAccelerationConstantAltitude("DL", altitude_m=150.0, speed_start_mps=60.0, speed_end_mps=45.0,
                                               acceleration_mps2=-0.5, parameters={"drag_device_area_m2": 0.4})
    with pytest.raises(InputError, match="drag_device_area_m2"):
        Mission(PolarVehicle(mass_kg=1610.0, wing_area_m2=14.76, CD0=0.0175, induced_drag_factor=0.045,
                             CL_alpha_per_rad=5.1, propulsive_efficiency=0.82, chain_efficiency=0.9),
                [seg], nodes=4).build(Problem("polar_device"))


def _level_deceleration(area_m2):
    """GA-2P (design frozen) decelerating 60 -> 45 m/s at 0.8 m/s^2 in level flight at 500 ft."""
    p = Problem("decel")
    v = Aircraft(ga2p(), n_stations=10, wing_strips=12, tail_strips=3)
    params = {"drag_device_area_m2": area_m2} if area_m2 > 0 else None
    seg = ConstantAccelerationConstantAltitude("DL", altitude_m=500 * u.FT, speed_start_mps=60.0,
                                               speed_end_mps=45.0, acceleration_mps2=-0.8, nodes=5,
                                               parameters=params)
    m = Mission(v, [seg], nodes=5).build(p)
    p.minimize(m.energy_used_J / u.KWH, unit="kWh", scale=1.0)
    p.freeze_design()
    return p, m, p.solve(verbose=False)


def test_device_makes_a_hard_deceleration_flyable():
    """0.8 m/s^2 needs about 1490 N of braking at 1866 kg; the airframe's drag is 1020-1100 N
    and the propellers, windmilling into a full battery, cannot give the rest: without the
    device the segment is infeasible at its last node; with 0.40 m^2 it flies, with the
    device partly out (356-464 N of its drag) and the force balance met everywhere."""
    _, _, sol0 = _level_deceleration(0.0)
    assert not sol0.success
    assert "force_along_path" in sol0.violation_report()
    p, m, sol = _level_deceleration(GA_APPROACH_DRAG_AREA_M2)
    assert sol.success, sol.violation_report()
    rows = m.report_rows()
    deploy = sol.value(rows["drag_device_deployment"][0]).ravel()
    dev_drag = sol.value(rows["drag_device_drag_N"][0]).ravel()
    q = 0.5 * sol.value(rows["speed_mps"][0]).ravel() ** 2 * 1.2077  # density at 500 ft
    assert np.all(deploy > -1e-6) and np.all(deploy < 1 + 1e-6)
    assert deploy[1:].mean() > 0.2                      # it is used
    assert dev_drag == pytest.approx(q * GA_APPROACH_DRAG_AREA_M2 * deploy, rel=2e-3)
    assert p.variables["drag_device_deployment"].shape == (1, 4)   # node 0 is the held copy of node 1
    # the first node enters no collocation defect: its deployment is held at the next node's
    assert deploy[0] == pytest.approx(deploy[1], abs=1e-12)
