// The integrator's unpivoted band LU against the pivoting SUNDIALS band solver, and its refusal
// of matrices that need pivoting.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <sundials/sundials_context.h>

#include "api/cable_api.h"
#include "numerics/band_solver.h"
#include "line/simulation.h"
#include "numerics/sundials_compat.h"

using namespace uc;

namespace {

struct Context {
    SUNContext ctx = nullptr;
    Context() { SUNContext_Create(UC_SUN_COMM_NULL, &ctx); }
    ~Context() { SUNContext_Free(&ctx); }
};

// A non-symmetric band matrix like the integrator's: a diagonal term (cj^2 M) plus couplings
// (K + cj D) of comparable size, not diagonally dominant row by row.
void fill(int n, int b, double diagonal, std::mt19937& rng, UnpivotedBandLU& A, BandSolver& B) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < n; ++i)
        for (int k = std::max(0, i - b); k <= std::min(n - 1, i + b); ++k) {
            const double v = u(rng) + (i == k ? diagonal : 0.0);
            A.add(i, k, v);
            B.add(i, k, v);
        }
}

}  // namespace

TEST(UnpivotedBandLU, SolvesAsThePivotingSolverDoes) {
    Context c;
    const int n = 123, b = 11;  // the default cable's free coordinates and bandwidth
    std::mt19937 rng(3);
    UnpivotedBandLU A(n, b);
    BandSolver B(c.ctx, n, b);
    fill(n, b, 8.0, rng, A, B);
    std::vector<double> x(n), y(n);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < n; ++i) x[i] = y[i] = u(rng);
    ASSERT_TRUE(A.factor());
    A.solve(x.data());
    ASSERT_TRUE(B.factor_and_solve(y.data()));
    double diff = 0.0, size = 0.0;
    for (int i = 0; i < n; ++i) {
        diff = std::max(diff, std::fabs(x[i] - y[i]));
        size = std::max(size, std::fabs(y[i]));
    }
    // Both backward stable on a well-conditioned matrix (row sums of |off-diagonal| < 23 against a
    // diagonal of 8 +- 1: condition number ~1e2): agreement to ~1e2 eps.
    EXPECT_LT(diff, 1e-13 * size);
}

TEST(UnpivotedBandLU, RefusesAMatrixThatNeedsPivoting) {
    // [[0, 1], [1, 0]]: the first pivot is zero; with pivoting the matrix is a permutation.
    UnpivotedBandLU A(2, 1);
    A.add(0, 1, 1.0);
    A.add(1, 0, 1.0);
    EXPECT_FALSE(A.factor());
    UnpivotedBandLU tiny(2, 1);  // a pivot 1e-12 of its row: refused too (kPivotTolerance 1e-10)
    tiny.add(0, 0, 1e-12);
    tiny.add(0, 1, 1.0);
    tiny.add(1, 0, 1.0);
    tiny.add(1, 1, 1.0);
    EXPECT_FALSE(tiny.factor());
}


TEST(UnpivotedBandLU, TheIntegratorsTwoLinearAlgebraPathsGiveTheSameManoeuvre) {
    // The Hopland acceleration for 40 s with the default (unpivoted) LU and with the pivoting
    // fallback forced: the Newton corrections differ only by round-off, so the trajectories agree
    // to the integration tolerance (relTol 1e-8 of positions ~ 1e-6 m, EA / l times that ~ 5 N in
    // tension); asserted 1e-3 of the tension, and the forced run must really have pivoted.
    UCParams p;
    uc_params_default(&p);
    auto run = [&](bool pivot, long& pivoted) {
        CableSimulation sim(p);
        sim.integrator().always_pivot(pivot);
        UCInputs in{};
        const double v0 = 1.1 * 1852.0 / 3600.0, a = (2.4 - 1.1) * 1852.0 / 3600.0 / 60.0;
        in.towVelocity[0] = v0;
        std::string error;
        EXPECT_TRUE(sim.initialize(0.0, in, error)) << error;
        for (int k = 0; k < 80; ++k) {
            const double t = 0.5 * k;  // inputs at the start of the step
            in.tow[0] = v0 * t + 0.5 * a * t * t;
            in.towVelocity[0] = v0 + a * t;
            in.towAcceleration[0] = a;
            in.towAccelerationGiven = 1;
            EXPECT_TRUE(sim.step(0.5 * k, 0.5, in, error)) << error;
        }
        pivoted = sim.integrator().pivoted_factorizations();
        return sim.outputs().towTension;
    };
    long pivotedDefault = 0, pivotedForced = 0;
    const double fast = run(false, pivotedDefault), pivoted = run(true, pivotedForced);
    EXPECT_EQ(pivotedDefault, 0);  // the mass-dominated matrices never needed pivoting here
    EXPECT_GT(pivotedForced, 10);
    EXPECT_NEAR(fast, pivoted, 1e-3 * pivoted);
}

// The product with a band matrix (the integrator's D b_q in every linear solve) sums four rows
// side by side; each row must still add its terms in order, so it equals the plain row-by-row sum
// bit for bit, at every size (fewer rows than the band, and row counts that leave a remainder).
TEST(BandMatrix, ProductAddsEachRowInOrder) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int b : {1, 5, 11}) {
        for (int n : {1, 3, 12, 23, 24, 25, 26, 123}) {
            BandMatrix A(n, b);
            for (int i = 0; i < n; ++i)
                for (int k = std::max(0, i - b); k <= std::min(n - 1, i + b); ++k) A.add(i, k, u(rng));
            std::vector<double> x(n), y(n), expected(n);
            for (int i = 0; i < n; ++i) {
                x[i] = u(rng);
                y[i] = expected[i] = u(rng);
            }
            for (int i = 0; i < n; ++i)
                for (int k = std::max(0, i - b); k <= std::min(n - 1, i + b); ++k) expected[i] += A.get(i, k) * x[k];
            A.add_product(x.data(), y.data());
            for (int i = 0; i < n; ++i) EXPECT_EQ(y[i], expected[i]) << "n " << n << ", b " << b << ", row " << i;
        }
    }
}
