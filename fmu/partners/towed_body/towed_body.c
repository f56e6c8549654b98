/*
 * towed_body.c - a towed body (towfish, depressor, clump weight) as a point body: the partner FMU
 * "TowedBody" (adapter: ../common/partner_fmi.c). Two ways to couple it to the cable FMU
 * (docs/cosimulation.md):
 *
 * integrateTranslation = false (default): a force element. The cable FMU integrates the body's
 *   translation inside its implicit solve (bottomEnd 2 with body.mass, body.addedMass, body.volume:
 *   inertia, weight and buoyancy; body.CdA = 0), and this FMU supplies the body's hydrodynamic force
 *   with its velocity linearization: inputs end.* / end.v* (the cable's endPosition / endVelocity),
 *   outputs force.* (to the cable's endLoad.*), forceVelocity.* (to endLoadVelocity.*) and
 *   forceDamping.* = -dforce/dv (to endLoadDamping.*). No state: the outputs are functions of the
 *   inputs. Stable at any communication step (the mass is inside the implicit integrator).
 * integrateTranslation = true: the body integrates its own translation from the cable force
 *   (input cableForce.*, the cable's endForce.*, held constant over a step, Runge-Kutta substeps) and
 *   the cable follows its outputs position.* / velocity.* (bottomEnd 3, end.* inputs). The explicit
 *   coupling: stable only below a critical step (docs/cosimulation.md).
 *
 * Forces (relative water velocity u = current - v, Earth frame, z up):
 *   drag            F_d = 1/2 rho CdA |u| u                       (as the cable FMU's internal body)
 *   depressor lift  F_l = -1/2 rho CLA |u_h|^2 e_z                (u_h the horizontal part of u: a wing
 *                   of fixed attitude that keeps its angle of attack in the horizontal flow, lifting
 *                   down for CLA > 0)
 *   weight in water (rho V - m) g e_z                             (integrateTranslation only; in the
 *                   force-element coupling the cable FMU applies it from body.mass and body.volume)
 *   (m + ma) dv/dt = cableForce + F_d + F_l + (rho V - m) g e_z.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "partner.h"

/* |u| is evaluated as sqrt(|u|^2 + floor^2): smooth at rest, as the cable FMU's drag. */
static const double kDragVelocityFloor = 1e-6;

typedef struct TowedBodyData {
    /* parameters */
    double mass, addedMass, volume, CdA, CLA, waterDensity, gravity;
    double current[2];
    double integrateTranslation; /* Boolean */
    double position0[3], velocity0[3];
    double maxSubstep;
    /* inputs */
    double end[3], endVelocity[3], cableForce[3];
    /* states (integrateTranslation): position, velocity */
    double state[6];
    /* outputs */
    double position[3], velocity[3], acceleration[3];
    double force[3], forceVelocity[3], forceDamping[9];
} TowedBodyData;

/* Hydrodynamic force at velocity v and D = -dF/dv (row-major 3x3). */
static void hydrodynamic_force(const TowedBodyData* d, const double* v, double* F, double* D) {
    double u[3] = {d->current[0] - v[0], d->current[1] - v[1], -v[2]};
    double speed = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2] + kDragVelocityFloor * kDragVelocityFloor);
    double cd = 0.5 * d->waterDensity * d->CdA;
    double cl = 0.5 * d->waterDensity * d->CLA;
    for (int i = 0; i < 3; ++i) {
        F[i] = cd * speed * u[i];
        /* dF_d/dv = -cd (speed I + u u^T / speed) */
        for (int j = 0; j < 3; ++j) D[3 * i + j] = cd * ((i == j ? speed : 0.0) + u[i] * u[j] / speed);
    }
    F[2] -= cl * (u[0] * u[0] + u[1] * u[1]);
    /* dF_l,z/dv_j = 2 cl u_j (j = x, y): D_zj = -2 cl u_j */
    D[6] -= 2.0 * cl * u[0];
    D[7] -= 2.0 * cl * u[1];
}

static void acceleration(const TowedBodyData* d, const double* v, const double* cableForce, double* a) {
    double F[3], D[9];
    hydrodynamic_force(d, v, F, D);
    double inertia = d->mass + d->addedMass;
    double wet = (d->mass - d->waterDensity * d->volume) * d->gravity;
    for (int i = 0; i < 3; ++i) a[i] = (cableForce[i] + F[i]) / inertia;
    a[2] -= wet / inertia;
}

static int integrating(const TowedBodyData* d) { return d->integrateTranslation != 0.0; }

static void update_outputs(TowedBodyData* d) {
    const double* p = integrating(d) ? d->state : d->end;
    const double* v = integrating(d) ? d->state + 3 : d->endVelocity;
    for (int i = 0; i < 3; ++i) {
        d->position[i] = p[i];
        d->velocity[i] = v[i];
        d->forceVelocity[i] = v[i];
    }
    hydrodynamic_force(d, v, d->force, d->forceDamping);
    acceleration(d, v, d->cableForce, d->acceleration);
}

static int towed_body_check(const void* data, char* msg, size_t msgSize) {
    const TowedBodyData* d = data;
    if (d->mass + d->addedMass <= 0.0) {
        snprintf(msg, msgSize, "mass + addedMass = %g must be positive: the body's inertia", d->mass + d->addedMass);
        return 1;
    }
    return 0;
}

static int towed_body_initialize(void* data, const void* derived, double t0, char* msg, size_t msgSize) {
    (void)derived;
    (void)t0, (void)msg, (void)msgSize;
    TowedBodyData* d = data;
    for (int i = 0; i < 3; ++i) {
        d->state[i] = d->position0[i];
        d->state[3 + i] = d->velocity0[i];
    }
    update_outputs(d);
    return 0;
}

static void derivatives(const TowedBodyData* d, const double* x, double* dx) {
    for (int i = 0; i < 3; ++i) dx[i] = x[3 + i];
    acceleration(d, x + 3, d->cableForce, dx + 3);
}

static int towed_body_do_step(void* data, const void* derived, double t, double h, char* msg, size_t msgSize) {
    (void)derived;
    (void)t, (void)msg, (void)msgSize;
    TowedBodyData* d = data;
    if (integrating(d)) {
        int n = (int)ceil(h / d->maxSubstep - 1e-12);
        if (n < 1) n = 1;
        double dt = h / n, k1[6], k2[6], k3[6], k4[6], tmp[6];
        double* x = d->state;
        for (int s = 0; s < n; ++s) {
            derivatives(d, x, k1);
            for (int j = 0; j < 6; ++j) tmp[j] = x[j] + 0.5 * dt * k1[j];
            derivatives(d, tmp, k2);
            for (int j = 0; j < 6; ++j) tmp[j] = x[j] + 0.5 * dt * k2[j];
            derivatives(d, tmp, k3);
            for (int j = 0; j < 6; ++j) tmp[j] = x[j] + dt * k3[j];
            derivatives(d, tmp, k4);
            for (int j = 0; j < 6; ++j) x[j] += dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        }
    }
    update_outputs(d);
    return 0;
}

#define P(field, name, start, min, max, unit, why, description) \
    PM_PAR(TowedBodyData, field, name, start, min, max, unit, why, description)
#define I(field, name, unit, description) PM_IN(TowedBodyData, field, name, unit, description)
#define O(field, name, unit, feedthrough, description) PM_OUT(TowedBodyData, field, name, unit, feedthrough, description)
#define DAMPING(i, j, name) \
    O(forceDamping[3 * (i) + (j)], "forceDamping." name, "N.s/m", 1, \
      "-d(force." name ")/dv: row = force component, column = velocity component (to the cable's endLoadDamping)")

static const PMVariable kVariables[] = {
    P(mass, "mass", 400.0, 0.0, 1e8, "kg", "a mass cannot be negative", "Mass of the body in air"),
    P(addedMass, "addedMass", 100.0, 0.0, 1e8, "kg", "added mass cannot be negative", "Added mass (isotropic)"),
    P(volume, "volume", 0.1, 0.0, 1e5, "m3", "a volume cannot be negative", "Displaced volume"),
    P(CdA, "CdA", 0.3, 0.0, 1e4, "m2", "drag must dissipate", "Drag area: drag = 1/2 rho CdA |u| u"),
    P(CLA, "CLA", 0.0, -1e4, 1e4, "m2", "a lift area within +-1e4 m2",
      "Lift area of a depressor wing: lift = 1/2 rho CLA |u_h|^2 downwards (u_h horizontal flow)"),
    P(waterDensity, "waterDensity", 1025.0, 1e-3, 1e5, "kg/m3", "the water must have a positive density",
      "Sea water density"),
    P(gravity, "gravity", 9.81, 0.0, 100.0, "m/s2", "gravity within [0, 100] m/s2", "Gravitational acceleration"),
    P(current[0], "current.x", 0.0, -20.0, 20.0, "m/s", "a current within +-20 m/s", "x velocity of the uniform current"),
    P(current[1], "current.y", 0.0, -20.0, 20.0, "m/s", "a current within +-20 m/s", "y velocity of the uniform current"),
    PM_BOOL_PAR(TowedBodyData, integrateTranslation, "integrateTranslation", 0.0,
                "false: a force element, the cable FMU integrates the translation (bottomEnd 2, implicit); true: "
                "the body integrates its translation from cableForce (the cable's bottomEnd 3, explicit)"),
    P(position0[0], "position0.x", 0.0, -1e8, 1e8, "m", "a position on Earth", "Initial x (integrateTranslation)"),
    P(position0[1], "position0.y", 0.0, -1e8, 1e8, "m", "a position on Earth", "Initial y (integrateTranslation)"),
    P(position0[2], "position0.z", 0.0, -1e5, 1e5, "m", "a position on Earth", "Initial z (integrateTranslation)"),
    P(velocity0[0], "velocity0.x", 0.0, -100.0, 100.0, "m/s", "a velocity within +-100 m/s",
      "Initial x velocity (integrateTranslation)"),
    P(velocity0[1], "velocity0.y", 0.0, -100.0, 100.0, "m/s", "a velocity within +-100 m/s",
      "Initial y velocity (integrateTranslation)"),
    P(velocity0[2], "velocity0.z", 0.0, -100.0, 100.0, "m/s", "a velocity within +-100 m/s",
      "Initial z velocity (integrateTranslation)"),
    P(maxSubstep, "maxSubstep", 0.01, 1e-5, 10.0, "s", "a Runge-Kutta substep within [1e-5, 10] s",
      "Largest Runge-Kutta substep inside a communication step (integrateTranslation)"),
    I(end[0], "end.x", "m", "x of the cable's far end (cable endPosition.x; force element)"),
    I(end[1], "end.y", "m", "y of the cable's far end (cable endPosition.y)"),
    I(end[2], "end.z", "m", "z of the cable's far end (cable endPosition.z)"),
    I(endVelocity[0], "end.vx", "m/s", "x velocity of the cable's far end (cable endVelocity.x; force element)"),
    I(endVelocity[1], "end.vy", "m/s", "y velocity of the cable's far end (cable endVelocity.y)"),
    I(endVelocity[2], "end.vz", "m/s", "z velocity of the cable's far end (cable endVelocity.z)"),
    I(cableForce[0], "cableForce.x", "N", "x of the force of the cable on the body (cable endForce.x)"),
    I(cableForce[1], "cableForce.y", "N", "y of the force of the cable on the body (cable endForce.y)"),
    I(cableForce[2], "cableForce.z", "N", "z of the force of the cable on the body (cable endForce.z)"),
    O(position[0], "position.x", "m", 1, "x of the body (to the cable's end.x when integrateTranslation)"),
    O(position[1], "position.y", "m", 1, "y of the body"),
    O(position[2], "position.z", "m", 1, "z of the body"),
    O(velocity[0], "velocity.x", "m/s", 1, "x velocity of the body (to the cable's end.vx when integrateTranslation)"),
    O(velocity[1], "velocity.y", "m/s", 1, "y velocity of the body"),
    O(velocity[2], "velocity.z", "m/s", 1, "z velocity of the body"),
    O(acceleration[0], "acceleration.x", "m/s2", 1, "x acceleration of the body from all forces on it"),
    O(acceleration[1], "acceleration.y", "m/s2", 1, "y acceleration of the body"),
    O(acceleration[2], "acceleration.z", "m/s2", 1, "z acceleration of the body"),
    O(force[0], "force.x", "N", 1, "x of the hydrodynamic force (drag + lift) at forceVelocity (to the cable's endLoad.x)"),
    O(force[1], "force.y", "N", 1, "y of the hydrodynamic force (to the cable's endLoad.y)"),
    O(force[2], "force.z", "N", 1, "z of the hydrodynamic force (to the cable's endLoad.z)"),
    O(forceVelocity[0], "forceVelocity.x", "m/s", 1, "x of the velocity at which force is evaluated (to endLoadVelocity.x)"),
    O(forceVelocity[1], "forceVelocity.y", "m/s", 1, "y of the velocity at which force is evaluated"),
    O(forceVelocity[2], "forceVelocity.z", "m/s", 1, "z of the velocity at which force is evaluated"),
    DAMPING(0, 0, "xx"), DAMPING(0, 1, "xy"), DAMPING(0, 2, "xz"),
    DAMPING(1, 0, "yx"), DAMPING(1, 1, "yy"), DAMPING(1, 2, "yz"),
    DAMPING(2, 0, "zx"), DAMPING(2, 1, "zy"), DAMPING(2, 2, "zz"),
};

const PMModel kPartnerModel = {
    "TowedBody",
    "Towed body (towfish, depressor): drag, depressor lift and weight of a point body; a force element for the "
    "cable FMU's implicit far end, or a body that integrates its own translation",
    sizeof(TowedBodyData),
    kVariables,
    sizeof kVariables / sizeof kVariables[0],
    towed_body_check,
    towed_body_initialize,
    towed_body_do_step,
    NULL,
    NULL,
};
