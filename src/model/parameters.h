/*
 * parameters.h - all the physics may know of the FMU: the structs UCParams, UCInputs and UCOutputs (one
 * field per FMU variable, generated from schema/variables.toml) and the constants their fields take
 * (modes, bit masks, limits). Plain C, so that the adapter (fmu/) reads the same header through
 * api/cable_api.h; the physics includes this header and never the API.
 */
#ifndef UNDERWATERCABLE_PARAMETERS_H
#define UNDERWATERCABLE_PARAMETERS_H

/* UCParams, UCInputs and UCOutputs (one field per FMU variable, same names as the FMU's) and
 * UC_NUM_STATIONS are generated from the variable schema, schema/variables.toml (docs/schema.md). */
#include "generated/uc_schema.h"

/* bottomEnd values */
#define UC_BOTTOM_FREE 0
#define UC_BOTTOM_ANCHORED 1
#define UC_BOTTOM_TOWED_BODY 2
#define UC_BOTTOM_EXTERNAL 3
#define UC_BOTTOM_PROXY 4

/* torqueMode values */
#define UC_TORQUE_FREE 0
#define UC_TORQUE_PRESCRIBED 1
#define UC_TORQUE_ROTATION 2

/* topEnd values */
#define UC_TOP_HINGED 0
#define UC_TOP_CLAMPED 1

/* deckKeep bits: the parameters a lineFile deck also sets that the importer set explicitly, and which then
 * keep the importer's value (docs/lines.md, "Seabed") */
#define UC_DECK_KEEP_WATER_DEPTH (1 << 0)
#define UC_DECK_KEEP_GRAVITY (1 << 1)
#define UC_DECK_KEEP_WATER_DENSITY (1 << 2)
#define UC_DECK_KEEP_ENABLE_SEABED (1 << 3)
#define UC_DECK_KEEP_SEABED_STIFFNESS (1 << 4)
#define UC_DECK_KEEP_SEABED_DAMPING (1 << 5)
#define UC_DECK_KEEP_SEABED_FRICTION (1 << 6)
#define UC_DECK_KEEP_ENABLE_COMPRESSION (1 << 7)

/* winchMode */
#define UC_WINCH_FIXED 0
#define UC_WINCH_RATE 1
#define UC_WINCH_TENSION 2

/* bodyOrientation: the inputs of a mooring system's coupled body's orientation */
#define UC_ORIENTATION_ANGLES_XYZ 0 /* body[k].roll/pitch/yaw, R = Rx(roll) Ry(pitch) Rz(yaw) (MoorDyn's) */
#define UC_ORIENTATION_QUATERNION 1 /* body[k].q0/q1/q2/q3, scalar first */
#define UC_ORIENTATION_ANGLES_ZYX 2 /* body[k].roll/pitch/yaw, R = Rz(yaw) Ry(pitch) Rx(roll) (OpenFAST's, MoorPy's) */

/* The body inputs of uc_body_derivatives: x, y, z, roll, pitch, yaw, vx, vy, vz, wx, wy, wz, q0, q1, q2, q3 */
#define UC_BODY_DERIVATIVE_INPUTS 16

/* water.source: the water at the lines' load points */
#define UC_WATER_OWN 0    /* the FMU's current and waves */
#define UC_WATER_PUSHED 1 /* pushed by the importer (FMI 3.0 arrays waterVelocity.*, waterAcceleration.*) */

/* initMode values */
#define UC_INIT_EQUILIBRIUM 0
#define UC_INIT_STRAIGHT 1

/* The shortest communication step [s]: over a step a driven end follows a quintic whose coefficients
 * scale with h^-5, which is not representable in doubles for much shorter steps (h^5 underflows). */
#define UC_MIN_STEP_SIZE 1e-10

/* Tow position inputs farther than this [m] from uc_tow_position are reported (once per run): the
 * extrapolation of consistent inputs misses by millimetres (jerk h^3 / 6). */
#define UC_TOW_MISMATCH_TOLERANCE 0.05

/* The driven inputs whose positions uc_driven_position reports, and the adapter checks against them as it
 * checks the tow point: the far end of bottomEnd 3 (end.*), a mooring system's coupled body (body[k].*, its
 * reference point) and coupled point (point[k].*). */
#define UC_DRIVEN_END 0
#define UC_DRIVEN_BODY 1
#define UC_DRIVEN_POINT 2

/* UCInputs.towAccelerationGiven (endAccelerationGiven): 0 when the master gave no acceleration for the step;
 * otherwise bit 0, and UC_ACCELERATION_AS_INPUT(k) when component k is the input tow.a{k} (end.a{k}) set as a
 * value (fmi2SetReal) rather than an input derivative. Only such a component, held at 0 while its velocity
 * input changes, is taken as not set (a master that fills every input with 0; docs/interface.md). */
#define UC_ACCELERATION_AS_INPUT(k) (2 << (k))
#define UC_ACCELERATION_FLOOR 0.01
#define UC_ACCELERATION_MARGIN 0.5

#endif /* UNDERWATERCABLE_PARAMETERS_H */
