#pragma once
// Agreement between a model curve and a reference curve.
#include <cstddef>
#include <vector>

namespace sloshsph {

struct NormalisedError {
  double epsilon = 0.0;  // sqrt(sum (F_model - F_ref)^2 / sum F_ref^2)
  std::size_t points = 0;  // reference points used
  std::size_t skipped = 0;  // reference points outside the model's abscissa range
};

// Thesis eq. 2.29 (after Love & Tait 2013): eps = sqrt(sum_i (F_i^SPH - F_i^exp)^2 / sum_i (F_i^exp)^2)
// over the reference points i (e.g. the frequencies of a measured frequency response). The model
// curve is linearly interpolated onto the reference abscissae; reference points outside the
// model's range are skipped (and counted) rather than extrapolated. Love & Tait suggest
// eps <= 0.1 as acceptable. The model abscissae must be strictly increasing; throws
// std::invalid_argument otherwise, or if no reference point can be used.
NormalisedError normalised_error(const std::vector<double>& x_ref, const std::vector<double>& f_ref,
                                 const std::vector<double>& x_model, const std::vector<double>& f_model);

}  // namespace sloshsph
