#include "sloshsph/schemes/ppe_multigrid.hpp"

#include "sloshsph/core/state_io.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sloshsph {

namespace {

// Loops shorter than this run on one thread: on the coarse levels the fork costs more than the
// work. (A loop's result does not depend on it: every loop is a gather.)
constexpr std::size_t kParallelRows = 2048;

constexpr std::size_t kMaxLevels = 40;

template <class V> std::size_t capacity_bytes(const V& v) { return v.capacity() * sizeof(typename V::value_type); }

// The aggregates of the next level: the rows of the finer level whose cells, halved `shift`
// times, coincide. Rows are numbered in the order of their cells (x fastest, then y, then z),
// members in the order of the finer rows, so the numbering does not depend on the thread count.
// `fine` holds the cells along each axis; in 2D the z axis is left empty.
void aggregate(const CellIndices& fine, int shift, Multigrid& mg, MultigridLevel& L) {
  const std::size_t n = fine[0].size();
  const int axes = fine[2].empty() ? 2 : 3;
  std::int64_t low[3], high[3];
  for (int k = 0; k < axes; ++k) {
    low[k] = std::numeric_limits<std::int64_t>::max();
    high[k] = std::numeric_limits<std::int64_t>::min();
    for (std::size_t i = 0; i < n; ++i) {
      low[k] = std::min(low[k], fine[k][i] >> shift);
      high[k] = std::max(high[k], fine[k][i] >> shift);
    }
  }
  const auto width = static_cast<std::uint64_t>(high[0] - low[0] + 1);
  const auto depth = static_cast<std::uint64_t>(high[1] - low[1] + 1);
  auto& keys = mg.sort_keys;
  keys.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t row = static_cast<std::uint64_t>((fine[1][i] >> shift) - low[1]);
    if (axes == 3) row += static_cast<std::uint64_t>((fine[2][i] >> shift) - low[2]) * depth;
    keys[i] = {row * width + static_cast<std::uint64_t>((fine[0][i] >> shift) - low[0]), static_cast<std::uint32_t>(i)};
  }
  std::sort(keys.begin(), keys.end());
  L.parent.resize(n);
  L.member.resize(n);
  L.member_begin.clear();
  for (int k = 0; k < 3; ++k) L.cell[k].clear();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = keys[k].second;
    if (k == 0 || keys[k].first != keys[k - 1].first) {
      L.member_begin.push_back(k);
      for (int a = 0; a < axes; ++a) L.cell[a].push_back(fine[a][i] >> shift);
    }
    L.member[k] = i;
    L.parent[i] = static_cast<std::uint32_t>(L.member_begin.size() - 1);
  }
  L.member_begin.push_back(n);
}

// L.A = R A P with R = P^T D^-1 (D = diag A) and P the piecewise-constant prolongation of the
// aggregates; the diagonal first in each row. Two passes over the aggregates: the length of each
// coarse row, then its entries.
void galerkin(const SparseRows& A, const std::vector<double>& inverse_diagonal, Multigrid& mg, MultigridLevel& L) {
  const std::size_t rows = L.member_begin.size() - 1;
  const int threads = omp_get_max_threads();
  mg.stamp.resize(threads);
  mg.slot.resize(threads);
  std::vector<std::size_t>& length = mg.row_length;
  length.resize(rows);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) L.A.reserve_rows(length);
#pragma omp parallel if (rows > kParallelRows / 4)
    {
      auto& stamp = mg.stamp[omp_get_thread_num()];
      auto& slot = mg.slot[omp_get_thread_num()];
      stamp.assign(rows, -1);
      slot.resize(rows);
#pragma omp for schedule(static)
      for (std::size_t I = 0; I < rows; ++I) {
        const auto row = static_cast<std::int32_t>(I);
        const std::size_t begin = pass == 0 ? 0 : L.A.slot_begin[I];
        std::size_t next = begin;
        auto enter = [&](std::size_t J) {
          stamp[J] = row;
          slot[J] = static_cast<std::int32_t>(next - begin);
          if (pass == 1) {
            L.A.column[next] = static_cast<std::uint32_t>(J);
            L.A.value[next] = 0.0;
          }
          ++next;
        };
        enter(I);  // the diagonal first
        for (std::size_t m = L.member_begin[I]; m < L.member_begin[I + 1]; ++m) {
          const std::size_t i = L.member[m];
          for (std::size_t k = A.slot_begin[i]; k < A.slot_end[i]; ++k) {
            const std::size_t J = L.parent[A.column[k]];
            if (stamp[J] != row) enter(J);
            if (pass == 1) L.A.value[begin + slot[J]] += inverse_diagonal[i] * A.value[k];
          }
        }
        if (pass == 0) length[I] = next;
        else L.A.slot_end[I] = next;
      }
    }
  }
  L.inverse_diagonal.resize(rows);
  for (std::size_t I = 0; I < rows; ++I) L.inverse_diagonal[I] = L.A.inverse_diagonal(I);
  L.b.resize(rows);
  L.x.resize(rows);
  L.r.resize(rows);
}

bool factor_coarsest(Multigrid& mg) {
  const SparseRows& A = mg.levels.back().A;
  const auto n = static_cast<Eigen::Index>(A.rows());
  mg.coarsest_dense.setZero(n, n);
  for (Eigen::Index r = 0; r < n; ++r)
    for (std::size_t k = A.slot_begin[r]; k < A.slot_end[r]; ++k) mg.coarsest_dense(r, A.column[k]) += A.value[k];
  if (!mg.coarsest_dense.allFinite()) return false;
  mg.coarsest.compute(mg.coarsest_dense);
  const double rcond = mg.coarsest.rcond();
  return std::isfinite(rcond) && rcond > 1e-13;
}

// A level of the cycle: its operator and vectors. The finest level's are the caller's.
struct LevelView {
  const SparseRows* A;
  const std::vector<double>* inverse_diagonal;
  const std::vector<double>* b;
  std::vector<double>* x;
  std::vector<double>* r;
};

// r = b - A x.
void residual(const LevelView& v) {
  const std::size_t n = v.A->rows();
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (std::size_t i = 0; i < n; ++i) (*v.r)[i] = (*v.b)[i] - v.A->row_times(i, *v.x);
}

// x += weight D^-1 r.
void jacobi_update(const LevelView& v, double weight) {
  const std::size_t n = v.A->rows();
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (std::size_t i = 0; i < n; ++i) (*v.x)[i] += weight * (*v.inverse_diagonal)[i] * (*v.r)[i];
}

LevelView view(MultigridLevel& L) { return {&L.A, &L.inverse_diagonal, &L.b, &L.x, &L.r}; }

// x = M^-1 b on level `fine` (the finest when fine.A is the caller's matrix); `next` is the index
// in mg.levels of the level below.
void cycle(Multigrid& mg, const LevelView& fine, std::size_t next) {
  const MultigridOptions& o = mg.options;
  const std::size_t n = fine.A->rows();
  // Pre-smoothing from x = 0: the first sweep is x = w D^-1 b.
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (std::size_t i = 0; i < n; ++i) (*fine.x)[i] = o.jacobi_weight * (*fine.inverse_diagonal)[i] * (*fine.b)[i];
  for (int s = 1; s < o.smoothing_sweeps; ++s) {
    residual(fine);
    jacobi_update(fine, o.jacobi_weight);
  }
  residual(fine);
  MultigridLevel& C = mg.levels[next];
  const std::size_t rows = C.A.rows();
#pragma omp parallel for schedule(static) if (rows > kParallelRows)
  for (std::size_t I = 0; I < rows; ++I) {
    double sum = 0.0;
    for (std::size_t m = C.member_begin[I]; m < C.member_begin[I + 1]; ++m) {
      const std::size_t i = C.member[m];
      sum += (*fine.inverse_diagonal)[i] * (*fine.r)[i];
    }
    C.b[I] = sum;
  }
  if (next + 1 == mg.levels.size()) {
    const Eigen::Map<const Eigen::VectorXd> b(C.b.data(), static_cast<Eigen::Index>(rows));
    Eigen::Map<Eigen::VectorXd>(C.x.data(), static_cast<Eigen::Index>(rows)) = mg.coarsest.solve(b);
  } else {
    cycle(mg, view(C), next + 1);
  }
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (std::size_t i = 0; i < n; ++i) (*fine.x)[i] += o.overcorrection * C.x[C.parent[i]];
  for (int s = 0; s < o.smoothing_sweeps; ++s) {
    residual(fine);
    jacobi_update(fine, o.jacobi_weight);
  }
}

}  // namespace

std::size_t Multigrid::memory_bytes() const {
  std::size_t bytes = capacity_bytes(fine_inverse_diagonal) + capacity_bytes(fine_r) + capacity_bytes(fine_cell[0]) + capacity_bytes(fine_cell[1]) + capacity_bytes(fine_cell[2]) +
                      capacity_bytes(sort_keys) + capacity_bytes(row_length) + static_cast<std::size_t>(coarsest_dense.size()) * sizeof(double) * 2;
  for (const auto& v : stamp) bytes += capacity_bytes(v);
  for (const auto& v : slot) bytes += capacity_bytes(v);
  for (const MultigridLevel& L : levels)
    bytes += L.A.memory_bytes() + capacity_bytes(L.inverse_diagonal) + capacity_bytes(L.member_begin) +
             capacity_bytes(L.member) + capacity_bytes(L.parent) + capacity_bytes(L.cell[0]) +
             capacity_bytes(L.cell[1]) + capacity_bytes(L.cell[2]) + capacity_bytes(L.b) + capacity_bytes(L.x) + capacity_bytes(L.r);
  return bytes;
}

template <int D>
bool build_multigrid(const SparseRows& A, const std::vector<Vec<D>>& position, double cell, Multigrid& mg) {
  mg.ready = false;
  const std::size_t n = A.rows();
  refresh_fine_diagonal(A, mg);
  const std::vector<double>& inverse_diagonal = mg.fine_inverse_diagonal;
  if (n <= mg.options.coarsest_rows || !(cell > 0.0)) return false;
  for (int k = 0; k < 3; ++k) mg.fine_cell[k].resize(k < D ? n : 0);
  // A position that is not finite (a run about to fail its finite-value check) or absurdly far
  // has no cell: that step keeps the Jacobi preconditioner.
  // So that the cell keys ((z depth + y) width + x) fit in 64 bits.
  constexpr double kFarthestCell = D == 2 ? 1e9 : 1e6;
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) {
      const double c = std::floor(component(position[i], k) / cell);
      if (!(std::abs(c) < kFarthestCell)) return false;
      mg.fine_cell[k][i] = static_cast<std::int64_t>(c);
    }
  // Level k aggregates the rows of level k - 1 (the caller's matrix for k = 0). Levels are
  // addressed by index: emplace_back may move them.
  std::size_t count = 0;
  while (count < kMaxLevels) {
    if (mg.levels.size() <= count) mg.levels.emplace_back();
    MultigridLevel& L = mg.levels[count];
    if (count == 0) {
      aggregate(mg.fine_cell, 0, mg, L);
      galerkin(A, inverse_diagonal, mg, L);
    } else {
      const MultigridLevel& F = mg.levels[count - 1];
      aggregate(F.cell, 1, mg, L);
      galerkin(F.A, F.inverse_diagonal, mg, L);
    }
    ++count;
    if (L.A.rows() <= mg.options.coarsest_rows) break;
  }
  mg.levels.resize(count);
  mg.fine_r.resize(n);
  mg.ready = factor_coarsest(mg);
  return mg.ready;
}

template bool build_multigrid<2>(const SparseRows&, const std::vector<Vec2>&, double, Multigrid&);
template bool build_multigrid<3>(const SparseRows&, const std::vector<Vec3>&, double, Multigrid&);

void refresh_fine_diagonal(const SparseRows& A, Multigrid& mg) {
  const std::size_t n = A.rows();
  mg.fine_inverse_diagonal.resize(n);
#pragma omp parallel for schedule(static) if (n > kParallelRows)
  for (std::size_t i = 0; i < n; ++i) mg.fine_inverse_diagonal[i] = A.inverse_diagonal(i);
}

void save_multigrid(const Multigrid& mg, StateWriter& w) {
  w.value("multigrid.ready", static_cast<std::uint8_t>(mg.ready));
  w.value("multigrid.levels", static_cast<std::uint64_t>(mg.ready ? mg.levels.size() : 0));
  if (!mg.ready) return;
  w.value("multigrid.fine_rows", static_cast<std::uint64_t>(mg.fine_inverse_diagonal.size()));
  for (const MultigridLevel& L : mg.levels) {
    w.array("multigrid.slot_begin", L.A.slot_begin);
    w.array("multigrid.slot_end", L.A.slot_end);
    w.array("multigrid.column", L.A.column);
    w.array("multigrid.value", L.A.value);
    w.array("multigrid.inverse_diagonal", L.inverse_diagonal);
    w.array("multigrid.member_begin", L.member_begin);
    w.array("multigrid.member", L.member);
    w.array("multigrid.parent", L.parent);
  }
}

void load_multigrid(Multigrid& mg, StateReader& r) {
  mg.ready = r.value<std::uint8_t>("multigrid.ready") != 0;
  const auto count = static_cast<std::size_t>(r.value<std::uint64_t>("multigrid.levels"));
  mg.levels.clear();
  if (!mg.ready) return;
  const auto fine_rows = static_cast<std::size_t>(r.value<std::uint64_t>("multigrid.fine_rows"));
  mg.fine_inverse_diagonal.assign(fine_rows, 1.0);  // refreshed from the matrix before use
  mg.fine_r.resize(fine_rows);
  mg.levels.resize(count);
  for (MultigridLevel& L : mg.levels) {
    L.A.slot_begin = r.array<std::size_t>("multigrid.slot_begin");
    L.A.slot_end = r.array<std::size_t>("multigrid.slot_end");
    L.A.column = r.array<std::uint32_t>("multigrid.column");
    L.A.value = r.array<double>("multigrid.value");
    L.inverse_diagonal = r.array<double>("multigrid.inverse_diagonal");
    L.member_begin = r.array<std::size_t>("multigrid.member_begin");
    L.member = r.array<std::uint32_t>("multigrid.member");
    L.parent = r.array<std::uint32_t>("multigrid.parent");
    const std::size_t rows = L.A.rows();
    L.b.resize(rows);
    L.x.resize(rows);
    L.r.resize(rows);
  }
  mg.ready = count > 0 && factor_coarsest(mg);
}

void apply_multigrid(const SparseRows& A, Multigrid& mg, const std::vector<double>& r, std::vector<double>& z) {
  const std::vector<double>& inverse_diagonal = mg.fine_inverse_diagonal;
  if (!mg.ready) {
    const std::size_t n = A.rows();
#pragma omp parallel for schedule(static) if (n > kParallelRows)
    for (std::size_t i = 0; i < n; ++i) z[i] = inverse_diagonal[i] * r[i];
    return;
  }
  cycle(mg, {&A, &inverse_diagonal, &r, &z, &mg.fine_r}, 0);
}

}  // namespace sloshsph
