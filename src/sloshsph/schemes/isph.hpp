#pragma once
// Incompressible SPH of thesis chapter 2 (eqs. 2.1-2.20): a projection scheme with a
// blended pressure Poisson equation, Adami dummy walls with free slip, free-surface
// detection by kernel-summed density, laminar viscosity and SPS turbulence.
//
// The solver data (per-particle scratch arrays) live in IsphData, apart from the
// solver; the particle store holds only what persists between steps.
#include <cstdint>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/particles.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/schemes/ppe_multigrid.hpp"
#include "sloshsph/schemes/ppe_solver.hpp"
#include "sloshsph/physics/shifting.hpp"
#include "sloshsph/physics/turbulence.hpp"
#include "sloshsph/schemes/step.hpp"
#include "sloshsph/sph/neighbours.hpp"
#include "sloshsph/sph/pairs.hpp"

namespace sloshsph {

template <int D>
struct BasicIsphData {
  std::vector<Vec<D>> velocity_old;    // u(t)
  std::vector<Vec<D>> velocity_star;   // u*, eq. 2.10
  std::vector<Vec<D>> position_star;   // r*, eq. 2.11 (walls: their fixed position)
  std::vector<double> ppe_source;    // right-hand side of eq. 2.13, 1/s^2
  std::vector<std::uint8_t> free_surface;  // eq. 2.20
  std::vector<SymTensor<D>> sps_stress;    // tau / rho, eq. 2.8, m^2/s^2
  std::vector<Vec<D>> wall_acceleration;   // acceleration of each fluid particle due to wall particles
  std::vector<Vec<D>> extra_acceleration;  // driver-supplied (screens), psi_sc of eq. 2.10
  // The implicit PPE: unknown row of each particle (-1: known pressure), the particle of each
  // row, the matrix, right side, solution and the Krylov scratch vectors (kept between steps).
  std::vector<int> ppe_row;
  std::vector<std::uint32_t> ppe_particle;
  std::vector<std::size_t> ppe_row_capacity;
  SparseRows ppe_matrix;
  std::vector<double> ppe_rhs, ppe_solution;
  BicgstabWork krylov;
  Multigrid multigrid;
  std::vector<Vec<D>> ppe_row_position;  // r* of each row's particle (multigrid aggregates)
  // The hierarchy is kept from step to step while the PPE has the same rows (the same particles in
  // the same order: no neighbour-list rebuild, which reorders them) for at most
  // kMultigridKeptSteps steps (IsphScheme::solve_assembled_ppe).
  std::vector<std::uint32_t> multigrid_rows;  // ppe_particle when the hierarchy was built
  std::uint64_t multigrid_neighbour_builds = 0;  // the neighbour list's build count then
  std::uint32_t multigrid_age = 0;            // steps that have used it since
  // The pairs within the kernel's support, built at r(t) at the start of a step and again at r*
  // after the prediction (sph/pairs.hpp).
  BasicPairList<D> pairs;
  BasicShiftingWork<D> shifting;  // scheme.shifting (physics/shifting.hpp)
  void resize(std::size_t n);
  MemoryParts memory_parts() const;  // without the neighbour list, which the scheme owns
};
using IsphData = BasicIsphData<2>;

// The stages of IsphScheme::step after the wall velocities, in their order.
enum class IsphStage { sps_stress, predict, density_and_ppe_source, pressure_solve, correct_and_advance, shift };

// In 2 or 3 dimensions (IsphScheme is the 2D one, IsphScheme3 the 3D one; instantiated for both in
// isph.cpp). The repulsive walls of thesis eq. 3.18 act from the first wall layer in either.
template <int D>
class BasicIsphScheme {
 public:
  using ParticleSet = BasicParticles<D>;
  using Input = BasicStepInput<D>;
  using Diagnostics = BasicStepDiagnostics<D>;

  BasicIsphScheme(const CaseSpec& spec, double h);

  // One time step of thesis Figure 2.1; particles are advanced in place.
  void step(ParticleSet& particles, const Input& input);

  // Before the first step: free-slip wall velocities, and the pressure (fluid and walls) that
  // holds the fluid at rest as it is placed, from one solve of the discrete PPE.
  void initialise(ParticleSet& particles, const BasicFrameForce<D>& frame);

  // One stage alone on `particles`, with the solver data the last step left (the stage
  // benchmarks, bench/bench_stages.cpp); step() is these in order. prepare_stage builds the pairs
  // the stage reads (at r(t) of `particles`, or at the r* the last step left) and must come first.
  void prepare_stage(IsphStage stage, const ParticleSet& particles);
  void run_stage(IsphStage stage, ParticleSet& particles, const Input& input);

  const Diagnostics& diagnostics() const { return diagnostics_; }
  const BasicNeighbourList<D>& neighbours() const { return neighbours_; }
  double reference_density() const { return rho_ref_; }
  double h() const { return h_; }
  // scheme.repulsive_walls: the strength D of each wall particle (index w - n_fluid; 0 outside the
  // first layer of the tank walls), set by the first step. Empty before it and without the option.
  const std::vector<double>& repulsion_strength() const { return repulsion_strength_; }
  // Checkpoints: besides the particles, ISPH keeps its neighbour list and the multigrid hierarchy
  // (with what decides whether it is kept) between steps.
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);
  MemoryParts memory_parts() const;

 private:
  void build_pairs(const std::vector<Vec<D>>& position);
  static bool reads_pairs_at_r_star(IsphStage stage);
  void stage(IsphStage stage, ParticleSet& p, const Input& in);
  void solve_pressure_explicit(ParticleSet& p, const Input& in);
  void solve_pressure_implicit(ParticleSet& p, const Input& in);
  void assemble_ppe(const ParticleSet& p, const Input& in);
  std::size_t pin_unanchored_blocks(const ParticleSet& p);
  double assemble_ppe_row(const ParticleSet& p, const Input& in, std::size_t i, std::size_t row);
  KrylovReport solve_ppe_system(bool multigrid);
  KrylovReport solve_assembled_ppe(bool multigrid, bool keep_hierarchy);
  bool can_keep_multigrid() const;
  void update_neighbours(ParticleSet& p);
  double clip(double pressure) const;
  void mark_repulsive_layer(const ParticleSet& p);

  SchemeSpec scheme_;
  KernelType kernel_type_;
  double h_;
  double dp_;
  double rho0_;
  double nu_;
  double eta2_;     // (0.01 h)^2, eqs. 2.5 and 2.16
  double rho_ref_;  // kernel sum of a full lattice: the density of the undisturbed fluid
  double lambda_full_ = 0.0;  // sum of the Laplacian pair weights over a full lattice (air model)
  BasicNeighbourList<D> neighbours_;
  // scheme.repulsive_walls (thesis eq. 3.18): strength D = coefficient g max(H_w, h) of each
  // wall particle (index w - n_fluid), 0 for those not in the first layer of the tank walls.
  TankSpec tank_;
  std::string tank_where_;
  double still_depth_ = 0.0;  // fill depth above the lowest point
  double gravity_ = 0.0;
  std::vector<double> repulsion_strength_;
  ShiftingRule shifting_;  // scheme.shifting = "lind"
  BasicIsphData<D> data_;
  Diagnostics diagnostics_;
};

using IsphScheme = BasicIsphScheme<2>;
using IsphScheme3 = BasicIsphScheme<3>;

// lattice_number_density and times_particle_volume (the reference density of both schemes) are in
// sph/kernel.hpp, where the screens' undisturbed weight uses them too.

// The free-surface flag of a fluid particle from its kernel sums, in any one unit (densities or
// concentrations): `fluid_sum` and `wall_sum` the shares of fluid and wall neighbours, `total` the
// whole sum with the particle's own share, `full` the sum of undisturbed fluid. 2: spray, when
// fluid fills less than half of the part of the kernel that walls leave free (so a particle in a
// corner of still water is not spray, a thin jet along a wall is); 1: free surface, `total` below
// `threshold` times `full` (eq. 2.20); 0: inside the fluid. The ISPH stage 5 and the WCSPH shift.
std::uint8_t free_surface_flag(double fluid_sum, double wall_sum, double total, double full, double threshold);

}  // namespace sloshsph
