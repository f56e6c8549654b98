// The residual and the Jacobian never allocate. This test binary counts every C++
// allocation (global operator new replaced below) while the integrator's two callbacks run, and
// while whole communication steps run (IDA itself allocates nothing per step; SUNDIALS is C and
// does not go through operator new, so only our code is counted).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <new>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "line/simulation.h"

namespace {
long g_allocations = 0;
bool g_counting = false;
}  // namespace

void* operator new(std::size_t size) {
    if (g_counting) ++g_allocations;
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace uc;

namespace {

// A scene that exercises every term: seabed contact with friction, drag in a current, bending,
// added mass, torque, a towed body, tension-only chain law, an irregular sea (its kinematics from the
// polynomials, with or without Wheeler stretching).
UCParams busy_scene(int stretching) {
    UCParams p;
    uc_params_default(&p);
    p.enableSeabed = 1;
    p.waterDepth = 250.0;
    p.seabedFriction = 0.3;
    p.enableTorsion = 1;
    p.torqueMode = UC_TORQUE_PRESCRIBED;
    p.enableCompression = 0;
    p.bottomEnd = UC_BOTTOM_TOWED_BODY;
    p.bodyMass = 500.0;
    p.bodyVolume = 0.1;
    p.bodyCdA = 0.5;
    p.fatigueArea = 1e-3;  // the online rainflow count after every internal step
    p.wavesMode = 2;
    p.wavesHeight = 2.0;
    p.wavesPeriod = 8.0;
    p.wavesNComponents = 100;
    p.wavesStretching = stretching;
    return p;
}

long count_allocations(const std::function<void()>& work) {
    g_allocations = 0;
    g_counting = true;
    work();
    g_counting = false;
    return g_allocations;
}

}  // namespace

TEST(NoAllocation, ResidualAndJacobianNeverAllocate) {
    CableSimulation sim(busy_scene(1));
    UCInputs in{};
    in.towVelocity[0] = 1.0;
    in.current[0] = 0.2;
    in.torque = 50.0;
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    ASSERT_TRUE(sim.step(0.0, 0.5, in, error)) << error;  // a state with motion
    SecondOrderSystem& system = sim;
    std::vector<double> q, v, a;
    sim.free_state(q, v, a);
    const size_t n = q.size();
    std::vector<double> y(2 * n), yp(2 * n), r(2 * n);
    for (size_t j = 0; j < n; ++j) {
        y[2 * j] = q[j];
        y[2 * j + 1] = v[j];
        yp[2 * j] = v[j];
        yp[2 * j + 1] = a[j];
    }
    double sum = 0.0;
    auto sink = [&](int, int, double dq, double dv, double da) { sum += dq + dv + da; };
    const long allocations = count_allocations([&] {
        for (int k = 0; k < 3; ++k) {
            system.residual(0.5, y.data(), yp.data(), r.data());
            system.jacobian(0.5, y.data(), yp.data(), SecondOrderSystem::EntrySink(sink));
        }
    });
    EXPECT_EQ(allocations, 0);
    EXPECT_TRUE(std::isfinite(sum));
}

namespace {

void expect_steps_without_allocation(const UCParams& p) {
    CableSimulation sim(p);
    UCInputs in{};
    in.towVelocity[0] = 1.0;
    std::string error;
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    ASSERT_TRUE(sim.step(0.0, 0.5, in, error)) << error;  // the integrator's first restart
    bool ok = true;
    const long allocations = count_allocations([&] {
        for (int k = 1; k < 20; ++k) {
            in.tow[0] = 0.5 * k;
            ok = ok && sim.step(0.5 * k, 0.5, in, error);
        }
    });
    ASSERT_TRUE(ok) << error;
    EXPECT_EQ(allocations, 0);
    EXPECT_GT(sim.outputs().fatigueDamage, 0.0);  // the counter ran
    EXPECT_GT(sim.outputs().towTensionMax, sim.outputs().towTensionMin);
}

}  // namespace

TEST(NoAllocation, CommunicationStepsDoNotAllocate) { expect_steps_without_allocation(busy_scene(0)); }

TEST(NoAllocation, CommunicationStepsWithProjectedErrorControlDoNotAllocate) {
    UCParams p = busy_scene(0);
    p.projectedErrorControl = 1;
    expect_steps_without_allocation(p);
}

// The water pushed by the importer (water.source 1): after the first step, the positions read and the water
// set before every step allocate nothing, and neither do the steps.
TEST(NoAllocation, StepsWithPushedWaterDoNotAllocate) {
    UCParams p = busy_scene(0);
    p.wavesMode = 0;
    p.waterSource = UC_WATER_PUSHED;
    CableSimulation sim(p);
    const size_t n = sim.water_points();
    ASSERT_EQ(n, 3u * static_cast<size_t>(p.nElements));
    std::vector<double> buffer(9 * n, 0.0);
    double* x = buffer.data() + 6 * n;
    const double* const u[3] = {buffer.data(), buffer.data() + n, buffer.data() + 2 * n};
    const double* const a[3] = {buffer.data() + 3 * n, buffer.data() + 4 * n, buffer.data() + 5 * n};
    auto push = [&](double t) {  // a current along x that grows with depth and time, accelerating
        sim.water_positions(x, x + n, x + 2 * n);
        for (size_t i = 0; i < n; ++i) {
            buffer[i] = 0.2 + 0.001 * t - 1e-4 * x[2 * n + i];
            buffer[3 * n + i] = 0.001;
        }
        sim.set_water(t, u, a);
    };
    UCInputs in{};
    in.towVelocity[0] = 1.0;
    in.torque = 50.0;
    std::string error;
    push(0.0);
    ASSERT_TRUE(sim.initialize(0.0, in, error)) << error;
    push(0.0);
    ASSERT_TRUE(sim.step(0.0, 0.5, in, error)) << error;
    bool ok = true;
    const long allocations = count_allocations([&] {
        for (int k = 1; k < 20; ++k) {
            in.tow[0] = 0.5 * k;
            push(0.5 * k);
            ok = ok && sim.step(0.5 * k, 0.5, in, error);
        }
    });
    ASSERT_TRUE(ok) << error;
    EXPECT_EQ(allocations, 0);
    EXPECT_GT(sim.outputs().towTensionMax, sim.outputs().towTensionMin);
}
