#pragma once
// Shepard (zeroth-order) re-normalised interpolation of the weakly compressible scheme:
// the density re-normalisation of Shao et al. 2012 (eqs. 10-11) and the field values of the
// virtual particles of their coupled dynamic solid boundary treatment (eqs. 29-30).
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

// Shao eqs. 10-11: rho_i <- sum_j m_j W_ij / sum_j (m_j / rho_j) W_ij, the sum over i itself
// and every neighbour (fluid and wall particles, the walls carrying the densities of their
// pressure). A constant density is reproduced exactly whatever the particle arrangement,
// including at a free surface where the kernel is truncated; particle-scale noise is
// averaged out. Writes the fluid densities to `out` (size >= n_fluid); reads p.density.
template <int D>
void shepard_density(const BasicParticles<D>& p, const BasicPairList<D>& pairs, std::vector<double>& out) {
  const double m = p.mass, w0 = pairs.self_w();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    double num = m * w0, den = m * w0 / p.density[i];
    pairs.for_each(i, [&](const BasicPair<D>& q) {
      num += m * q.w;
      den += m * q.w / p.density[q.j];
    });
    out[i] = num / den;
  }
}

// Shao eqs. 29-30 for the virtual (wall) particles, interpolated from the fluid around them
// with the Shepard-normalised kernel W_new = W / sum_f V_f W:
//   rho_w = sum_f m W / sum_f V_f W            (eq. 29)
//   u_w   = -sum_f V_f u_f W / sum_f V_f W     (eq. 30: no slip, the image of the fluid velocity)
// V_f = m / rho_f. A wall particle with no fluid around it gets rho0 and zero velocity.
// Writes p.density and p.velocity of the wall particles only.
template <int D>
void shepard_wall_values(BasicParticles<D>& p, const BasicPairList<D>& pairs, double rho0) {
  const double m = p.mass;
#pragma omp parallel for schedule(static)
  for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
    double mass_sum = 0.0, volume_sum = 0.0;
    Vec<D> u_sum;
    pairs.for_each(w, [&](const BasicPair<D>& q) {
      const double VW = m / p.density[q.j] * q.w;
      mass_sum += m * q.w;
      volume_sum += VW;
      u_sum += VW * p.velocity[q.j];
    });
    if (volume_sum > 0.0) {
      p.density[w] = mass_sum / volume_sum;
      p.velocity[w] = -(u_sum / volume_sum);
    } else {
      p.density[w] = rho0;
      p.velocity[w] = {};
    }
  }
}

}  // namespace sloshsph
