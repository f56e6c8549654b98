// A current given as data (docs/waves.md, "A current given as data"): MoorDyn's current profile changing
// in time (Currents 2) and its grid in x, y, z and t (Currents 5), read from their text, interpolated as
// MoorDyn does, and applied where the current enters a line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "api/cable_api.h"
#include "deck/line_file.h"
#include "line/simulation.h"
#include "terms/current_grid.h"
#include "terms/hydrodynamics.h"

using namespace uc;

namespace {

// A field linear in x, y, z and t: trilinear interpolation in space and linear in time reproduce it
// exactly inside the grid (to round-off).
Vec3 linear_field(const Vec3& r, double t) {
    return Vec3(0.3 + 0.01 * r.x() - 0.02 * r.y() + 0.004 * r.z() + 0.05 * t,
                -0.1 + 0.003 * r.x() + 0.01 * r.y() - 0.006 * r.z() - 0.02 * t,
                0.002 * r.x() + 0.001 * r.z() + 0.01 * t);
}
const Mat3 kGradient = (Mat3() << 0.01, -0.02, 0.004, 0.003, 0.01, -0.006, 0.002, 0.0, 0.001).finished();
const Vec3 kRate(0.05, -0.02, 0.01);

// The text of a current_profile_4d.txt of the field f on the axes (rows in the order of MoorDyn's example).
template <class F>
std::string text_4d(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                    const std::vector<double>& t, F f) {
    std::ostringstream s;
    s.precision(17);
    s << x.size() << " " << y.size() << " " << z.size() << " " << t.size() << "\n";
    for (const auto* axis : {&x, &y, &z, &t}) {
        for (double v : *axis) s << v << " ";
        s << "\n";
    }
    for (double xi : x)
        for (double yi : y)
            for (double zi : z)
                for (double ti : t) {
                    const Vec3 u = f(Vec3(xi, yi, zi), ti);
                    s << xi << " " << yi << " " << zi << " " << ti << " " << u.x() << " " << u.y() << " " << u.z() << "\n";
                }
    return s.str();
}

// The text of a current_profile_dynamic.txt of the profile f(z, t) (ux, uy; depths on line 5, rows from 7).
template <class F>
std::string text_dynamic(const std::vector<double>& z, const std::vector<double>& t, F f) {
    std::ostringstream s;
    s.precision(17);
    s << "--- MoorDyn dynamic currents file ---\nheader\n2\n3\n";
    for (double zi : z) s << zi << " ";
    s << "\n\n";
    for (double ti : t) {
        s << ti;
        for (double zi : z) s << " " << f(zi, ti).x();
        for (double zi : z) s << " " << f(zi, ti).y();
        s << "\n";
    }
    return s.str();
}

const std::vector<double> kX{-40.0, -25.0, -10.0, 0.0, 12.0}, kY{-3.0, 1.0, 4.0}, kZ{-50.0, -30.0, -22.0, -5.0, 0.0},
    kT{0.0, 2.0, 4.0, 6.0};

}  // namespace

TEST(CurrentGrid, AFieldLinearInSpaceAndTimeIsReproducedWithItsGradientAndRate) {
    std::string error;
    const auto grid = CurrentGrid::read(5, text_4d(kX, kY, kZ, kT, linear_field), error);
    ASSERT_TRUE(grid) << error;
    for (const auto& [r, t] : {std::pair<Vec3, double>{Vec3(-33.3, 0.2, -41.0), 0.7}, {Vec3(-10.0, 1.0, -22.0), 2.0},
                               {Vec3(5.5, 3.9, -1.25), 5.99}, {Vec3(-12.0, -2.5, -29.0), 3.3}}) {
        Vec3 u, rate;
        Mat3 du, drate;
        EXPECT_EQ(grid->at(r, t, u, &du, &rate, &drate), 0u);
        EXPECT_LT((u - linear_field(r, t)).norm(), 1e-14) << r.transpose() << " t " << t;
        // on a node the interval below it is taken (MoorDyn's): the slopes are the same for a linear field
        EXPECT_LT((du - kGradient).norm(), 1e-14) << r.transpose();
        EXPECT_LT((rate - kRate).norm(), 1e-14) << r.transpose();
        EXPECT_LT(drate.norm(), 1e-14);
    }
}

TEST(CurrentGrid, OutsideTheGridTheEdgeValuesAreHeldAndReported) {
    std::string error;
    const auto grid = CurrentGrid::read(5, text_4d(kX, kY, kZ, kT, linear_field), error);
    ASSERT_TRUE(grid) << error;
    Vec3 u, rate;
    Mat3 du;
    // below the grid's deepest z and beyond its x: the values of the nearest edge, no slope across it
    EXPECT_EQ(grid->at(Vec3(-60.0, 0.0, -70.0), 1.0, u, &du, &rate), unsigned(CurrentGrid::kOutsideSpace));
    EXPECT_LT((u - linear_field(Vec3(-40.0, 0.0, -50.0), 1.0)).norm(), 1e-14);
    EXPECT_EQ(du.col(0).norm(), 0.0);
    EXPECT_EQ(du.col(2).norm(), 0.0);
    EXPECT_LT((du.col(1) - kGradient.col(1)).norm(), 1e-14);
    // after the last sample: held at it, no rate
    EXPECT_EQ(grid->at(Vec3(0.0, 0.0, -10.0), 9.0, u, &du, &rate), unsigned(CurrentGrid::kAfterRecord));
    EXPECT_LT((u - linear_field(Vec3(0.0, 0.0, -10.0), 6.0)).norm(), 1e-14);
    EXPECT_EQ(rate.norm(), 0.0);
    // at the last sample exactly: inside
    EXPECT_EQ(grid->at(Vec3(0.0, 0.0, -10.0), 6.0, u), 0u);
}

TEST(CurrentGrid, GradientsEqualFiniteDifferencesOfACurvedField) {
    // a field the grid does not hold exactly: its interpolant's own gradients against differences
    auto f = [](const Vec3& r, double t) {
        return Vec3(std::sin(0.1 * r.x()) * std::cos(0.05 * r.z()) + 0.1 * t * t, r.y() * r.y() * 0.01 + 0.02 * r.z() * t,
                    0.001 * r.x() * r.z());
    };
    std::string error;
    const auto grid = CurrentGrid::read(5, text_4d(kX, kY, kZ, kT, f), error);
    ASSERT_TRUE(grid) << error;
    const Vec3 r(-17.0, 2.2, -13.0);
    const double t = 3.1, h = 1e-5;
    Vec3 u, rate, up, um, rp, rm;
    Mat3 du, drate;
    grid->at(r, t, u, &du, &rate, &drate);
    for (int a = 0; a < 3; ++a) {
        Vec3 dr = Vec3::Zero();
        dr[a] = h;
        grid->at(r + dr, t, up, nullptr, &rp);
        grid->at(r - dr, t, um, nullptr, &rm);
        EXPECT_LT((du.col(a) - (up - um) / (2 * h)).norm(), 1e-9) << "axis " << a;
        EXPECT_LT((drate.col(a) - (rp - rm) / (2 * h)).norm(), 1e-9) << "axis " << a;
    }
    grid->at(r, t + h, up);
    grid->at(r, t - h, um);
    EXPECT_LT((rate - (up - um) / (2 * h)).norm(), 1e-9);
}

TEST(CurrentGrid, AProfileChangingInTimeIsReadAsMoorDynReadsIt) {
    auto f = [](double z, double t) { return Vec3(0.5 + 0.01 * z + 0.1 * t, -0.2 - 0.003 * z + 0.05 * t, 0.0); };
    std::string error;
    const auto grid = CurrentGrid::read(2, text_dynamic({-41.0, -20.0, -3.0, 0.0}, {0.0, 1.0, 2.0, 3.0}, f), error);
    ASSERT_TRUE(grid) << error;
    Vec3 u, rate;
    Mat3 du;
    // the same at every x and y: a profile
    for (const Vec3& r : {Vec3(-400.0, 7.0, -30.0), Vec3(25.0, -3.0, -30.0)}) {
        EXPECT_EQ(grid->at(r, 1.7, u, &du, &rate), 0u);
        EXPECT_LT((u - f(-30.0, 1.7)).norm(), 1e-14);
        EXPECT_LT((du.col(2) - Vec3(0.01, -0.003, 0.0)).norm(), 1e-14);
        EXPECT_EQ(du.col(0).norm() + du.col(1).norm(), 0.0);
        EXPECT_LT((rate - Vec3(0.1, 0.05, 0.0)).norm(), 1e-14);
    }
    // below the deepest row (a seabed at 50 m): the deepest row's values, as MoorDyn holds them
    EXPECT_EQ(grid->at(Vec3(0.0, 0.0, -50.0), 1.0, u), unsigned(CurrentGrid::kOutsideSpace));
    EXPECT_LT((u - f(-41.0, 1.0)).norm(), 1e-14);
}

TEST(CurrentGrid, TimesAreResampledAtTheSmallestIntervalFromZeroAsMoorDynDoes) {
    // rows at 0, 1.5 and 2.5 s: MoorDyn samples at 0, 1 and 2 s (dtWave = 1 s, up to floor(2.5 / 1) = 2):
    // values 0, 2 and 2 (the record interpolated there), the row at 2.5 s is not reached
    auto f = [](double, double t) { return Vec3(t == 0.0 ? 0.0 : t == 1.5 ? 3.0 : 1.0, 0.0, 0.0); };
    std::string error;
    const auto grid = CurrentGrid::read(2, text_dynamic({-10.0, 0.0}, {0.0, 1.5, 2.5}, f), error);
    ASSERT_TRUE(grid) << error;
    EXPECT_EQ(grid->dt(), 1.0);
    EXPECT_EQ(grid->nt(), 3);
    Vec3 u;
    grid->at(Vec3(0, 0, -5), 1.0, u);
    EXPECT_DOUBLE_EQ(u.x(), 2.0);
    grid->at(Vec3(0, 0, -5), 1.5, u);
    EXPECT_DOUBLE_EQ(u.x(), 2.0);
    EXPECT_EQ(grid->at(Vec3(0, 0, -5), 2.4, u), unsigned(CurrentGrid::kAfterRecord));
    EXPECT_DOUBLE_EQ(u.x(), 2.0);
}

TEST(CurrentGrid, FilesThatAreNotSuchDataAreRefusedNamingTheLine) {
    std::string error;
    std::string text = text_4d({0.0, 1.0}, {0.0}, {-1.0, 0.0}, {0.0}, linear_field);
    EXPECT_TRUE(CurrentGrid::read(5, text, error)) << error;
    // a missing node
    EXPECT_FALSE(CurrentGrid::read(5, text.substr(0, text.rfind('\n', text.size() - 2) + 1), error));
    EXPECT_NE(error.find("3 rows of nodes, the grid 2 x 1 x 2 x 1 has 4"), std::string::npos) << error;
    // a coordinate off the axis
    std::string off = text;
    off.replace(off.find("\n0 0 -1 0 "), 10, "\n0.5 0 -1 0 ");
    EXPECT_FALSE(CurrentGrid::read(5, off, error));
    EXPECT_NE(error.find("line 6: x = 0.5 is not a value of the x axis on line 2"), std::string::npos) << error;
    // axes not increasing
    EXPECT_FALSE(CurrentGrid::read(5, "2 1 1 1\n1 0\n0\n0\n0\n", error));
    EXPECT_NE(error.find("line 2: x = 0 after 1"), std::string::npos) << error;
    // a dynamic row of the wrong length, a word
    const std::string dyn = text_dynamic({-5.0, 0.0}, {0.0, 1.0}, [](double, double) { return Vec3(1, 0, 0); });
    EXPECT_FALSE(CurrentGrid::read(2, dyn + "2 1 1 1\n", error));
    EXPECT_NE(error.find("line 9: 4 numbers"), std::string::npos) << error;
    EXPECT_FALSE(CurrentGrid::read(2, dyn + "3 x 1\n", error));
    EXPECT_NE(error.find("line 9: 'x' is not a number"), std::string::npos) << error;
    EXPECT_FALSE(CurrentGrid::read(3, dyn, error));
}

namespace {

UCParams hanging_line() {
    UCParams p;
    uc_params_default(&p);
    p.nElements = 8;
    p.length = 60.0;
    return p;
}

// A hanging line in a uniform current given as inputs, and in the same current given as data: the same
// water everywhere, so the same line.
void run(CableSimulation& s, double current, double rate, int steps, double h, std::vector<double>& tension) {
    std::string error;
    UCInputs in{};
    uc_inputs_default(&in);
    in.current[0] = current;
    ASSERT_TRUE(s.initialize(0.0, in, error)) << error;
    tension.push_back(s.outputs().towTension);
    for (int k = 0; k < steps; ++k) {
        in.current[0] = current + rate * s.time();
        in.currentRate[0] = rate;
        ASSERT_TRUE(s.step(s.time(), h, in, error)) << error;
        tension.push_back(s.outputs().towTension);
    }
}

}  // namespace

TEST(CurrentGridLine, StartsInAndFollowsTheCurrentAsTheInputsCurrentDoes) {
    const UCParams p = hanging_line();
    // 0.4 m/s along x growing by 0.02 m/s^2: as data linear in time (and uniform), as inputs with their rate
    const std::vector<double> z{-200.0, 10.0}, t{0.0, 10.0, 20.0};
    auto f = [](double, double time) { return Vec3(0.4 + 0.02 * time, 0.0, 0.0); };
    std::string error;
    const auto grid = CurrentGrid::read(2, text_dynamic(z, t, f), error);
    ASSERT_TRUE(grid) << error;
    CableSimulation byInputs(p), byData(p);
    byData.set_current_grid(grid);
    std::vector<double> a, b;
    run(byInputs, 0.4, 0.02, 10, 1.0, a);
    run(byData, 0.0, 0.0, 10, 1.0, b);
    ASSERT_EQ(a.size(), b.size());
    // the statics at t = 0 in the same current: the same equilibrium to the static solver's round-off
    EXPECT_NEAR(b[0], a[0], 1e-9 * a[0]);
    EXPECT_GT(std::abs(b[0] - [&] {
                  CableSimulation calm(p);
                  std::vector<double> c;
                  run(calm, 0.0, 0.0, 0, 1.0, c);
                  return c[0];
              }()),
              1.0);  // and the current matters
    // the run: the same water each instant (the data's rate is the inputs' derivative): within the
    // integrator's tolerance (tensionTolerance 1e-3 of the tension scale)
    for (size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(b[k], a[k], 2e-3 * a[0]) << "step " << k;
}

TEST(CurrentGridLine, WarnsOnceWhenTheRunPassesTheLastSample) {
    const UCParams p = hanging_line();
    std::string error;
    const auto grid =
        CurrentGrid::read(2, text_dynamic({-200.0, 10.0}, {0.0, 1.0}, [](double, double t) { return Vec3(0.3 + 0.1 * t, 0, 0); }),
                          error);
    ASSERT_TRUE(grid) << error;
    CableSimulation s(p);
    s.set_current_grid(grid);
    std::vector<double> tension;
    UCInputs in{};
    uc_inputs_default(&in);
    ASSERT_TRUE(s.initialize(0.0, in, error)) << error;
    EXPECT_EQ(s.take_event(), "");
    ASSERT_TRUE(s.step(0.0, 0.5, in, error)) << error;
    EXPECT_EQ(s.take_event(), "");
    ASSERT_TRUE(s.step(0.5, 1.0, in, error)) << error;
    const std::string warning = s.take_event();
    EXPECT_NE(warning.find("warning: at t = 1.5 s the run passes the current's last sample (t = 1 s)"), std::string::npos)
        << warning;
    ASSERT_TRUE(s.step(1.5, 1.0, in, error)) << error;
    EXPECT_EQ(s.take_event(), "");  // once
}

TEST(CurrentGridLine, ALineWhoseDataWereNotGivenIsRefused) {
    UCParams p = hanging_line();
    p.currentsMode = 2;
    std::snprintf(p.currentsFile, sizeof p.currentsFile, "%s", "current_profile_dynamic.txt");
    CableSimulation s(p);
    std::string error;
    UCInputs in{};
    uc_inputs_default(&in);
    EXPECT_FALSE(s.initialize(0.0, in, error));
    EXPECT_NE(error.find("currents.mode = 2: the current's data (currents.file = 'current_profile_dynamic.txt') were not "
                         "given"),
              std::string::npos)
        << error;
}

TEST(CurrentGridLine, ParametersNameTheModeAndTheFile) {
    UCParams p = hanging_line();
    char msg[512];
    p.currentsMode = 3;
    EXPECT_NE(uc_params_check(&p, msg, sizeof msg), 0);
    EXPECT_NE(std::string(msg).find("currents.mode"), std::string::npos) << msg;
    p.currentsMode = 5;
    EXPECT_NE(uc_params_check(&p, msg, sizeof msg), 0);
    EXPECT_NE(std::string(msg).find("currents.mode = 5 needs the file of its data: currents.file is empty"),
              std::string::npos)
        << msg;
    p.currentsMode = 0;
    std::snprintf(p.currentsFile, sizeof p.currentsFile, "%s", "c.txt");
    EXPECT_NE(uc_params_check(&p, msg, sizeof msg), 0);
    EXPECT_NE(std::string(msg).find("currents.file = 'c.txt' is set with currents.mode = 0"), std::string::npos) << msg;
}
