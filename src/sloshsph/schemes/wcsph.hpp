#pragma once
// Weakly compressible delta-SPH (Dincer 2019 sec. 2.1, eqs. 5-13, after Marrone et al. 2011)
// with the options of Shao et al. 2012 (sec. 2: density re-normalisation, kernel gradient
// correction, Smagorinsky turbulence, coupled dynamic solid boundary). WcsphSpec
// (core/case_spec.hpp) selects the options.
//
// Per fluid particle i (V_j = m / rho_j, grad W = grad_i W_ij, r_ij = r_i - r_j, u_ij = u_i - u_j):
//   drho_i/dt = sum_j m u_ij . grad W  +  delta h c0 sum_{j fluid} V_j psi_ij . grad W     (eqs. 5, 7)
//   du_i/dt   = -(1/rho_i) sum_j V_j (p_i + p_j) grad W
//               + alpha h c0 (rho0/rho_i) sum_j V_j pi_ij grad W   (or the laminar viscosity)
//               + turbulence + wall repulsion + body force                               (eq. 6)
//   p_i = c0^2 (rho_i - rho0)                                                             (eq. 10)
//   dr_i/dt = u_i + eps sum_{j fluid} m (u_j - u_i) / rho_ij W_ij                          (eq. 11)
// Walls: Adami dummy particles with free slip (physics/walls.hpp), or Shao's repulsive
// particles (the first wall layer) plus ghost particles with Shepard-interpolated values.
//
// The driver calls initialise() once, then step() with dt <= stable_dt(). Each step makes one
// evaluation of the rates (a gather sweep per stage, each particle writing only itself, so the
// result does not depend on the number of threads).
//
// Written once for 2 and 3 dimensions (issue 31): BasicWcsphScheme<D>; WcsphScheme is the 2D one,
// WcsphScheme3 the 3D one; Shao's repulsive wall particles are the first wall layer in either.
#include <cstdint>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/state_io.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/physics/kernel_correction.hpp"
#include "sloshsph/physics/shifting.hpp"
#include "sloshsph/schemes/isph.hpp"  // SymTensor, lattice_number_density, times_particle_volume
#include "sloshsph/schemes/step.hpp"
#include "sloshsph/sph/neighbours.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

template <int D>
struct BasicWcsphData {
  // Kept between steps, one per fluid particle, in particle order; `id` names the particle
  // each entry belongs to (the driver may remove leaked particles between steps).
  std::vector<std::int32_t> id;
  std::vector<Vec<D>> acceleration;    // du/dt of the last evaluation without the body force, m/s^2
  std::vector<double> density_rate;  // drho/dt of the last evaluation, kg/m^3/s
  std::vector<Vec<D>> xsph;            // XSPH velocity correction of the last evaluation, m/s
  std::vector<Vec<D>> position_at_build;  // fluid positions at the last neighbour-list build

  // Scratch of one step.
  std::vector<Vec<D>> extra_acceleration;  // driver-supplied (screens), constant over the step
  std::vector<Vec<D>> position_start;  // r at the start of the step
  std::vector<Vec<D>> velocity_start;  // u at the start of the step (leap-frog: at the half step)
  std::vector<double> density_start; // rho at the start of the step (leap-frog: at the half step)
  std::vector<double> volume;        // m / rho, every particle
  std::vector<Vec<D>> density_gradient;  // renormalised grad rho (Dincer eqs. 8-9), fluid
  std::vector<Mat<D>> correction;      // kernel gradient correction L_i (Shao eq. 17), fluid
  std::vector<SymTensor<D>> stress;    // turbulent stress R / rho (Shao eq. 21), m^2/s^2, fluid
  std::vector<Vec<D>> wall_acceleration; // part of du/dt due to wall particles (base shear), fluid
  std::vector<double> scratch;         // Shepard densities
  BasicPairList<D> pairs;  // within the kernel's support at the positions of the current evaluation
  // scheme.shifting = "delta_plus": the free-surface flags of the shift and its scratch.
  std::vector<std::uint8_t> surface;
  BasicShiftingWork<D> shifting;

  void resize_fluid(std::size_t n_fluid);
  void resize_all(std::size_t n);
};

template <int D>
class BasicWcsphScheme {
 public:
  using ParticleSet = BasicParticles<D>;
  using Input = BasicStepInput<D>;
  using Frame = BasicFrameForce<D>;

  BasicWcsphScheme(const CaseSpec& spec, double h);

  // Fluid densities from the pressures the particles carry (inverse equation of state: the
  // scene's hydrostatic pressure becomes a hydrostatic density), wall values, and one
  // evaluation of the rates for the first step.
  void initialise(ParticleSet& particles, const Frame& frame);

  // Advances the particles by input.dt (symplectic position Verlet or leap-frog, by
  // WcsphSpec::integrator). input.frame is the body force at the middle of the step.
  void step(ParticleSet& particles, const Input& input);

  // The largest stable step for the current state:
  //   dt = min( cfl h / (c0 + u_max),          acoustic CFL condition (covers the artificial viscosity)
  //             cfl sqrt(h / a_max),            force condition, a_max = max |du/dt| of the last evaluation
  //                                             (with the body force frame.at(r, u))
  //             0.125 h^2 / (nu + nu_t,max) )   viscous diffusion (Morris et al. 1997); nu counts only
  //                                             when the laminar viscosity is used (artificial_viscosity == 0)
  // with cfl = WcsphSpec::cfl. The artificial viscosity's diffusion limit, 0.125 h^2 / nu_av with
  // nu_av = alpha h c0 / 8, is h / (alpha c0): 1/alpha times h / c0, so it never binds.
  double stable_dt(const ParticleSet& particles, const Frame& frame) const;

  double sound_speed() const { return c0_; }
  // Checkpoints: the state kept between steps (last rates, XSPH, counters, neighbour list).
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);
  const BasicStepDiagnostics<D>& diagnostics() const { return diagnostics_; }
  const BasicNeighbourList<D>& neighbours() const { return neighbours_; }
  // Kernel sum of undisturbed fluid (as IsphScheme::reference_density), for surface detection by
  // the driver's gauges.
  double reference_density() const { return rho_ref_; }
  double h() const { return h_; }
  // Per wall particle (index w - n_fluid): 1 in Shao's repulsive layer (walls = "repulsive"), set by
  // initialise; all 0 with Adami walls.
  const std::vector<std::uint8_t>& repulsive_layer() const { return repulsive_; }
  MemoryParts memory_parts() const;

 private:
  void build_pairs(const ParticleSet& p, std::size_t first_row = 0);
  void step_symplectic(ParticleSet& p, const Input& in);
  void step_leapfrog(ParticleSet& p, const Input& in);
  void evaluate(ParticleSet& p, const Frame& frame);
  void wall_values(ParticleSet& p, const Frame& frame);
  void finish_step(ParticleSet& p, const Input& in);
  std::size_t shift(ParticleSet& p, double dt, double max_speed);
  void update_neighbours(ParticleSet& p, double dt, const Frame& frame);
  bool sync_state(const ParticleSet& p);
  void fluid_pressure(ParticleSet& p) const;
  void mark_repulsive_layer(const ParticleSet& p);

  WcsphSpec spec_;
  KernelType kernel_type_;
  double h_;
  double dp_;
  double rho0_;
  double nu_;
  double c0_;
  double eta2_;        // 0.01 h^2, Shao eq. 6
  double rho_ref_;
  double ct_;          // SPS constant C_t (SchemeSpec::ct)
  double max_eddy_viscosity_ = 0.0;
  Vec<D> last_wall_force_;   // leap-frog: wall force of the last evaluation
  Moment<D> last_wall_moment_{};  // and its moment about the origin
  long steps_ = 0;
  TankSpec tank_;
  std::string tank_where_;
  std::vector<std::uint8_t> repulsive_;  // per wall particle (index w - n_fluid): first layer
  BasicNeighbourList<D> neighbours_;
  bool shifting_on_ = false;  // scheme.shifting = "delta_plus"
  ShiftingRule shifting_;
  BasicWcsphData<D> data_;
  BasicStepDiagnostics<D> diagnostics_;
};

extern template struct BasicWcsphData<2>;
extern template struct BasicWcsphData<3>;
extern template class BasicWcsphScheme<2>;
extern template class BasicWcsphScheme<3>;
using WcsphData = BasicWcsphData<2>;
using WcsphScheme = BasicWcsphScheme<2>;
using WcsphScheme3 = BasicWcsphScheme<3>;

}  // namespace sloshsph
