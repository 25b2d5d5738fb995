// The PPE's linear solver (schemes/ppe_solver.hpp): BiCGSTAB with a Jacobi preconditioner on
// row-slot sparse rows. References: a non-symmetric system whose solution is chosen first (so
// the right side is exact), Eigen's dense LU for the same system, and the same solve on 1 and 2
// OpenMP threads (the solver's sums are blocked in a fixed order: bitwise equal).
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "sloshsph/schemes/ppe_solver.hpp"

namespace sloshsph {
namespace {

// A 2D grid Laplacian (5-point, n x n) plus a first-order upwind term: diagonally dominant and
// non-symmetric, like the PPE's fluid rows beside its wall rows. Rows reserve one slot more than
// they use, as the PPE's bound may.
SparseRows convection_diffusion(int n, double upwind) {
  SparseRows A;
  A.reserve_rows(std::vector<std::size_t>(static_cast<std::size_t>(n * n), 6));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::size_t row = static_cast<std::size_t>(i * n + j);
      std::size_t slot = A.slot_begin[row];
      A.column[slot] = static_cast<std::uint32_t>(row);
      A.value[slot++] = 4.0 + upwind;
      auto add = [&](int ii, int jj, double v) {
        if (ii < 0 || jj < 0 || ii >= n || jj >= n) return;
        A.column[slot] = static_cast<std::uint32_t>(ii * n + jj);
        A.value[slot++] = v;
      };
      add(i - 1, j, -1.0 - upwind);
      add(i + 1, j, -1.0);
      add(i, j - 1, -1.0);
      add(i, j + 1, -1.0);
      A.slot_end[row] = slot;
    }
  return A;
}

std::vector<double> times(const SparseRows& A, const std::vector<double>& x) {
  std::vector<double> y(A.rows(), 0.0);
  for (std::size_t r = 0; r < A.rows(); ++r)
    for (std::size_t k = A.slot_begin[r]; k < A.slot_end[r]; ++k) y[r] += A.value[k] * x[A.column[k]];
  return y;
}

double norm(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

TEST(PpeSolver, SolvesANonSymmetricSystemToItsTolerance) {
  const SparseRows A = convection_diffusion(30, 0.5);
  std::vector<double> exact(A.rows());
  for (std::size_t i = 0; i < exact.size(); ++i) exact[i] = std::sin(0.1 * static_cast<double>(i)) + 2.0;
  const std::vector<double> b = times(A, exact);
  std::vector<double> x(A.rows(), 0.0);
  BicgstabWork work;
  const KrylovReport report = solve_bicgstab(A, b, x, 1e-10, 1000, work);
  ASSERT_TRUE(report.converged);
  EXPECT_GT(report.iterations, 1);
  EXPECT_LE(report.relative_residual, 1e-10);
  // The reported residual is the true one (recomputed here from x).
  std::vector<double> r = times(A, x);
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = b[i] - r[i];
  EXPECT_NEAR(norm(r) / norm(b), report.relative_residual, 1e-12);
  // Against Eigen's dense LU of the same matrix: 900 unknowns, condition number about 500.
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(A.rows(), A.rows());
  for (std::size_t row = 0; row < A.rows(); ++row)
    for (std::size_t k = A.slot_begin[row]; k < A.slot_end[row]; ++k) dense(row, A.column[k]) = A.value[k];
  const Eigen::VectorXd lu = dense.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(b.data(), b.size()));
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(x[i] - lu[i]));
  EXPECT_LT(worst, 1e-7);
}

TEST(PpeSolver, AWarmStartAtTheSolutionNeedsNoIteration) {
  const SparseRows A = convection_diffusion(10, 0.2);
  std::vector<double> x(A.rows(), 3.0);
  const std::vector<double> b = times(A, x);
  BicgstabWork work;
  const KrylovReport report = solve_bicgstab(A, b, x, 1e-8, 100, work);
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.iterations, 0);
  EXPECT_EQ(x[17], 3.0);
}

TEST(PpeSolver, AZeroRightSideGivesZero) {
  const SparseRows A = convection_diffusion(5, 0.0);
  std::vector<double> x(A.rows(), 1.0);
  BicgstabWork work;
  const KrylovReport report = solve_bicgstab(A, std::vector<double>(A.rows(), 0.0), x, 1e-8, 100, work);
  EXPECT_TRUE(report.converged);
  for (double v : x) EXPECT_EQ(v, 0.0);
}

TEST(PpeSolver, ReportsNoConvergenceAtTheIterationLimit) {
  const SparseRows A = convection_diffusion(40, 0.0);
  std::vector<double> b(A.rows(), 1.0), x(A.rows(), 0.0);
  BicgstabWork work;
  const KrylovReport report = solve_bicgstab(A, b, x, 1e-12, 3, work);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.iterations, 3);
  EXPECT_GT(report.relative_residual, 1e-12);
}

TEST(PpeSolver, SameBitsOnOneAndTwoThreads) {
  const SparseRows A = convection_diffusion(40, 0.3);  // 1,600 rows: 7 blocks of the sums
  std::vector<double> b(A.rows());
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = std::cos(0.37 * static_cast<double>(i));
  auto solve_on = [&](int threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    std::vector<double> x(A.rows(), 0.0);
    BicgstabWork work;
    const KrylovReport report = solve_bicgstab(A, b, x, 1e-9, 1000, work);
    omp_set_num_threads(before);
    EXPECT_TRUE(report.converged);
    return std::make_pair(x, report.iterations);
  };
  const auto one = solve_on(1), two = solve_on(2);
  EXPECT_EQ(one.second, two.second);
  EXPECT_EQ(one.first, two.first);  // bitwise
}

// rows_without_anchor: a matrix of two independent blocks. The grid Laplacian above is anchored
// at its edges (a missing neighbour leaves its row summing to 1 > 0: a p = 0 condition there).
// The second block is the pure-Neumann Laplacian of three fluid rows (a triangle: diagonal 2, -1
// to each other; every row sums to 0) and a wall-like row that refers to one of them while no
// fluid row refers to it (connected in one direction only). Reference: that block's four rows.
// The sparse matrix of rows given as (column, value) lists.
using RowLists = std::vector<std::vector<std::pair<std::uint32_t, double>>>;
SparseRows sparse_rows(const RowLists& rows) {
  SparseRows A;
  std::vector<std::size_t> capacity;
  for (const auto& row : rows) capacity.push_back(row.size());
  A.reserve_rows(capacity);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::size_t slot = A.slot_begin[r];
    for (const auto& [column, value] : rows[r]) {
      A.column[slot] = column;
      A.value[slot++] = value;
    }
    A.slot_end[r] = slot;
  }
  return A;
}

// The (column, value) lists of A's rows.
RowLists row_lists(const SparseRows& A) {
  RowLists rows(A.rows());
  for (std::size_t r = 0; r < A.rows(); ++r)
    for (std::size_t k = A.slot_begin[r]; k < A.slot_end[r]; ++k) rows[r].push_back({A.column[k], A.value[k]});
  return rows;
}

SparseRows grid_and_cluster(double cluster_diagonal) {
  const int n = 4;
  RowLists rows = row_lists(convection_diffusion(n, 0.0));
  const std::size_t m = rows.size();
  rows.resize(m + 4);
  const auto c = static_cast<std::uint32_t>(m);
  rows[m] = {{c, cluster_diagonal}, {c + 1, -1.0}, {c + 2, -1.0}};
  rows[m + 1] = {{c + 1, 2.0}, {c, -1.0}, {c + 2, -1.0}};
  rows[m + 2] = {{c + 2, 2.0}, {c, -1.0}, {c + 1, -1.0}};
  rows[m + 3] = {{c + 3, 0.5}, {c, -0.5}};  // the wall row: a weighted average of one fluid row
  return sparse_rows(rows);
}

TEST(PpeSolver, FindsTheBlockThatNoAnchorReaches) {
  const SparseRows A = grid_and_cluster(2.0);
  const std::vector<std::uint32_t> expected = {16, 17, 18, 19};
  EXPECT_EQ(rows_without_anchor(A), expected);
  // One row of the cluster that does not sum to zero (a missing neighbour at p = 0) anchors it.
  EXPECT_TRUE(rows_without_anchor(grid_and_cluster(2.5)).empty());
  // The singular block makes the solve fail (its right side does not sum to zero): why the
  // scheme sets such blocks to p = 0 before solving.
  std::vector<double> b(A.rows(), 1.0), x(A.rows(), 0.0);
  BicgstabWork work;
  EXPECT_FALSE(solve_bicgstab(A, b, x, 1e-8, 500, work).converged);
}

// A block held to the anchored grid by one weak link (1e-7 of the diagonal; the cluster row's sum
// stays zero): anchored at the default tolerance (1e-8), left unanchored at the scheme's 1e-6
// (kWeakPpeLink), so that the scheme pins it rather than solving it to absurd pressures.
TEST(PpeSolver, AWeakLinkDoesNotAnchorABlock) {
  RowLists rows = row_lists(grid_and_cluster(2.0));
  const std::size_t c = 16;  // the cluster's first row: its diagonal first
  ASSERT_EQ(rows[c].front().first, c);
  rows[c].front().second = 2.0 + 1e-7;
  rows[c].push_back({0, -1e-7});
  const SparseRows B = sparse_rows(rows);
  EXPECT_TRUE(rows_without_anchor(B).empty());
  const std::vector<std::uint32_t> expected = {16, 17, 18, 19};
  EXPECT_EQ(rows_without_anchor(B, 1e-6), expected);
}

}  // namespace
}  // namespace sloshsph
