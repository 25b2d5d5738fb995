#include "sloshsph/schemes/wcsph.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/cylinder_tank.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/physics/repulsive_force.hpp"
#include "sloshsph/physics/walls.hpp"
#include "sloshsph/physics/wcsph_density.hpp"
#include "sloshsph/physics/wcsph_eos.hpp"
#include "sloshsph/sph/kernel.hpp"
#include "sloshsph/sph/operators.hpp"

namespace sloshsph {

template <int D>
void BasicWcsphData<D>::resize_fluid(std::size_t n_fluid) {
  id.resize(n_fluid);
  acceleration.resize(n_fluid);
  density_rate.resize(n_fluid);
  xsph.resize(n_fluid);
  position_start.resize(n_fluid);
  velocity_start.resize(n_fluid);
  density_start.resize(n_fluid);
  density_gradient.resize(n_fluid);
  correction.resize(n_fluid);
  stress.resize(n_fluid);
  wall_acceleration.resize(n_fluid);
}

template <int D>
void BasicWcsphData<D>::resize_all(std::size_t n) {
  volume.resize(n);
  scratch.resize(n);
}

namespace {

template <class T>
void permute(std::vector<T>& v, const std::vector<std::uint32_t>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
  std::copy(out.begin(), out.end(), v.begin());
}

}  // namespace

template <int D>
BasicWcsphScheme<D>::BasicWcsphScheme(const CaseSpec& spec, double h)
    : spec_(spec.scheme.wcsph),
      kernel_type_(spec.particles.kernel),
      h_(h),
      dp_(spec.particles.dp),
      rho0_(spec.fluid.density),
      nu_(spec.fluid.viscosity),
      c0_(case_sound_speed(spec)),
      eta2_(0.01 * h * h),
      rho_ref_(times_particle_volume<D>(spec.fluid.density, spec.particles.dp) *
               lattice_number_density(spec.particles.kernel, h, spec.particles.dp, D)),
      ct_(spec.scheme.ct),
      tank_(spec.tank),
      tank_where_(spec.where("tank.shape")),
      neighbours_(2.0 * h, spec.scheme.neighbour_skin * 2.0 * h) {
  if (!(c0_ > 0.0) || !std::isfinite(c0_)) {
    const std::string key = spec.scheme.wcsph.sound_speed > 0.0 ? "scheme.sound_speed"
                                                                : "scheme.max_density_variation";
    throw InputError(spec.where(key), key,
                     "gives no positive sound speed (c0 = " + std::to_string(c0_) +
                         " m/s); set scheme.sound_speed or check the fill depth, tank length and gravity");
  }
  if (!(spec_.cfl > 0.0))
    throw InputError(spec.where("scheme.cfl"), "scheme.cfl", "must be positive");
  shifting_on_ = spec.scheme.shifting == ShiftingModel::delta_plus;
  shifting_.h = h;
  shifting_.dp = dp_;
  shifting_.max_shift = spec.scheme.shifting_max * dp_;
  shifting_.w_dp = with_kernel(kernel_type_, h, [&](const auto& k) { return k.w(dp_); }, D);
}

template <int D>
MemoryParts BasicWcsphScheme<D>::memory_parts() const {
  const BasicWcsphData<D>& d = data_;
  const std::size_t n = d.id.capacity();
  const std::size_t per_fluid = sizeof(std::int32_t) + 6 * sizeof(Vec<D>) + 2 * sizeof(double) + sizeof(Mat<D>) +
                                sizeof(SymTensor<D>);
  const std::size_t particle_arrays = n * per_fluid + d.position_at_build.capacity() * sizeof(Vec<D>) +
                                      (d.volume.capacity() + d.scratch.capacity()) * sizeof(double) +
                                      repulsive_.capacity() + d.surface.capacity();
  return {{"particle_arrays", particle_arrays},
          {"neighbour_list", neighbours_.memory_bytes()},
          {"pairs", d.pairs.memory_bytes()},
          {"shifting", d.shifting.memory_bytes()}};
}

// ---------------------------------------------------------------------------------------
// Bookkeeping: the rates kept between steps follow the particles through re-sorting and
// removals; the neighbour list is rebuilt early enough to stay valid over a whole step.

// The stored rates belong to the particles named in data_.id. After the driver removed
// leaked particles, they are remapped by id. Returns false if some particle has none.
template <int D>
bool BasicWcsphScheme<D>::sync_state(const ParticleSet& p) {
  BasicWcsphData<D>& d = data_;
  const std::size_t n = p.n_fluid;
  if (d.id.size() == n && std::equal(d.id.begin(), d.id.end(), p.id.begin())) return true;
  bool complete = !d.id.empty();
  std::vector<Vec<D>> acc(n), xs(n);
  std::vector<double> rate(n, 0.0);
  if (complete) {
    std::int32_t max_id = 0;
    for (std::int32_t v : d.id) max_id = std::max(max_id, v);
    std::vector<std::int64_t> where(static_cast<std::size_t>(max_id) + 1, -1);
    for (std::size_t k = 0; k < d.id.size(); ++k) where[static_cast<std::size_t>(d.id[k])] = static_cast<std::int64_t>(k);
    for (std::size_t i = 0; i < n; ++i) {
      const std::int32_t v = p.id[i];
      const std::int64_t k = (v >= 0 && v <= max_id) ? where[static_cast<std::size_t>(v)] : -1;
      if (k < 0) {
        complete = false;
        continue;
      }
      acc[i] = d.acceleration[static_cast<std::size_t>(k)];
      xs[i] = d.xsph[static_cast<std::size_t>(k)];
      rate[i] = d.density_rate[static_cast<std::size_t>(k)];
    }
  }
  d.resize_fluid(n);
  std::copy(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(n), d.id.begin());
  d.acceleration = std::move(acc);
  d.xsph = std::move(xs);
  d.density_rate = std::move(rate);
  return complete;
}

// Rebuilt when NeighbourList::stale says so, and also when some fluid particle could move
// more than half the skin by the end of this step (its displacement since the build plus
// dt (|u| + |u_xsph| + dt |a|), a the last rate plus the body force): every evaluation inside
// the step then sees all pairs within 2h.
template <int D>
void BasicWcsphScheme<D>::update_neighbours(ParticleSet& p, double dt, const Frame& frame) {
  BasicWcsphData<D>& d = data_;
  diagnostics_.neighbours_rebuilt = false;
  bool rebuild = neighbours_.stale(p.position, p.n_fluid) || d.position_at_build.size() != p.n_fluid;
  if (!rebuild) {
    const double limit = 0.5 * neighbours_.skin();
    const double shift_reach = shifting_on_ ? shifting_.max_shift : 0.0;  // the shift at the end of the step
    bool far = false;
#pragma omp parallel for reduction(|| : far) schedule(static)
    for (std::size_t i = 0; i < p.n_fluid; ++i) {
      const Vec<D> a = d.acceleration[i] + frame.at(p.position[i], p.velocity[i]);
      const double reach = norm(p.position[i] - d.position_at_build[i]) + dt * (norm(p.velocity[i]) + norm(d.xsph[i]) + dt * norm(a)) +
                           shift_reach;
      far = far || reach > limit;
    }
    rebuild = far;
  }
  if (!rebuild) return;
  // Keep the fluid in cell order: neighbours then sit close in memory.
  const std::vector<std::uint32_t> order = cell_order(p.position, p.n_fluid, neighbours_.search_radius());
  p.permute_fluid(order);
  permute(d.id, order);
  permute(d.acceleration, order);
  permute(d.density_rate, order);
  permute(d.xsph, order);
  neighbours_.build(p.position, p.n_fluid);
  d.position_at_build.assign(p.position.begin(), p.position.begin() + static_cast<std::ptrdiff_t>(p.n_fluid));
  diagnostics_.neighbours_rebuilt = true;
}

// Shao's repulsive particles are the first layer of wall particles: sample_walls puts it
// dp/2 outside the wall surface, at the lattice spacing dp from the first fluid row, so the
// repulsive force (zero beyond dp, Shao eq. 27) vanishes for fluid at rest as it is placed. In 3D
// the first layer of the side, end and bottom walls (or the cylinder's side and bottom) alike.
template <int D>
void BasicWcsphScheme<D>::mark_repulsive_layer(const ParticleSet& p) {
  repulsive_.assign(p.n_wall(), 0);
  if (spec_.walls != WallTreatment::repulsive) return;
  const std::function<double(Vec<D>)> distance = tank_signed_distance<D>(tank_, tank_where_);
  for (std::size_t w = p.n_fluid; w < p.size(); ++w)
    repulsive_[w - p.n_fluid] = distance(p.position[w]) > -dp_ ? 1 : 0;
}

template <int D>
void BasicWcsphScheme<D>::fluid_pressure(ParticleSet& p) const {
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) p.pressure[i] = eos_pressure(p.density[i], rho0_, c0_);
}

// ---------------------------------------------------------------------------------------
// The stages of one evaluation of the rates. Each is a gather loop over particles (each
// writes only itself), so the result does not depend on the number of threads.

namespace {

// Velocity gradient of fluid particle i for its turbulent stress (physics/turbulence.hpp):
// grad(u)_kl = sum_j V_j (u_j - u_i)_k (L_i grad W)_l (walls carry their image velocities).
//  * Smagorinsky (Shao eqs. 21-23): nu_t = (Cs h)^2 sqrt(2 S:S), R = 2 nu_t S. Shao gives no
//    closure for the turbulent kinetic energy k; its isotropic part -2/3 k I only adds to the
//    pressure, so k = 0 here.
//  * SPS (as the ISPH scheme, thesis eqs. 2.8-2.9): nu_t = (Cs dp)^2 |S|, k = (nu_t / (Ct dp))^2,
//    R = 2 nu_t S - 2/3 k I.
template <int D>
BasicVelocityGradient<D> corrected_velocity_gradient(const BasicParticles<D>& p, const BasicPairList<D>& pairs,
                                                     const std::vector<double>& volume, const Mat<D>& correction,
                                                     std::size_t i) {
  const Vec<D> ui = p.velocity[i];
  BasicVelocityGradient<D> grad;
  pairs.for_each(i, [&](const BasicPair<D>& q) {
    if (q.f == 0.0) return;
    const Vec<D> g = correction * (q.rij * q.f);
    const Vec<D> du = (p.velocity[q.j] - ui) * volume[q.j];
    for (int k = 0; k < D; ++k)
      for (int l = 0; l < D; ++l) grad.c[k][l] += component(du, k) * component(g, l);
  });
  return grad;
}

// R / rho of a turbulent stress, component by component.
inline SymTensor2 divided(const SymTensor2& r, double rho) { return {r.xx / rho, r.xy / rho, r.yy / rho}; }
inline SymTensor3 divided(const SymTensor3& r, double rho) {
  return {r.xx / rho, r.xy / rho, r.xz / rho, r.yy / rho, r.yz / rho, r.zz / rho};
}

// The constants of the rate sweep.
struct RateTerms {
  double mass = 0.0;
  double rho0 = 0.0;
  double c0 = 0.0;
  double h = 0.0;
  double dp = 0.0;
  double delta = 0.0;       // delta-SPH coefficient
  double viscosity_av = 0.0;  // alpha h c0 rho0 (Dincer eq. 6), 0: laminar
  double nu = 0.0;          // laminar kinematic viscosity
  double eta2 = 0.0;        // 0.01 h^2
  double xsph = 0.0;        // epsilon
  bool correct = false;     // kernel gradient correction
  bool turbulence = false;
  bool repulsive = false;   // wall treatment
};

// drho/dt, du/dt (without the body force), the XSPH correction, and the share of du/dt due
// to wall particles, for every fluid particle.
//  * Continuity, Dincer eq. 5 (Shao eq. 5): sum_j m u_ij . grad W (corrected gradient with KGC).
//  * delta-SPH diffusion, Dincer eqs. 5 and 7 (Marrone et al. 2011):
//      delta h c0 sum_j V_j psi_ij . grad W,
//      psi_ij = 2 (rho_j - rho_i) r_ji / |r_ij|^2 - (<grad rho>_i^L + <grad rho>_j^L).
//    With grad W = F r_ij: psi_ij . grad W = -F (2 (rho_j - rho_i) + (g_i + g_j) . r_ij), which
//    vanishes for any linear density field (the hydrostatic one) since the renormalised
//    gradients are exact there. Summed over fluid neighbours only: the wall densities are
//    extrapolations, not fluid to diffuse into, and the fluid-only renormalised gradient is exact
//    for linear fields next to walls as well.
//  * Pressure, Dincer eq. 6 with V_j = m_j / rho_j (the extracted text prints m_j; rho_i du/dt has
//    the units of sum_j V_j p grad W): -(1/rho_i) sum_j V_j (p_i + p_j) grad W. Antisymmetric in
//    i, j: conserves momentum (without KGC).
//  * Artificial viscosity, Dincer eq. 6: alpha h c0 (rho0 / rho_i) sum_j V_j pi_ij grad W,
//    pi_ij = (u_j - u_i).(r_j - r_i) / |r_ij|^2 = u_ij . r_ij / r^2 (the extracted text lost the
//    minus signs; this sign damps approach and separation alike). Uncorrected kernel gradient.
//  * Laminar viscosity (artificial_viscosity == 0), Shao eq. 6 (Morris et al. 1997) with
//    mu = rho0 nu: sum_j 8 m mu F r^2 / ((rho_i + rho_j)^2 (r^2 + 0.01 h^2)) u_ij =
//    nu sum_j laplacian_weight(4 m rho0 / (rho_i + rho_j)^2, F, r^2, eta^2) u_ij.
//  * Turbulence, Shao eq. 24 (with the mass m_j the extraction lost): sum_j m (R_i/rho_i + R_j/rho_j) . grad W;
//    a wall particle mirrors the stress of i (zero normal gradient at the wall), as in the ISPH scheme.
//  * Repulsive wall particles (Shao eqs. 25-28): physics/repulsive_force.hpp.
//  * XSPH, Dincer eq. 11 (the minus sign lost in extraction restored): eps sum_{j fluid} m (u_j - u_i)
//    W_ij / rho_ij, rho_ij = (rho_i + rho_j) / 2. Fluid neighbours only: the velocity is smoothed
//    within the fluid; its pair terms cancel, so the mean drift is the mean velocity.
template <int D>
void rates(const BasicParticles<D>& p, const BasicPairList<D>& pairs, const RateTerms& t,
           const std::vector<std::uint8_t>& repulsive, BasicWcsphData<D>& d) {
  const std::size_t nf = p.n_fluid;
  const double m = t.mass;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nf; ++i) {
    const Vec<D> ui = p.velocity[i];
    const double rho_i = p.density[i], pi = p.pressure[i];
    const Mat<D> L = t.correct ? d.correction[i] : Mat<D>{};
    const Vec<D> gi = d.density_gradient[i];
    const SymTensor<D> Ri = t.turbulence ? d.stress[i] : SymTensor<D>{};
    double drho = 0.0, diffusion = 0.0;
    Vec<D> a_fluid, a_wall, xs;
    pairs.for_each(i, [&](const BasicPair<D>& q) {
      const std::size_t j = q.j;
      const Vec<D> rij = q.rij;
      const double r2 = q.r2();
      const double F = q.f;
      const bool fluid_j = j < nf;
      Vec<D> a;
      if constexpr (D == 2)
        if (!fluid_j && t.repulsive && repulsive[j - nf]) a += repulsive_acceleration(rij, t.c0, t.h, t.dp);
      if (F != 0.0) {
        const Vec<D> grad = rij * F;
        const Vec<D> grad_c = t.correct ? L * grad : grad;
        const double Vj = d.volume[j], rho_j = p.density[j];
        const Vec<D> uij = ui - p.velocity[j];
        drho += m * dot(uij, grad_c);
        if (fluid_j && t.delta > 0.0)
          diffusion += Vj * (-F) * (2.0 * (rho_j - rho_i) + dot(gi + d.density_gradient[j], rij));
        a += grad_c * (-Vj * (pi + p.pressure[j]) / rho_i);
        if (t.viscosity_av > 0.0) {
          // pi_ij grad W = F (u_ij . r_ij) r_ij / r^2 is bounded (|F| |u_ij|), but its direction is
          // undefined for two particles at one point: such a pair (two particles pressed into
          // the same tank corner by the repulsive walls, Faltinsen case at t = 32.1 s) adds nothing.
          if (r2 > 0.0) a += grad * (t.viscosity_av / rho_i * Vj * dot(uij, rij) / r2);
        } else if (t.nu > 0.0) {
          const double rho_sum = rho_i + rho_j;
          a += uij * (t.nu * laplacian_weight(4.0 * m * t.rho0 / (rho_sum * rho_sum), F, r2, t.eta2));
        }
        if (t.turbulence) {
          const SymTensor<D>& Rj = fluid_j ? d.stress[j] : Ri;  // a reference: see predict_velocity (isph.cpp)
          a += sum_times(divided(Ri, rho_i), divided(Rj, rho_j), grad_c) * m;
        }
        if (fluid_j && t.xsph > 0.0) xs += (p.velocity[j] - ui) * (2.0 * m * q.w / (rho_i + rho_j));
      }
      if (fluid_j) a_fluid += a;
      else a_wall += a;
    });
    d.density_rate[i] = drho + t.delta * t.h * t.c0 * diffusion;
    d.acceleration[i] = a_fluid + a_wall;
    d.wall_acceleration[i] = a_wall;
    d.xsph[i] = t.xsph * xs;
  }
}

// The whole acceleration of fluid particle i at (r, u): the evaluated rates, the frame's body
// force and the driver's extra (screen) acceleration, which is constant over the step.
template <int D>
Vec<D> total_acceleration(const BasicWcsphData<D>& d, const BasicFrameForce<D>& frame, std::size_t i, Vec<D> r,
                          Vec<D> u) {
  return d.acceleration[i] + frame.at(r, u) + (d.extra_acceleration.empty() ? Vec<D>{} : d.extra_acceleration[i]);
}

}  // namespace

// Wall pressure, density and velocity from the fluid around each wall particle.
//  * Adami (default): free-slip image velocity and the pressure of thesis eq. 2.19 / Adami et al.
//    2012 eq. 27 (physics/walls.hpp), the density from the inverse equation of state.
//  * Repulsive (Shao sec. 2.5): Shepard-normalised density and no-slip image velocity of the fluid
//    around (Shao eqs. 29-30, physics/wcsph_density.hpp), the pressure from the equation of state.
//    Shao takes the ghost values from the fluid and the repulsive particles; the neighbour list has
//    no wall-wall pairs, and the repulsive particles' values are themselves Shepard averages of
//    the same fluid, so both layers here interpolate the fluid directly. The pressure is clipped
//    at 0 as adami_wall_pressure does (above the free surface the mirrored medium is air).
template <int D>
void BasicWcsphScheme<D>::wall_values(ParticleSet& p, const Frame& frame) {
  const BasicPairList<D>& pairs = data_.pairs;
  if (spec_.walls == WallTreatment::repulsive) {
    shepard_wall_values(p, pairs, rho0_);
#pragma omp parallel for schedule(static)
    for (std::size_t w = p.n_fluid; w < p.size(); ++w) {
      p.pressure[w] = std::max(0.0, eos_pressure(p.density[w], rho0_, c0_));
      p.density[w] = eos_density(p.pressure[w], rho0_, c0_);
    }
    return;
  }
  extrapolate_wall_velocity(p, pairs, p.velocity);
  adami_wall_pressure(p, pairs, frame, rho0_);
#pragma omp parallel for schedule(static)
  for (std::size_t w = p.n_fluid; w < p.size(); ++w) p.density[w] = eos_density(p.pressure[w], rho0_, c0_);
}

template <int D>
void BasicWcsphScheme<D>::build_pairs(const ParticleSet& p, std::size_t first_row) {
  data_.pairs.build(kernel_type_, h_, p.position, neighbours_, first_row);
}

// One evaluation of the rates at the state the particles hold (positions, velocities, densities).
template <int D>
void BasicWcsphScheme<D>::evaluate(ParticleSet& p, const Frame& frame) {
  BasicWcsphData<D>& d = data_;
  const std::size_t nf = p.n_fluid;
  d.resize_fluid(nf);
  d.resize_all(p.size());
  if (repulsive_.size() != p.n_wall()) mark_repulsive_layer(p);
  build_pairs(p);              // the pairs at the positions of this evaluation

  fluid_pressure(p);           // Dincer eq. 10
  wall_values(p, frame);       // walls: Adami or Shao eqs. 29-30
#pragma omp parallel for schedule(static)
  for (std::size_t j = 0; j < p.size(); ++j) d.volume[j] = p.mass / p.density[j];

  // Renormalised density gradient (Dincer eqs. 8-9), kernel gradient correction (Shao eqs.
  // 16-17) and turbulent stress: per particle, before the rates that read them for neighbours.
  const bool turbulence = spec_.turbulence != WcsphTurbulence::none;
  SpsClosure closure;
  if (spec_.turbulence == WcsphTurbulence::smagorinsky) closure.mixing_length2 = (spec_.smagorinsky * h_) * (spec_.smagorinsky * h_);
  else closure.mixing_length2 = (spec_.smagorinsky * dp_) * (spec_.smagorinsky * dp_);
  closure.ct_dp = spec_.turbulence == WcsphTurbulence::sps ? ct_ * dp_ : 0.0;
  double nu_t_max = 0.0;
  if (spec_.delta > 0.0 || spec_.kernel_gradient_correction || turbulence) {
    auto fluid_only = [nf](std::size_t j) { return j < nf; };
    auto all = [](std::size_t) { return true; };
#pragma omp parallel for schedule(static) reduction(max : nu_t_max)
    for (std::size_t i = 0; i < nf; ++i) {
      if (spec_.delta > 0.0)
        d.density_gradient[i] = renormalised_gradient(d.pairs, p.density, d.volume, i, fluid_only).gradient;
      const Mat<D> L = spec_.kernel_gradient_correction ? kernel_correction_matrix(d.pairs, d.volume, i, all) : Mat<D>{};
      d.correction[i] = L;
      if (turbulence) {
        double nu_t = 0.0;
        d.stress[i] = sps_stress_of(corrected_velocity_gradient(p, d.pairs, d.volume, L, i), closure, nu_t);
        nu_t_max = std::max(nu_t_max, nu_t);
      }
    }
  }
  max_eddy_viscosity_ = nu_t_max;

  RateTerms t;
  t.mass = p.mass;
  t.rho0 = rho0_;
  t.c0 = c0_;
  t.h = h_;
  t.dp = dp_;
  t.delta = spec_.delta;
  t.viscosity_av = spec_.artificial_viscosity * h_ * c0_ * rho0_;
  t.nu = nu_;
  t.eta2 = eta2_;
  t.xsph = spec_.xsph;
  t.correct = spec_.kernel_gradient_correction;
  t.turbulence = turbulence;
  t.repulsive = spec_.walls == WallTreatment::repulsive;
  rates(p, d.pairs, t, repulsive_, d);

  Vec<D> wall;  // fixed-order sums: independent of the thread count
  Moment<D> moment{};
  for (std::size_t i = 0; i < nf; ++i) {
    wall += d.wall_acceleration[i];
    moment += cross(p.position[i], d.wall_acceleration[i]);
  }
  last_wall_force_ = wall * p.mass;
  last_wall_moment_ = moment * p.mass;
}

template <int D>
void BasicWcsphScheme<D>::initialise(ParticleSet& p, const Frame& frame) {
  sync_state(p);
  update_neighbours(p, 0.0, frame);
  mark_repulsive_layer(p);
  // The scene's (hydrostatic) pressures become densities: the state is then in discrete
  // balance up to the free-surface rows.
  for (std::size_t i = 0; i < p.n_fluid; ++i) p.density[i] = eos_density(p.pressure[i], rho0_, c0_);
  evaluate(p, frame);
  steps_ = 0;
}

// ---------------------------------------------------------------------------------------
// Time integration. Both integrators evaluate the rates once per step; the body force
// frame.at(r, u) is added where it is used, with the frame of this step (the driver passes
// the frame at the middle of the step), so an imposed motion enters at second order.

// Position Verlet, the symplectic "drift-kick-drift" scheme (Monaghan 2005, Rep. Prog. Phys. 68,
// section on time stepping; velocity-dependent forces take a predicted half-step velocity):
//   r^{n+1/2} = r^n + dt/2 u^n
//   evaluate at r^{n+1/2}, with u^{n+1/2} ~ u^n + dt/2 a^{n-1/2} and rho^{n+1/2} = rho^n + dt/2 D^{n-1/2}
//   (the rates of the last evaluation, for the velocity- and density-dependent terms)
//   u^{n+1} = u^n + dt a^{n+1/2},   rho^{n+1} = rho^n + dt D^{n+1/2}
//   r^{n+1} = r^{n+1/2} + dt/2 u^{n+1} + dt u_xsph^{n+1/2}
// The wall force reported is that of the midpoint evaluation: the one that changed the
// momentum over the step.
template <int D>
void BasicWcsphScheme<D>::step_symplectic(ParticleSet& p, const Input& in) {
  BasicWcsphData<D>& d = data_;
  const double dt = in.dt;
  const std::size_t nf = p.n_fluid;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nf; ++i) {
    const Vec<D> r = p.position[i], u = p.velocity[i];
    const double rho = p.density[i];
    d.position_start[i] = r;
    d.velocity_start[i] = u;
    d.density_start[i] = rho;
    const Vec<D> a = total_acceleration(d, in.frame, i, r, u);
    p.position[i] = r + 0.5 * dt * u;
    p.velocity[i] = u + 0.5 * dt * a;
    p.density[i] = rho + 0.5 * dt * d.density_rate[i];
  }
  evaluate(p, in.frame);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nf; ++i) {
    const Vec<D> a = total_acceleration(d, in.frame, i, p.position[i], p.velocity[i]);
    const Vec<D> u = d.velocity_start[i] + dt * a;
    p.velocity[i] = u;
    p.density[i] = d.density_start[i] + dt * d.density_rate[i];
    p.position[i] += 0.5 * dt * u + dt * d.xsph[i];
  }
  diagnostics_.wall_force = last_wall_force_;
  diagnostics_.wall_moment = last_wall_moment_;
}

// Leap-frog (Dincer 2019 sec. 2.1) in its kick-drift-kick (velocity Verlet) form:
//   u^{n+1/2} = u^n + dt/2 a^n,  rho^{n+1/2} = rho^n + dt/2 D^n
//   r^{n+1} = r^n + dt (u^{n+1/2} + u_xsph^n)
//   evaluate at r^{n+1}, with u^{n+1} ~ u^{n+1/2} + dt/2 a^n and rho^{n+1} ~ rho^{n+1/2} + dt/2 D^n
//   u^{n+1} = u^{n+1/2} + dt/2 a^{n+1},  rho^{n+1} = rho^{n+1/2} + dt/2 D^{n+1}
// The momentum change over the step is dt (F^n + F^{n+1}) / 2, so the wall force reported is
// the mean of the wall forces of the two evaluations.
template <int D>
void BasicWcsphScheme<D>::step_leapfrog(ParticleSet& p, const Input& in) {
  BasicWcsphData<D>& d = data_;
  const double dt = in.dt;
  const std::size_t nf = p.n_fluid;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nf; ++i) {
    const Vec<D> r = p.position[i], u = p.velocity[i];
    const Vec<D> a = total_acceleration(d, in.frame, i, r, u);
    const Vec<D> u_half = u + 0.5 * dt * a;
    const double rho_half = p.density[i] + 0.5 * dt * d.density_rate[i];
    d.velocity_start[i] = u_half;
    d.density_start[i] = rho_half;
    p.position[i] = r + dt * (u_half + d.xsph[i]);
    p.velocity[i] = u_half + 0.5 * dt * a;
    p.density[i] = rho_half + 0.5 * dt * d.density_rate[i];
  }
  const Vec<D> wall_before = last_wall_force_;
  const Moment<D> moment_before = last_wall_moment_;
  evaluate(p, in.frame);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nf; ++i) {
    const Vec<D> a = total_acceleration(d, in.frame, i, p.position[i], p.velocity[i]);
    p.velocity[i] = d.velocity_start[i] + 0.5 * dt * a;
    p.density[i] = d.density_start[i] + 0.5 * dt * d.density_rate[i];
  }
  diagnostics_.wall_force = 0.5 * (wall_before + last_wall_force_);
  diagnostics_.wall_moment = 0.5 * (moment_before + last_wall_moment_);
}

// Pressures of the new densities, the Shepard re-normalisation when due (Shao eqs. 10-11,
// every shepard_interval steps), wall values at the new positions (for output), diagnostics.
template <int D>
void BasicWcsphScheme<D>::finish_step(ParticleSet& p, const Input& in) {
  const Frame& frame = in.frame;
  ++steps_;
  fluid_pressure(p);
  // The pairs at the new positions: the Shepard filter and the shift read the fluid's rows, the
  // wall values only the walls'.
  const bool shepard = spec_.shepard_interval > 0 && steps_ % spec_.shepard_interval == 0;
  build_pairs(p, shepard || shifting_on_ ? 0 : p.n_fluid);
  if (shepard) {
    wall_values(p, frame);
    shepard_density(p, data_.pairs, data_.scratch);
    std::copy(data_.scratch.begin(), data_.scratch.begin() + static_cast<std::ptrdiff_t>(p.n_fluid), p.density.begin());
    fluid_pressure(p);
  }
  wall_values(p, frame);
  double vmax2 = 0.0;
  for (std::size_t i = 0; i < p.n_fluid; ++i) vmax2 = std::max(vmax2, norm2(p.velocity[i]));
  diagnostics_.shifts_limited = 0;
  if (shifting_on_) {
    diagnostics_.shifts_limited = shift(p, in.dt, std::sqrt(vmax2));
    fluid_pressure(p);
    build_pairs(p, p.n_fluid);  // the walls' rows at the shifted positions
    wall_values(p, frame);
    vmax2 = 0.0;
    for (std::size_t i = 0; i < p.n_fluid; ++i) vmax2 = std::max(vmax2, norm2(p.velocity[i]));
  }
  diagnostics_.max_speed = std::sqrt(vmax2);
  diagnostics_.free_surface = 0;
  diagnostics_.solver_iterations = 0;
  diagnostics_.solver_residual = 0.0;
}

template <int D>
void BasicWcsphScheme<D>::step(ParticleSet& p, const Input& in) {
  const bool have_rates = sync_state(p);
  update_neighbours(p, in.dt, in.frame);
  data_.resize_fluid(p.n_fluid);
  data_.extra_acceleration.clear();
  if (in.extra) in.extra(p, data_.extra_acceleration);  // screens: constant over the step
  if (!have_rates) evaluate(p, in.frame);  // first step without initialise(), or new particles
  if (spec_.integrator == Integrator::leapfrog) step_leapfrog(p, in);
  else step_symplectic(p, in);
  finish_step(p, in);
}

// The shift of delta-plus-SPH (physics/shifting.hpp; Sun et al. 2017): D = CFL Ma (2h)^2 with
// CFL = c0 dt / h and Ma = U_max / c0, i.e. 4 h U_max dt for every particle, on the pairs at the
// end of the step. The free surface is found as in the ISPH scheme (free_surface_flag: thesis
// eq. 2.20 with its spray fraction, at ISPH's default threshold 0.9), from the kernel sums m W
// against rho_ref (Sun et al. detect it from the eigenvalues of the renormalisation matrix
// instead; not done).
template <int D>
std::size_t BasicWcsphScheme<D>::shift(ParticleSet& p, double dt, double max_speed) {
  constexpr double kSurfaceThreshold = 0.9;
  BasicWcsphData<D>& d = data_;
  const BasicPairList<D>& pairs = d.pairs;
  const double m = p.mass;
  d.surface.assign(p.n_fluid, kShiftInterior);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    double wsum = pairs.self_w(), wall_sum = 0.0;
    pairs.for_each(i, [&](const BasicPair<D>& q) {
      wsum += q.w;
      if (!p.is_fluid(q.j)) wall_sum += q.w;
    });
    d.surface[i] = free_surface_flag(m * (wsum - wall_sum), m * wall_sum, m * wsum, rho_ref_, kSurfaceThreshold);
  }
  const double diffusion = 4.0 * h_ * max_speed * dt;
  return shift_fluid(p, pairs, d.surface, shifting_, [diffusion](std::size_t) { return diffusion; }, &p.density,
                     d.shifting);
}

template <int D>
double BasicWcsphScheme<D>::stable_dt(const ParticleSet& p, const Frame& frame) const {
  const BasicWcsphData<D>& d = data_;
  const bool have = d.acceleration.size() == p.n_fluid;
  double u_max = 0.0, a_max = 0.0;
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    u_max = std::max(u_max, norm(p.velocity[i]));
    const Vec<D> a = (have ? d.acceleration[i] : Vec<D>{}) + frame.at(p.position[i], p.velocity[i]);
    a_max = std::max(a_max, norm(a));
  }
  double dt = spec_.cfl * h_ / (c0_ + u_max);
  if (a_max > 0.0) dt = std::min(dt, spec_.cfl * std::sqrt(h_ / a_max));
  const double nu = (spec_.artificial_viscosity > 0.0 ? 0.0 : nu_) + max_eddy_viscosity_;
  if (nu > 0.0) dt = std::min(dt, 0.125 * h_ * h_ / nu);
  return dt;
}

template <int D>
void BasicWcsphScheme<D>::save_state(StateWriter& w) const {
  w.array("wcsph.id", data_.id);
  w.array("wcsph.acceleration", data_.acceleration);
  w.array("wcsph.density_rate", data_.density_rate);
  w.array("wcsph.xsph", data_.xsph);
  w.array("wcsph.position_at_build", data_.position_at_build);
  w.value("wcsph.max_eddy_viscosity", max_eddy_viscosity_);
  w.value("wcsph.last_wall_force", last_wall_force_);
  w.value("wcsph.last_wall_moment", last_wall_moment_);
  w.value("wcsph.steps", steps_);
  neighbours_.save(w);
}

template <int D>
void BasicWcsphScheme<D>::load_state(StateReader& r) {
  data_.id = r.array<std::int32_t>("wcsph.id");
  data_.acceleration = r.array<Vec<D>>("wcsph.acceleration");
  data_.density_rate = r.array<double>("wcsph.density_rate");
  data_.xsph = r.array<Vec<D>>("wcsph.xsph");
  data_.position_at_build = r.array<Vec<D>>("wcsph.position_at_build");
  max_eddy_viscosity_ = r.value<double>("wcsph.max_eddy_viscosity");
  last_wall_force_ = r.value<Vec<D>>("wcsph.last_wall_force");
  if (r.next_is("wcsph.last_wall_moment"))  // a checkpoint from before the moment column has none
    last_wall_moment_ = r.value<Moment<D>>("wcsph.last_wall_moment");
  steps_ = r.value<long>("wcsph.steps");
  neighbours_.load(r);
}

template struct BasicWcsphData<2>;
template struct BasicWcsphData<3>;
template class BasicWcsphScheme<2>;
template class BasicWcsphScheme<3>;

}  // namespace sloshsph
