"""A coupled body's orientation as the FMU's inputs give it (parameter bodyOrientation,
docs/systems_mooring.md): roll, pitch, yaw with R = Rx Ry Rz (0, MoorDyn's) or R = Rz Ry Rx (2, OpenFAST's
and MoorPy's), or the unit quaternion (q0, q1, q2, q3), scalar first (1)."""

from __future__ import annotations

import math

ANGLES_XYZ, QUATERNION, ANGLES_ZYX = 0, 1, 2


def quaternion_product(a, b):
    """The Hamilton product a b of two quaternions (scalar first): the rotation b, then a."""
    a0, a1, a2, a3 = a
    b0, b1, b2, b3 = b
    return (a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3, a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
            a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1, a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0)


def quaternion_from_angles(roll: float, pitch: float, yaw: float, convention: int = ANGLES_XYZ):
    """The unit quaternion of R = Rx(roll) Ry(pitch) Rz(yaw) (ANGLES_XYZ) or Rz(yaw) Ry(pitch) Rx(roll)
    (ANGLES_ZYX), with q0 >= 0."""
    qx = (math.cos(roll / 2.0), math.sin(roll / 2.0), 0.0, 0.0)
    qy = (math.cos(pitch / 2.0), 0.0, math.sin(pitch / 2.0), 0.0)
    qz = (math.cos(yaw / 2.0), 0.0, 0.0, math.sin(yaw / 2.0))
    if convention == ANGLES_XYZ:
        q = quaternion_product(qx, quaternion_product(qy, qz))
    elif convention == ANGLES_ZYX:
        q = quaternion_product(qz, quaternion_product(qy, qx))
    else:
        raise ValueError(f"angle convention {convention}: expected {ANGLES_XYZ} (R = Rx Ry Rz) or {ANGLES_ZYX} "
                         "(R = Rz Ry Rx)")
    return tuple(-x for x in q) if q[0] < 0.0 else q

