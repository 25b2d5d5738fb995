// The multigrid preconditioner of the PPE (schemes/ppe_multigrid.hpp). References: systems whose
// solution is chosen first, so the right side is exact; the Jacobi-preconditioned solve of the
// same system (same tolerance, so both must reach the same answer); the iteration counts of
// both under refinement (the point of a multigrid: nearly flat counts where Jacobi's grow like
// sqrt(N)); the same solve on 1 and 2 OpenMP threads (bitwise equal); a hierarchy kept for a
// later matrix (as IsphScheme keeps one for several steps) and one read back from a checkpoint.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "sloshsph/core/state_io.hpp"
#include "sloshsph/schemes/ppe_multigrid.hpp"
#include "sloshsph/schemes/ppe_solver.hpp"

namespace sloshsph {
namespace {

// The PPE of a rectangle of particles on a square lattice of spacing `dp`, n wide and m deep:
// 5-point Laplacian rows, p = 0 above the top row (free surface: a Dirichlet neighbour left out),
// and a layer of wall rows below the bottom row that carry p_w = p_f (Adami's condition, eq. 2.19,
// in its simplest form: non-symmetric rows of another scale, as in the PPE). Row positions for
// the aggregates are the particles'.
struct LatticePpe {
  SparseRows A;
  std::vector<Vec2> position;
};

LatticePpe lattice_ppe(int n, int m, double dp) {
  LatticePpe s;
  const int fluid = n * m;
  const int rows = fluid + n;  // fluid rows, then the wall row under each bottom column
  s.A.reserve_rows(std::vector<std::size_t>(static_cast<std::size_t>(rows), 5));
  s.position.resize(static_cast<std::size_t>(rows));
  const double lambda = 1.0 / (dp * dp);  // Laplacian weight of the PPE's scale
  auto fluid_row = [&](int i, int j) { return j * n + i; };  // column i, row j (0 = bottom)
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const auto row = static_cast<std::size_t>(fluid_row(i, j));
      s.position[row] = {(i + 0.5) * dp, (j + 0.5) * dp};
      std::size_t slot = s.A.slot_begin[row];
      s.A.column[slot] = static_cast<std::uint32_t>(row);
      s.A.value[slot++] = 4.0 * lambda;
      auto add = [&](std::size_t col) {
        s.A.column[slot] = static_cast<std::uint32_t>(col);
        s.A.value[slot++] = -lambda;
      };
      if (i > 0) add(static_cast<std::size_t>(fluid_row(i - 1, j)));
      if (i + 1 < n) add(static_cast<std::size_t>(fluid_row(i + 1, j)));
      if (j + 1 < m) add(static_cast<std::size_t>(fluid_row(i, j + 1)));  // the top row's is p = 0
      add(j > 0 ? static_cast<std::size_t>(fluid_row(i, j - 1)) : static_cast<std::size_t>(fluid + i));
      if (i == 0 || i + 1 == n) s.A.value[s.A.slot_begin[row]] -= lambda;  // side walls: zero normal gradient
      s.A.slot_end[row] = slot;
    }
  for (int i = 0; i < n; ++i) {
    const auto row = static_cast<std::size_t>(fluid + i);
    s.position[row] = {(i + 0.5) * dp, -0.5 * dp};
    const std::size_t slot = s.A.slot_begin[row];
    s.A.column[slot] = static_cast<std::uint32_t>(row);
    s.A.value[slot] = 0.3;  // a kernel weight: another scale than the fluid rows'
    s.A.column[slot + 1] = static_cast<std::uint32_t>(fluid_row(i, 0));
    s.A.value[slot + 1] = -0.3;
    s.A.slot_end[row] = slot + 2;
  }
  return s;
}

std::vector<double> times(const SparseRows& A, const std::vector<double>& x) {
  std::vector<double> y(A.rows(), 0.0);
  for (std::size_t r = 0; r < A.rows(); ++r) y[r] = A.row_times(r, x);
  return y;
}

struct Solved {
  std::vector<double> x;
  KrylovReport report;
};

Solved solve(const LatticePpe& s, const std::vector<double>& b, bool multigrid, double dp) {
  Solved out;
  out.x.assign(s.A.rows(), 0.0);
  BicgstabWork work;
  Multigrid mg;
  if (multigrid) {
    EXPECT_TRUE(build_multigrid(s.A, s.position, 2.0 * dp, mg));
  }
  out.report = solve_bicgstab(s.A, b, out.x, 1e-8, 20000, work, multigrid ? &mg : nullptr);
  return out;
}

// A hydrostatic-like field plus a disturbance: the solution chosen first.
std::vector<double> chosen_solution(const LatticePpe& s) {
  std::vector<double> x(s.A.rows());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = 1000.0 * (1.0 - s.position[i].y) + 50.0 * std::sin(7.0 * s.position[i].x);
  return x;
}

TEST(PpeMultigrid, ReachesTheSameSolutionAsJacobiInFarFewerIterations) {
  const double dp = 0.01;
  const LatticePpe s = lattice_ppe(120, 30, dp);
  const std::vector<double> exact = chosen_solution(s);
  const std::vector<double> b = times(s.A, exact);
  const Solved jacobi = solve(s, b, false, dp), multigrid = solve(s, b, true, dp);
  ASSERT_TRUE(jacobi.report.converged);
  ASSERT_TRUE(multigrid.report.converged);
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    worst = std::max(worst, std::abs(multigrid.x[i] - exact[i]));
    scale = std::max(scale, std::abs(exact[i]));
  }
  EXPECT_LT(worst, 1e-5 * scale);  // the residual tolerance 1e-8 times the condition of the system
  EXPECT_LT(5 * multigrid.report.iterations, jacobi.report.iterations)
      << "multigrid " << multigrid.report.iterations << ", Jacobi " << jacobi.report.iterations;
}

// Refining the lattice 4 x in particle count: Jacobi's iterations about double (sqrt(N)); the
// multigrid's may grow by at most half (the aggregation V-cycle's slow growth with the levels).
TEST(PpeMultigrid, IterationsStayNearlyFlatUnderRefinement) {
  int iterations[2][2];
  for (int level = 0; level < 2; ++level) {
    const int scale = level == 0 ? 1 : 2;
    const double dp = 0.01 / scale;
    const LatticePpe s = lattice_ppe(100 * scale, 40 * scale, dp);
    const std::vector<double> b = times(s.A, chosen_solution(s));
    for (int mg = 0; mg < 2; ++mg) {
      const Solved r = solve(s, b, mg == 1, dp);
      ASSERT_TRUE(r.report.converged);
      iterations[level][mg] = r.report.iterations;
    }
  }
  EXPECT_GT(iterations[1][0], 1.6 * iterations[0][0]) << "Jacobi " << iterations[0][0] << " -> " << iterations[1][0];
  EXPECT_LE(iterations[1][1], 1.5 * iterations[0][1]) << "multigrid " << iterations[0][1] << " -> " << iterations[1][1];
}

TEST(PpeMultigrid, SameBitsOnOneAndTwoThreads) {
  const double dp = 0.01;
  const LatticePpe s = lattice_ppe(150, 40, dp);  // 6,150 rows: the fine levels run in parallel
  const std::vector<double> b = times(s.A, chosen_solution(s));
  auto solve_on = [&](int threads) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    const Solved r = solve(s, b, true, dp);
    omp_set_num_threads(before);
    EXPECT_TRUE(r.report.converged);
    return r;
  };
  const Solved one = solve_on(1), two = solve_on(2);
  EXPECT_EQ(one.report.iterations, two.report.iterations);
  EXPECT_EQ(one.x, two.x);  // bitwise
}

// Too few rows for a hierarchy: the build says so and the cycle is the Jacobi preconditioner.
TEST(PpeMultigrid, FallsBackToJacobiOnASmallSystem) {
  const double dp = 0.01;
  const LatticePpe s = lattice_ppe(6, 4, dp);
  Multigrid mg;
  EXPECT_FALSE(build_multigrid(s.A, s.position, 2.0 * dp, mg));
  const std::vector<double> r(s.A.rows(), 2.0);
  std::vector<double> z(s.A.rows());
  apply_multigrid(s.A, mg, r, z);
  for (std::size_t i = 0; i < z.size(); ++i) EXPECT_EQ(z[i], 2.0 / s.A.value[s.A.slot_begin[i]]);
}

// The same kind of system in 3D (issue 31): the 7-point Laplacian of an n x n x m box of
// particles, p = 0 above the top layer, zero normal gradient at the four sides and the bottom.
// Reference: the solution chosen first; the multigrid (aggregates of 2 x 2 x 2 cells) reaches it
// and needs at most a fifth of Jacobi's iterations, as in 2D.
TEST(PpeMultigrid, ThreeDimensionalBoxReachesTheSolutionInFarFewerIterations) {
  const int n = 24, m = 12;
  const double dp = 0.01, lambda = 1.0 / (dp * dp);
  const int rows = n * n * m;
  SparseRows A;
  A.reserve_rows(std::vector<std::size_t>(static_cast<std::size_t>(rows), 7));
  std::vector<Vec3> position(static_cast<std::size_t>(rows));
  auto index = [&](int i, int j, int k) { return static_cast<std::size_t>((k * n + j) * n + i); };
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t row = index(i, j, k);
        position[row] = {(i + 0.5) * dp, (j + 0.5) * dp, (k + 0.5) * dp};
        std::size_t slot = A.slot_begin[row];
        A.column[slot] = static_cast<std::uint32_t>(row);
        A.value[slot++] = 6.0 * lambda;
        auto add = [&](bool inside, std::size_t col) {
          if (inside) {
            A.column[slot] = static_cast<std::uint32_t>(col);
            A.value[slot++] = -lambda;
          } else {
            A.value[A.slot_begin[row]] -= lambda;  // a wall: zero normal gradient
          }
        };
        add(i > 0, i > 0 ? index(i - 1, j, k) : 0);
        add(i + 1 < n, i + 1 < n ? index(i + 1, j, k) : 0);
        add(j > 0, j > 0 ? index(i, j - 1, k) : 0);
        add(j + 1 < n, j + 1 < n ? index(i, j + 1, k) : 0);
        add(k > 0, k > 0 ? index(i, j, k - 1) : 0);
        if (k + 1 < m) add(true, index(i, j, k + 1));  // the top layer's is p = 0
        A.slot_end[row] = slot;
      }
  std::vector<double> exact(static_cast<std::size_t>(rows));
  for (std::size_t r = 0; r < exact.size(); ++r)
    exact[r] = 1000.0 * (1.0 - position[r].z) + 50.0 * std::sin(7.0 * position[r].x) * std::cos(5.0 * position[r].y);
  const std::vector<double> b = times(A, exact);
  int iterations[2];
  for (int use_mg = 0; use_mg < 2; ++use_mg) {
    std::vector<double> x(exact.size(), 0.0);
    BicgstabWork work;
    Multigrid mg;
    if (use_mg == 1) {
      ASSERT_TRUE(build_multigrid(A, position, 2.0 * dp, mg));
      EXPECT_EQ(mg.levels[0].A.rows(), static_cast<std::size_t>(rows / 8)) << "2 x 2 x 2 aggregates";
    }
    const KrylovReport report = solve_bicgstab(A, b, x, 1e-8, 20000, work, use_mg == 1 ? &mg : nullptr);
    ASSERT_TRUE(report.converged);
    iterations[use_mg] = report.iterations;
    std::printf("  %s: %d iterations\n", use_mg == 1 ? "multigrid" : "Jacobi", report.iterations);
    double worst = 0.0;
    for (std::size_t r = 0; r < x.size(); ++r) worst = std::max(worst, std::abs(x[r] - exact[r]));
    EXPECT_LT(worst, 1e-5 * 1050.0);
  }
  EXPECT_LT(5 * iterations[1], iterations[0]) << "multigrid " << iterations[1] << ", Jacobi " << iterations[0];
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// A row at a position that is not finite (a run about to fail) gives no hierarchy: that step
// keeps the Jacobi preconditioner rather than casting NaN to a cell index.
TEST(PpeMultigrid, FallsBackToJacobiWhenAPositionIsNotFinite) {
  const double dp = 0.01;
  LatticePpe s = lattice_ppe(60, 20, dp);
  s.position[17].x = std::nan("");
  Multigrid mg;
  EXPECT_FALSE(build_multigrid(s.A, s.position, 2.0 * dp, mg));
  EXPECT_FALSE(mg.ready);
}

}  // namespace
}  // namespace sloshsph

namespace sloshsph {
namespace {

// The matrix of a later step: every entry of the fluid rows scaled by a smooth factor of the
// position (up to +-10%, far more than the particles move in the 20 steps a hierarchy is kept),
// the wall rows unchanged.
LatticePpe later_matrix(const LatticePpe& s, int fluid_rows) {
  LatticePpe t = s;
  for (int row = 0; row < fluid_rows; ++row) {
    const auto r = static_cast<std::size_t>(row);
    const double factor = 1.0 + 0.1 * std::sin(9.0 * t.position[r].x) * std::cos(5.0 * t.position[r].y);
    for (std::size_t k = t.A.slot_begin[r]; k < t.A.slot_end[r]; ++k) t.A.value[k] *= factor;
  }
  return t;
}

// IsphScheme keeps a hierarchy for several steps (refresh_fine_diagonal): preconditioning the
// later matrix with the hierarchy of the earlier one must still reach the tolerance and the chosen
// solution, in about as many iterations as a hierarchy built for it (at most 2 more), and far
// fewer than Jacobi's.
TEST(PpeMultigrid, AHierarchyKeptForALaterMatrixStillConvergesFast) {
  const double dp = 0.01;
  const int n = 120, m = 30;
  const LatticePpe earlier = lattice_ppe(n, m, dp);
  const LatticePpe later = later_matrix(earlier, n * m);
  const std::vector<double> exact = chosen_solution(later);
  const std::vector<double> b = times(later.A, exact);
  Multigrid kept;
  ASSERT_TRUE(build_multigrid(earlier.A, earlier.position, 2.0 * dp, kept));
  refresh_fine_diagonal(later.A, kept);
  std::vector<double> x(later.A.rows(), 0.0);
  BicgstabWork work;
  const KrylovReport report = solve_bicgstab(later.A, b, x, 1e-8, 20000, work, &kept);
  ASSERT_TRUE(report.converged);
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    worst = std::max(worst, std::abs(x[i] - exact[i]));
    scale = std::max(scale, std::abs(exact[i]));
  }
  EXPECT_LT(worst, 1e-5 * scale);
  const Solved fresh = solve(later, b, true, dp), jacobi = solve(later, b, false, dp);
  EXPECT_LE(report.iterations, fresh.report.iterations + 2)
      << "kept " << report.iterations << ", built for the matrix " << fresh.report.iterations;
  EXPECT_LT(5 * report.iterations, jacobi.report.iterations) << "kept " << report.iterations << ", Jacobi "
                                                             << jacobi.report.iterations;
}

// A checkpoint holds the hierarchy: loaded into a new Multigrid it gives the same V-cycle, bit for
// bit (the coarsest LU factored again from the stored matrix).
TEST(PpeMultigrid, SavedAndLoadedHierarchyGivesTheSameBits) {
  const double dp = 0.01;
  const LatticePpe s = lattice_ppe(100, 30, dp);
  Multigrid built;
  ASSERT_TRUE(build_multigrid(s.A, s.position, 2.0 * dp, built));
  StateWriter writer;
  save_multigrid(built, writer);
  StateReader reader(writer.bytes(), "test checkpoint");
  Multigrid loaded;
  load_multigrid(loaded, reader);
  EXPECT_TRUE(reader.at_end());
  ASSERT_TRUE(loaded.ready);
  refresh_fine_diagonal(s.A, loaded);
  std::vector<double> r(s.A.rows());
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = std::sin(0.37 * static_cast<double>(i));
  std::vector<double> z_built(r.size()), z_loaded(r.size());
  apply_multigrid(s.A, built, r, z_built);
  apply_multigrid(s.A, loaded, r, z_loaded);
  EXPECT_EQ(z_built, z_loaded);  // bitwise
}

}  // namespace
}  // namespace sloshsph
