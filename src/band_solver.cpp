// band_solver.cpp - SUNDIALS band matrix and band LU behind a small interface.
#include "band_solver.h"

#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>

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

bool BandSolver::factor() { return SUNLinSolSetup(solver_, A_) == SUNLS_SUCCESS; }

bool BandSolver::factor_and_solve(double* b) { return factor() && solve(b); }

bool BandSolver::solve(double* b) {
    double* bb = N_VGetArrayPointer(b_);
    for (int i = 0; i < n_; ++i) bb[i] = b[i];
    if (SUNLinSolSolve(solver_, A_, x_, b_, 0.0) != SUNLS_SUCCESS) return false;
    const double* xx = N_VGetArrayPointer(x_);
    for (int i = 0; i < n_; ++i) b[i] = xx[i];
    return true;
}

}  // namespace uc
