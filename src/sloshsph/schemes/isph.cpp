#include "sloshsph/schemes/isph.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/core/state_io.hpp"
#include "sloshsph/geometry/cylinder_tank.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/physics/wall_repulsion.hpp"
#include "sloshsph/physics/walls.hpp"
#include "sloshsph/sph/kernel.hpp"
#include "sloshsph/sph/operators.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

template <int D>
void BasicIsphData<D>::resize(std::size_t n) {
  velocity_old.resize(n);
  velocity_star.resize(n);
  position_star.resize(n);
  ppe_source.resize(n);
  free_surface.resize(n);
  sps_stress.resize(n);
  wall_acceleration.resize(n);
}

// Below this fraction of fluid in its kernel a particle is spray in flight: its pressure is 0
// in both free-surface models. (A lone particle has 0.28 of a full kernel at h = 1.4 dp, the
// top row of still water 0.77.) Without it the "air" model solves the PPE for a cluster of a
// few droplets, unconnected to any p = 0 condition: measured, a jet of three particles along
// a wall reached -6e5 Pa and 30 m/s.
constexpr double kSplashFraction = 0.5;

std::uint8_t free_surface_flag(double fluid_sum, double wall_sum, double total, double full, double threshold) {
  const double fluid_fraction = fluid_sum / std::max(full - wall_sum, 0.25 * full);
  return fluid_fraction < kSplashFraction ? 2 : total < threshold * full ? 1 : 0;
}

template <int D>
BasicIsphScheme<D>::BasicIsphScheme(const CaseSpec& spec, double h)
    : scheme_(spec.scheme),
      kernel_type_(spec.particles.kernel),
      h_(h),
      dp_(spec.particles.dp),
      rho0_(spec.fluid.density),
      nu_(spec.fluid.viscosity),
      eta2_(0.01 * h * 0.01 * h),
      rho_ref_(times_particle_volume<D>(spec.fluid.density, spec.particles.dp) *
               lattice_number_density(spec.particles.kernel, h, spec.particles.dp, D)),
      neighbours_(2.0 * h, spec.scheme.neighbour_skin * 2.0 * h),
      tank_(spec.tank),
      tank_where_(spec.where("tank.shape")),
      still_depth_(spec.fill.depth),
      gravity_(spec.fluid.gravity) {
  with_kernel(
      kernel_type_, h,
      [&](const auto& k) {
        const double dp = dp_;
        const int n = static_cast<int>(std::ceil(k.support() / dp)) + 1;
        lambda_full_ = 0.0;
        for_each_lattice_point(D, n, [&](int a, int b, int c) {
          if (a == 0 && b == 0 && c == 0) return;
          const double r2 = dp * dp * (a * a + b * b + c * c);
          lambda_full_ += laplacian_weight(times_particle_volume<D>(1.0, dp), k.gradient_factor(std::sqrt(r2)), r2, eta2_) / rho0_;
        });
        shifting_.w_dp = k.w(dp);
      },
      D);
  // The explicit update reads the density at the step's end; the case reader refuses the pair.
  assert(!(scheme_.pressure == PressureSolve::explicit_update && scheme_.predictor == PositionPredictor::midpoint));
  shifting_.coefficient = spec.scheme.shifting_coefficient;
  shifting_.h = h;
  shifting_.dp = dp_;
  shifting_.max_shift = spec.scheme.shifting_max * dp_;
}

template <int D>
MemoryParts BasicIsphData<D>::memory_parts() const {
  const std::size_t n = velocity_old.capacity();
  const std::size_t per = 4 * sizeof(Vec<D>) + sizeof(double) + 1 + sizeof(SymTensor<D>);
  const std::size_t particle_arrays = n * per + extra_acceleration.capacity() * sizeof(Vec<D>);
  const std::size_t ppe_vectors = ppe_row.capacity() * sizeof(int) + ppe_particle.capacity() * sizeof(std::uint32_t) +
                                  ppe_row_capacity.capacity() * sizeof(std::size_t) +
                                  (ppe_rhs.capacity() + ppe_solution.capacity()) * sizeof(double) +
                                  ppe_row_position.capacity() * sizeof(Vec<D>) +
                                  multigrid_rows.capacity() * sizeof(std::uint32_t);
  return {{"particle_arrays", particle_arrays},
          {"pairs", pairs.memory_bytes()},
          {"ppe_matrix", ppe_matrix.memory_bytes()},
          {"ppe_vectors", ppe_vectors},
          {"krylov", krylov.memory_bytes()},
          {"multigrid", multigrid.memory_bytes()},
          {"shifting", shifting.memory_bytes()}};
}

template <int D>
MemoryParts BasicIsphScheme<D>::memory_parts() const {
  MemoryParts parts = data_.memory_parts();
  parts.push_back({"neighbour_list", neighbours_.memory_bytes()});
  return parts;
}

template <int D>
void BasicIsphScheme<D>::update_neighbours(ParticleSet& p) {
  diagnostics_.neighbours_rebuilt = false;
  if (!neighbours_.stale(p.position, p.n_fluid)) return;
  // Keep the fluid in cell order: neighbours then sit close in memory.
  p.permute_fluid(cell_order(p.position, p.n_fluid, neighbours_.search_radius()));
  neighbours_.build(p.position, p.n_fluid);
  diagnostics_.neighbours_rebuilt = true;
}

// The first layer of the tank walls: sample_walls puts it dp/2 outside the wall surface (the
// next layers at 3dp/2, ...); explicit screen slats stand inside the section and are left out
// (the fluid must pass between them). Each gets D = coefficient g max(H_w, h) (eq. 3.18,
// physics/wall_repulsion.hpp), H_w the still-water depth above it (the height is y in 2D, z in 3D).
template <int D>
void BasicIsphScheme<D>::mark_repulsive_layer(const ParticleSet& p) {
  repulsion_strength_.assign(p.n_wall(), 0.0);
  if (!scheme_.repulsive_walls) return;
  const std::function<double(Vec<D>)> distance = tank_signed_distance<D>(tank_, tank_where_);
  // A cylinder's bottom is that of the section it stands in (plane_section: a rectangle, bottom 0).
  const double bottom = make_tank(plane_section(tank_), tank_where_).y_bottom;
  const double level = bottom + still_depth_;
  for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
    const double d = distance(p.position[w]);
    if (d < 0.0 && d > -dp_)
      repulsion_strength_[w - p.n_fluid] =
          scheme_.repulsive_coefficient * gravity_ * std::max(level - component(p.position[w], D - 1), h_);
  }
}

template <int D>
void BasicIsphScheme<D>::build_pairs(const std::vector<Vec<D>>& position) {
  data_.pairs.build(kernel_type_, h_, position, neighbours_);
}

template <int D>
void BasicIsphScheme<D>::initialise(ParticleSet& p, const BasicFrameForce<D>& frame) {
  update_neighbours(p);
  data_.resize(p.size());
  BasicIsphData<D>& d = data_;
  for (std::size_t i = 0; i < p.size(); ++i) d.position_star[i] = p.position[i];
  build_pairs(d.position_star);
  extrapolate_wall_velocity(p, d.pairs, p.velocity);
  // The pressure that holds the particles as they are: the discrete PPE with a zero source
  // (fluid at rest), its free surface and wall conditions, solved once. Starting from the
  // analytic hydrostatic field instead would start a pressure transient (the top particles
  // sit dp/2 below the free surface they stand for, and carry p = 0).
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    double wsum = d.pairs.self_w();
    d.pairs.for_each(i, [&](const BasicPair<D>& q) { wsum += q.w; });
    d.free_surface[i] = p.mass * wsum < scheme_.free_surface_threshold * rho_ref_ ? 1 : 0;
    d.ppe_source[i] = 0.0;
  }
  Input in;
  in.frame = frame;
  solve_pressure_implicit(p, in);
}

// ---------------------------------------------------------------------------------------
// The stages. Each is a gather loop over particles (each writes only itself), so the
// result does not depend on the number of threads.

namespace {

// Velocity gradient -> SPS stress tau/rho, thesis eqs. 2.8, 2.9 with the mixing length Cs dp
// (physics/turbulence.hpp). Walls carry their free-slip image velocity.
template <int D>
void sps_stress(const BasicParticles<D>& p, const BasicPairList<D>& pairs, double cs, double ct, double dp,
                std::vector<SymTensor<D>>& tau) {
  const SpsClosure closure{(cs * dp) * (cs * dp), ct * dp};
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    double nu_t = 0.0;
    tau[i] = sps_stress_of(velocity_gradient(pairs, p.velocity, p.volume, i), closure, nu_t);
  }
}

// Eq. 2.10: u* = u + dt (nu lap u + div(tau)/rho + body force). Laminar term eq. 2.16 with
// rho_i = rho_j = rho0: 8 m mu / (2 rho0)^2 = 2 V nu. SPS term eq. 2.17; a wall neighbour
// mirrors the stress of particle i (zero normal gradient of tau at the wall).
template <int D>
void predict_velocity(const BasicParticles<D>& p, const BasicPairList<D>& pairs, const BasicStepInput<D>& in,
                      double nu, double eta2, bool turbulence, const std::vector<double>& repulsion,
                      double repulsion_range, BasicIsphData<D>& d) {
  const double V = p.volume;
  const bool repulsive = !repulsion.empty();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    const Vec<D> ri = p.position[i], ui = p.velocity[i];
    const SymTensor<D> ti = turbulence ? d.sps_stress[i] : SymTensor<D>{};
    Vec<D> a_fluid, a_wall;
    pairs.for_each(i, [&](const BasicPair<D>& q) {
      if (q.f == 0.0) return;
      const std::size_t j = q.j;
      const Vec<D> rij = q.rij;
      const double F = q.f;
      Vec<D> a = (ui - p.velocity[j]) * (nu * laplacian_weight(V, F, q.r2(), eta2));
      if (turbulence) {
        // A reference, not a copy: the copy of the selected 24-byte tensor went through the stack
        // and its reload stalled on store forwarding (a third of this loop's time, perf annotate).
        const SymTensor<D>& tj = p.is_fluid(j) ? d.sps_stress[j] : ti;
        a += sum_times(ti, tj, rij) * (V * F);
      }
      if (p.is_fluid(j)) {
        a_fluid += a;
        return;
      }
      // Thesis eq. 3.18: the first wall layer repels fluid closer than r0 (a wall force, so it
      // is part of the base shear).
      const double strength = repulsive ? repulsion[j - p.n_fluid] : 0.0;
      if (strength > 0.0) a += thesis_wall_repulsion(rij, strength, repulsion_range);
      a_wall += a;
    });
    d.wall_acceleration[i] = a_wall;
    d.velocity_old[i] = ui;
    const Vec<D> extra = d.extra_acceleration.empty() ? Vec<D>{} : d.extra_acceleration[i];
    d.velocity_star[i] = ui + in.dt * (a_fluid + a_wall + in.frame.at(ri, ui) + extra);
  }
}

// Eq. 2.11 for fluid (r* = r + dt u*, or r + (dt/2) u* with the midpoint predictor, where the
// pressure of the step then acts at the middle of the step: see PositionPredictor); walls stay
// where they are, and carry u*_w = u_w + dt (g - a_w) (see density_and_ppe_source), worked out
// here once per wall particle instead of once per pair.
template <int D>
void predict_position(const BasicParticles<D>& p, const BasicStepInput<D>& in, PositionPredictor predictor,
                      BasicIsphData<D>& d) {
  const double dt = in.dt;
  const double reach = predictor == PositionPredictor::midpoint ? 0.5 * dt : dt;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.is_fluid(i)) {
      d.position_star[i] = p.position[i] + reach * d.velocity_star[i];
      continue;
    }
    d.position_star[i] = p.position[i];
    d.velocity_star[i] = p.velocity[i] + dt * (in.frame.at(p.position[i], Vec<D>{}) - p.wall_acceleration(i));
  }
}

// The alpha of eq. 2.13 for a step of dt. With alpha fixed, the density term's weight against the
// divergence term grows as 1/dt: in div(u(t+dt)) = alpha (div(u*) + |compression|/dt) a compression
// relaxes over dt/alpha, 50 ms at the thesis's 0.01 and 0.5 ms, half that at 0.25 ms, and the
// crest of resonant sloshing follows it (docs/validation/notes.md). density_relaxation_time fixes
// that time instead.
double blending_factor(const SchemeSpec& scheme, double dt) {
  if (scheme.density_relaxation_time <= 0.0) return scheme.alpha;
  return std::min(1.0, dt / scheme.density_relaxation_time);
}

// Kernel-summed density at r*, the free-surface flag and the right-hand side of the
// blended PPE.
//  * rho* = m sum_j W(r*_ij), the density at the intermediate positions (eq. 2.12 by
//    kernel summation; with rho0 in place of rho^n, as the extracted eq. 2.12 reads, the
//    two source terms would be identical and alpha would do nothing).
//  * Free surface (eq. 2.20): rho* below `threshold` times rho_ref, the kernel sum of
//    undisturbed fluid (a lattice), means a truncated kernel: p = 0.
//  * Source (eq. 2.13 in the dimensionally consistent form of thesis eq. 3.12):
//      lap(p)/rho0 = alpha min(0, rho_ref - rho*) / (rho_ref dt^2) + (1 - alpha) div(u*) / dt.
//    The density term acts on compression only: near the free surface rho* < rho_ref
//    because the kernel is truncated, not because the fluid is rarefied, and that deficit
//    would act as a suction (measured: unstable within 0.4 s at rest, docs/physics.md).
//  * In div(u*) a wall particle carries u*_w = u_w + dt (g - a): its free-slip image velocity
//    (the normal component of the nearby fluid reflected, which resists penetration) plus
//    the body-force increment the fluid received (less the wall's own acceleration for a moving
//    wall). The wall pressure of eq. 2.19 already
//    imposes dp/dn = rho (g - a).n; with u*_w = 0 the source would impose it a second time.
template <int D>
void density_and_ppe_source(BasicParticles<D>& p, const BasicPairList<D>& pairs, const BasicStepInput<D>& in,
                            double alpha, double rho_ref, double threshold, BasicIsphData<D>& d) {
  const double V = p.volume, m = p.mass, w0 = pairs.self_w(), dt = in.dt;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    const Vec<D> ui = d.velocity_star[i];
    double wsum = w0, wall_sum = 0.0, div = 0.0;
    pairs.for_each(i, [&](const BasicPair<D>& q) {
      const std::size_t j = q.j;
      wsum += q.w;
      if (!p.is_fluid(j)) wall_sum += q.w;
      div += V * q.f * dot(d.velocity_star[j] - ui, q.rij);  // walls: u*_w of predict_position
    });
    const double rho_star = m * wsum;
    p.density[i] = rho_star;
    d.free_surface[i] = free_surface_flag(m * (wsum - wall_sum), m * wall_sum, rho_star, rho_ref, threshold);
    d.ppe_source[i] = alpha * std::min(0.0, rho_ref - rho_star) / (rho_ref * dt * dt) + (1.0 - alpha) * div / dt;
  }
}

// Eq. 2.14 with the symmetric gradient of eq. 2.4 at r*:
//   -grad(p)_i / rho0 = -(1/rho0) sum_j V (p_i + p_j) grad_i W_ij,
// then eq. 2.15 for the position. Pressure forces of wall neighbours are kept apart for
// the base shear.
template <int D>
void correct_and_advance(BasicParticles<D>& p, const BasicPairList<D>& pairs, double dt, double rho0,
                         BasicIsphData<D>& d) {
  const double c = p.volume / rho0;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    const Vec<D> ri = d.position_star[i];
    const double pi = p.pressure[i];
    Vec<D> a_fluid, a_wall;
    pairs.for_each(i, [&](const BasicPair<D>& q) {
      const std::size_t j = q.j;
      const double pj = p.is_fluid(j) ? p.pressure[j] : wall_pressure_seen_from(p, j, ri);
      const Vec<D> a = q.rij * (-c * (pi + pj) * q.f);
      if (p.is_fluid(j)) a_fluid += a;
      else a_wall += a;
    });
    const Vec<D> u_new = d.velocity_star[i] + dt * (a_fluid + a_wall);
    d.wall_acceleration[i] += a_wall;
    p.position[i] += 0.5 * dt * (d.velocity_old[i] + u_new);
    p.velocity[i] = u_new;
  }
}

// Particle shifting at the end of the step (physics/shifting.hpp: Lind et al. 2012,
// D = A h |u_i| dt), with the pairs at r*, which the step's last motion moved by
// dt (u(t+dt) - u*)/2, a small fraction of dp, and the free-surface flags of stage 5 (1: surface,
// 2: spray). Returns how many shifts were cut.
template <int D>
std::size_t shift_particles(BasicParticles<D>& p, const BasicPairList<D>& pairs, const ShiftingRule& rule, double dt,
                            BasicIsphData<D>& d) {
  const double scale = rule.coefficient * rule.h * dt;
  return shift_fluid(p, pairs, d.free_surface, rule, [&](std::size_t i) { return scale * norm(p.velocity[i]); },
                     nullptr, d.shifting);
}

}  // namespace

// scheme.negative_pressure = "clip": the fluid pressure is kept >= 0 after each solve. Sloshing
// liquid does not sustain tension (the gauge pressure of water cannot even fall below about
// -1e5 Pa); in the discrete PPE a blob thrown up by a breaking wave, with few p = 0 points on
// its surface, can be given tensions of megapascals that tear it apart (measured: -5 MPa and
// 22 m/s, Tait tank without screens at X0/L = 0.016). Clipping lets such a blob separate
// instead, the way a real free surface forms.
template <int D>
double BasicIsphScheme<D>::clip(double pressure) const {
  return scheme_.clip_negative_pressure ? std::max(pressure, 0.0) : pressure;
}

template <int D>
void BasicIsphScheme<D>::solve_pressure_explicit(ParticleSet& p, const Input& in) {
  // Eq. 2.18 (Yeylaghi et al. 2016): one Jacobi sweep of the discrete PPE per step from
  // the previous pressures, p_i = (b_i + sum_j lambda_ij p_j) / sum_j lambda_ij, with
  // lambda_ij = (2 V / rho0) F_ij r^2 / (r^2 + eta^2) (eq. 2.5 with rho_i = rho_j).
  const double eta2 = eta2_;
  const bool dirichlet = scheme_.free_surface == FreeSurfaceModel::thesis;
  const std::uint8_t zero_from = dirichlet ? 1 : 2;  // flags with p = 0
  BasicIsphData<D>& d = data_;
  std::vector<double>& next = d.ppe_source;  // overwritten in place: b_i is read once per i
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    if (d.free_surface[i] >= zero_from) {
      next[i] = 0.0;
      continue;
    }
    const Vec<D> ri = d.position_star[i];
    double diag = 0.0, off = 0.0;
    d.pairs.for_each(i, [&](const BasicPair<D>& q) {
      const std::size_t j = q.j;
      const double lambda = laplacian_weight(p.volume, q.f, q.r2(), eta2) / rho0_;
      diag += lambda;
      const bool zero = p.is_fluid(j) && d.free_surface[j] >= zero_from;
      const double pj = p.is_fluid(j) ? p.pressure[j] : wall_pressure_seen_from(p, j, ri);
      off += zero ? 0.0 : lambda * pj;
    });
    if (!dirichlet) diag = std::min(diag, lambda_full_);  // missing neighbours: air at p = 0 (lambda < 0)
    next[i] = diag != 0.0 ? (d.ppe_source[i] + off) / diag : 0.0;
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) p.pressure[i] = clip(next[i]);
  adami_wall_pressure(p, d.pairs, in.frame, rho0_);
  diagnostics_.solver_iterations = 1;
  diagnostics_.solver_residual = 0.0;
}

// How neighbour j enters row i of the PPE, from geometry alone (shared by the slot bound and the
// assembly, so the two cannot disagree): a wall row takes only the fluid in front of its wall
// (eq. 2.19); a fluid row sees a wall particle whose wall it stands behind (a thin wall) through
// that particle's back pressure, known from the last step; everything else is a coefficient.
namespace {

enum class PpeNeighbour { ignored, back_pressure, coefficient };

template <int D>
PpeNeighbour ppe_neighbour(const BasicParticles<D>& p, std::size_t i, std::size_t j, Vec<D> ri, Vec<D> rij) {
  if (!p.is_fluid(i)) return dot(rij, p.normal[i]) > 0.0 ? PpeNeighbour::ignored : PpeNeighbour::coefficient;
  if (!p.is_fluid(j) && dot(ri - p.position[j], p.normal[j]) < 0.0) return PpeNeighbour::back_pressure;
  return PpeNeighbour::coefficient;
}

}  // namespace

// One row of the implicit PPE (see solve_pressure_implicit) into its reserved slots, the diagonal
// first; entries of zero weight (neighbours of the Verlet skin beyond the kernel's support) are
// left out. Returns the right side of the row.
template <int D>
double BasicIsphScheme<D>::assemble_ppe_row(const ParticleSet& p, const Input& in, std::size_t i, std::size_t row) {
  BasicIsphData<D>& d = data_;
  SparseRows& A = d.ppe_matrix;
  const bool dirichlet = scheme_.free_surface == FreeSurfaceModel::thesis;
  const Vec<D> ri = d.position_star[i];
  std::size_t slot = A.slot_begin[row] + 1;
  double diag = 0.0;
  double rhs = p.is_fluid(i) ? d.ppe_source[i] : 0.0;
  // A wall row's g - a_w (moving walls), once per row rather than once per pair.
  const Vec<D> wall_body_force = p.is_fluid(i) ? Vec<D>{} : in.frame.at(ri, Vec<D>{}) - p.wall_acceleration(i);
  d.pairs.for_each(i, [&](const BasicPair<D>& q) {
    const std::size_t j = q.j;
    const PpeNeighbour kind = ppe_neighbour(p, i, j, ri, q.rij);
    if (kind == PpeNeighbour::ignored) return;
    double coef;
    if (p.is_fluid(i)) {
      coef = laplacian_weight(p.volume, q.f, q.r2(), eta2_) / rho0_;
      if (kind == PpeNeighbour::back_pressure) {
        diag += coef;
        rhs += coef * p.pressure_back[j];
        return;
      }
    } else {
      coef = q.w;
      rhs += dot(wall_body_force, q.rij) * rho0_ * coef;
    }
    if (coef == 0.0) return;
    diag += coef;
    if (d.ppe_row[j] >= 0) {
      assert(slot < A.slot_begin[row] + d.ppe_row_capacity[row] && "a row has at most one slot per pair");
      A.column[slot] = static_cast<std::uint32_t>(d.ppe_row[j]);
      A.value[slot++] = -coef;
    }
  });
  if (diag == 0.0) diag = 1.0;  // isolated wall particle: p_w = 0
  if (!dirichlet && p.is_fluid(i)) diag = std::min(diag, lambda_full_);  // air at p = 0
  A.column[A.slot_begin[row]] = static_cast<std::uint32_t>(row);
  A.value[A.slot_begin[row]] = diag;
  A.slot_end[row] = slot;
  return rhs;
}

template <int D>
KrylovReport BasicIsphScheme<D>::solve_ppe_system(bool multigrid) {
  BasicIsphData<D>& d = data_;
  return solve_bicgstab(d.ppe_matrix, d.ppe_rhs, d.ppe_solution, scheme_.solver_tolerance,
                        scheme_.solver_max_iterations, d.krylov, multigrid ? &d.multigrid : nullptr);
}

// How many steps one multigrid hierarchy may serve. Its aggregates and coarse operators then come
// from a matrix up to this many steps old; the fine level (smoother, residuals, restriction
// weights) is always this step's. Measured on the Tait tank with screens (docs/performance.md,
// "The kept multigrid hierarchy and the stored kernel"): kept until the next neighbour-list rebuild
// (about 10 steps in sloshing, up to 50 from rest) the mean BiCGSTAB iterations did not change
// (3.40 against 3.41 over 2 s), and building the hierarchy had been 15% of a step. The cap bounds
// the age in still water, where the neighbour list is rarely rebuilt.
constexpr std::uint32_t kMultigridKeptSteps = 20;

// The hierarchy of the last build may precondition this step's system: it was built for the same
// rows (the same particles in the same order, the neighbour list not rebuilt since) and is young.
template <int D>
bool BasicIsphScheme<D>::can_keep_multigrid() const {
  const BasicIsphData<D>& d = data_;
  return d.multigrid.ready && d.multigrid_neighbour_builds == neighbours_.builds() &&
         d.multigrid_age < kMultigridKeptSteps && d.multigrid_rows == d.ppe_particle;
}

// The assembled system solved with its preconditioner: the multigrid built for it first, or kept
// from an earlier step (keep_hierarchy, which the caller sets from can_keep_multigrid).
template <int D>
KrylovReport BasicIsphScheme<D>::solve_assembled_ppe(bool multigrid, bool keep_hierarchy) {
  BasicIsphData<D>& d = data_;
  if (multigrid && keep_hierarchy) {
    refresh_fine_diagonal(d.ppe_matrix, d.multigrid);
    ++d.multigrid_age;
  } else if (multigrid) {
    const std::size_t rows = d.ppe_particle.size();
    d.ppe_row_position.resize(rows);
    for (std::size_t row = 0; row < rows; ++row) d.ppe_row_position[row] = d.position_star[d.ppe_particle[row]];
    build_multigrid(d.ppe_matrix, d.ppe_row_position, 2.0 * dp_, d.multigrid);  // aggregates of about 2 x 2
    d.multigrid_rows = d.ppe_particle;
    d.multigrid_neighbour_builds = neighbours_.builds();
    d.multigrid_age = 0;
  }
  return solve_ppe_system(multigrid);
}

template <int D>
void BasicIsphScheme<D>::save_state(StateWriter& w) const {
  neighbours_.save(w);
  save_multigrid(data_.multigrid, w);
  w.array("isph.multigrid_rows", data_.multigrid_rows);
  w.value("isph.multigrid_neighbour_builds", data_.multigrid_neighbour_builds);
  w.value("isph.multigrid_age", data_.multigrid_age);
}

template <int D>
void BasicIsphScheme<D>::load_state(StateReader& r) {
  neighbours_.load(r);
  load_multigrid(data_.multigrid, r);
  data_.multigrid_rows = r.array<std::uint32_t>("isph.multigrid_rows");
  data_.multigrid_neighbour_builds = r.value<std::uint64_t>("isph.multigrid_neighbour_builds");
  data_.multigrid_age = r.value<std::uint32_t>("isph.multigrid_age");
}

// The unknowns of the implicit PPE (fluid not at p = 0, walls with neighbours) and their rows,
// written in parallel into slots reserved per row; the solution starts from p(t).
template <int D>
void BasicIsphScheme<D>::assemble_ppe(const ParticleSet& p, const Input& in) {
  BasicIsphData<D>& d = data_;
  const std::size_t n = p.size();
  const bool dirichlet = scheme_.free_surface == FreeSurfaceModel::thesis;
  const std::uint8_t zero_from = dirichlet ? 1 : 2;  // flags with p = 0
  d.ppe_row.assign(n, -1);
  d.ppe_particle.clear();
  auto add_unknown = [&](std::size_t i) {
    d.ppe_row[i] = static_cast<int>(d.ppe_particle.size());
    d.ppe_particle.push_back(static_cast<std::uint32_t>(i));
  };
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    if (d.free_surface[i] < zero_from) add_unknown(i);
  for (std::size_t w = p.n_fluid; w < n; ++w)
    if (neighbours_.count(w) > 0) add_unknown(w);
  const std::size_t rows = d.ppe_particle.size();
  d.ppe_row_capacity.resize(rows);
  // A row has its diagonal and at most one slot per pair within the support (the exact count, of
  // the right kind, would cost a pass over the pairs).
  for (std::size_t row = 0; row < rows; ++row) d.ppe_row_capacity[row] = d.pairs.count(d.ppe_particle[row]) + 1;
  d.ppe_matrix.reserve_rows(d.ppe_row_capacity);
  d.ppe_rhs.resize(rows);
  d.ppe_solution.resize(rows);
#pragma omp parallel for schedule(static)
  for (std::size_t row = 0; row < rows; ++row) {
    const std::size_t i = d.ppe_particle[row];
    d.ppe_solution[row] = p.pressure[i];
    d.ppe_rhs[row] = assemble_ppe_row(p, in, i, row);
  }
}

namespace {

// The largest |x_i| (infinite if some x_i is not finite).
double largest_magnitude(const std::vector<double>& x) {
  double largest = 0.0;
  for (const double v : x) largest = std::isfinite(v) ? std::max(largest, std::abs(v)) : HUGE_VAL;
  return largest;
}

// A PPE coefficient below this fraction of its row's diagonal does not hold a block to the rest
// (rows_without_anchor): a block held only by such links is treated as held by none.
constexpr double kWeakPpeLink = 1e-6;

}  // namespace

// The fluid particles of the PPE's blocks that no p = 0 condition reaches, or only through links
// weaker than kWeakPpeLink (rows_without_anchor), become spray (flag 2: p = 0, not unknowns) for
// this step. Returns how many.
template <int D>
std::size_t BasicIsphScheme<D>::pin_unanchored_blocks(const ParticleSet& p) {
  BasicIsphData<D>& d = data_;
  std::size_t pinned = 0;
  for (const std::uint32_t row : rows_without_anchor(d.ppe_matrix, kWeakPpeLink)) {
    const std::size_t i = d.ppe_particle[row];
    if (!p.is_fluid(i)) continue;
    d.free_surface[i] = 2;
    ++pinned;
  }
  return pinned;
}

template <int D>
void BasicIsphScheme<D>::solve_pressure_implicit(ParticleSet& p, const Input& in) {
  // The same discrete equations as the explicit update, solved exactly each step:
  // fluid rows  sum_j lambda_ij (p_i - p_j) = b_i        (free-surface p = 0),
  // wall rows   sum_f W_wf p_w - sum_f W_wf p_f = (g - a)·sum_f rho0 r_wf W_wf   (eq. 2.19).
  // Non-symmetric, so BiCGSTAB (schemes/ppe_solver.hpp) with a diagonal or multigrid
  // preconditioner (scheme.preconditioner), warm-started from p(t).
  BasicIsphData<D>& d = data_;
  diagnostics_.pinned_particles = 0;
  assemble_ppe(p, in);
  const bool multigrid = scheme_.preconditioner == Preconditioner::multigrid;
  const bool kept = multigrid && can_keep_multigrid();
  KrylovReport report = solve_assembled_ppe(multigrid, kept);
  int iterations = report.iterations;
  if (!report.converged && kept) {
    // A kept hierarchy that no longer preconditions well enough: built anew for this matrix, and
    // the solve started again from p(t).
    for (std::size_t row = 0; row < d.ppe_particle.size(); ++row) d.ppe_solution[row] = p.pressure[d.ppe_particle[row]];
    report = solve_assembled_ppe(multigrid, false);
    iterations += report.iterations;
  }
  // Pressures that would move a particle by more than 100 dp in one step if they fell to 0 over dp
  // (dt^2 p / (rho0 dp) > 100 dp) may be those of a nearly singular block (rows_without_anchor),
  // so the blocks are looked for then too: 40 MPa for the building tanks (dp = 0.1 m, dt = 5 ms),
  // where the largest pressures of the runs are 40-60 kPa. A level that high is not always a
  // fault (the SF tank at 44 milli-g, t = 137.18 s: 7.1e7 Pa with no weakly held block, and the
  // run went on at rest there): if no block is found, the solution stands.
  const double bound = 100.0 * rho0_ * dp_ * dp_ / (in.dt * in.dt);
  if (!report.converged || largest_magnitude(d.ppe_solution) > bound) {
    // A cluster of fluid that no p = 0 condition reaches (a thin jet pressed into the top of a
    // wall, its particles closer than dp, so that walls and each other fill their kernels and the
    // spray fraction misses it) makes a singular block with no solution, on which BiCGSTAB
    // diverges (measured: SF tank at 44 milli-g, t = 1633 s, 3 particles; relative residual 6.2
    // after 1001 iterations); one held to the rest only by links at the edge of the support solves
    // to absurd pressures instead (the bound above). Its fluid is set to p = 0 as spray for this
    // step and the system is assembled and solved again. Looked for only when a solve fails or
    // breaks the bound (one pass over the matrix, 0.4 ms at 6,219 rows, would be 2-3% of every
    // step): a step that keeps it is unchanged.
    diagnostics_.pinned_particles = pin_unanchored_blocks(p);
    if (diagnostics_.pinned_particles > 0) {
      assemble_ppe(p, in);
      report = solve_assembled_ppe(multigrid, false);
      iterations += report.iterations;
    }
  }
  if (!report.converged) {
    // BiCGSTAB can break down (a vanishing inner product); a restart from zero with the Jacobi
    // preconditioner almost always gets past it. If it does not, the step fails with the
    // solver's numbers.
    std::fill(d.ppe_solution.begin(), d.ppe_solution.end(), 0.0);
    report = solve_ppe_system(false);
    iterations += report.iterations;
    if (!report.converged)
      throw RunFailure("the implicit pressure solve did not converge (BiCGSTAB, " + std::to_string(d.ppe_particle.size()) +
                       " unknowns, " + std::to_string(iterations) + " iterations, relative residual " +
                       std::to_string(report.relative_residual) +
                       "); try a smaller time.dt or scheme.solver_max_iterations");
  }
  diagnostics_.solver_iterations = iterations;
  diagnostics_.solver_residual = report.relative_residual;
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    p.pressure[i] = d.ppe_row[i] >= 0 ? clip(d.ppe_solution[d.ppe_row[i]]) : 0.0;
  // Wall pressures from the solved fluid, with the clipping at 0 of adami_wall_pressure
  // (the linear system cannot hold the clip; it matters only near the free surface).
  adami_wall_pressure(p, d.pairs, in.frame, rho0_);
}

// The pairs each stage reads: those at r(t) before the prediction, at r* from the density on.
template <int D>
bool BasicIsphScheme<D>::reads_pairs_at_r_star(IsphStage stage) {
  return stage == IsphStage::density_and_ppe_source || stage == IsphStage::pressure_solve ||
         stage == IsphStage::correct_and_advance || stage == IsphStage::shift;
}

template <int D>
void BasicIsphScheme<D>::stage(IsphStage stage, ParticleSet& p, const Input& in) {
  BasicIsphData<D>& d = data_;
  switch (stage) {
    case IsphStage::sps_stress:
      sps_stress(p, d.pairs, scheme_.smagorinsky, scheme_.ct, dp_, d.sps_stress);
      break;
    case IsphStage::predict: {
      if (scheme_.repulsive_walls && repulsion_strength_.size() != p.n_wall()) mark_repulsive_layer(p);
      static const std::vector<double> none;
      predict_velocity(p, d.pairs, in, nu_, eta2_, scheme_.turbulence,
                       scheme_.repulsive_walls ? repulsion_strength_ : none, scheme_.repulsive_range * h_, d);
      predict_position(p, in, scheme_.predictor, d);
      break;
    }
    case IsphStage::density_and_ppe_source:
      density_and_ppe_source(p, d.pairs, in, blending_factor(scheme_, in.dt), rho_ref_, scheme_.free_surface_threshold, d);
      break;
    case IsphStage::pressure_solve:
      if (scheme_.pressure == PressureSolve::implicit_krylov) solve_pressure_implicit(p, in);
      else solve_pressure_explicit(p, in);
      break;
    case IsphStage::correct_and_advance:
      correct_and_advance(p, d.pairs, in.dt, rho0_, d);
      break;
    case IsphStage::shift:
      diagnostics_.shifts_limited = shift_particles(p, d.pairs, shifting_, in.dt, d);
      break;
  }
}

template <int D>
void BasicIsphScheme<D>::prepare_stage(IsphStage stage, const ParticleSet& p) {
  data_.resize(p.size());
  build_pairs(reads_pairs_at_r_star(stage) ? data_.position_star : p.position);
}

template <int D>
void BasicIsphScheme<D>::run_stage(IsphStage stage, ParticleSet& p, const Input& in) {
  assert(data_.pairs.rows() == p.size() && "prepare_stage first");
  this->stage(stage, p, in);
}

template <int D>
void BasicIsphScheme<D>::step(ParticleSet& p, const Input& in) {
  update_neighbours(p);
  data_.resize(p.size());
  BasicIsphData<D>& d = data_;
  d.extra_acceleration.clear();
  if (in.extra) in.extra(p, d.extra_acceleration);                  // screens, eq. 2.28
  build_pairs(p.position);                                          // the pairs at r(t)
  extrapolate_wall_velocity(p, d.pairs, p.velocity);                // free slip, 2.4.3.1
  if (scheme_.turbulence) stage(IsphStage::sps_stress, p, in);     // eqs. 2.8-2.9
  stage(IsphStage::predict, p, in);                                 // eqs. 2.10, 2.11, 3.18
  build_pairs(d.position_star);                                     // the pairs at r*
  stage(IsphStage::density_and_ppe_source, p, in);                  // eqs. 2.12, 2.13, 2.20
  stage(IsphStage::pressure_solve, p, in);                          // eqs. 2.18 or 2.13, 2.19
  stage(IsphStage::correct_and_advance, p, in);                     // eqs. 2.14, 2.15
  diagnostics_.shifts_limited = 0;
  if (scheme_.shifting == ShiftingModel::lind) stage(IsphStage::shift, p, in);  // Lind et al. 2012

  // Diagnostics, reduced in a fixed order so they do not depend on the thread count.
  Vec<D> wall{};
  Moment<D> moment{};
  double vmax2 = 0.0;
  std::size_t surface = 0;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    wall += d.wall_acceleration[i];
    moment += cross(d.position_star[i], d.wall_acceleration[i]);  // the pressure part acted at r*
    vmax2 = std::max(vmax2, norm2(p.velocity[i]));
    surface += d.free_surface[i] > 0 ? 1 : 0;
  }
  diagnostics_.wall_force = wall * p.mass;
  diagnostics_.wall_moment = moment * p.mass;
  diagnostics_.max_speed = std::sqrt(vmax2);
  diagnostics_.free_surface = surface;
}

// The two dimensions.
template struct BasicIsphData<2>;
template struct BasicIsphData<3>;
template class BasicIsphScheme<2>;
template class BasicIsphScheme<3>;

}  // namespace sloshsph
