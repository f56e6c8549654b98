// band_solver.cpp - SUNDIALS band matrix and band LU behind a small interface.
#include "numerics/band_solver.h"

#include "numerics/sundials_compat.h"

#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

#include <algorithm>
#include <cmath>
#include <new>

namespace uc {

BandSolver::BandSolver(SUNContext context, int n, int bandwidth) : n_(n) {
    A_ = SUNBandMatrix(n, bandwidth, bandwidth, context);
    x_ = N_VNew_Serial(n, context);
    b_ = N_VNew_Serial(n, context);
    if (A_ && x_) solver_ = SUNLinSol_Band(x_, A_, context);
    if (!A_ || !x_ || !b_ || !solver_) {
        release();
        throw std::bad_alloc();
    }
}

BandSolver::~BandSolver() { release(); }

void BandSolver::release() {
    if (solver_) SUNLinSolFree(solver_);
    if (A_) SUNMatDestroy(A_);
    if (x_) N_VDestroy(x_);
    if (b_) N_VDestroy(b_);
    solver_ = nullptr;
    A_ = nullptr;
    x_ = b_ = nullptr;
}

void BandSolver::clear() { SUNMatZero(A_); }

void BandSolver::add(int row, int col, double value) { SM_ELEMENT_B(A_, row, col) += value; }

bool BandSolver::factor() { return SUNLinSolSetup(solver_, A_) == kLinearSolverSuccess; }

bool BandSolver::factor_and_solve(double* b) { return factor() && solve(b); }

bool BandSolver::solve(double* b) {
    double* bb = N_VGetArrayPointer(b_);
    for (int i = 0; i < n_; ++i) bb[i] = b[i];
    if (SUNLinSolSolve(solver_, A_, x_, b_, 0.0) != kLinearSolverSuccess) return false;
    const double* xx = N_VGetArrayPointer(x_);
    for (int i = 0; i < n_; ++i) b[i] = xx[i];
    return true;
}

BandMatrix::BandMatrix(int n, int bandwidth)
    : n_(n), b_(bandwidth), w_(2 * bandwidth + 1), a_(static_cast<size_t>(n) * (2 * bandwidth + 1), 0.0) {}

void BandMatrix::clear() { std::fill(a_.begin(), a_.end(), 0.0); }

void BandMatrix::add_product(const double* x, double* y) const {
    // Each row's sum is a chain of dependent additions, as long as the band is wide. Four rows
    // summed side by side make four independent chains the processor overlaps; every row still
    // adds its terms in the order of k, so the result is the same to the last bit.
    auto rowSum = [&](int i) {
        const double* r = row(i);
        double s = y[i];
        const int kEnd = std::min(n_ - 1, i + b_);
        for (int k = std::max(0, i - b_); k <= kEnd; ++k) s += r[k] * x[k];
        y[i] = s;
    };
    const int interiorEnd = n_ - 1 - b_;  // rows i in [b_, interiorEnd] have all 2 b_ + 1 entries
    int i = 0;
    for (; i < std::min(b_, n_); ++i) rowSum(i);
    for (; i + 3 <= interiorEnd; i += 4) {
        const double* r0 = &a_[static_cast<size_t>(i) * w_];  // entry j of row i + m: A(i + m, i + m - b_ + j)
        const double* r1 = r0 + w_;
        const double* r2 = r1 + w_;
        const double* r3 = r2 + w_;
        const double* x0 = x + i - b_;
        double s0 = y[i], s1 = y[i + 1], s2 = y[i + 2], s3 = y[i + 3];
        for (int j = 0; j < w_; ++j) {
            s0 += r0[j] * x0[j];
            s1 += r1[j] * x0[j + 1];
            s2 += r2[j] * x0[j + 2];
            s3 += r3[j] * x0[j + 3];
        }
        y[i] = s0;
        y[i + 1] = s1;
        y[i + 2] = s2;
        y[i + 3] = s3;
    }
    for (; i < n_; ++i) rowSum(i);
}

bool UnpivotedBandLU::factor() {
    for (int p = 0; p < n_; ++p) {
        double* rowP = row(p);
        double scale = 0.0;
        const int kEnd = std::min(n_ - 1, p + b_);
        for (int k = std::max(0, p - b_); k <= kEnd; ++k) scale = std::max(scale, std::fabs(rowP[k]));
        const double pivot = rowP[p];
        if (!(std::fabs(pivot) > kPivotTolerance * scale)) return false;
        const double inverse = 1.0 / pivot;
        for (int i = p + 1; i <= kEnd; ++i) {
            double* rowI = row(i);
            const double l = rowI[p] * inverse;
            rowI[p] = l;
            if (l == 0.0) continue;
            for (int k = p + 1; k <= kEnd; ++k) rowI[k] -= l * rowP[k];
        }
    }
    return true;
}

void UnpivotedBandLU::solve(double* x) const {
    for (int i = 0; i < n_; ++i) {  // L y = b (unit diagonal)
        const double* r = row(i);
        double s = x[i];
        for (int k = std::max(0, i - b_); k < i; ++k) s -= r[k] * x[k];
        x[i] = s;
    }
    for (int i = n_ - 1; i >= 0; --i) {  // U x = y
        const double* r = row(i);
        double s = x[i];
        const int kEnd = std::min(n_ - 1, i + b_);
        for (int k = i + 1; k <= kEnd; ++k) s -= r[k] * x[k];
        x[i] = s / r[i];
    }
}

}  // namespace uc
