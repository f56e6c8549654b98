// band_solver.h - a banded matrix with its LU solve (SUNDIALS band matrix + band linear solver),
// for the static Newton iterations and consistent initial accelerations. Never dense.
#pragma once

#include <vector>

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

namespace uc {

class BandSolver {
public:
    BandSolver(SUNContext context, int n, int bandwidth);
    ~BandSolver();
    BandSolver(const BandSolver&) = delete;
    BandSolver& operator=(const BandSolver&) = delete;

    int size() const { return n_; }
    void clear();
    void add(int row, int col, double value);  // |row - col| <= bandwidth
    // Factorizes A (LU with partial pivoting). False if the matrix is singular.
    bool factor();
    // Factorizes and solves A x = b in place (b becomes x). False if the matrix is singular.
    bool factor_and_solve(double* b);
    // Solves with the last factorization.
    bool solve(double* b);

private:
    void release();
    int n_;
    SUNMatrix A_ = nullptr;
    SUNLinearSolver solver_ = nullptr;
    N_Vector x_ = nullptr, b_ = nullptr;
};

// An n x n matrix with entries only for |row - col| <= bandwidth, in row-major band storage.
class BandMatrix {
public:
    BandMatrix(int n, int bandwidth);
    int size() const { return n_; }
    int bandwidth() const { return b_; }
    void clear();
    void add(int row, int col, double value) { a_[row * w_ + col - row + b_] += value; }
    double get(int row, int col) const { return a_[row * w_ + col - row + b_]; }
    // The storage, row by row, 2 bandwidth + 1 entries each (A(i, k) at i (2b + 1) + k - i + b;
    // entries outside the matrix stay 0): matrices of the same size combine entry by entry.
    double* values() { return a_.data(); }
    const double* values() const { return a_.data(); }
    size_t value_count() const { return a_.size(); }
    // y_i += sum_k A(i, k) x_k, the terms of each row added in the order of k.
    void add_product(const double* x, double* y) const;

protected:
    double* row(int i) { return &a_[static_cast<size_t>(i) * w_ + b_ - i]; }  // row(i)[k] = A(i, k)
    const double* row(int i) const { return &a_[static_cast<size_t>(i) * w_ + b_ - i]; }
    int n_, b_, w_;
    std::vector<double> a_;
};

// A band matrix factored in place by LU without pivoting, for the integrator's Newton matrices
// (mass-dominated: K + cj D with D ~ cj M). factor() refuses, and the caller falls back to the
// pivoting BandSolver, when a pivot is below kPivotTolerance times its row's largest entry; the
// band is then left unusable until the next clear().
class UnpivotedBandLU : public BandMatrix {
public:
    using BandMatrix::BandMatrix;
    bool factor();
    void solve(double* x) const;  // in place

    static constexpr double kPivotTolerance = 1e-10;
};

}  // namespace uc
