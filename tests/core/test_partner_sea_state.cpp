// The partner FMUs' sea state (C, fmu/partners/vessel_rao/sea_state.c) against the cable's (C++,
// src/terms/waves.cpp): given the same waves.* parameters both must generate the same components (amplitudes,
// frequencies, wavenumbers, SplitMix64 phases) and so the same elevation, so that a vessel driven by its
// RAOs and the cable see one sea. The two evaluate the same expressions in the same order: agreement to
// round-off, 1e-12 relative (elevations: of the wave height).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "terms/waves.h"

extern "C" {
#include "sea_state.h"
}

using namespace uc;

namespace {

struct Case {
    int mode;
    double height, period, gamma, direction;
    int seed, nComponents;
    double depth, rampTime;
};

UCParams cable_params(const Case& c) {
    UCParams p;
    uc_params_default(&p);
    p.wavesMode = c.mode;
    p.wavesHeight = c.height;
    p.wavesPeriod = c.period;
    p.wavesGamma = c.gamma;
    p.wavesDirection = c.direction;
    p.wavesSeed = c.seed;
    p.wavesNComponents = c.nComponents;
    p.wavesRampTime = c.rampTime;
    p.waterDepth = c.depth;
    return p;
}

PMWaves partner_waves(const Case& c, double gravity) {
    PMWaves w;
    w.mode = c.mode;
    w.height = c.height;
    w.period = c.period;
    w.gamma = c.gamma;
    w.direction = c.direction;
    w.seed = static_cast<uint64_t>(c.seed);
    w.nComponents = c.nComponents;
    w.rampTime = c.rampTime;
    w.depth = c.depth;
    w.gravity = gravity;
    return w;
}

const Case kCases[] = {
    {1, 2.0, 8.0, 3.3, 0.0, 1, 200, 1000.0, 0.0},       // regular, deep
    {1, 1.5, 12.0, 3.3, 0.7, 1, 200, 30.0, 20.0},       // regular, finite depth, ramped
    {2, 3.0, 10.0, 3.3, 0.0, 1, 200, 1000.0, 0.0},      // the default JONSWAP sea
    {2, 3.0, 10.0, 3.3, -2.1, 0, 200, 1000.0, 0.0},     // seed 0
    {2, 4.5, 12.0, 1.0, 1.2, 42, 64, 80.0, 30.0},       // Pierson-Moskowitz, shallow, ramped
    {2, 2.0, 7.0, 5.0, 3.0, 999999999, 1000, 500.0, 0.0},
};

}  // namespace

TEST(PartnerSeaState, SplitMix64IsTheCablesGenerator) {
    for (unsigned long long seed : {0ULL, 1ULL, 42ULL, 999999999ULL}) {
        SplitMix64 cable(seed);
        uint64_t partner = seed;
        for (int i = 0; i < 1000; ++i) {
            ASSERT_EQ(cable.uniform(), pm_splitmix64_uniform(&partner)) << seed << " " << i;
        }
    }
}

TEST(PartnerSeaState, ComponentsAndElevationEqualTheCables) {
    for (const Case& c : kCases) {
        const UCParams p = cable_params(c);
        SeaState sea;
        std::string error;
        ASSERT_TRUE(sea.build(p, error)) << error;
        const PMWaves w = partner_waves(c, p.gravity);
        const size_t n = pm_sea_size(&w);
        ASSERT_EQ(n, sea.components().size()) << c.mode << " " << c.seed;
        std::vector<PMWaveComponent> mine(n);
        char msg[300];
        ASSERT_EQ(pm_sea_components(&w, mine.data(), msg, sizeof msg), 0) << msg;
        for (size_t i = 0; i < n; ++i) {
            const WaveComponent& ref = sea.components()[i];
            EXPECT_NEAR(mine[i].amplitude, ref.amplitude, 1e-12 * ref.amplitude) << i;
            EXPECT_NEAR(mine[i].omega, ref.omega, 1e-12 * ref.omega) << i;
            EXPECT_NEAR(mine[i].k, ref.k, 1e-12 * ref.k) << i;
            EXPECT_NEAR(mine[i].phase, ref.phase, 1e-12) << i;
        }
        for (double t : {0.0, 3.7, 11.0, 25.0, 1234.5}) {
            const double origin = sea.elevation(0.0, 0.0, t);
            EXPECT_NEAR(pm_sea_elevation(mine.data(), n, c.direction, c.rampTime, 0.0, 0.0, t), origin,
                        1e-12 * c.height)
                << "mode " << c.mode << " seed " << c.seed << " t " << t;
            const double away = sea.elevation(-40.0, 17.0, t);
            EXPECT_NEAR(pm_sea_elevation(mine.data(), n, c.direction, c.rampTime, -40.0, 17.0, t), away,
                        1e-12 * c.height)
                << "mode " << c.mode << " seed " << c.seed << " t " << t;
        }
    }
}

TEST(PartnerSeaState, CalmAndBreakingSeasAsTheCable) {
    Case calm = kCases[0];
    calm.mode = 0;
    PMWaves w = partner_waves(calm, 9.81);
    EXPECT_EQ(pm_sea_size(&w), 0u);
    calm.mode = 2;
    calm.height = 0.0;
    w = partner_waves(calm, 9.81);
    EXPECT_EQ(pm_sea_size(&w), 0u);

    Case steep = kCases[0];
    steep.height = 20.0;  // H / lambda = 20 / 100 m at 8 s
    const UCParams p = cable_params(steep);
    SeaState sea;
    std::string error;
    ASSERT_FALSE(sea.build(p, error));
    w = partner_waves(steep, p.gravity);
    PMWaveComponent c;
    char msg[300];
    ASSERT_NE(pm_sea_components(&w, &c, msg, sizeof msg), 0);
    EXPECT_EQ(std::string(msg), error);
}

TEST(PartnerSeaState, RampDerivativesAreThoseOfTheRamp) {
    const double T = 20.0, h = 1e-4;
    for (double t : {0.5, 7.0, 13.0, 19.5}) {
        double f, df, ddf, fp, dfp, ddfp, fm, dfm, ddfm;
        pm_sea_ramp(T, t, &f, &df, &ddf);
        pm_sea_ramp(T, t + h, &fp, &dfp, &ddfp);
        pm_sea_ramp(T, t - h, &fm, &dfm, &ddfm);
        // central differences: truncation (pi / T)^3 h^2 / 6 ~ 6e-12, round-off 1e-16 / h ~ 1e-12
        EXPECT_NEAR(df, (fp - fm) / (2 * h), 1e-10) << t;
        EXPECT_NEAR(ddf, (dfp - dfm) / (2 * h), 1e-10) << t;
    }
}
