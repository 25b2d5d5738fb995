#pragma once
// An aggregation multigrid preconditioner for the pressure Poisson equation (issue 8: the
// Jacobi-preconditioned Krylov solve needs iterations that grow like the square root of the
// particle count, about 5,000 a step at 200,000 particles; a multigrid cycle removes the smooth
// error that Jacobi cannot, so the count stays nearly flat).
//
// The hierarchy is geometric and rebuilt every step (the matrix changes with the particles):
//  * aggregates: the rows whose particles fall in one square cell of side 2 dp, then 4 dp, ...
//    (about four rows per aggregate in 2D); piecewise-constant prolongation P;
//  * restriction R = P^T D^-1 (each fine row scaled by its diagonal first, so that the wall rows
//    of eq. 2.19 and the fluid rows of eq. 2.13, whose scales differ, weigh alike), and the
//    Galerkin coarse operator A_c = R A P;
//  * one damped-Jacobi sweep before and after each coarse correction (a V-cycle), the coarse
//    correction scaled by `overcorrection` (piecewise-constant prolongation leaves the coarse
//    correction short of the smooth error; over-correcting it is the usual remedy for plain
//    aggregation, as in Notay's AGMG);
//  * the coarsest level (at most `coarsest_rows`) solved exactly (dense LU).
// The weights (jacobi_weight, overcorrection) were chosen by measurement: mean BiCGSTAB
// iterations a step on the Tait tank with screens at dp = 7 mm (2,858 particles): 5.1 at
// (0.7, 1.6), 7.0 at (0.5, 1.6), 7.4 at (0.7, 2.0), 3.0 at (0.9, 1.3); on a 51,518-particle tank
// at rest: 11.5 at (0.9, 1.0), 9.8 at (0.9, 1.6), 8.9 at (0.9, 1.3). A second sweep saved
// iterations (3.1 against 5.1) but not time.
// Every loop is a gather in a fixed order, so a cycle gives the same bits on any thread count,
// and it is a fixed linear operator, as a Krylov preconditioner must be.
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "sloshsph/core/vec2.hpp"
#include "sloshsph/schemes/ppe_solver.hpp"

namespace sloshsph {

struct MultigridOptions {
  double jacobi_weight = 0.9;    // damping of the Jacobi smoother
  double overcorrection = 1.3;   // scale of the coarse-grid correction
  int smoothing_sweeps = 1;      // before and after each coarse correction
  std::size_t coarsest_rows = 96;
};

// The cell of each row along x, y and z (z empty in 2D).
using CellIndices = std::array<std::vector<std::int64_t>, 3>;

// One level below the finest: its operator, and how its rows gather the finer level's rows.
struct MultigridLevel {
  SparseRows A;
  std::vector<double> inverse_diagonal;
  std::vector<std::size_t> member_begin;  // this level's row I aggregates finer rows
  std::vector<std::uint32_t> member;      //   member[member_begin[I] .. member_begin[I + 1])
  std::vector<std::uint32_t> parent;      // the finer level's row -> this level's row
  CellIndices cell;                       // the cell of each row (its key for the next level)
  std::vector<double> b, x, r;            // right side, correction, residual
};

struct Multigrid {
  MultigridOptions options;
  std::vector<MultigridLevel> levels;  // levels[0] is the first coarse level
  Eigen::PartialPivLU<Eigen::MatrixXd> coarsest;
  Eigen::MatrixXd coarsest_dense;
  std::vector<double> fine_inverse_diagonal, fine_r;  // of the finest level
  CellIndices fine_cell;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sort_keys;  // (cell, row)
  std::vector<std::size_t> row_length;
  std::vector<std::vector<std::int32_t>> stamp, slot;  // per thread: coarse column -> last row, slot
  bool ready = false;                  // false: the last build failed (use Jacobi instead)
  std::size_t memory_bytes() const;
};

class StateWriter;
class StateReader;

// Builds the hierarchy for A (diagonal first in each row, as SparseRows holds it), the rows at
// `position` (m), the fine aggregates cells of side `cell` (m). Returns false (and leaves
// mg.ready false) when the coarsest matrix is singular or not finite.
// In 2 or 3 dimensions (aggregates of cells of side `cell`).
template <int D>
bool build_multigrid(const SparseRows& A, const std::vector<Vec<D>>& position, double cell, Multigrid& mg);

// The finest level's diagonal from A, for a hierarchy built for an earlier matrix of the same rows
// (IsphScheme keeps a hierarchy for several steps, docs/physics.md): the smoother and the
// restriction then use this step's diagonal, the coarse levels the one of the build.
void refresh_fine_diagonal(const SparseRows& A, Multigrid& mg);

// Checkpoints: the hierarchy as built (a kept hierarchy is part of the run's state, so that a
// resumed run gives the same bits as an unbroken one). The coarsest level's LU is factored again
// on loading, from the stored coarse matrix.
void save_multigrid(const Multigrid& mg, StateWriter& w);
void load_multigrid(Multigrid& mg, StateReader& r);

// z = M^-1 r by one V-cycle from z = 0 (z = D^-1 r if the last build failed).
void apply_multigrid(const SparseRows& A, Multigrid& mg, const std::vector<double>& r, std::vector<double>& z);

}  // namespace sloshsph
