"""Tutorial 3: put one mdo block in your own ``casadi.Opti`` problem.

    python docs/tutorials/block_in_opti.py

The vortex lattice (``mdo.wing.VLM``) on a tapered wing of the GA-2P's area and the
baseline's span, with the section twists as the user's variables: the least induced
drag at CL = 0.5.  Prandtl's lifting-line theory says no planar wing does better than
the elliptic loading, CDi = CL^2 / (pi AR) (e = 1); the optimum twist gets within a
fraction of a percent of it.  The README shows the same with the BEMT rotor.
"""
import math

import casadi as ca

from mdo.wing import VLM
from mdo.wing.geometry import constant_area

AREA_M2, SPAN_M, TAPER, CL = 14.76, 11.4, 0.6, 0.5

opti = ca.Opti()
twist = opti.variable(4)              # section twists (rad) at eta = 0, 1/3, 2/3, 1
alpha = opti.variable()               # angle of attack (rad)
wing = constant_area("wing", AREA_M2, SPAN_M, TAPER, [twist[i] for i in range(4)], nspan=16)
res = VLM([wing]).solve(alpha, 70.0)  # the block: circulation and loads at one operating point

opti.subject_to(res["CL"] == CL)
opti.subject_to(twist[0] == 0)        # twist relative to the root
opti.subject_to(opti.bounded(-0.1, twist, 0.1))
opti.minimize(1e3 * res["CDi"])
opti.solver("ipopt", {"print_time": False}, {"print_level": 0, "sb": "yes"})
sol = opti.solve()

cdi = float(sol.value(res["CDi"]))
ideal = CL ** 2 / (math.pi * SPAN_M ** 2 / AREA_M2)
print("twist (deg):", ", ".join(f"{math.degrees(t):.2f}" for t in sol.value(twist)))
print(f"alpha {math.degrees(sol.value(alpha)):.2f} deg, CDi {cdi:.5f}, elliptic {ideal:.5f}, "
      f"span efficiency e = {ideal / cdi:.4f}")
