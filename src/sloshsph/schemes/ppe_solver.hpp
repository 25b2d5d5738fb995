#pragma once
// The linear solver of the implicit pressure Poisson equation (IsphScheme): a sparse matrix in
// row-slot form, written straight from the neighbour list, and BiCGSTAB with a diagonal (Jacobi)
// or multigrid (ppe_multigrid.hpp) preconditioner.
//
// Why not Eigen's BiCGSTAB, which this replaced: its vector operations and products run on one
// thread (EIGEN_DONT_PARALLELIZE: Eigen's own OpenMP products cost more in fork/join than they
// gain at these sizes), so half of a step did not use the second core; and its matrix came
// through a triplet list and a sort (7% of the instructions, docs/performance.md). Here every
// loop runs on all threads and every sum is taken over fixed blocks in a fixed order, so the
// result is the same, bit for bit, on any number of threads.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sloshsph {

struct Multigrid;

// Row r holds its entries at [slot_begin[r], slot_end[r]) of `column` and `value`; the slots of a
// row are reserved before it is filled (an upper bound of its length: its neighbour count + 1),
// so the rows can be written in parallel and no entries move afterwards. The first entry of each
// row is its diagonal.
struct SparseRows {
  std::vector<std::size_t> slot_begin, slot_end;
  std::vector<std::uint32_t> column;
  std::vector<double> value;

  std::size_t rows() const { return slot_begin.size(); }
  // 1 / A_rr (the diagonal is a row's first entry), or 1 for a row without one: the Jacobi
  // preconditioner and the multigrid's smoother and restriction.
  double inverse_diagonal(std::size_t r) const {
    const double d = slot_end[r] > slot_begin[r] ? value[slot_begin[r]] : 0.0;
    return d != 0.0 ? 1.0 / d : 1.0;
  }
  // Row r times x, in four partial sums (slots k, k+1, k+2, k+3 mod 4), so that a row is not one
  // chain of dependent additions: 4.8% fewer instructions a step of the Tait tank with screens
  // (callgrind); no wall-time gain stood out of the machine's noise on its own. The sum order is
  // fixed, so the result does not depend on the thread count.
  double row_times(std::size_t r, const std::vector<double>& x) const {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    std::size_t k = slot_begin[r];
    const std::size_t end = slot_end[r];
    for (; k + 4 <= end; k += 4) {
      s0 += value[k] * x[column[k]];
      s1 += value[k + 1] * x[column[k + 1]];
      s2 += value[k + 2] * x[column[k + 2]];
      s3 += value[k + 3] * x[column[k + 3]];
    }
    for (; k < end; ++k) s0 += value[k] * x[column[k]];
    return (s0 + s1) + (s2 + s3);
  }
  // Reserves `capacity[r]` slots for each row r (and empties all rows).
  void reserve_rows(const std::vector<std::size_t>& capacity);
  std::size_t memory_bytes() const;
};

struct KrylovReport {
  int iterations = 0;
  double relative_residual = 0.0;  // |b - A x| / |b| at the end
  bool converged = false;
};

// Scratch vectors of the solver, kept between calls so that the time loop does not allocate.
struct BicgstabWork {
  std::vector<double> inverse_diagonal, r, r0, p, v, t, y;
  std::vector<double> block_sums;
  std::size_t memory_bytes() const;
};

// The rows of blocks of A that no anchored row reaches: A x = b splits into independent blocks (the
// connected components of the graph of A's entries, in either direction), and a block is singular
// when none of its rows is anchored, that is when in every row the entries sum to zero
// (|sum_k A_rk| <= weak |A_rr|): the pure-Neumann Laplacian of a cluster of fluid that no p = 0
// condition reaches, whose pressure level is undetermined and whose equations, with a right side
// that does not sum to zero, have no solution. An entry |A_rk| <= weak |A_rr| does not connect
// (nor does a row sum that small anchor): a block held to the rest only by such links is nearly
// singular, and its solution, however well converged, is absurd (found 2026-12-07: SF tank at
// 44 milli-g, t = 279.785 s, 3 particles at 7e18 Pa after the solve converged to 8e-7; a pair at
// the edge of the kernel's support gives a coefficient of (1 - q/2)^3, 1e-6 at q = 1.98). Returns
// those rows in increasing order (empty when every block is anchored). Serial union-find over the
// entries: O(entries).
std::vector<std::uint32_t> rows_without_anchor(const SparseRows& A, double weak = 1e-8);

// Solves A x = b from the initial guess in x: BiCGSTAB (van der Vorst 1992) with a right
// preconditioner, to |b - A x| <= tolerance |b| or max_iterations. The preconditioner is
// diag(A) (Jacobi), or one V-cycle of `multigrid` when given (built for A by build_multigrid,
// schemes/ppe_multigrid.hpp). A vanishing inner product (breakdown) restarts it from the current
// x with r0 = r. A zero right side gives x = 0. Deterministic: the same result on any number of
// OpenMP threads.
KrylovReport solve_bicgstab(const SparseRows& A, const std::vector<double>& b, std::vector<double>& x, double tolerance,
                            int max_iterations, BicgstabWork& work, Multigrid* multigrid = nullptr);

}  // namespace sloshsph
