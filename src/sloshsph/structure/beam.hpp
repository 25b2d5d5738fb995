#pragma once
// Eigen's core and sparse containers only: the decompositions are in beam.cpp (this header reaches
// every file that includes run/simulation.hpp; Dense + Sparse cost about 5 s of compiling each).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "sloshsph/core/state_io.hpp"
#include "sloshsph/core/vec2.hpp"
#include "sloshsph/structure/banded_lu.hpp"
#include "sloshsph/structure/beam_element.hpp"
#include "sloshsph/structure/beam_loads.hpp"

// A slender elastic body (plate strip, gate, flap) in 2D with large deflections: a chain of
// geometrically exact Reissner beam elements (beam_element.hpp), Rayleigh damping C = b0 M + b1 K
// (Dincer 2019, eq. 15), implicit time integration with Newton iterations: an energy-conserving
// midpoint rule (default) or HHT-alpha / Newmark. Units SI; with the default width b = 1 m, forces,
// masses and energies are per metre of the out-of-plane width. The solver works in the frame of the
// support (the tank frame): base motion enters as BeamLoads::body_acceleration.
//
// Typical coupling loop (fluid boundary particles attached to material points of the body):
//   Beam beam(spec);                                    // undeformed body
//   BeamMaterialPoint p = beam.material_point(x0);      // once per boundary particle, x0 on a face
//   each step: BeamLoads loads = beam.zero_loads();
//              beam.add_force(p, fluid_force_on_particle, loads);   // for every particle
//              loads.body_acceleration = -tank_acceleration;
//              beam.step(dt, loads);
//              x = beam.position(p); v = beam.velocity(p);          // move the particles
namespace sloshsph {

enum class BeamSupport { kFree, kPinned, kClamped };
enum class BeamMass { kConsistent, kLumped };
// kEnergyConserving: implicit midpoint / average-acceleration rule with a discrete-gradient internal force
//   (beam_element.hpp): the discrete energy balance is exact, so the nonlinear motion cannot blow up.
//   Identical to Newmark's average acceleration rule for linear problems. The default.
// kHHT: Hilber-Hughes-Taylor alpha method (hht_alpha in [-1/3, 0]; 0 is plain Newmark average
//   acceleration), numerical damping of the high modes for alpha < 0.
enum class BeamIntegrator { kEnergyConserving, kHHT };

// Extra per-node constraints (fixed to the initial position / rotation; zero prescribed values).
struct BeamNodeConstraint {
  int node = 0;
  bool fix_x = false;
  bool fix_y = false;
  bool fix_rotation = false;
};

struct BeamSpec {
  // Geometry: either `node_points` (>= 2 points, one straight element between consecutive points)
  // or, when node_points is empty, the straight segment start -> end cut into `elements` equal elements.
  std::vector<Vec2> node_points;
  Vec2 start{};
  Vec2 end{};
  int elements = 20;

  double thickness = 0.0;        // t [m], in the plane of the simulation
  double width = 1.0;            // b [m], out of plane (1 m: loads and energies per metre)
  double youngs_modulus = 0.0;   // E [Pa]
  double poisson_ratio = 0.3;    // nu [-]; enters G = E / (2 (1 + nu)) and the plane-strain modulus
  bool plane_strain = false;     // use E / (1 - nu^2) for EA and EI (wide plate in cylindrical bending)
  double shear_correction = 5.0 / 6.0;  // k for a rectangular section (Timoshenko shear area k A)
  double density = 0.0;          // rho_s [kg/m^3]

  double rayleigh_mass = 0.0;       // b0 [1/s] in C = b0 M + b1 K (Dincer 2019 eq. 15)
  double rayleigh_stiffness = 0.0;  // b1 [s]

  BeamSupport start_support = BeamSupport::kClamped;
  BeamSupport end_support = BeamSupport::kFree;
  std::vector<BeamNodeConstraint> constraints;

  Vec2 gravity{};                  // [m/s^2] body load, e.g. {0, -9.81}
  // Lumped is the default: with these reduced-integration elements it gives the more accurate bending
  // frequencies (docs/validation.md, "Structure and signals") and a diagonal mass.
  BeamMass mass = BeamMass::kLumped;

  BeamIntegrator integrator = BeamIntegrator::kEnergyConserving;
  double hht_alpha = 0.0;  // kHHT only: in [-1/3, 0] (Hilber, Hughes & Taylor 1977)
  double newton_tolerance = 1e-10;            // residual, relative to the largest force term
  double newton_increment_tolerance = 1e-12;  // Newton correction, relative to the beam length
  int newton_max_iterations = 30;
};

// A point of the body fixed in the material: element, position along it and offset across the
// thickness (along the section director). Used to attach fluid boundary particles to the beam.
struct BeamMaterialPoint {
  int element = 0;
  double xi = 0.0;      // 0 at the element's first node, 1 at its second
  double offset = 0.0;  // [m] signed distance along the director (+ towards the side +1 face)
};

struct BeamSolveReport {
  int iterations = 0;  // Newton iterations (summed over load steps / sub-steps)
  int substeps = 1;    // load increments (static) or time sub-steps (dynamic) actually used
};

struct BeamModes {
  std::vector<double> omega;                 // angular frequencies [rad/s], ascending
  std::vector<Eigen::VectorXd> shapes;       // mass-normalised, 3 DOFs per node (x, y, theta)
};

class Beam {
 public:
  explicit Beam(const BeamSpec& spec);

  const BeamSpec& spec() const { return spec_; }
  int node_count() const { return static_cast<int>(initial_positions_.size()); }
  int element_count() const { return node_count() - 1; }
  SectionStiffness section() const { return section_; }
  double mass_per_length() const { return mass_per_length_; }  // rho b t [kg/m]
  double length() const { return total_length_; }              // undeformed length [m]
  double time() const { return state_.time; }

  // Loads with the vectors sized for this beam (all zero).
  BeamLoads zero_loads() const;

  // Static equilibrium under dead loads (and follower pressure): the load is applied in
  // `load_steps` equal increments, each solved by Newton; an increment that does not converge is
  // bisected. Afterwards the beam is at rest in the equilibrium. Throws RunFailure on failure.
  BeamSolveReport static_solve(const BeamLoads& loads, int load_steps = 1);

  // Advances the motion by dt with the loads acting at the end of the step (t + dt).
  // A step whose Newton iteration fails is retried as sub-steps; throws RunFailure if that fails too.
  BeamSolveReport step(double dt, const BeamLoads& loads);
  BeamSolveReport step(double dt, const std::vector<Vec2>& nodal_forces, Vec2 body_acceleration = {});

  // State (current configuration).
  const std::vector<Vec2>& initial_positions() const { return initial_positions_; }
  std::vector<Vec2> node_positions() const;
  std::vector<Vec2> node_displacements() const;
  std::vector<Vec2> node_velocities() const;
  std::vector<double> node_rotations() const;          // section rotation from the initial state [rad]
  std::vector<double> node_angular_velocities() const;  // [rad/s]
  std::vector<Vec2> node_directors() const;             // unit vectors across the thickness (to side +1)

  // The faces of the body: node positions offset by side * t/2 along the node director (side +1 or -1),
  // their velocities, and the closed outline (face +1 first -> last node, then face -1 back).
  std::vector<Vec2> surface(int side) const;
  std::vector<Vec2> surface_velocities(int side) const;
  std::vector<Vec2> outline() const;

  // Material points (for fluid boundary particles): locate a point of the *undeformed* body, then
  // follow it; forces at a material point are turned into work-consistent nodal forces and moments.
  BeamMaterialPoint material_point(Vec2 reference_point) const;
  Vec2 position(const BeamMaterialPoint& point) const;
  Vec2 velocity(const BeamMaterialPoint& point) const;
  void add_force(const BeamMaterialPoint& point, Vec2 force, BeamLoads& loads) const;
  // Multiplies all velocities by `factor` (damped settling of a coupled run); the acceleration is
  // then recomputed from the equation of motion at the next step.
  void scale_velocities(double factor);

  // Rotation of the section at a material point since the undeformed state [rad] (counter-clockwise).
  double rotation(const BeamMaterialPoint& point) const;

  // Checkpoints: the motion state (displacements, velocities, accelerations, energy sums). A
  // Beam built from the same spec and loaded continues bitwise as the saved one would have.
  void save_state(StateWriter& w, const std::string& prefix) const;
  void load_state(StateReader& r, const std::string& prefix);

  // Small vibrations about the current configuration (with its stresses): K_T phi = omega^2 M phi
  // on the unconstrained DOFs, solved densely (fine up to a few hundred elements). `count` lowest
  // modes; follower-load stiffness is not included. A negative value -sqrt(|lambda|) flags an
  // unstable (buckled) state.
  BeamModes modes(int count) const;
  std::vector<double> natural_frequencies(int count) const;  // [rad/s]

  double kinetic_energy() const;       // 1/2 v^T M v [J]
  double strain_energy() const;        // sum of element energies [J]
  double external_work() const { return state_.external_work; }      // work of all loads since start [J]
  double damping_dissipation() const { return state_.dissipated; }   // energy taken by Rayleigh damping [J]

 private:
  struct Assembly;
  struct TangentFactors {  // effective tangent of the static / HHT residual
    double stiffness = 1.0;  // on K_T + d f_damp/dq - d f_ext/dq
    double damping = 0.0;    // on d f_damp/dv = b0 M + b1 K_material
    double mass = 0.0;       // on M
  };
  void assemble(const Eigen::VectorXd& q, const Eigen::VectorXd& v, const BeamLoads& loads, double load_factor,
                bool with_damping, const TangentFactors& factors, Assembly& out) const;
  void assemble_midpoint(const Eigen::VectorXd& q0, const Eigen::VectorXd& q1, const BeamLoads& loads, double dt,
                         Assembly& out) const;
  void add_pressure_loads(int element, const Eigen::VectorXd& q, const BeamLoads& loads, double load_factor,
                          double tangent_factor, BeamElementMatrix& k_eff, Eigen::VectorXd& external) const;
  void add_nodal_and_body_loads(const BeamLoads& loads, double load_factor, Eigen::VectorXd& external) const;
  void scatter(int element, const BeamElementMatrix& k_eff, std::vector<Eigen::Triplet<double>>& triplets) const;
  BeamElementState element_state(const Eigen::VectorXd& q, int element) const;
  bool try_step(double dt, const BeamLoads& loads, int& iterations);
  bool try_step_hht(double dt, const BeamLoads& loads, int& iterations);
  bool try_step_midpoint(double dt, const BeamLoads& loads, int& iterations);
  Eigen::VectorXd expand(const Eigen::VectorXd& free) const;
  void prepare_initial_acceleration(const BeamLoads& loads);
  bool solve_linear(const std::vector<Eigen::Triplet<double>>& triplets, const Eigen::VectorXd& rhs,
                    Eigen::VectorXd& solution);
  Eigen::VectorXd free_part(const Eigen::VectorXd& full) const;
  // One Newton correction, q += K_T^-1 (-residual) on the free DOFs; `small_increment` says whether
  // it fell below newton_increment_tolerance. False if the tangent could not be factorised.
  bool newton_correction(const Assembly& assembly, const Eigen::VectorXd& residual, Eigen::VectorXd& q,
                         bool& small_increment);
  void check_loads(const BeamLoads& loads) const;
  double section_angle(int element, double xi) const;

  BeamSpec spec_;
  SectionStiffness section_;
  double mass_per_length_ = 0.0;
  double rotary_inertia_per_length_ = 0.0;
  double total_length_ = 0.0;
  std::vector<Vec2> initial_positions_;
  std::vector<BeamElementGeometry> elements_;
  std::vector<Vec2> initial_directors_;  // per node
  std::vector<int> equation_;             // per DOF: equation index, -1 if constrained
  int free_dofs_ = 0;
  Eigen::SparseMatrix<double> mass_;      // full DOF mass matrix (constant)

  // Everything a time step changes, grouped so that a failed step can be undone.
  struct State {
    Eigen::VectorXd q;  // DOFs per node: displacement x, y from the initial position, rotation theta
    Eigen::VectorXd v;
    Eigen::VectorXd a;
    bool acceleration_ready = false;          // a consistent with the equation of motion at t
    Eigen::VectorXd previous_force_balance;   // f_int + f_damp - f_ext at t (HHT-alpha needs it)
    Eigen::VectorXd previous_external;        // f_ext at t (work accounting)
    Eigen::VectorXd previous_damping;         // f_damp at t
    double time = 0.0;
    double external_work = 0.0;
    double dissipated = 0.0;
  };
  State state_;

  BandedLu solver_;  // Newton systems on the free DOFs (bandwidth of one element)
};

}  // namespace sloshsph
