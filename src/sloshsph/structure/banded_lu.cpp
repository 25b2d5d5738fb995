#include "sloshsph/structure/banded_lu.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace sloshsph {

BandedLu::BandedLu(int n, int lower, int upper)
    : n_(n), lower_(lower), upper_(upper), width_(static_cast<std::size_t>(2 * lower + upper + 1)) {
  if (n < 0 || lower < 0 || upper < 0) throw std::invalid_argument("BandedLu: negative size or bandwidth");
  values_.assign(static_cast<std::size_t>(n) * width_, 0.0);
  pivots_.assign(static_cast<std::size_t>(n), 0);
}

void BandedLu::set_zero() { std::fill(values_.begin(), values_.end(), 0.0); }

void BandedLu::add(int row, int col, double value) {
  if (row < 0 || row >= n_ || col < 0 || col >= n_ || col - row < -lower_ || col - row > upper_) {
    throw std::out_of_range("BandedLu: entry (" + std::to_string(row) + ", " + std::to_string(col) +
                            ") outside the band");
  }
  at(row, col) += value;
}

// Column k: pick the largest pivot among rows k..k+lower, swap it into row k (columns k..k+upper+lower,
// the reach of the pivot row after earlier swaps), then eliminate below. The multipliers stay where
// they were computed; solve() replays the interchanges and eliminations in the same order.
bool BandedLu::factorize() {
  for (int k = 0; k < n_; ++k) {
    const int last_row = std::min(n_ - 1, k + lower_);
    const int last_col = std::min(n_ - 1, k + upper_ + lower_);
    int pivot = k;
    for (int i = k + 1; i <= last_row; ++i) {
      if (std::abs(at(i, k)) > std::abs(at(pivot, k))) pivot = i;
    }
    pivots_[static_cast<std::size_t>(k)] = pivot;
    if (at(pivot, k) == 0.0 || !std::isfinite(at(pivot, k))) return false;
    if (pivot != k) {
      for (int j = k; j <= last_col; ++j) std::swap(at(k, j), at(pivot, j));
    }
    const double inverse_pivot = 1.0 / at(k, k);
    for (int i = k + 1; i <= last_row; ++i) {
      const double multiplier = at(i, k) * inverse_pivot;
      at(i, k) = multiplier;
      if (multiplier == 0.0) continue;
      for (int j = k + 1; j <= last_col; ++j) at(i, j) -= multiplier * at(k, j);
    }
  }
  return true;
}

void BandedLu::solve(Eigen::VectorXd& rhs) const {
  for (int k = 0; k < n_; ++k) {
    const int pivot = pivots_[static_cast<std::size_t>(k)];
    if (pivot != k) std::swap(rhs[k], rhs[pivot]);
    const int last_row = std::min(n_ - 1, k + lower_);
    for (int i = k + 1; i <= last_row; ++i) rhs[i] -= at(i, k) * rhs[k];
  }
  for (int k = n_ - 1; k >= 0; --k) {
    const int last_col = std::min(n_ - 1, k + upper_ + lower_);
    double sum = rhs[k];
    for (int j = k + 1; j <= last_col; ++j) sum -= at(k, j) * rhs[j];
    rhs[k] = sum / at(k, k);
  }
}

}  // namespace sloshsph
