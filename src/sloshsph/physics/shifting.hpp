#pragma once
// Particle shifting (scheme.shifting): after each step, every fluid particle is moved a little
// down the gradient of the particle concentration, which evens out the clusters and voids that a
// purely Lagrangian motion leaves behind in sheared and violent flow and that degrade the pressure
// and the fronts. The seeds do not shift; the field has since made it standard for ISPH.
//
// Fickian shifting of Lind, Xu, Stansby & Rogers (2012, J. Comput. Phys. 231, 1499-1523):
//   delta_r_i = -D grad C_i,   D = A h |u_i| dt
//   grad C_i = sum_j V_j (1 + R (W_ij / W(dp))^n) grad_i W_ij,  R = 0.2, n = 4
// (the factor in R is the anti-clustering term after Monaghan 2000: it keeps apart a pair that
// came too close, where the plain gradient vanishes)
// with A = 2 (Lind et al. use A = 2; the admissible range they give is 1 to 6). Wall particles
// (Adami dummy particles, V = dp^2) count in C, so that a full kernel next to a wall is uniform.
//
// At the free surface C is low because the kernel is truncated, not because the fluid is sparse,
// and shifting along grad C would push particles out of the fluid. Lind et al. (2012, 3.2) keep
// only the shift along the surface there (their alpha = 0): delta_r <- delta_r - (delta_r.n) n,
// n = grad C / |grad C| from the gradient without the anti-clustering factor (the part of the shift
// that this factor adds is what moves a near-surface particle away from a close neighbour). We apply it to every particle whose kernel reaches the surface (a
// surface or spray particle among its neighbours, or itself flagged), since below the top row the
// truncation still dominates grad C; spray (too little fluid in its kernel to define C) is not
// shifted.
//
// The quantities a particle carries are corrected to its new position by a first-order Taylor
// term (Lind et al. 2012): u_i <- u_i + (delta_r . grad) u_i. ISPH's pressure is solved afresh
// each step and is not transported, so it is not corrected.
//
// The weakly compressible scheme uses the same shift with the diffusion coefficient of the
// particle shifting technique of delta-plus-SPH (Sun, Colagrossi, Marrone, Antuono & Zhang 2017,
// Comput. Methods Appl. Mech. Engrg. 315, 25-49): delta_r_i = -CFL Ma (2h)^2 grad C_i with the same
// anti-clustering term, where CFL = c0 dt / h and Ma = U_max / c0, i.e. D = 4 h U_max dt, one value
// for all particles; its density is corrected by the same Taylor term as the velocity.
//
// Limits (issue 30): a shift is at most `max_shift` long, and never moves a particle towards a
// wall particle's plane closer than dp (the spacing of still water at a wall: fluid stands dp/2
// inside the wall surface, the first wall layer dp/2 outside), so that a shift never carries a
// particle through a wall, a thin plate or a slat. A shift cut by either limit is counted.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

struct ShiftingRule {
  double coefficient = 2.0;  // A of D = A h |u| dt (Lind et al. 2012); unused by the WCSPH shift
  double h = 0.0;            // m, smoothing length
  double dp = 0.0;           // m, particle spacing
  double w_dp = 0.0;         // W(dp), 1/m^2 (1/m^3 in 3D), for the anti-clustering term
  double max_shift = 0.0;    // m, the longest shift of one step
};

// The concentration gradient at particle i (1/m): `shifting` with the anti-clustering factor
// 1 + 0.2 (W_ij / W(dp))^4 of Lind et al. (2012), which drives the shift, and `plain` without it,
// which gives the free-surface normal. (Taken from the shift's own gradient, the normal would be
// parallel to the shift, and removing the normal part would leave nothing near the surface.)
template <int D>
struct ConcentrationGradient {
  Vec<D> shifting;
  Vec<D> plain;
};
template <int D>
ConcentrationGradient<D> concentration_gradient(const BasicPairList<D>& pairs, double volume, double w_dp,
                                                std::size_t i) {
  ConcentrationGradient<D> g;
  pairs.for_each(i, [&](const BasicPair<D>& q) {
    const double ratio = q.w / w_dp;
    const double r2 = ratio * ratio;
    const Vec<D> term = q.rij * (volume * q.f);
    g.plain += term;
    g.shifting += term * (1.0 + 0.2 * r2 * r2);
  });
  return g;
}

// The shift with its component along grad C (the surface normal, from the plain gradient) removed
// (Lind et al. 2012, 3.2).
template <int D>
Vec<D> along_free_surface(Vec<D> shift, Vec<D> grad_c) {
  const double g2 = norm2(grad_c);
  if (g2 == 0.0) return shift;
  return shift - grad_c * (dot(shift, grad_c) / g2);
}

// Wall particle j's plane as fluid at ri sees it: the normal on ri's side (a thin plate or slat
// has fluid on both faces) and ri's distance from the plane along it.
template <int D>
struct WallPlane {
  Vec<D> normal;
  double distance;
};
template <int D>
WallPlane<D> wall_plane_seen_from(const BasicParticles<D>& p, std::size_t j, Vec<D> ri) {
  const double s = dot(ri - p.position[j], p.normal[j]);
  return s >= 0.0 ? WallPlane<D>{p.normal[j], s} : WallPlane<D>{-p.normal[j], -s};
}

// `shift` of fluid particle i (at p.position[i]) limited so that it brings the particle no closer
// than dp to the plane of any wall particle among its pairs; a particle already closer may not
// come closer still. Returns whether the shift was cut.
template <int D>
bool keep_shift_off_walls(const BasicParticles<D>& p, const BasicPairList<D>& pairs, std::size_t i, double dp,
                          Vec<D>& shift) {
  const Vec<D> ri = p.position[i];
  // The most negative move along the plane's normal that keeps the particle dp from it.
  auto allowed = [dp](const WallPlane<D>& w) { return -std::max(w.distance - dp, 0.0); };
  bool cut = false;
  pairs.for_each(i, [&](const BasicPair<D>& q) {
    if (p.is_fluid(q.j)) return;
    const WallPlane<D> w = wall_plane_seen_from(p, q.j, ri);
    const double towards = dot(shift, w.normal);
    if (towards >= allowed(w)) return;
    shift += w.normal * (allowed(w) - towards);
    cut = true;
  });
  if (!cut) return false;
  // A later limit can undo an earlier one only where wall normals point against each other (both
  // faces of a thin plate in one kernel): no shift at all then.
  pairs.for_each(i, [&](const BasicPair<D>& q) {
    if (p.is_fluid(q.j)) return;
    const WallPlane<D> w = wall_plane_seen_from(p, q.j, ri);
    if (dot(shift, w.normal) < allowed(w) - 1e-12 * dp) shift = Vec<D>{};
  });
  return true;
}

// Free-surface flags the shift reads, one per fluid particle: 0 inside the fluid, 1 at the free
// surface, 2 spray (not shifted).
enum : std::uint8_t { kShiftInterior = 0, kShiftSurface = 1, kShiftSpray = 2 };

// Scratch of shift_fluid, kept by the scheme between steps.
template <int D>
struct BasicShiftingWork {
  std::vector<Vec<D>> shift;         // delta_r of each fluid particle, m
  std::vector<Vec<D>> velocity;      // (delta_r . grad) u, m/s
  std::vector<double> density;       // (delta_r . grad) rho (WCSPH), kg/m^3
  std::size_t memory_bytes() const {
    return (shift.capacity() + velocity.capacity()) * sizeof(Vec<D>) + density.capacity() * sizeof(double);
  }
};
using ShiftingWork = BasicShiftingWork<2>;

// The shift of every fluid particle of `p` (pairs at about its present positions), with
// diffusion coefficient diffusion(i) (m^2), the surface treatment, the limits and the Taylor
// correction of the velocity (and of the density, when `density` is given: the WCSPH scheme
// carries it). Every shift is worked out before any particle moves (gather), so the result does not
// depend on the thread count. Returns how many shifts were cut by a limit.
template <int D, class Diffusion>
std::size_t shift_fluid(BasicParticles<D>& p, const BasicPairList<D>& pairs, const std::vector<std::uint8_t>& surface,
                        const ShiftingRule& rule, Diffusion&& diffusion, std::vector<double>* density,
                        BasicShiftingWork<D>& work) {
  const double V = p.volume;
  const std::size_t nf = p.n_fluid;
  work.shift.assign(nf, Vec<D>{});
  work.velocity.assign(nf, Vec<D>{});
  work.density.assign(density ? nf : 0, 0.0);
  std::size_t cut = 0;
#pragma omp parallel for schedule(static) reduction(+ : cut)
  for (std::size_t i = 0; i < nf; ++i) {
    if (surface[i] == kShiftSpray) continue;  // too little fluid in its kernel to define C
    bool near_surface = surface[i] == kShiftSurface;
    pairs.for_each(i, [&](const BasicPair<D>& q) { near_surface |= p.is_fluid(q.j) && surface[q.j] != kShiftInterior; });
    const ConcentrationGradient<D> grad_c = concentration_gradient(pairs, V, rule.w_dp, i);
    Vec<D> shift = grad_c.shifting * -diffusion(i);
    if (near_surface) shift = along_free_surface(shift, grad_c.plain);
    bool limited = false;
    const double length = norm(shift);
    if (length > rule.max_shift) {
      shift = shift * (rule.max_shift / length);
      limited = true;
    }
    limited = keep_shift_off_walls(p, pairs, i, rule.dp, shift) || limited;
    cut += limited ? 1 : 0;
    // (delta_r . grad) phi with the SPH gradient sum_j V (phi_j - phi_i) grad_i W_ij; a wall
    // neighbour carries its wall values (ISPH: the free-slip image velocity).
    const Vec<D> ui = p.velocity[i];
    const double rho_i = p.density[i];
    Vec<D> du;
    double drho = 0.0;
    pairs.for_each(i, [&](const BasicPair<D>& q) {
      const double along = V * q.f * dot(q.rij, shift);
      du += (p.velocity[q.j] - ui) * along;
      if (density) drho += (p.density[q.j] - rho_i) * along;
    });
    work.shift[i] = shift;
    work.velocity[i] = du;
    if (density) work.density[i] = drho;
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nf; ++i) {
    p.position[i] += work.shift[i];
    p.velocity[i] += work.velocity[i];
    if (density) (*density)[i] += work.density[i];
  }
  return cut;
}

}  // namespace sloshsph
