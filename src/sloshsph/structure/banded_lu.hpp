#pragma once
#include <Eigen/Core>
#include <vector>

// LU factorisation with partial pivoting of a general banded matrix (Golub & Van Loan, "Matrix
// Computations", 4th ed., sec. 4.3.5, band Gaussian elimination with partial pivoting). A beam's
// stiffness couples only neighbouring nodes, so its bandwidth is fixed (5 on each side for 3 DOFs per
// node) and a factorisation costs O(n) instead of a general sparse solver's overhead. The matrix may be
// unsymmetric (follower loads, the energy-conserving tangent, damping derivatives).
namespace sloshsph {

class BandedLu {
 public:
  BandedLu() = default;
  // n x n matrix with `lower` sub-diagonals and `upper` super-diagonals.
  BandedLu(int n, int lower, int upper);

  int size() const { return n_; }
  void set_zero();
  // Adds to entry (row, col); throws std::out_of_range outside the band.
  void add(int row, int col, double value);
  // Factorises in place; false if a zero pivot makes the matrix singular.
  bool factorize();
  // Solves A x = rhs with the factors, in place.
  void solve(Eigen::VectorXd& rhs) const;

 private:
  double& at(int row, int col) { return values_[static_cast<std::size_t>(row) * width_ + (col - row + lower_)]; }
  double at(int row, int col) const {
    return values_[static_cast<std::size_t>(row) * width_ + (col - row + lower_)];
  }

  int n_ = 0;
  int lower_ = 0;
  int upper_ = 0;
  std::size_t width_ = 0;       // lower + (upper + lower) + 1: room for the fill-in of row interchanges
  std::vector<double> values_;  // row-wise band storage, entry (i, j) for j - i in [-lower, upper + lower]
  std::vector<int> pivots_;
};

}  // namespace sloshsph
