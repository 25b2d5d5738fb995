#include "sloshsph/schemes/ppe_solver.hpp"

#include "sloshsph/schemes/ppe_multigrid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace sloshsph {

void SparseRows::reserve_rows(const std::vector<std::size_t>& capacity) {
  const std::size_t n = capacity.size();
  slot_begin.resize(n);
  slot_end.resize(n);
  std::size_t next = 0;
  for (std::size_t r = 0; r < n; ++r) {
    slot_begin[r] = slot_end[r] = next;
    next += capacity[r];
  }
  // Grown by a tenth beyond the need, not doubled as resize would: the matrix is the largest
  // array of a step, and its size varies a little from step to step.
  if (column.capacity() < next) {
    column.reserve(next + next / 10);
    value.reserve(next + next / 10);
  }
  column.resize(next);
  value.resize(next);
}

std::size_t SparseRows::memory_bytes() const {
  return (slot_begin.capacity() + slot_end.capacity()) * sizeof(std::size_t) +
         column.capacity() * sizeof(std::uint32_t) + value.capacity() * sizeof(double);
}

std::size_t BicgstabWork::memory_bytes() const {
  std::size_t n = block_sums.capacity();
  for (const auto* v : {&inverse_diagonal, &r, &r0, &p, &v, &t, &y}) n += v->capacity();
  return n * sizeof(double);
}

namespace {

// Sums are taken per block of kBlock rows, then over the blocks in order: the blocks do not
// depend on the thread count, so neither does any sum.
constexpr std::size_t kBlock = 256;

template <int K, class Body>
std::array<double, K> blocked_sums(std::size_t n, std::vector<double>& sums, const Body& body) {
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  sums.resize(blocks * K);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < blocks; ++b) {
    std::array<double, K> part{};
    body(b * kBlock, std::min(n, (b + 1) * kBlock), part);
    for (int k = 0; k < K; ++k) sums[b * K + k] = part[k];
  }
  std::array<double, K> total{};
  for (std::size_t b = 0; b < blocks; ++b)
    for (int k = 0; k < K; ++k) total[k] += sums[b * K + k];
  return total;
}

// r = b - A x; returns |r|^2.
double residual(const SparseRows& A, const std::vector<double>& b, const std::vector<double>& x, std::vector<double>& r,
                std::vector<double>& sums) {
  return blocked_sums<1>(b.size(), sums, [&](std::size_t i0, std::size_t i1, std::array<double, 1>& acc) {
    for (std::size_t i = i0; i < i1; ++i) {
      r[i] = b[i] - A.row_times(i, x);
      acc[0] += r[i] * r[i];
    }
  })[0];
}

}  // namespace

KrylovReport solve_bicgstab(const SparseRows& A, const std::vector<double>& b, std::vector<double>& x, double tolerance,
                            int max_iterations, BicgstabWork& w, Multigrid* multigrid) {
  const std::size_t n = b.size();
  for (auto* v : {&w.inverse_diagonal, &w.r, &w.r0, &w.p, &w.v, &w.t, &w.y}) v->resize(n);
  KrylovReport report;
  const double b2 = blocked_sums<1>(n, w.block_sums, [&](std::size_t i0, std::size_t i1, std::array<double, 1>& acc) {
    for (std::size_t i = i0; i < i1; ++i) {
      acc[0] += b[i] * b[i];
      w.inverse_diagonal[i] = A.inverse_diagonal(i);
    }
  })[0];
  if (b2 == 0.0) {
    std::fill(x.begin(), x.end(), 0.0);
    report.converged = true;
    return report;
  }
  double r2 = residual(A, b, x, w.r, w.block_sums);
  w.r0 = w.r;
  double r0_2 = r2;
  std::fill(w.p.begin(), w.p.end(), 0.0);
  std::fill(w.v.begin(), w.v.end(), 0.0);
  const double tol2 = tolerance * tolerance * b2;
  const double eps2 = std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();
  double rho = 1.0, alpha = 1.0, omega = 1.0;
  double r0_r = r2;  // r0·r, the next rho
  int restarts = 0;
  int i = 0;
  while (r2 > tol2 && i < max_iterations) {
    const double rho_old = rho;
    rho = r0_r;
    if (std::abs(rho) < eps2 * r0_2) {
      // r has become orthogonal to r0: start again from here with r0 = r.
      r2 = residual(A, b, x, w.r, w.block_sums);
      w.r0 = w.r;
      rho = r0_2 = r2;
      if (restarts++ == 0) i = 0;
    }
    const double beta = (rho / rho_old) * (alpha / omega);
    // y holds M^-1 p, then M^-1 s; r holds s = r - alpha v, then the new residual s - omega t.
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      w.p[k] = w.r[k] + beta * (w.p[k] - omega * w.v[k]);
      if (!multigrid) w.y[k] = w.inverse_diagonal[k] * w.p[k];
    }
    if (multigrid) apply_multigrid(A, *multigrid, w.p, w.y);
    const double r0_v = blocked_sums<1>(n, w.block_sums, [&](std::size_t i0, std::size_t i1, std::array<double, 1>& acc) {
      for (std::size_t k = i0; k < i1; ++k) {
        w.v[k] = A.row_times(k, w.y);
        acc[0] += w.r0[k] * w.v[k];
      }
    })[0];
    alpha = rho / r0_v;
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      x[k] += alpha * w.y[k];
      w.r[k] -= alpha * w.v[k];
      if (!multigrid) w.y[k] = w.inverse_diagonal[k] * w.r[k];
    }
    if (multigrid) apply_multigrid(A, *multigrid, w.r, w.y);
    const auto ts = blocked_sums<2>(n, w.block_sums, [&](std::size_t i0, std::size_t i1, std::array<double, 2>& acc) {
      for (std::size_t k = i0; k < i1; ++k) {
        w.t[k] = A.row_times(k, w.y);
        acc[0] += w.t[k] * w.t[k];
        acc[1] += w.t[k] * w.r[k];
      }
    });
    omega = ts[0] > 0.0 ? ts[1] / ts[0] : 0.0;
    const auto next = blocked_sums<2>(n, w.block_sums, [&](std::size_t i0, std::size_t i1, std::array<double, 2>& acc) {
      for (std::size_t k = i0; k < i1; ++k) {
        x[k] += omega * w.y[k];
        w.r[k] -= omega * w.t[k];
        acc[0] += w.r[k] * w.r[k];
        acc[1] += w.r0[k] * w.r[k];
      }
    });
    r2 = next[0];
    r0_r = next[1];
    ++i;
  }
  report.iterations = i;
  report.relative_residual = std::sqrt(r2 / b2);
  report.converged = std::isfinite(r2) && r2 <= tol2;
  return report;
}

namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t r) {
  while (parent[r] != r) r = parent[r] = parent[parent[r]];  // path halving
  return r;
}

}  // namespace

std::vector<std::uint32_t> rows_without_anchor(const SparseRows& A, double weak) {
  const std::size_t n = A.rows();
  std::vector<std::uint32_t> parent(n);
  for (std::size_t r = 0; r < n; ++r) parent[r] = static_cast<std::uint32_t>(r);
  std::vector<char> anchored(n, 0);
  for (std::size_t r = 0; r < n; ++r) {
    double sum = 0.0, diagonal = 0.0;
    for (std::size_t k = A.slot_begin[r]; k < A.slot_end[r]; ++k) {
      sum += A.value[k];
      if (A.column[k] == r) diagonal = A.value[k];
    }
    for (std::size_t k = A.slot_begin[r]; k < A.slot_end[r]; ++k) {
      if (std::abs(A.value[k]) <= weak * std::abs(diagonal)) continue;  // a link too weak to count
      const std::uint32_t a = find_root(parent, static_cast<std::uint32_t>(r)), b = find_root(parent, A.column[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
    anchored[r] = std::abs(sum) > weak * std::abs(diagonal) || diagonal == 0.0;
  }
  std::vector<char> root_anchored(n, 0);
  for (std::size_t r = 0; r < n; ++r)
    if (anchored[r]) root_anchored[find_root(parent, static_cast<std::uint32_t>(r))] = 1;
  std::vector<std::uint32_t> rows;
  for (std::size_t r = 0; r < n; ++r)
    if (!root_anchored[find_root(parent, static_cast<std::uint32_t>(r))]) rows.push_back(static_cast<std::uint32_t>(r));
  return rows;
}

}  // namespace sloshsph
