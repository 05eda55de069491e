import pytest

from mdo.core import units as u


def test_conversions():
    assert u.ft_to_m(1000) == pytest.approx(304.8)
    assert u.mph_to_mps(175) == pytest.approx(78.232)
    assert u.kn_to_mps(1) == pytest.approx(0.514444, rel=1e-6)
    assert u.lb_to_kg(3549) == pytest.approx(1609.8, rel=1e-4)
    assert u.hp_to_w(95) == pytest.approx(70841.5, rel=1e-5)
    assert u.kwh_to_j(1) == 3.6e6
    assert u.fpm_to_mps(600) == pytest.approx(3.048)
    assert u.mps_to_mph(u.mph_to_mps(42.0)) == pytest.approx(42.0)
    assert u.radps_to_rpm(u.rpm_to_radps(2400)) == pytest.approx(2400)
