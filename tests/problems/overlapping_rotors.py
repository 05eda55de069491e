"""GA-8P with propellers too large for their spacing: rejected when the vehicle is built."""
from dataclasses import replace

from mdo.vehicle.catalog import ga8p


def build():
    cfg = ga8p()
    g = replace(cfg.rotor_groups[0], radius_m=0.8)
    replace(cfg, rotor_groups=(g,))     # raises InputError: rotors overlap
    raise AssertionError("overlapping rotors were accepted")
