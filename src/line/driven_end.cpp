// driven_end.cpp - a driven end (the tow point; the far end of bottomEnd 3): its quintic over a step from
// the master's inputs, and how far two acceleration inputs disagree with the velocities.
#include <algorithm>
#include <cmath>

#include "line/simulation.h"
#include "line/simulation_internal.h"

namespace uc {

namespace {

// The jerk of a driven end at the current inputs, from the acceleration inputs of this step and
// the previous one (both given by the master), trusted per component only as far as the
// velocity inputs confirm it: an acceleration that changes linearly over the previous step
// changes the velocity by the trapezoid h (a + aLast) / 2. Where it does not (an acceleration
// that jumped, as at the start or end of a ramp), extrapolating the jerk would overshoot; the
// weight falls linearly from 1 to 0 as the trapezoid's miss grows to half of h |a - aLast| / 2
// (a jump at a communication point misses by all of it, a smooth heave sampled 10 times per
// period by 5 %).
Vec3 jerk_estimate(const Vec3& a, const Vec3& aLast, const Vec3& v, const Vec3& vLast, double hLast) {
    Vec3 j = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
        const double da = a[k] - aLast[k];
        const double scale = 0.5 * hLast * std::fabs(da);
        if (!(scale > 0.0)) continue;
        const double miss = std::fabs(v[k] - vLast[k] - 0.5 * hLast * (a[k] + aLast[k]));
        const double weight = std::max(0.0, 1.0 - 2.0 * miss / scale);
        j[k] = weight * da / hLast;
    }
    return j;
}

}  // namespace

double acceleration_disagreement(double a0, double a1, double dv, double h) {
    if (!(h > 0.0)) return 0.0;
    const double mean = dv / h;
    const double low = std::min(a0, a1), high = std::max(a0, a1);
    const double miss = mean < low ? low - mean : mean > high ? mean - high : 0.0;
    const double allowance =
        UC_ACCELERATION_FLOOR + UC_ACCELERATION_MARGIN * std::max({std::fabs(mean), std::fabs(a0), std::fabs(a1)});
    return miss > allowance ? miss : 0.0;
}

void DrivenEndState::reset(const Vec3& p, const Vec3& v, const Vec3& a, bool accelerationGiven) {
    Eigen::Map<Vec3>{position} = p;
    Eigen::Map<Vec3>{velocity} = v;
    Eigen::Map<Vec3>{acceleration} = a;
    Eigen::Map<Vec3>{lastVelocityInput} = v;
    Eigen::Map<Vec3>{lastAccelerationInput} = a;
    lastAccelerationGiven = accelerationGiven ? 1.0 : 0.0;
}

TowTrajectory DrivenEndState::next(double t, double h, double lastStep, const Vec3& positionInput,
                                   const Vec3& velocityInput, const Vec3& accelerationInput, int accelerationFlags,
                                   Vec3& a) const {
    const Vec3 lastVelocityInput = vec(this->lastVelocityInput), lastAccelerationInput = vec(this->lastAccelerationInput);
    const bool lastAccelerationGiven = this->lastAccelerationGiven != 0.0;
    // The acceleration is the master's input derivative when given; otherwise the difference of
    // the last two velocity inputs (0 before there are two), so that an accelerating tow sampled
    // at communication points is still followed smoothly. A component set as the input tow.a* (not
    // an input derivative) to 0 here and at the previous communication point while its velocity
    // input changed over the step (beyond acceleration_disagreement's allowance) is a master
    // that fills every input with 0, not an acceleration: it is estimated from the velocities too
    // (docs/interface.md, "How the FMU reads a driven end").
    const bool accelerationGiven = accelerationFlags != 0;
    const Vec3 estimate = lastStep > 0.0 ? Vec3((velocityInput - lastVelocityInput) / lastStep) : Vec3::Zero();
    a = accelerationGiven ? accelerationInput : estimate;  // what the next step remembers
    Vec3 used = a;
    bool zeroHeld[3] = {false, false, false};
    if (accelerationGiven && lastAccelerationGiven && lastStep > 0.0) {
        for (int k = 0; k < 3; ++k) {
            zeroHeld[k] = (accelerationFlags & UC_ACCELERATION_AS_INPUT(k)) != 0 && accelerationInput[k] == 0.0 &&
                          lastAccelerationInput[k] == 0.0 &&
                          acceleration_disagreement(0.0, 0.0, velocityInput[k] - lastVelocityInput[k], lastStep) > 0.0;
            if (zeroHeld[k]) used[k] = estimate[k];
        }
    }
    Vec3 j = accelerationGiven && lastAccelerationGiven && lastStep > 0.0
                 ? jerk_estimate(used, lastAccelerationInput, velocityInput, lastVelocityInput, lastStep)
                 : Vec3::Zero();
    for (int k = 0; k < 3; ++k)
        if (zeroHeld[k]) j[k] = 0.0;
    const Vec3 p1 = positionInput + h * (velocityInput + h * (0.5 * used + h * (j / 6.0)));
    const Vec3 v1 = velocityInput + h * (used + h * (0.5 * j));
    const Vec3 a1 = used + h * j;
    return TowTrajectory::quintic(t, h, p(), v(), this->a(), p1, v1, a1);
}

void DrivenEndState::advance(const TowTrajectory& traj, const Vec3& velocityInput, const Vec3& a,
                             bool accelerationGiven) {
    Eigen::Map<Vec3>{position} = traj.p1;
    Eigen::Map<Vec3>{velocity} = traj.v1;
    Eigen::Map<Vec3>{acceleration} = traj.a1;
    Eigen::Map<Vec3>{lastVelocityInput} = velocityInput;
    Eigen::Map<Vec3>{lastAccelerationInput} = a;
    lastAccelerationGiven = accelerationGiven ? 1.0 : 0.0;
}

void DrivenEnd::reset(const Vec3& p, const Vec3& v, const Vec3& a, bool accelerationGiven) {
    position = p;
    velocity = v;
    acceleration = a;
    lastVelocityInput = v;
    lastAccelerationInput = a;
    lastAccelerationGiven = accelerationGiven;
}

TowTrajectory DrivenEnd::next(double t, double h, double lastStep, const Vec3& positionInput,
                              const Vec3& velocityInput, const Vec3& accelerationInput, int accelerationGiven,
                              Vec3& a) const {
    DrivenEndState s;
    save(s);
    return s.next(t, h, lastStep, positionInput, velocityInput, accelerationInput, accelerationGiven, a);
}

void DrivenEnd::advance(const TowTrajectory& traj, const Vec3& velocityInput, const Vec3& a, bool accelerationGiven) {
    DrivenEndState s;
    save(s);
    s.advance(traj, velocityInput, a, accelerationGiven);
    load(s);
}

void DrivenEnd::save(DrivenEndState& s) const {
    for (int k = 0; k < 3; ++k) {
        s.position[k] = position[k];
        s.velocity[k] = velocity[k];
        s.acceleration[k] = acceleration[k];
        s.lastVelocityInput[k] = lastVelocityInput[k];
        s.lastAccelerationInput[k] = lastAccelerationInput[k];
    }
    s.lastAccelerationGiven = lastAccelerationGiven ? 1.0 : 0.0;
}

void DrivenEnd::load(const DrivenEndState& s) {
    position = vec(s.position);
    velocity = vec(s.velocity);
    acceleration = vec(s.acceleration);
    lastVelocityInput = vec(s.lastVelocityInput);
    lastAccelerationInput = vec(s.lastAccelerationInput);
    lastAccelerationGiven = s.lastAccelerationGiven != 0.0;
}

}  // namespace uc
