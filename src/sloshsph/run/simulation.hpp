#pragma once
// One simulation in memory: scene, scheme, excitation and observers, advanced step by
// step. The command line (run_case) and the tests drive it the same way.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sloshsph/core/case_spec.hpp"
#include "sloshsph/core/state_io.hpp"
#include "sloshsph/geometry/scene.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/physics/excitation.hpp"
#include "sloshsph/physics/pair_contact.hpp"
#include "sloshsph/physics/porous.hpp"
#include "sloshsph/physics/wall_contact.hpp"
#include "sloshsph/run/plate_coupling.hpp"
#include "sloshsph/run/structure_coupling.hpp"
#include "sloshsph/schemes/scheme.hpp"

namespace sloshsph {

// Fills what the case leaves to be derived: the excitation's omega from `frequency` or
// from `beta` times the tank's first linear sloshing frequency. Throws InputError.
CaseSpec resolve_case(CaseSpec spec);

// First linear sloshing angular frequency of the case's tank and fill (rad/s): the closed
// form for a rectangle, the modal solver (linear/modal.hpp) for any other section.
double first_sloshing_omega(const CaseSpec& spec);

// The frequency `beta` refers to: first_sloshing_omega, or the thesis's closed form when
// excitation.beta_reference = "thesis".
double reference_omega(const CaseSpec& spec);

template <int D>
class BasicSimulation;

// What one sample works out once for all its columns: the tank's motion, the means over the
// interval since the last sample, the fluid's energies and momentum, the pressure probes and the
// fluid inside each plate. Per metre of breadth in 2D (kg/m, N/m, J/m), whole in 3D (kg, N, J).
template <int D>
struct BasicSampleBasis {
  BaseMotion motion;               // in 3D in tank axes (physics/excitation.hpp, in_tank_axes)
  double fluid_mass = 0.0;         // kg/m
  Vec<D> wall_force;               // N/m, interval mean of the walls' (and screens') force on the fluid
  Moment<D> wall_moment{};         // N m/m (N m), its moment about the origin, interval mean
  double base_acceleration = 0.0;    // m/s^2, interval mean of the frame's acceleration along x
  double base_acceleration_y = 0.0;  // m/s^2, the same along y (3D)
  double kinetic_energy = 0.0, potential_energy = 0.0;  // of the fluid, tank frame
  double momentum_x = 0.0, momentum_y = 0.0;            // of the fluid, tank frame (momentum_y: 3D)
  std::vector<double> probe_pressure;  // Pa, each pressure probe (one cell grid for all)
  std::vector<double> plate_inside;    // fluid particles inside each plate
};

// One column of timeseries.csv: its name, its unit, and its value in a sample. Each column is
// defined once, with its value (Simulation::build_columns), so names and values cannot drift apart.
template <int D>
struct BasicColumn {
  std::string name;
  std::string unit;
  std::function<double(const BasicSimulation<D>&, const BasicSampleBasis<D>&)> value;
};

template <int D>
struct BasicLeakRecord {
  double time = 0.0;
  std::int32_t id = 0;
  Vec<D> position;
};

// How a Simulation begins: with the fluid settled for time.settle (a new run), or unsettled, to
// be overwritten at once by load_state (a resume: settling would be thrown away).
enum class SimulationStart { settled, for_checkpoint };

// In 2D (Simulation) every feature of a case; in 3D (Simulation3, tank.dimensions = 3) the ISPH
// scheme, a translation along excitation.direction, gauges, point probes and the structure with
// its sway along x and y, porous screens and explicit slats, and plates across the breadth of a box
// or prism (issue 31; run/plate_coupling.hpp).
template <int D>
class BasicSimulation {
 public:
  using Column = BasicColumn<D>;
  using SampleBasis = BasicSampleBasis<D>;
  using LeakRecord = BasicLeakRecord<D>;

  // `spec` must have been through resolve_case. Throws InputError for a bad geometry.
  explicit BasicSimulation(const CaseSpec& spec, SimulationStart start = SimulationStart::settled);

  // Advances one time step. Throws RunFailure (non-finite values, speed beyond the bound,
  // more leaked particles than allowed), leaving the last completed state in place.
  void step();

  double time() const { return time_; }
  std::size_t steps() const { return steps_; }
  bool finished() const { return time_ >= spec_.time.end - 1e-12; }

  // The time-series columns and the current values (resets the interval averages).
  const std::vector<Column>& columns() const { return columns_; }
  std::vector<double> sample();

  const CaseSpec& spec() const { return spec_; }
  const BasicScene<D>& scene() const { return scene_; }
  const BasicParticles<D>& particles() const { return scene_.particles; }
  const BasicAnyScheme<D>& scheme() const { return scheme_; }
  const BasicScreenParticles<D>& screens() const { return screens_; }
  // The imposed motion of [excitation]; with [structure] the ground motion under the structure.
  const BaseMotionSource& base() const { return base_; }
  // The imposed motion of [excitation] at t, in 3D in tank axes (in_tank_axes): with [structure]
  // the ground motion under it.
  BaseMotion ground_motion(double t) const;
  // The motion of the tank now: the imposed base motion, or the structure's (ground + relative).
  BaseMotion tank_motion() const;
  // [structure]: the structure carrying the tank (nullptr without one); in 3D its sway along x.
  const StructureCoupling* structure() const { return structure_ ? &*structure_ : nullptr; }
  // [structure.y] (3D): the structure's sway along y (nullptr without one).
  const StructureCoupling* structure_y() const { return structure_y_ ? &*structure_y_ : nullptr; }
  // [[plates]]: the elastic plates, in case order.
  const std::vector<BasicPlateCoupling<D>>& plates() const { return plates_; }
  const std::vector<LeakRecord>& leaks() const { return leaks_; }
  std::size_t leaked() const { return leaks_.size(); }
  // Fluid particles stopped at the tank walls since t = 0 (scheme.wall_contact).
  std::size_t wall_contacts() const { return wall_contacts_; }
  // Pairs of fluid particles kept apart since t = 0 (scheme.pair_contact).
  std::size_t pair_contacts() const { return pair_contacts_; }
  std::size_t pair_contact_memory_bytes() const { return pair_contact_.memory_bytes(); }
  std::size_t shifts_limited() const { return shifts_limited_; }
  // Implicit PPE: steps in which a block of fluid that no p = 0 condition reaches was set to p = 0
  // (IsphScheme::pin_unanchored_blocks), and its particles summed over those steps; counted since
  // this object was made (a resumed run counts from the resume: not kept in checkpoints, so that
  // checkpoints stay readable across versions). last_step_pinned(): particles in the last step.
  std::size_t pinned_steps() const { return pinned_steps_; }
  // time.dt_min: the steps that took the floor because the adaptive bound fell below it, and the
  // largest u_max dt / dp of those steps; counted since this object was made, as pinned_steps.
  std::size_t floor_steps() const { return floor_steps_; }
  double largest_floor_cfl() const { return largest_floor_cfl_; }
  std::size_t pinned_particles() const { return pinned_particles_; }
  std::size_t last_step_pinned() const { return scheme_.diagnostics().pinned_particles; }
  double fluid_mass() const { return scene_.particles.mass * static_cast<double>(scene_.particles.n_fluid); }
  double max_speed() const { return max_speed_; }
  double linear_omega() const { return linear_omega_; }  // first_sloshing_omega of the case
  double last_dt() const { return last_dt_; }
  // Checkpoints: everything that evolves (particles, scheme, time, interval sums, leaks, the
  // structure); the rest is rebuilt from the case. load_state needs a Simulation built from the
  // same case; a resumed run then continues bitwise as the original would have.
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

  double surface_height(std::size_t gauge) const;  // current free-surface height (y; 3D: z) at gauge k
  double probe_pressure(std::size_t probe) const;  // current pressure at probe k

 private:
  double next_dt(bool* floored = nullptr) const;  // *floored: the step is time.dt_min, raised to it
  double adaptive_bound() const;  // s, the adaptive step's bound before its ceiling and floor
  void settle();
  void check_state() const;                         // at the current time and step
  void check_state(const std::string& when) const;  // RunFailure naming `when` otherwise
  void remove_leaked();
  // Spacing of the sampled container distance (leak test, first wall-contact test), m.
  double container_grid() const { return 0.5 * spec_.particles.dp; }
  // The sampled signed distance of the container (leak test, first wall-contact test): in 3D the
  // section's sampled distance and the end walls.
  double container_distance(Vec<D> p) const;
  // The tank-frame body force of a motion of the tank.
  BasicFrameForce<D> frame_of(const BaseMotion& m) const { return frame_force_in<D>(spec_.fluid.gravity, m); }
  BasicWallContact<D> wall_contact(double dt);
  void start_plates();
  void advance_plates(double dt, const BasicFrameForce<D>& frame);
  void build_columns();
  void add_column(std::string name, std::string unit,
                  std::function<double(const BasicSimulation&, const SampleBasis&)> value);
  SampleBasis sample_basis();
  void reset_interval_sums();

  CaseSpec spec_;
  BasicScene<D> scene_;
  ContainerDistance container_;  // of the section
  BaseMotionSource base_;
  BaseMotionSource base_y_;  // [excitation.y] (3D): the motion along y; unused without it
  BasicAnyScheme<D> scheme_;
  // Porous screens (Ergun, Morison): their particles, buffers, and the last step's loads.
  BasicScreenParticles<D> screens_;
  BasicScreenDragWork<D> screen_work_;
  std::vector<BasicScreenElementLoad<D>> screen_loads_;
  std::vector<Vec<D>> acc_screen_force_;  // interval sums of dt x force, per element
  double time_ = 0.0;
  std::size_t steps_ = 0;
  double last_dt_ = 0.0;
  double max_speed_ = 0.0;
  double speed_limit_ = 0.0;
  double linear_omega_ = 0.0;
  double c_full_ = 1.0;                  // kernel sum sum_j V W of undisturbed fluid
  std::vector<double> gauge_datum_;      // surface height of each gauge at t = 0
  std::vector<LeakRecord> leaks_;
  std::size_t wall_contacts_ = 0;
  std::size_t pair_contacts_ = 0;
  BasicPairContactStep<D> pair_contact_;  // scheme.pair_contact
  std::size_t shifts_limited_ = 0;  // scheme.shifting: shifts cut by their cap or a wall, over the run
  std::size_t pinned_steps_ = 0, pinned_particles_ = 0;
  std::size_t floor_steps_ = 0;     // time.dt_min
  double largest_floor_cfl_ = 0.0;
  std::vector<Column> columns_;
  // Accumulated over the steps since the last sample (forces are interval means).
  double acc_dt_ = 0.0;
  Vec<D> acc_wall_force_;
  Moment<D> acc_wall_moment_{};  // about the tank frame's origin
  Vec<D> moment_point_;          // output.moment_point (default: the centre of the tank's bottom)
  double acc_base_acceleration_ = 0.0, acc_base_acceleration_y_ = 0.0;  // along x and (3D) y
  double work_on_fluid_ = 0.0;  // J/m, integral of F_w dX since t = 0
  // [structure] (thesis 4.2.3): the SDOF carrying the tank, the sloshing force of the last
  // fluid step (N/m, fed to the structure in the next one) and the interval sum of dt x F_TLD.
  std::optional<StructureCoupling> structure_;
  // [structure.y] (3D): the sway along y, its sloshing force (N) and interval sum of dt x F_TLD_y.
  std::optional<StructureCoupling> structure_y_;
  double sloshing_force_y_ = 0.0;
  double acc_tld_force_y_ = 0.0;
  // [[plates]] (Dincer 2019): elastic plates moved by the fluid, and the interval sums of dt x the
  // fluid force on each.
  std::vector<BasicPlateCoupling<D>> plates_;
  std::vector<Vec2> acc_plate_force_;
  double sloshing_force_ = 0.0;
  double acc_tld_force_ = 0.0;
};

extern template class BasicSimulation<2>;
extern template class BasicSimulation<3>;
using Simulation = BasicSimulation<2>;
using Simulation3 = BasicSimulation<3>;
using Column = BasicColumn<2>;
using SampleBasis = BasicSampleBasis<2>;
using LeakRecord = BasicLeakRecord<2>;

}  // namespace sloshsph
