#pragma once
// The plain, validated description of one simulation, in SI units.
// io/case_reader fills it from a TOML case file; every later layer reads only this.
// docs/case-format.md documents each field under its TOML key.
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sloshsph/core/vec2.hpp"

namespace sloshsph {

struct FluidSpec {
  double density = 1000.0;    // kg/m^3
  double viscosity = 1.0e-6;  // m^2/s, kinematic
  double gravity = 9.81;      // m/s^2
};

struct TankSpec {
  // 2: a tank section (x along the length, y up); 3: that section extruded over `breadth` (x along
  // the length, y across the breadth, z up; geometry/prism_tank.hpp). Issue 31.
  int dimensions = 2;
  double breadth = 0.0;       // m, 3D: the inner breadth, between the end walls y = 0 and y = breadth
  double radius = 0.0;        // m, 3D "cylinder": inner radius (length and breadth are then 2 radius)
  // "rectangle", "sloped" (alias "triangle", "trapezoid"), "parabolic", "circular", "polyline";
  // 3D only: "cylinder" (upright, geometry/cylinder_tank.hpp).
  std::string shape = "rectangle";
  double length = 0.0;        // m, inner length (width of the section at the top of the walls)
  double height = 0.0;        // m, wall height above the lowest point of the bottom
  double coefficient = 1.0;   // 1/m, parabolic: bottom y = coefficient * (x - length/2)^2
  double angle = 45.0;        // deg, sloped: bottom slope from the horizontal
  double bottom_width = 0.0;  // m, sloped: flat part of the bottom, centred
  std::vector<Vec2> points;   // m, polyline: the wall from the top left, down, to the top right
};

// A rectangle of water at rest (a dam-break column, or two levels either side of a screen).
struct FluidBlock {
  Vec2 from, to;  // m, lower-left and upper-right corners, in the coordinates of the section
};

struct FillSpec {
  // m, still-water depth above the lowest point of the bottom. With blocks: the depth their
  // water settles to (given, or computed from the blocks' area by the case reader).
  double depth = 0.0;
  // Empty: the fluid fills the section below `depth`. Otherwise the fluid is the union of the
  // blocks, each hydrostatic below its own top.
  std::vector<FluidBlock> blocks;
  // m, with blocks: the highest block top above the lowest point (set by the case reader).
  double block_head = 0.0;
};

// m, the largest head of water above the lowest point at the start: the depth, or the highest
// block top.
inline double fill_head(const FillSpec& f) { return f.blocks.empty() ? f.depth : f.block_head; }

// m/s, the speed scale of the fill: the shallow-water wave speed sqrt(g depth) for still
// water; the speed sqrt(2 g head) of a particle falling the head for blocks (a collapsing column).
inline double fill_speed_scale(const FillSpec& f, double gravity) {
  return f.blocks.empty() ? std::sqrt(gravity * f.depth) : std::sqrt(2.0 * gravity * f.block_head);
}

enum class KernelType { wendland_c2, cubic_spline };

// The dummy wall layers that fill the kernel of a fluid particle at rest dp/2 from a wall: the
// layers stand (k - 1/2) dp behind the wall surface, k = 1, 2, ..., and layer k is within the
// support 2h of that particle when k dp < 2h, so n = ceil(2 h/dp) - 1 layers are needed
// (2 up to h = 1.5 dp, 3 up to 2 dp, 4 up to 2.5 dp). With fewer, the fluid finds a hole in its
// kernel behind the wall: at h = 1.8 dp with 2 layers it came within dp/4 of the walls and the
// wall-contact step acted every step (docs/validation/notes.md).
inline int wall_layers_needed(double kernel_ratio) {
  return static_cast<int>(std::ceil(2.0 * kernel_ratio - 1e-9)) - 1;
}

struct ParticleSpec {
  double dp = 0.0;             // m, initial particle spacing
  double kernel_ratio = 1.4;   // h / dp
  int wall_layers = 2;         // layers of dummy wall particles (default: wall_layers_needed, at least 2)
  KernelType kernel = KernelType::wendland_c2;
};

// Weakly compressible delta-SPH (Dincer 2019 eqs. 5-13) with the options of Shao et al. 2012.
enum class WallTreatment { adami, repulsive };
enum class Integrator { symplectic, leapfrog };
enum class WcsphTurbulence { none, sps, smagorinsky };

struct WcsphSpec {
  double sound_speed = 0.0;          // m/s; 0: from the Morris et al. estimate (Shao eq. 9, Dincer eq. 13)
  double max_density_variation = 0.01;  // Delta rho / rho0 allowed by that estimate
  double delta = 0.1;                // delta-SPH density diffusion coefficient (Dincer eq. 5)
  double artificial_viscosity = 0.02;  // alpha of the artificial viscosity (Dincer eq. 6); 0: laminar viscosity
  double xsph = 0.0;                 // XSPH epsilon (Dincer eq. 11 uses 0.05)
  bool kernel_gradient_correction = false;  // Shao eqs. 16-17
  int shepard_interval = 0;          // steps between Shepard density re-normalisations (Shao eqs. 10-11); 0: off
  WcsphTurbulence turbulence = WcsphTurbulence::none;  // Shao eqs. 21-24 (Smagorinsky, Cs = 0.12)
  double smagorinsky = 0.12;
  WallTreatment walls = WallTreatment::adami;  // or Shao's coupled dynamic solid boundary (eqs. 25-30)
  Integrator integrator = Integrator::symplectic;
  double cfl = 0.2;                  // dt = cfl * h / (c0 + u_max), with viscous and force bounds
};

enum class PressureSolve { explicit_update, implicit_krylov };

// The preconditioner of the implicit PPE's Krylov solve (schemes/ppe_solver.hpp).
//  multigrid: one aggregation V-cycle (schemes/ppe_multigrid.hpp): iterations nearly flat in N;
//  jacobi:    diag(A): cheaper per iteration, but the iterations grow like sqrt(N)
//             (docs/performance.md: 1,358 a step at 51,518 particles against 9).
enum class Preconditioner { jacobi, multigrid };

// How the free surface enters the pressure Poisson equation.
//  thesis: p = 0 on the particles whose kernel-summed density is below the threshold (eq. 2.20).
//  air:    p = 0 in the air that fills the truncated part of each kernel, so surface particles
//          carry the small pressure of their depth (docs/physics.md, "Free surface").
enum class FreeSurfaceModel { air, thesis };

// Particle shifting: none (the seeds); Fickian shifting after Lind et al. (2012) for ISPH; the
// particle shifting technique of delta-plus-SPH (Sun et al. 2017) for WCSPH.
enum class ShiftingModel { none, lind, delta_plus };

// Where the ISPH step solves the pressure (the intermediate positions r*):
//  euler:    r* = r + dt u* (thesis eq. 2.11), the end of the step predicted by a forward Euler
//            step. The pressure then acts on the velocity as a force evaluated at the step's end,
//            and the trapezoidal position update of eq. 2.15 damps an oscillation of frequency w
//            by about w dt / 4 of critical (docs/physics.md, "The position predictor").
//  midpoint: r* = r + (dt/2) u*, the middle of the step: a second-order, non-damping scheme.
enum class PositionPredictor { euler, midpoint };

struct SchemeSpec {
  std::string type = "isph";
  double alpha = 0.01;                   // PPE blending factor (thesis eq. 2.13)
  // ISPH: > 0 replaces alpha by dt / density_relaxation_time each step, so that the density
  // term relaxes a compression over a time that does not depend on the step (s; 0: alpha).
  double density_relaxation_time = 0.0;
  PositionPredictor predictor = PositionPredictor::euler;  // ISPH: where r* is
  PressureSolve pressure = PressureSolve::implicit_krylov;
  FreeSurfaceModel free_surface = FreeSurfaceModel::air;  // default: air (implicit), thesis (explicit)
  double free_surface_threshold = 0.9;   // rho_n / rho_0 below which a particle is free surface (eq. 2.20)
  bool turbulence = true;                // SPS (thesis eqs. 2.8, 2.9, 2.17)
  bool clip_negative_pressure = true;    // keep p >= 0 after each pressure solve
  double smagorinsky = 0.1;              // Cs
  double ct = 0.08;                      // Ct, for k_t
  double solver_tolerance = 1.0e-6;      // implicit PPE: relative residual
  int solver_max_iterations = 1000;      // implicit PPE
  Preconditioner preconditioner = Preconditioner::multigrid;  // implicit PPE
  double neighbour_skin = 0.2;           // Verlet skin as a fraction of the support radius 2h
  // ISPH: repulsive force of the first wall layer (thesis eq. 3.18, physics/wall_repulsion.hpp).
  bool repulsive_walls = false;
  double repulsive_coefficient = 1.0;    // D = coefficient g H_w
  double repulsive_range = 0.5;          // r0 / h (eq. 3.18: h_k / 2)
  // Particle shifting after each step (physics/shifting.hpp): ISPH "lind", WCSPH "delta_plus".
  ShiftingModel shifting = ShiftingModel::none;
  double shifting_coefficient = 2.0;     // ISPH: A of D = A h |u| dt
  double shifting_max = 0.2;             // the longest shift of a step, a fraction of dp
  // Both schemes: stop fluid particles at the tank walls (physics/wall_contact.hpp).
  bool wall_contact = true;
  // Both schemes: keep two fluid particles from reaching one point (physics/pair_contact.hpp).
  bool pair_contact = true;
  WcsphSpec wcsph;                       // used when type = "wcsph"
};

// A porous element (screen, baffle, perforated floor) or an explicit slat screen (thesis 2.5, 4.2.2).
enum class ScreenModel { ergun, morison, explicit_slats };

// The case key's spelling of a model (`screens.N.model`): "ergun", "morison", "explicit".
inline const char* screen_model_name(ScreenModel m) {
  switch (m) {
    case ScreenModel::ergun: return "ergun";
    case ScreenModel::morison: return "morison";
    case ScreenModel::explicit_slats: return "explicit";
  }
  return "?";
}

struct ScreenSpec {
  std::string name;
  Vec2 from, to;                 // m, the element's centre line
  bool full_height = false;      // given by `x`: a vertical screen from the bottom to the top of the walls
  // 3D, given by `y` (issue 31): a full-height screen in the plane y = plane_y across the whole
  // length of a box (its section element stands at x = length / 2 until the driver lays it out).
  std::optional<double> plane_y;
  // 3D, given by `plan_from` and `plan_to` (issue 31): a full-height screen in the vertical plane
  // through that segment of the plan (x, y), at any angle, in a box or a cylinder (its section
  // element stands at the segment's middle x until the driver lays it out along the segment).
  std::optional<std::pair<Vec2, Vec2>> plan;
  double solidity = 0.0;         // S = 1 - porosity (thesis eq. 2.23)
  double slat_height = 0.0;      // m, explicit slats (and S = h_slat / (h_slat + h_gap) if given)
  double slat_gap = 0.0;         // m
  double thickness = 0.001;      // m, t_sc
  ScreenModel model = ScreenModel::ergun;
  double spacing = 0.0;          // m, screen particle spacing dp_sc (0: dp)
  double interaction_radius = 0.0;  // m, kernel smoothing length h_sc of the screen (0: 2.5 h)
  double loss_coefficient = 0.0;    // Morison: C_l (0: from the solidity, docs/physics.md)
  // The fluid velocity at a screen particle: false, the kernel sum of thesis eq. 2.26 (truncated
  // near walls and the free surface); true, Shepard-normalised (velocity = "shepard").
  bool shepard_velocity = false;
};

// An elastic plate (flap, baffle, gate) in the tank: a geometrically exact beam
// (structure/beam.hpp) coupled two-way with the fluid (run/plate_coupling.hpp, Dincer 2019).
// [[plates]]. The centre line runs from `from` (the first end, usually the clamped one) to `to`.
enum class PlateSupport { free, pinned, clamped };

struct PlateSpec {
  std::string name;
  Vec2 from, to;                   // m, centre line in the tank frame
  double standing_height = 0.0;    // m: given by `x` and `height`, standing on the bottom at from.x
                                   // (from.y and `to` resolved by geometry/build_scene); 0 otherwise
  double thickness = 0.0;          // m, t (in the plane)
  double youngs_modulus = 0.0;     // Pa
  double poisson_ratio = 0.3;      // -, G = E / (2 (1 + nu)) for the shear stiffness
  double density = 0.0;            // kg/m^3
  int elements = 40;               // beam elements along the centre line
  PlateSupport from_support = PlateSupport::clamped;
  PlateSupport to_support = PlateSupport::free;
  double rayleigh_mass = 0.0;      // b0 [1/s] of C = b0 M + b1 K (Dincer eq. 15)
  double rayleigh_stiffness = 0.0; // b1 [s]
  double hht_alpha = -0.3;         // HHT-alpha time integration of the plate, in [-1/3, 0]
};

struct TimeSpec {
  double end = 0.0;          // s
  double dt = 5.0e-4;        // s, fixed step (or the ceiling of an adaptive step)
  bool adaptive = false;     // CFL-adaptive step, thesis 2.6.3.2
  double cfl = 0.1;          // factor of dt <= cfl * min(dp / u_max, dp^2 / nu)
  double dt_min = 0.0;       // s, the adaptive step's floor (0: none); held to the fixed step's bound
  double settle = 0.0;       // s, damped settling at rest before t = 0 (0: none)
};

// Imposed motion of the tank (thesis 2.6.2, 4.4.2; Shao et al. 3.3; Dincer 3).
//  harmonic: X(t) = amplitude sin(omega t + phase), horizontal
//  pitch:    theta(t) = angle sin(omega t + phase) about `pivot`, or theta(t) from a file
//            (two columns: time, angle; a not-a-knot cubic spline, physics/excitation.hpp)
//  record:   a ground-acceleration record (PEER AT2 in g, or CSV time,value)
//  pulse:    one-cycle sine or cosine acceleration pulse (Dincer 2019, 3.1)
//  noise:    band-limited white-noise acceleration (deterministic from its seed)
enum class ExcitationType { none, harmonic, pitch, record, pulse, noise };

// What `beta` is relative to: the first natural frequency from the modal solver (exact linear
// theory for the section) or the thesis's closed forms (eqs. 3.29-3.36, 4.29), to reproduce its set-ups.
enum class BetaReference { modal, thesis };

struct ExcitationSpec {
  ExcitationType type = ExcitationType::none;
  double amplitude = 0.0;            // m (harmonic)
  double angle = 0.0;                // rad (pitch; given in degrees in the case)
  Vec2 pivot;                        // m, tank frame (pitch); in 3D (x, z)
  double pivot_across = 0.0;         // m, 3D: the pivot's y (across the breadth)
  // 3D (issue 31): the rotation's axis, a unit vector in tank axes; the angle is right-handed about
  // it. The default (0, -1, 0) is the 2D pitch's sense: a positive angle raises the wall at x = length.
  Vec3 axis{0.0, -1.0, 0.0};
  std::optional<double> frequency;   // Hz, as given
  std::optional<double> beta;        // ratio to the tank's first linear sloshing frequency
  BetaReference beta_reference = BetaReference::modal;
  double omega = 0.0;                // rad/s, resolved (from frequency, omega or beta)
  double ramp = 0.0;                 // s, smooth ramp-up time
  double phase = 0.0;                // rad
  // 3D: the horizontal unit vector (x, y) along which a translation (harmonic, record, pulse, noise)
  // moves the tank; its signal is the displacement along it. 2D: always (1, 0).
  Vec2 direction{1.0, 0.0};
  double stop = -1.0;                // s, harmonic/pitch motion stops after this time (< 0: never)
  // record (and pitch from a file: file, time_scale, value_unit, start)
  std::string file;                  // resolved path of the record (pitch: empty for the harmonic pitch)
  std::string format;                // "at2" or "csv"
  double scale = 1.0;                // multiplies the record (after unit conversion)
  double time_scale = 1.0;           // CSV: multiplies the time column to give seconds
  double value_unit = 1.0;           // CSV: multiplies the values to give m/s^2 (9.80665 for g);
                                     // pitch file: to give rad (pi/180 for "deg", 1 for "rad")
  bool baseline_correction = true;   // remove the drift velocity so the base ends at rest
  double start = 0.0;                // s, the record or pulse starts at this time (pitch file:
                                     // added to the file's scaled times, may be negative)
  // pulse
  std::string shape = "sine";        // "sine" or "cosine"
  double acceleration = 0.0;         // m/s^2, peak acceleration of a pulse
  double period = 0.0;               // s, pulse period
  // noise
  std::uint64_t seed = 1;
  double band_low = 0.05, band_high = 0.5;  // Hz
  double rms = 0.0;                  // m/s^2, RMS acceleration of the noise
  std::string table = "excitation";  // the case's table, for messages ("excitation.y" for [excitation.y])
};

// A pitch whose angle history comes from a file (not the harmonic pitch).
inline bool is_pitch_record(const ExcitationSpec& e) { return e.type == ExcitationType::pitch && !e.file.empty(); }

struct GaugeSpec {
  std::string name;
  double x = 0.0;       // m from the left wall
  double across = 0.0;  // m, 3D: the breadth coordinate y of the gauge's vertical line
};

struct PressureProbeSpec {
  std::string name;
  Vec2 position;   // m: x from the left wall, and the height above the lowest point of the bottom
                   // (case key y in 2D, z in 3D)
  double across = 0.0;  // m, 3D: the breadth coordinate (case key y)
  std::optional<Vec2> face_end;  // m: with it, the probe is a sensor face from `position` to here
                                 // and reads the mean pressure over it (observe/probes.hpp)
  double size = 0.0;  // m: > 0: a sensor face this long centred on `position`, along the wall nearest
                      // to it (a transducer's diameter; geometry/scene.cpp); 0: a point (or `face_end`)
};

// The leading edge of a surge along the floor (dam-break front): the furthest fluid particle
// in `direction` within `band` above the lowest point, plus dp/2 (the particle's own extent).
struct FrontProbeSpec {
  std::string name;
  double band = 0.0;     // m above the lowest point of the bottom; 0: 2 dp
  bool rightward = true; // direction "right" (largest x) or "left" (smallest x)
};

struct OutputSpec {
  double sample_interval = 0.01;    // s, time series
  double snapshot_interval = 0.5;   // s, VTK particle snapshots (<= 0: none)
  bool snapshot_walls = true;       // include wall particles in snapshots
  int response_cycles = 10;         // steady-state averages over the last N excitation cycles
  double lowpass_hz = 5.0;          // zero-phase low-pass of the response series (0: none)
  // m, the point the moment columns (M_w; 3D M_wx, M_wy, M_wz) are taken about, in the tank frame:
  // 2D (x, y) with z = 0, 3D (x, y, z). None: the centre of the tank's bottom (resolved cases write
  // it only when it was given, so older cases keep their case.toml).
  std::optional<Vec3> moment_point;
};

struct RunSpec {
  double max_leaked_fraction = 0.01;  // of the initial fluid particles, before the run fails
  double max_speed_factor = 20.0;     // fail if any speed exceeds this times sqrt(g * depth)
};

// External force F_e(t) on the structure (thesis eq. 4.20), [structure.load].
//  harmonic: F = r(t) amplitude sin(2 pi frequency t), r the cosine ramp of the excitation
//  noise:    band-limited white noise (signals/white_noise.hpp), scaled to a target mean hourly
//            peak acceleration of the structure without TLD (thesis 4.4.2.1) or to a given RMS
//  record:   a two-column CSV force record (time, N) times `scale`
//  pulse:    one-cycle sine or cosine force pulse of peak `amplitude` (Dincer 2019, 3.1, as a force)
enum class StructureLoadType { none, harmonic, noise, record, pulse };

struct StructureLoadSpec {
  StructureLoadType type = StructureLoadType::none;
  double amplitude = 0.0;  // N: harmonic amplitude, pulse peak
  double frequency = 0.0;  // Hz (harmonic)
  double ramp = 0.0;       // s (harmonic)
  // record
  std::string file;         // resolved path
  double scale = 1.0;       // multiplies the force values
  double time_scale = 1.0;  // multiplies the time column to give seconds
  double start = 0.0;       // s, record or pulse start
  // pulse
  std::string shape = "sine";  // "sine" or "cosine"
  double period = 0.0;         // s
  // noise
  std::uint64_t seed = 1;
  double band_low = 0.05, band_high = 0.5;  // Hz (thesis 4.4.2.1)
  std::optional<double> target_peak_mg;     // milli-g: mean peak acceleration of the bare structure
  std::optional<double> rms;                // N: or the RMS force directly
  double peak_duration = 3600.0;            // s, the observation time of that mean peak (hourly)
};

// A single-degree-of-freedom structure carrying the tank(s) (thesis 4.2.3, eqs. 4.20-4.22),
// [structure]. The 2D fluid force per metre is multiplied by tank_width * tanks.
struct StructureSpec {
  double mass = 0.0;       // M_s, kg
  double damping = 0.0;    // C_s, N s/m
  double stiffness = 0.0;  // K_s, N/m
  double tank_width = 1.0;  // m, out-of-plane width b of one tank
  int tanks = 1;            // identical tanks (0: the fluid rides on the structure without acting back)
  double rigid_mass = 0.0;  // kg per metre of tank width, per tank: liquid or tank mass moving rigidly with it
  bool ground_from_excitation = false;  // [excitation] is the ground acceleration of the structure
  double initial_displacement = 0.0;    // m, relative to the ground
  double initial_velocity = 0.0;        // m/s
  StructureLoadSpec load;
};

struct CaseSpec {
  std::string source;  // file the case came from ("<built-in>" for the default case)
  std::string name;    // stem of the file, names the default output directory
  std::string title;   // free text
  FluidSpec fluid;
  TankSpec tank;
  FillSpec fill;
  ParticleSpec particles;
  SchemeSpec scheme;
  TimeSpec time;
  ExcitationSpec excitation;
  // [excitation.y] (3D only): a second, independent translation of the base along y (issue 31);
  // [excitation] is then the motion along x. Its direction is (0, 1).
  std::optional<ExcitationSpec> excitation_y;
  std::vector<GaugeSpec> gauges;
  std::vector<PressureProbeSpec> pressure_probes;
  std::vector<FrontProbeSpec> fronts;
  std::vector<ScreenSpec> screens;
  std::vector<PlateSpec> plates;
  std::optional<StructureSpec> structure;  // [structure]: the tank moves with an SDOF structure
  // [structure.y] (3D only): the structure's second sway mode, along y; tank_width, tanks,
  // rigid_mass and ground are copied from [structure].
  std::optional<StructureSpec> structure_y;
  OutputSpec output;
  RunSpec run;

  // Where each key was given: dotted key -> "file:line" or "--set key".
  std::map<std::string, std::string> locations;
  // Location of `key` for messages about it, or the case file when it was not given.
  std::string where(const std::string& key) const {
    auto it = locations.find(key);
    return it != locations.end() ? it->second : source;
  }
};

}  // namespace sloshsph
