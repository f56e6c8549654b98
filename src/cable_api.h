/*
 * cable_api.h - the only interface between the FMI adapter (fmu/, C) and the
 * physics core (src/, C++17). No FMI knowledge on this side; no physics on the other.
 *
 * Life cycle:  uc_params_default -> (caller edits fields) -> uc_params_check
 *              -> uc_create -> uc_initialize -> uc_do_step ... -> uc_free.
 * Every function that can fail returns 0 on success and non-zero on failure and
 * then writes a one-line, human-readable reason into msg (never NULL-terminated
 * past msgSize). No function throws, prints, aborts or keeps global state.
 *
 * Units are SI throughout (m, s, kg, N, rad). Earth frame: x, y horizontal, z up,
 * free surface at z = 0. Arc length s = 0 at the tow point, s = length at the far end.
 */
#ifndef UNDERWATERCABLE_CABLE_API_H
#define UNDERWATERCABLE_CABLE_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Number of output stations along the cable (fixed per FMU build, see FMI-CHECKLIST 2.2). */
#define UC_NUM_STATIONS 21

/* bottomEnd values */
#define UC_BOTTOM_FREE 0
#define UC_BOTTOM_ANCHORED 1
#define UC_BOTTOM_TOWED_BODY 2
#define UC_BOTTOM_EXTERNAL 3

/* torqueMode values */
#define UC_TORQUE_FREE 0
#define UC_TORQUE_PRESCRIBED 1
#define UC_TORQUE_ROTATION 2

/* Rows of the depth profile of the current (currentProfile.*[1..10]). */
#define UC_CURRENT_PROFILE_ROWS 10

/* topEnd values */
#define UC_TOP_HINGED 0
#define UC_TOP_CLAMPED 1

/* initMode values */
#define UC_INIT_EQUILIBRIUM 0
#define UC_INIT_STRAIGHT 1

/* All parameters (FMU names in comments). Fixed for the life of a UCCable. */
typedef struct UCParams {
    double length;            /* length [m]                 unstretched length */
    double diameter;          /* diameter [m]               hydrodynamic and displacement diameter */
    double massPerLength;     /* massPerLength [kg/m]       dry mass per unstretched length */
    double EA;                /* EA [N]                     axial stiffness */
    double EI;                /* EI [N.m2]                  bending stiffness */
    double axialDamping;      /* axialDamping [N.s]         internal damping c_a in T = EA eps + c_a deps/dt */
    double Cdn;               /* Cdn [1]                    normal drag coefficient (on d) */
    double Cdt;               /* Cdt [1]                    tangential drag coefficient (on pi d) */
    double Can;               /* Can [1]                    normal added-mass coefficient */
    double Cat;               /* Cat [1]                    tangential added-mass coefficient */
    double waterDensity;      /* waterDensity [kg/m3] */
    double gravity;           /* gravity [m/s2] */
    int nElements;            /* nElements                  number of cubic Hermite elements */
    double relTol;            /* relTol                     integrator relative tolerance */
    double absTol;            /* absTol                     integrator absolute tolerance */
    int bottomEnd;            /* bottomEnd                  UC_BOTTOM_* */
    int topEnd;               /* topEnd                     UC_TOP_* */
    double topTangent[3];     /* topTangent.x/y/z           clamped top direction (normalized internally) */
    double anchor[3];         /* anchor.x/y/z [m]           far-end position when anchored */
    double bodyMass;          /* body.mass [kg]             internal towed body (bottomEnd 2) */
    double bodyVolume;        /* body.volume [m3] */
    double bodyAddedMass;     /* body.addedMass [kg] */
    double bodyCdA;           /* body.CdA [m2]              quadratic drag: 0.5 rho CdA |u| u */
    int initMode;             /* initMode                   UC_INIT_* */
    double initialDirection[3]; /* initialDirection.x/y/z   straight initial line (and statics first guess) */
    int enableBending;        /* enableBending (Boolean)    EI term on/off */
    int enableAddedMass;      /* enableAddedMass (Boolean)  Can/Cat terms on/off */
    /* seabed (flat, at z = -waterDepth) */
    int enableSeabed;         /* enableSeabed (Boolean) */
    double waterDepth;        /* waterDepth [m] */
    double seabedStiffness;   /* seabedStiffness [N/m2]     force per length per metre of penetration */
    double seabedDamping;     /* seabedDamping [N.s/m2]     per length per m/s of penetration rate */
    double seabedFriction;    /* seabedFriction [1]         Coulomb coefficient (axial and lateral) */
    /* depth profile of the current, added to the uniform current.* inputs */
    int currentProfileRows;   /* currentProfileRows         rows in use, 0..10 (0: no profile) */
    double currentProfileDepth[UC_CURRENT_PROFILE_ROWS]; /* currentProfile.depth[k] [m], positive down, increasing */
    double currentProfileX[UC_CURRENT_PROFILE_ROWS];     /* currentProfile.x[k] [m/s] */
    double currentProfileY[UC_CURRENT_PROFILE_ROWS];     /* currentProfile.y[k] [m/s] */
    /* torsion */
    int enableTorsion;        /* enableTorsion (Boolean)    torque term of the equation of motion */
    double GJ;                /* GJ [N.m2]                  torsional stiffness */
    int torqueMode;           /* torqueMode                 UC_TORQUE_*: 0 swivel, 1 torque input, 2 twist input */
    /* axial law */
    int enableCompression;    /* enableCompression (Boolean) true: T = EA e + c de/dt both ways; false: tension only (chains, ropes) */
} UCParams;

/* Inputs, held constant (or extrapolated, see uc_do_step) over a communication step. */
typedef struct UCInputs {
    double tow[3];             /* tow.x/y/z [m]      tow point position at the communication point */
    double towVelocity[3];     /* tow.vx/vy/vz [m/s] tow point velocity */
    double towAcceleration[3]; /* [m/s2] from fmi2SetRealInputDerivatives (der(tow.v*) or der(tow.*,2)); 0 if not given */
    double endLoad[3];         /* endLoad.x/y/z [N]  extra point force at the far end */
    double endCouple[3];       /* endCouple.x/y/z [N.m] point couple at the far end (Earth frame) */
    double current[2];         /* current.x/y [m/s]  uniform current */
    int towAccelerationGiven;  /* 1 when towAcceleration came from the master for this step; 0: the
                                  core estimates it from the last two tow velocity inputs */
    double end[3];             /* end.x/y/z [m]      far-end position when bottomEnd = 3 */
    double endVelocity[3];     /* end.vx/vy/vz [m/s] far-end velocity when bottomEnd = 3 */
    double endAcceleration[3]; /* [m/s2] der(end.v*) from fmi2SetRealInputDerivatives */
    int endAccelerationGiven;  /* as towAccelerationGiven, for the far end */
    double torque;             /* torque [N.m]       cable torque when torqueMode = 1 */
    double twist;              /* twist [rad]        end-to-end rotation of the material frame when torqueMode = 2 */
} UCInputs;

/* Outputs, valid after uc_initialize and after every uc_do_step. */
typedef struct UCOutputs {
    double towForce[3];        /* towForce.x/y/z [N]    force of the cable on the tow point */
    double towTension;         /* towTension [N]        |towForce| */
    double endForce[3];        /* endForce.x/y/z [N]    force of the cable on whatever holds the far end */
    double endTension;         /* endTension [N]        |endForce| */
    double endPosition[3];     /* endPosition.x/y/z [m] */
    double endVelocity[3];     /* endVelocity.x/y/z [m/s] */
    double shapeX[UC_NUM_STATIONS]; /* shape.x[k] [m], k = 1..21 evenly spaced in unstretched arc length */
    double shapeY[UC_NUM_STATIONS];
    double shapeZ[UC_NUM_STATIONS];
    double tension[UC_NUM_STATIONS]; /* tension[k] [N]   axial force at the stations */
    double minTension;         /* minTension [N]        over the cable (quadrature points and stations) */
    double maxCurvature;       /* maxCurvature [1/m] */
    double maxBendingMoment;   /* maxBendingMoment [N.m] = EI * maxCurvature */
    double touchdownArcLength; /* touchdownArcLength [m] unstretched arc length from the tow point to the
                                  first seabed contact; the length when none */
    double minSeabedClearance; /* minSeabedClearance [m] min over the cable of z + waterDepth (< 0: penetration) */
    double cableTorque;        /* cableTorque [N.m]     torque H, constant along the cable */
    double twistAngle[UC_NUM_STATIONS]; /* twist[k] [rad] material twist from the tow point, relative to
                                  the parallel-transported (twist-free) frame: H s / GJ */
    double towMoment[3];       /* towMoment.x/y/z [N.m] moment of the cable on the tow point */
    double endMoment[3];       /* endMoment.x/y/z [N.m] moment of the cable on the far-end attachment */
    double curvature[UC_NUM_STATIONS]; /* curvature[k] [1/m] |r' x r''| / |r'|^3 at the stations */
    /* integrator statistics since uc_initialize (debug outputs) */
    double nSteps, nResidualEvals, nJacobianEvals, nNonlinearFailures, nErrorTestFailures;
} UCOutputs;

typedef struct UCCable UCCable;

/* Defaults: the Hopland 1993 tow cable, free lower end, hinged top, 20 elements. */
void uc_params_default(UCParams* p);

/* 0 if every parameter is admissible; otherwise 1 and msg reads like
 * "length = -3 is outside (0, inf): the cable must have a positive length". */
int uc_params_check(const UCParams* p, char* msg, size_t msgSize);

/* Checks the parameters and builds the immutable model and the workspace. NULL on failure (msg says why). */
UCCable* uc_create(const UCParams* p, char* msg, size_t msgSize);
void uc_free(UCCable* c);

/* Initial state at time t0 from the inputs: initMode 0 equilibrium (steady tow included), 1 straight line at rest. */
int uc_initialize(UCCable* c, double t0, const UCInputs* in, char* msg, size_t msgSize);

/* Integrates from t to exactly t + h (h > 0, t must equal the current time of the cable).
 * The tow point follows a cubic in time from the cable's current end state (position,
 * velocity) to in->tow + v h + a h^2/2 with velocity v + a h at t + h; when the inputs
 * agree with the current end state this is exactly tow + v (t' - t) + a (t' - t)^2 / 2.
 * a is in->towAcceleration when in->towAccelerationGiven, otherwise the difference of the
 * last two tow velocity inputs over the last step size (0 on the first step). */
int uc_do_step(UCCable* c, double t, double h, const UCInputs* in, char* msg, size_t msgSize);

double uc_time(const UCCable* c);
void uc_get_outputs(const UCCable* c, UCOutputs* out);

/* Exact state save/restore: a plain byte copy of everything that determines the future.
 * After uc_state_save or uc_state_restore, the next uc_do_step restarts the integrator from
 * the saved vectors, so a saved-and-continued run and a restored-and-continued run are
 * bit-identical. The buffer is only valid for a cable created with identical parameters. */
size_t uc_state_size(const UCCable* c);
int uc_state_save(UCCable* c, void* buffer, size_t size);
int uc_state_restore(UCCable* c, const void* buffer, size_t size, char* msg, size_t msgSize);

#ifdef __cplusplus
}
#endif

#endif /* UNDERWATERCABLE_CABLE_API_H */
