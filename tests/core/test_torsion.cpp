// Torsion: the torque term against finite differences and Greenhill's buckling torque.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "api/cable_api.h"
#include "line/simulation.h"

using namespace uc;

namespace {

using uc::kPi;

// Hinged-hinged rod along x: tow point fixed at the origin, far end anchored at L (1 + T/EA),
// weightless (gravity 0), light drag for damping.
UCParams greenhill_rod(double tension) {
    UCParams p;
    uc_params_default(&p);
    p.length = 10;
    p.diameter = 0.02;
    p.massPerLength = 1;
    p.EA = 1e6;
    p.EI = 100;
    p.gravity = 0;
    p.Cdn = 1;
    p.Cdt = 0;
    // The buckled helix has wavenumbers (H +- sqrt(H^2 - 4 EI T)) / (2 EI), up to 2 /m at T = 400 N:
    // 20 elements (0.5 m) resolve it with ~6 elements per wavelength.
    p.nElements = 20;
    p.bottomEnd = UC_BOTTOM_ANCHORED;
    p.anchor[0] = p.length * (1 + tension / p.EA);
    p.anchor[1] = 0;
    p.anchor[2] = -50;
    p.initialDirection[0] = 1;
    p.initialDirection[2] = 0;
    p.enableTorsion = 1;
    p.torqueMode = UC_TORQUE_PRESCRIBED;
    p.axialDamping = 0.01 * p.EA;
    return p;
}

// Largest lateral deflection after 60 s under torque H, starting from a tiny bend (a lateral
// couple of 1e-6 EI/L applied only during the initial equilibrium).
double deflection_growth(double tension, double H) {
    UCParams p = greenhill_rod(tension);
    CableSimulation sim(p);
    UCInputs in{};
    in.tow[2] = -50;
    in.endCouple[1] = 1e-6 * p.EI / p.length;
    std::string error;
    if (!sim.initialize(0.0, in, error)) ADD_FAILURE() << error;
    auto lateral = [&] {
        double m = 0;
        for (int k = 0; k < UC_NUM_STATIONS; ++k)
            m = std::max(m, std::hypot(sim.outputs().shapeY[k], sim.outputs().shapeZ[k] + 50));
        return m;
    };
    const double initial = lateral();
    in.endCouple[1] = 0;
    in.torque = H;
    double worst = initial;
    for (int k = 0; k < 120 && worst < 1e3 * initial; ++k) {
        if (!sim.step(sim.time(), 0.5, in, error)) break;  // a buckled rod may fail to integrate: unstable
        worst = std::max(worst, lateral());
    }
    return worst / initial;
}

double critical_torque(double tension) {
    const double EI = 100, L = 10;
    const double exact = 2 * EI * std::sqrt(kPi * kPi / (L * L) + tension / EI);
    double lo = 0.8 * exact, hi = 1.2 * exact;
    for (int i = 0; i < 7; ++i) {
        const double mid = 0.5 * (lo + hi);
        (deflection_growth(tension, mid) > 100 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi) / exact;
}

}  // namespace

TEST(Greenhill, CriticalTorqueWithin1Percent) {
    for (double T : {0.0, 100.0, 400.0}) {
        const double ratio = critical_torque(T);
        std::printf("T = %g N: H_found / H_cr = %.4f\n", T, ratio);
        EXPECT_NEAR(ratio, 1.0, 0.01) << "T = " << T;
    }
}

TEST(Torsion, SwitchedOffIsBitIdenticalToTheTorqueFreeModel) {
    // enableTorsion 0 ignores the torque input; torqueMode 0 (swivel) carries no torque either.
    auto run = [](int enable, int mode, double torque) {
        UCParams p = greenhill_rod(100.0);
        p.enableTorsion = enable;
        p.torqueMode = mode;
        CableSimulation sim(p);
        UCInputs in{};
        in.tow[2] = -50;
        in.endCouple[1] = 1e-3;
        in.torque = torque;
        std::string error;
        EXPECT_TRUE(sim.initialize(0.0, in, error)) << error;
        in.towVelocity[1] = 0.01;
        for (int k = 0; k < 10; ++k) {
            in.tow[1] = 0.01 * 0.5 * k;
            EXPECT_TRUE(sim.step(sim.time(), 0.5, in, error)) << error;
        }
        return sim.outputs();
    };
    const UCOutputs off = run(0, UC_TORQUE_FREE, 0.0);
    const UCOutputs offWithInput = run(0, UC_TORQUE_PRESCRIBED, 50.0);
    const UCOutputs swivel = run(1, UC_TORQUE_FREE, 50.0);
    EXPECT_EQ(std::memcmp(&off, &offWithInput, sizeof off), 0);
    EXPECT_EQ(std::memcmp(&off, &swivel, sizeof off), 0);
    const UCOutputs on = run(1, UC_TORQUE_PRESCRIBED, 50.0);
    EXPECT_EQ(on.cableTorque, 50.0);
    EXPECT_NE(on.shapeZ[10], off.shapeZ[10]);  // the torque does act on a bent rod
}
