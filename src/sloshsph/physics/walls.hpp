#pragma once
// Dummy wall particles (Adami, Hu & Adams 2012), as thesis 2.4.3.1 and 3.3.2.2: fixed tank walls,
// and moving ones (elastic plates) through Particles::wall_velocity / wall_acceleration; written
// once for 2 and 3 dimensions.
#include <algorithm>
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/physics/frame.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

// Free slip: each wall particle takes the Shepard-averaged fluid velocity u~ around it with
// its normal component reflected, u_w = u~ - 2 ((u~ - v_w) . n) n (v_w = 0 for a fixed wall). In viscous and turbulent terms
// the fluid then feels no tangential drag and twice its normal velocity (no penetration).
// Uses the local wall normal, so it holds on sloped and curved walls (thesis 3.3.2.2).
// `pairs` at the positions the velocities belong to.
template <int D>
void extrapolate_wall_velocity(const BasicParticles<D>& p, const BasicPairList<D>& pairs,
                               std::vector<Vec<D>>& velocity) {
#pragma omp parallel for schedule(static)
  for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
    Vec<D> sum;
    double wsum = 0.0;
    pairs.for_each(w, [&](const BasicPair<D>& q) {
      sum += q.w * p.velocity[q.j];
      wsum += q.w;
    });
    const Vec<D> u = wsum > 0.0 ? sum / wsum : Vec<D>{};
    const Vec<D> n = p.normal[w];
    // A moving wall (velocity v_w) reflects the normal velocity relative to itself: the mean of
    // fluid and image normal velocities is then the wall's, u_w.n = 2 v_w.n - u.n (Adami et al.
    // 2012, eq. 23, applied to the normal component only: free slip).
    velocity[w] = u - 2.0 * dot(u - p.wall_velocity(w), n) * n;
  }
}

// Thesis eq. 2.19 (Adami et al. 2012, eq. 27) with the frame acceleration:
//   p_w = (sum_f p_f W_wf + (g - a) . sum_f rho_f (r_w - r_f) W_wf) / sum_f W_wf,
// where g - a is the tank-frame body force at the wall particle (frame.at(r_w, 0)) less the
// wall's own acceleration in the tank frame (moving walls: elastic plates). `pairs` are taken at
// the fluid positions to use (r* inside an ISPH step). A wall particle with no fluid around it gets
// p = 0, and the result is clipped at 0: above the free surface the extrapolation goes negative,
// and a negative wall pressure would pull surface particles up along the wall (the fluid
// mirrored there is air, p = 0).
// Each side of a wall particle has its own sums: `pressure` from the fluid its normal points to,
// `pressure_back` from the fluid behind it. Tank walls have fluid on one side only; a thin wall
// (an explicit screen slat, one particle thick) has fluid on both, and each side must feel only
// its own fluid or the pressure drop across the screen would be averaged away.
template <int D>
void adami_wall_pressure(BasicParticles<D>& p, const BasicPairList<D>& pairs, const BasicFrameForce<D>& frame,
                         double rho0) {
#pragma omp parallel for schedule(static)
  for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
    const Vec<D> rw = p.position[w], n = p.normal[w];
    double psum[2] = {0.0, 0.0}, wsum[2] = {0.0, 0.0};
    Vec<D> rsum[2];
    pairs.for_each(w, [&](const BasicPair<D>& q) {
      const Vec<D> rwf = q.rij;
      const int side = dot(rwf, n) > 0.0 ? 1 : 0;  // fluid behind the wall: r_f - r_w against n
      psum[side] += q.w * p.pressure[q.j];
      rsum[side] += q.w * rwf;
      wsum[side] += q.w;
    });
    const Vec<D> g = frame.at(rw, Vec<D>{}) - p.wall_acceleration(w);  // Adami eq. 27: (g - a_w)
    auto extrapolate = [&](int s) { return wsum[s] > 0.0 ? std::max(0.0, (psum[s] + rho0 * dot(g, rsum[s])) / wsum[s]) : 0.0; };
    p.pressure[w] = extrapolate(0);
    p.pressure_back[w] = extrapolate(1);
  }
}

// The pressure of wall particle w as fluid at r_f sees it (see adami_wall_pressure).
template <int D>
double wall_pressure_seen_from(const BasicParticles<D>& p, std::size_t w, Vec<D> r_f) {
  return dot(r_f - p.position[w], p.normal[w]) < 0.0 ? p.pressure_back[w] : p.pressure[w];
}

}  // namespace sloshsph
