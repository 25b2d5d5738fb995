#include "sloshsph/run/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <sstream>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/linear/closed_form.hpp"
#include "sloshsph/linear/modal.hpp"
#include "sloshsph/linear/rectangular.hpp"
#include "sloshsph/geometry/prism_tank.hpp"
#include "sloshsph/observe/particle_spacing.hpp"
#include "sloshsph/observe/probes.hpp"
#include "sloshsph/physics/wall_contact.hpp"
#include "sloshsph/run/run_case.hpp"
#include "sloshsph/sph/kernel.hpp"

namespace sloshsph {

namespace {

// A pressure probe's reading: a point, or the mean over its face sampled every dp/4 (2D).
template <class K, int D>
double read_pressure_probe(const K& k, const BasicParticles<D>& p, const BasicCellGrid<D>& grid,
                           const BasicPressureSensor<D>& sensor, double dp) {
  if constexpr (D == 2)
    if (sensor.face) return pressure_on_face(k, p, grid, sensor.from, sensor.to, 0.25 * dp);
  (void)dp;
  return pressure_at(k, p, grid, sensor.from);
}

// A point for messages: "(x, y)" or "(x, y, z)".
template <int D>
std::string format_point(Vec<D> p) {
  std::ostringstream m;
  m << "(" << p.x << ", " << p.y;
  if constexpr (D == 3) m << ", " << p.z;
  m << ")";
  return m.str();
}

}  // namespace

// In 3D, too, the first mode of the section (along x): the (1, 0) mode of a box; for an upright
// cylinder its first mode (k = 1.8412 / R).
double first_sloshing_omega(const CaseSpec& spec) {
  if (spec.tank.shape == "cylinder")
    return cylinder_first_sloshing_omega(spec.tank.radius, spec.fill.depth, spec.fluid.gravity);
  if (spec.tank.shape == "rectangle")
    return rectangular_sloshing_omega(spec.tank.length, spec.fill.depth, spec.fluid.gravity);  // exact
  const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
  return first_sloshing_omega(tank, spec.fill.depth, spec.fluid.gravity);
}

double reference_omega(const CaseSpec& spec) {
  if (spec.excitation.beta_reference == BetaReference::thesis)
    return thesis_closed_form_omega(spec.tank, spec.fill.depth, spec.fluid.gravity);
  return first_sloshing_omega(spec);
}

// [excitation.y]'s `beta` refers to the first mode across the breadth: the (0, 1) mode of a box, the
// first mode of a cylinder. A prism's section varies along x, so its modes along y have no closed
// form here: it takes `frequency`.
double first_sloshing_omega_across(const CaseSpec& spec) {
  if (spec.tank.shape == "cylinder") return first_sloshing_omega(spec);
  if (spec.tank.shape == "rectangle")
    return rectangular_sloshing_omega(spec.tank.breadth, spec.fill.depth, spec.fluid.gravity);
  throw InputError(spec.where("excitation.y.beta"), "excitation.y.beta",
                   "refers to the first mode across the breadth, known here for a box or a cylinder only; give "
                   "'frequency' for a \"" + spec.tank.shape + "\" tank");
}

CaseSpec resolve_case(CaseSpec spec) {
  ExcitationSpec& e = spec.excitation;
  if (e.type == ExcitationType::harmonic || (e.type == ExcitationType::pitch && !is_pitch_record(e))) {
    if (e.frequency) e.omega = 2.0 * std::numbers::pi * *e.frequency;
    else e.omega = *e.beta * reference_omega(spec);
    if (!(e.omega > 0.0) || !std::isfinite(e.omega))
      throw InputError(spec.where("excitation.beta"), "excitation.beta", "gives no positive excitation frequency");
  }
  if (spec.excitation_y && spec.excitation_y->type == ExcitationType::harmonic) {
    ExcitationSpec& y = *spec.excitation_y;
    if (y.beta && y.beta_reference == BetaReference::thesis)
      throw InputError(spec.where("excitation.y.beta_reference"), "excitation.y.beta_reference",
                       "\"thesis\" is the closed form of a 2D section; across the breadth beta refers to the box's or "
                       "cylinder's first mode (\"modal\")");
    y.omega = y.frequency ? 2.0 * std::numbers::pi * *y.frequency : *y.beta * first_sloshing_omega_across(spec);
    if (!(y.omega > 0.0) || !std::isfinite(y.omega))
      throw InputError(spec.where("excitation.y.beta"), "excitation.y.beta", "gives no positive excitation frequency");
  }
  return spec;
}

// A function-try-block: the checks made while the scene and the excitation are built (fill
// depth, screen geometry, noise band, ...) name their key; here they get the case file and line.
// output.moment_point, or the centre of the tank's bottom: the middle of its length at its lowest
// point, and in 3D the middle of the breadth (a cylinder's axis at the bottom).
template <int D>
Vec<D> moment_point_of(const CaseSpec& spec, const TankGeometry& section) {
  const double x = 0.5 * (section.x_min + section.x_max);
  if constexpr (D == 2) {
    if (const std::optional<Vec3>& m = spec.output.moment_point) return {m->x, m->y};
    return {x, section.y_bottom};
  } else {
    if (const std::optional<Vec3>& m = spec.output.moment_point) return *m;
    return {x, 0.5 * spec.tank.breadth, section.y_bottom};
  }
}

template <int D>
BasicSimulation<D>::BasicSimulation(const CaseSpec& spec, SimulationStart start) try
    : spec_(spec),
      scene_(build_scene_in<D>(spec)),
      container_(*scene_.tank, container_grid(), (spec.particles.wall_layers + 2) * spec.particles.dp),
      base_(spec.excitation, spec.time.end),
      base_y_(spec.excitation_y ? BaseMotionSource(*spec.excitation_y, spec.time.end) : BaseMotionSource()),
      scheme_(spec, scene_.h),
      screens_(make_screen_particles_in<D>(scene_.screens, spec.particles.dp, scene_.h, *scene_.tank, scene_.breadth,
                                           spec.source, spec.tank.shape == "cylinder" ? spec.tank.radius : 0.0)),
      pair_contact_(spec.particles.dp) {
  acc_screen_force_.assign(screens_.elements.size(), Vec<D>{});
  moment_point_ = moment_point_of<D>(spec_, *scene_.tank);
  screen_loads_.assign(screens_.elements.size(), BasicScreenElementLoad<D>{});
  linear_omega_ = first_sloshing_omega(spec_);  // may throw InputError: before any output exists
  speed_limit_ = spec_.run.max_speed_factor * fill_speed_scale(spec_.fill, spec_.fluid.gravity);
  c_full_ = scheme_.reference_density() / spec_.fluid.density;
  start_plates();
  scheme_.initialise(scene_.particles, frame_of(ground_motion(0.0)));
  if (start == SimulationStart::settled) settle();
  for (std::size_t k = 0; k < spec_.gauges.size(); ++k) gauge_datum_.push_back(surface_height(k));
  if (spec_.structure) {
    // The structure is released at t = 0 with the settled fluid at rest in the tank.
    structure_.emplace(*spec_.structure, spec_.time.end);
    structure_->set_fluid_mass(fluid_mass());
    structure_->start(ground_motion(0.0).acceleration.x);
  }
  if (spec_.structure_y) {  // 3D: the sway along y, released alike
    structure_y_.emplace(*spec_.structure_y, spec_.time.end);
    structure_y_->set_fluid_mass(fluid_mass());
    structure_y_->start(ground_motion(0.0).acceleration_y);
  }
  build_columns();
} catch (const InputError& e) {
  throw e.located(spec.where(e.key()), spec.source);
}

// The plates' wall particles become moving walls. They settle with the fluid (time.settle): a
// plate under a standing load starts at t = 0 deflected, at rest.
template <int D>
void BasicSimulation<D>::start_plates() {
  if (scene_.plates.empty()) return;
  BasicParticles<D>& p = scene_.particles;
  p.wall_motion_velocity.assign(p.n_wall(), Vec<D>{});
  p.wall_motion_acceleration.assign(p.n_wall(), Vec<D>{});
  for (std::size_t k = 0; k < scene_.plates.size(); ++k) {
    plates_.emplace_back(scene_.plates[k], scene_.plate_first[k] - p.n_fluid, scene_.plate_planes, scene_.dp);
    plates_.back().place(p);
  }
  acc_plate_force_.assign(plates_.size(), Vec2{});
}

// After each fluid step (staggered, run/plate_coupling.hpp): the fluid's face pressures load the
// plates, which move to t + dt and carry their wall particles with them.
template <int D>
void BasicSimulation<D>::advance_plates(double dt, const BasicFrameForce<D>& frame) {
  BasicParticles<D>& p = scene_.particles;
  const BasicFrameForce<D> before = frame_of(tank_motion());
  for (std::size_t k = 0; k < plates_.size(); ++k) {
    acc_plate_force_[k] += dt * plates_[k].fluid_force(p, before, spec_.fluid.density);
    plates_[k].advance(p, dt, frame);
    plates_[k].keep_fluid_out(p, scheme_.neighbours(), spec_.particles.dp, dt, time_ + dt);
  }
}

template <int D>
BaseMotion BasicSimulation<D>::ground_motion(double t) const {
  if constexpr (D == 2) {
    return base_.at(t);
  } else {
    BaseMotion m = in_tank_axes(base_.at(t), spec_.excitation.direction);
    if (spec_.excitation_y) {  // [excitation.y]: the independent motion along y
      const BaseMotion y = base_y_.at(t);
      m.displacement_y += y.displacement.x;
      m.velocity_y += y.velocity.x;
      m.acceleration_y += y.acceleration.x;
    }
    return m;
  }
}

template <int D>
BaseMotion BasicSimulation<D>::tank_motion() const {
  BaseMotion m = ground_motion(time_);
  // The tank is fixed to the structure: ground motion plus the structure's relative motion.
  if (structure_) {
    m.displacement.x += structure_->displacement();
    m.velocity.x += structure_->velocity();
    m.acceleration.x = structure_->absolute_acceleration();
  }
  if (structure_y_) {
    m.displacement_y += structure_y_->displacement();
    m.velocity_y += structure_y_->velocity();
    m.acceleration_y = structure_y_->absolute_acceleration();
  }
  return m;
}

template <int D>
void BasicSimulation<D>::add_column(std::string name, std::string unit,
                                    std::function<double(const BasicSimulation&, const SampleBasis&)> value) {
  columns_.push_back({std::move(name), std::move(unit), std::move(value)});
}

// The columns of timeseries.csv, each with its value (docs/case-format.md, "Output"). Forces are
// means over the interval since the last sample; W_base is the base's work on the fluid since t = 0.
template <int D>
void BasicSimulation<D>::build_columns() {
  using S = const BasicSimulation&;
  using B = const SampleBasis&;
  // 2D: per metre of breadth; 3D: the whole tank.
  const std::string energy_unit = D == 2 ? "J/m" : "J";
  columns_.clear();
  add_column("time", "s", [](S s, B) { return s.time_; });
  if constexpr (D == 2) {
    add_column("x_base", "m", [](S, B b) { return b.motion.displacement.x; });
    add_column("v_base", "m/s", [](S, B b) { return b.motion.velocity.x; });
    add_column("a_base", "m/s^2", [](S, B b) { return b.motion.acceleration.x; });
  } else {
    add_column("x_base", "m", [](S, B b) { return b.motion.displacement.x; });
    add_column("y_base", "m", [](S, B b) { return b.motion.displacement_y; });
    add_column("v_base", "m/s", [](S, B b) { return b.motion.velocity.x; });
    add_column("v_base_y", "m/s", [](S, B b) { return b.motion.velocity_y; });
    add_column("a_base", "m/s^2", [](S, B b) { return b.motion.acceleration.x; });
    add_column("a_base_y", "m/s^2", [](S, B b) { return b.motion.acceleration_y; });
  }
  for (std::size_t k = 0; k < spec_.gauges.size(); ++k)
    add_column("eta:" + spec_.gauges[k].name, "m", [k](S s, B) { return s.surface_height(k) - s.gauge_datum_[k]; });
  for (std::size_t k = 0; k < spec_.pressure_probes.size(); ++k)
    add_column("p:" + spec_.pressure_probes[k].name, "Pa", [k](S, B b) { return b.probe_pressure[k]; });
  for (std::size_t k = 0; k < spec_.fronts.size(); ++k)
    add_column("front:" + spec_.fronts[k].name, "m", [k](S s, B) {
      const FrontProbeSpec& f = s.spec_.fronts[k];
      const double dp = s.spec_.particles.dp;
      return front_position<D>(s.scene_.particles, s.scene_.tank->y_bottom, f.band > 0.0 ? f.band : 2.0 * dp,
                               f.rightward, dp);
    });
  for (std::size_t e = 0; e < screens_.elements.size(); ++e) {
    if (screens_.elements[e].count == 0) continue;  // explicit slats are walls: their force is in F_w
    auto mean_force = [e](S s) { return s.acc_dt_ > 0.0 ? s.acc_screen_force_[e] / s.acc_dt_ : Vec<D>{}; };
    const std::string force_unit = D == 2 ? "N/m" : "N";
    add_column("F_screen:" + screens_.elements[e].name, force_unit, [mean_force](S s, B) { return mean_force(s).x; });
    add_column("F_screen_y:" + screens_.elements[e].name, force_unit, [mean_force](S s, B) { return mean_force(s).y; });
    if constexpr (D == 3)  // as F_w, F_wy, F_wz: y across the breadth, z up
      add_column("F_screen_z:" + screens_.elements[e].name, force_unit, [mean_force](S s, B) { return mean_force(s).z; });
  }
  // F_sw: the sloshing part, the wall force less the fluid's mass times the base acceleration.
  if constexpr (D == 2) {
    add_column("F_w", "N/m", [](S, B b) { return b.wall_force.x; });
    add_column("F_sw", "N/m", [](S, B b) { return b.wall_force.x - b.fluid_mass * b.base_acceleration; });
    add_column("F_wy", "N/m", [](S, B b) { return b.wall_force.y; });
  } else {
    add_column("F_w", "N", [](S, B b) { return b.wall_force.x; });
    add_column("F_sw", "N", [](S, B b) { return b.wall_force.x - b.fluid_mass * b.base_acceleration; });
    add_column("F_wy", "N", [](S, B b) { return b.wall_force.y; });
    add_column("F_sw_y", "N", [](S, B b) { return b.wall_force.y - b.fluid_mass * b.base_acceleration_y; });
    add_column("F_wz", "N", [](S, B b) { return b.wall_force.z; });
  }
  // The moment of that force about output.moment_point (the walls' and screens' on the fluid, as
  // F_w; the fluid's on the tank is its negative): M_P = M_0 - P x F.
  auto moment = [](S s, B b) { return b.wall_moment - cross(s.moment_point_, b.wall_force); };
  if constexpr (D == 2) {
    add_column("M_w", "N m/m", [moment](S s, B b) { return moment(s, b); });
  } else {
    add_column("M_wx", "N m", [moment](S s, B b) { return moment(s, b).x; });
    add_column("M_wy", "N m", [moment](S s, B b) { return moment(s, b).y; });
    add_column("M_wz", "N m", [moment](S s, B b) { return moment(s, b).z; });
  }
  add_column("W_base", energy_unit, [](S s, B) { return s.work_on_fluid_; });
  add_column("fluid_mass", D == 2 ? "kg/m" : "kg", [](S, B b) { return b.fluid_mass; });
  add_column("E_kin", energy_unit, [](S, B b) { return b.kinetic_energy; });
  add_column("E_pot", energy_unit, [](S, B b) { return b.potential_energy; });
  add_column("leaked", "1", [](S s, B) { return static_cast<double>(s.leaks_.size()); });
  add_column("max_speed", "m/s", [](S s, B) { return s.max_speed_; });
  add_column("dt", "s", [](S s, B) { return s.last_dt_; });
  add_column("ppe_iterations", "1", [](S s, B) { return static_cast<double>(s.scheme_.diagnostics().solver_iterations); });
  add_column("wall_contacts", "1", [](S s, B) { return static_cast<double>(s.wall_contacts_); });
  add_column("pair_contacts", "1", [](S s, B) { return static_cast<double>(s.pair_contacts_); });
  add_column("closest_pair", "dp", [](S s, B) {
    const double dp = s.spec_.particles.dp;
    return closest_fluid_pair(s.scene_.particles, dp) / dp;
  });
  if (spec_.scheme.shifting != ShiftingModel::none)
    add_column("shifts_limited", "1", [](S s, B) { return static_cast<double>(s.shifts_limited_); });
  // The plates: in 2D per metre (N/m, J/m) in the section (x, y); in 3D whole (the per-metre beam
  // times the plate's width) in (x, z), the section's height named z.
  const std::string up = D == 2 ? "y" : "z";
  for (std::size_t k = 0; k < plates_.size(); ++k) {
    const std::string& n = plates_[k].spec().name;
    const double width = plates_[k].width();  // 1 m in 2D (x 1 is exact: the same bits)
    auto force = [k, width](S s) {
      return width * (s.acc_dt_ > 0.0 ? s.acc_plate_force_[k] / s.acc_dt_ : s.plates_[k].last_force());
    };
    add_column("plate_dx:" + n, "m", [k](S s, B) { return s.plates_[k].tip_displacement().x; });
    add_column("plate_d" + up + ":" + n, "m", [k](S s, B) { return s.plates_[k].tip_displacement().y; });
    add_column("plate_mid_dx:" + n, "m", [k](S s, B) { return s.plates_[k].displacement_at(0.5).x; });
    add_column("plate_mid_d" + up + ":" + n, "m", [k](S s, B) { return s.plates_[k].displacement_at(0.5).y; });
    add_column("F_plate_x:" + n, D == 2 ? "N/m" : "N", [force](S s, B) { return force(s).x; });
    add_column("F_plate_" + up + ":" + n, D == 2 ? "N/m" : "N", [force](S s, B) { return force(s).y; });
    add_column("E_plate:" + n, energy_unit,
               [k, width](S s, B) { return width * (s.plates_[k].strain_energy() + s.plates_[k].kinetic_energy()); });
    add_column("plate_inside:" + n, "1", [k](S, B b) { return b.plate_inside[k]; });
    add_column("plate_contacts:" + n, "1", [k](S s, B) { return static_cast<double>(s.plates_[k].contacts()); });
    add_column("plate_crossings:" + n, "1", [k](S s, B) { return static_cast<double>(s.plates_[k].crossings()); });
  }
  if (!structure_) return;
  // [structure] (docs/case-format.md). The energies are relative to the ground (absolute without
  // ground motion): E_s = (M v^2 + K x^2)/2 of the structure alone; E_TLD = n b [sum m (u + v_s)^2 / 2
  // + m g y] + n b m_r v_s^2 / 2, the liquid of all tanks with the tank frame's velocity u turned
  // into the ground frame (in 3D v_s = (v_s, v_s_y, 0) and b = 1). With no damping, no load and no
  // ground motion E_s (+ E_s_y) + E_TLD is conserved but for the fluid's own dissipation.
  add_column("x_s", "m", [](S s, B) { return s.structure_->displacement(); });
  add_column("v_s", "m/s", [](S s, B) { return s.structure_->velocity(); });
  add_column("a_s", "m/s^2", [](S s, B) { return s.structure_->absolute_acceleration(); });
  add_column("F_TLD", "N", [](S s, B) { return s.acc_dt_ > 0.0 ? s.acc_tld_force_ / s.acc_dt_ : 0.0; });
  add_column("F_e", "N", [](S s, B) { return s.structure_->external_force(); });
  add_column("E_s", "J", [](S s, B) { return s.structure_->structure_energy(); });
  if (structure_y_) {
    add_column("x_s_y", "m", [](S s, B) { return s.structure_y_->displacement(); });
    add_column("v_s_y", "m/s", [](S s, B) { return s.structure_y_->velocity(); });
    add_column("a_s_y", "m/s^2", [](S s, B) { return s.structure_y_->absolute_acceleration(); });
    add_column("F_TLD_y", "N", [](S s, B) { return s.acc_dt_ > 0.0 ? s.acc_tld_force_y_ / s.acc_dt_ : 0.0; });
    add_column("F_e_y", "N", [](S s, B) { return s.structure_y_->external_force(); });
    add_column("E_s_y", "J", [](S s, B) { return s.structure_y_->structure_energy(); });
  }
  add_column("E_TLD", "J", [](S s, B b) {
    const StructureCoupling& st = *s.structure_;
    const double vs = st.velocity(), nb = st.tank_factor();
    const double vy = s.structure_y_ ? s.structure_y_->velocity() : 0.0;
    const double v2 = vs * vs + vy * vy;
    const double liquid = b.kinetic_energy + vs * b.momentum_x + vy * b.momentum_y + 0.5 * s.fluid_mass() * v2 +
                          b.potential_energy;
    return nb * (liquid + 0.5 * st.spec().rigid_mass * v2);
  });
}

// time.settle: before t = 0 the fluid settles under gravity alone (no excitation) while its
// kinetic energy is taken out: each step the velocities are scaled by exp(-dt / tau),
// tau = settle / 10. The lattice the fluid starts on is not the discrete equilibrium of the
// scheme (the free-surface rows carry p = 0 half a spacing below the surface they stand
// for); settling removes the start-up ripple that would otherwise sit on top of small
// sloshing amplitudes. Time, outputs and leak counts start after it.
template <int D>
void BasicSimulation<D>::settle() {
  const double duration = spec_.time.settle;
  if (duration <= 0.0) return;
  const double tau = 0.1 * duration;
  BasicStepInput<D> in;
  in.frame = frame_of(ground_motion(0.0));
  BasicParticles<D>& p = scene_.particles;
  for (double t = 0.0; t < duration - 1e-12;) {
    in.dt = std::min(spec_.time.dt, duration - t);
    if (const auto stable = scheme_.stable_dt(p, in.frame)) in.dt = std::min(in.dt, *stable);
    scheme_.step(p, in);
    const double factor = std::exp(-in.dt / tau);
    for (std::size_t i = 0; i < p.n_fluid; ++i) p.velocity[i] = factor * p.velocity[i];
    for (BasicPlateCoupling<D>& plate : plates_) {  // the plates settle with the fluid, damped alike
      plate.fluid_force(p, in.frame, spec_.fluid.density);
      plate.advance(p, in.dt, in.frame);
      plate.keep_fluid_out(p, scheme_.neighbours(), spec_.particles.dp, in.dt, -1.0);
      plate.damp(p, factor);
    }
    t += in.dt;
    // A settle that blows up fails the run here, with what and where, before a runaway
    // particle reaches the neighbour search (found: the thesis free surface at dp = 0.1 m).
    max_speed_ = scheme_.diagnostics().max_speed;
    char when[96];
    std::snprintf(when, sizeof when, "while the fluid settled (%.4g of %.4g s)", t, duration);
    try {
      check_state(when);
    } catch (const RunFailure& e) {
      std::string what = e.what();
      for (const std::string& w : scene_.warnings) what += "; warning given for this case: " + w;
      throw RunFailure(what);
    }
    // A long settle (fine dp, seconds of settling) must not hold up SIGINT/SIGTERM: there is
    // nothing to keep yet, so the command stops at once with exit code 4 (run_case.cpp).
    if (stop_requested() && t < duration - 1e-12) {
      char what[120];
      std::snprintf(what, sizeof what, "interrupted while the fluid settled (%.3g of %.3g s); nothing was written", t,
                    duration);
      throw Interrupted(what);
    }
  }
  for (BasicPlateCoupling<D>& plate : plates_) plate.restart();
  max_speed_ = 0.0;
  for (std::size_t i = 0; i < p.n_fluid; ++i) max_speed_ = std::max(max_speed_, norm(p.velocity[i]));
}

// The bound of the adaptive step, thesis 2.6.3.2: dt <= min(0.1 dp / u_max, 0.1 dp^2 / nu) with the
// factor time.cfl; plus the body-force bound 0.25 sqrt(h / |g - a|).
template <int D>
double BasicSimulation<D>::adaptive_bound() const {
  double dt = HUGE_VAL;
  const double dp = spec_.particles.dp;
  const double cfl = spec_.time.cfl;
  if (max_speed_ > 0.0) dt = std::min(dt, cfl * dp / max_speed_);
  if (spec_.fluid.viscosity > 0.0) dt = std::min(dt, cfl * dp * dp / spec_.fluid.viscosity);
  const Vec<D> body = frame_of(tank_motion()).uniform;
  if (norm(body) > 0.0) dt = std::min(dt, 0.25 * std::sqrt(scene_.h / norm(body)));
  return dt;
}

template <int D>
double BasicSimulation<D>::next_dt(bool* floored) const {
  double dt = spec_.time.dt;
  if (floored) *floored = false;
  if (spec_.time.adaptive) {
    // Between the floor time.dt_min (0: none; a spray droplet's speed would otherwise set the step
    // of the whole tank) and the ceiling time.dt.
    const double bound = adaptive_bound();
    dt = std::min(dt, std::max(bound, spec_.time.dt_min));
    if (floored) *floored = bound < spec_.time.dt_min && spec_.time.dt_min < spec_.time.end - time_;
  }
  // An explicit (weakly compressible) scheme takes its own CFL step; time.dt caps it.
  if (const auto stable = scheme_.stable_dt(scene_.particles, frame_of(tank_motion())))
    dt = std::min(dt, *stable);
  return std::min(dt, spec_.time.end - time_);
}

template <int D>
void BasicSimulation<D>::step() {
  bool at_floor = false;  // the step is time.dt_min because the adaptive bound fell below it
  const double dt = next_dt(&at_floor);
  if (!(dt > 0.0)) return;
  const BaseMotion before = tank_motion();
  // Body force at the middle of the step: second-order in time for the imposed motion.
  BaseMotion mid = ground_motion(time_ + 0.5 * dt);
  BaseMotion after = ground_motion(time_ + dt);  // the ground at the end; the tank's is added below
  // Restored if the fluid step fails.
  std::optional<StructureCoupling> structure_before = structure_, structure_y_before = structure_y_;
  if (structure_) {
    // Thesis 4.2.3: the structure moves first (with the sloshing force of the last step), the
    // fluid then feels the structure's mean absolute acceleration over the step (a_n + a_n+1)/2,
    // which is exactly Newmark's velocity change / dt (run/structure_coupling.hpp).
    structure_->advance(dt, sloshing_force_, after.acceleration.x);
    mid.acceleration.x = 0.5 * (before.acceleration.x + structure_->absolute_acceleration());
  }
  if (structure_y_) {  // 3D: the sway along y, the same way
    structure_y_->advance(dt, sloshing_force_y_, after.acceleration_y);
    mid.acceleration_y = 0.5 * (before.acceleration_y + structure_y_->absolute_acceleration());
  }
  BasicStepInput<D> in;
  in.dt = dt;
  in.frame = frame_of(mid);
  if (!screens_.position.empty()) {
    // Thesis eqs. 2.25-2.28 with the fluid state at the start of the step.
    in.extra = [this](const BasicParticles<D>& p, std::vector<Vec<D>>& a) {
      screen_drag(screens_, p, p.velocity, spec_.fluid.density, spec_.fluid.density * spec_.fluid.viscosity,
                  screen_work_, a, screen_loads_);
    };
  }
  try {
    scheme_.step(scene_.particles, in);
  } catch (...) {
    structure_ = std::move(structure_before);
    structure_y_ = std::move(structure_y_before);
    throw;
  }

  if (!plates_.empty()) advance_plates(dt, frame_of(after));
  if (structure_) after.displacement.x += structure_->displacement();
  if (structure_y_) after.displacement_y += structure_y_->displacement();
  // Base shear: the walls and the screens (fixed to the tank) act on the fluid.
  Vec<D> wall_force = scheme_.diagnostics().wall_force;
  Moment<D> wall_moment = scheme_.diagnostics().wall_moment;
  if (spec_.scheme.pair_contact)  // before the wall contact, which then has the last word at the walls
    pair_contacts_ += pair_contact_.apply(scene_.particles, scheme_.neighbours());
  if (spec_.scheme.wall_contact) {
    const BasicWallContact<D> contact = wall_contact(dt);
    wall_contacts_ += contact.corrected;
    wall_force += contact.force_on_fluid;
    wall_moment += contact.moment_on_fluid;
  }
  if (!screens_.position.empty()) wall_moment += screen_moment_on_fluid(screens_, screen_work_);
  for (std::size_t e = 0; e < screen_loads_.size(); ++e) {
    wall_force += screen_loads_[e].force_on_fluid;
    acc_screen_force_[e] += dt * screen_loads_[e].force_on_fluid;
  }
  if (structure_) {
    // F_w is the force of the walls ON the fluid (F_wy > 0 carries the weight): the fluid
    // pushes the tank with -F_w. Sloshing part for the next structure step (thesis 2.6.3.1).
    sloshing_force_ = wall_force.x - fluid_mass() * mid.acceleration.x;
    acc_tld_force_ += dt * structure_->tld_force(wall_force.x, mid.acceleration.x);
  }
  if constexpr (D == 3)
    if (structure_y_) {
      sloshing_force_y_ = wall_force.y - fluid_mass() * mid.acceleration_y;
      acc_tld_force_y_ += dt * structure_y_->tld_force(wall_force.y, mid.acceleration_y);
    }
  shifts_limited_ += scheme_.diagnostics().shifts_limited;
  acc_dt_ += dt;
  acc_wall_force_ += dt * wall_force;
  acc_wall_moment_ += dt * wall_moment;
  acc_base_acceleration_ += dt * mid.acceleration.x;
  if constexpr (D == 2) {
    work_on_fluid_ += wall_force.x * (after.displacement.x - before.displacement.x);
  } else {
    acc_base_acceleration_y_ += dt * mid.acceleration_y;
    work_on_fluid_ += dot(wall_force, displacement3(after) - displacement3(before));
  }

  ++steps_;
  const bool fixed = !spec_.time.adaptive && spec_.scheme.type == "isph";
  time_ = fixed ? std::min(steps_ * spec_.time.dt, spec_.time.end) : time_ + dt;
  last_dt_ = dt;
  if (at_floor) {  // max_speed_ is still the speed the step was chosen from
    ++floor_steps_;
    largest_floor_cfl_ = std::max(largest_floor_cfl_, max_speed_ * dt / spec_.particles.dp);
  }
  max_speed_ = scheme_.diagnostics().max_speed;
  if (const std::size_t pinned = scheme_.diagnostics().pinned_particles; pinned > 0) {
    ++pinned_steps_;
    pinned_particles_ += pinned;
  }
  check_state();
  remove_leaked();
}

template <int D>
void BasicSimulation<D>::remove_leaked() {
  BasicParticles<D>& p = scene_.particles;
  const double limit = -0.5 * spec_.particles.dp;
  std::vector<std::uint8_t> out(p.n_fluid, 0);
  bool any = false;
#pragma omp parallel for reduction(|| : any) schedule(static)
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    if (container_distance(p.position[i]) < limit) {
      out[i] = 1;
      any = true;
    }
  }
  if (!any) return;
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    if (out[i]) leaks_.push_back({time_, p.id[i], p.position[i]});
  p.remove_fluid(out);
  for (std::optional<StructureCoupling>* st : {&structure_, &structure_y_})  // the added mass follows the fluid
    if (*st) (*st)->set_fluid_mass(fluid_mass());
  const double fraction = static_cast<double>(leaks_.size()) / static_cast<double>(scene_.initial_fluid_count);
  if (fraction > spec_.run.max_leaked_fraction) {
    const LeakRecord& first = leaks_.front();
    std::ostringstream m;
    m << leaks_.size() << " fluid particles (" << 100.0 * fraction << "% of " << scene_.initial_fluid_count
      << ") have left the tank by t = " << time_ << " s, more than run.max_leaked_fraction = "
      << spec_.run.max_leaked_fraction << "; the first (id " << first.id << ") at t = " << first.time << " s near "
      << format_point<D>(first.position) << " m";
    throw RunFailure(m.str());
  }
}

template <int D>
void BasicSimulation<D>::check_state() const {
  std::ostringstream when;
  when << "at t = " << time_ << " s (step " << steps_ << ")";
  check_state(when.str());
}

template <int D>
void BasicSimulation<D>::check_state(const std::string& when) const {
  const BasicParticles<D>& p = scene_.particles;
  std::size_t bad = p.size();
#pragma omp parallel for reduction(min : bad) schedule(static)
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool ok = is_finite(p.position[i]) && is_finite(p.velocity[i]) && std::isfinite(p.pressure[i]);
    if (!ok) bad = std::min(bad, i);
  }
  if (bad < p.size()) {
    std::ostringstream m;
    m << "non-finite value " << when << " in "
      << (p.is_fluid(bad) ? "fluid" : "wall") << " particle id " << p.id[bad] << " at " << format_point<D>(p.position[bad])
      << " m: velocity " << format_point<D>(p.velocity[bad]) << ", pressure " << p.pressure[bad] << " Pa";
    throw RunFailure(m.str());
  }
  if (max_speed_ > speed_limit_) {
    std::size_t fast = 0;
    for (std::size_t i = 0; i < p.n_fluid; ++i)
      if (norm(p.velocity[i]) > norm(p.velocity[fast])) fast = i;
    std::ostringstream m;
    m << "speed " << max_speed_ << " m/s " << when << " exceeds the bound "
      << speed_limit_ << " m/s (run.max_speed_factor x the fill speed scale), fluid particle id " << p.id[fast] << " at "
      << format_point<D>(p.position[fast]) << " m";
    throw RunFailure(m.str());
  }
}

template <int D>
double BasicSimulation<D>::surface_height(std::size_t gauge) const {
  const GaugeSpec& g = spec_.gauges[gauge];
  const double floor = scene_.tank->bottom_at(g.x);
  if constexpr (D == 2) {
    return with_kernel(spec_.particles.kernel, scene_.h,
                       [&](const auto& k) { return free_surface_height(k, scene_.particles, g.x, floor, c_full_); });
  } else {
    return with_kernel(
        spec_.particles.kernel, scene_.h,
        [&](const auto& k) { return free_surface_height(k, scene_.particles, Vec3{g.x, g.across, 0.0}, floor, c_full_); },
        3);
  }
}

template <int D>
double BasicSimulation<D>::probe_pressure(std::size_t probe) const {
  BasicCellGrid<D> grid;
  grid.build(scene_.particles.position, 0, scene_.particles.size(), 2.0 * scene_.h);
  const BasicPressureSensor<D>& sensor = scene_.pressure_sensors[probe];
  return with_kernel(
      spec_.particles.kernel, scene_.h,
      [&](const auto& k) { return read_pressure_probe(k, scene_.particles, grid, sensor, spec_.particles.dp); }, D);
}

// Not const: PlateCoupling::fluid_inside keeps scratch.
template <int D>
typename BasicSimulation<D>::SampleBasis BasicSimulation<D>::sample_basis() {
  const BasicParticles<D>& p = scene_.particles;
  SampleBasis b;
  if (!spec_.pressure_probes.empty()) {
    BasicCellGrid<D> grid;
    grid.build(p.position, 0, p.size(), 2.0 * scene_.h);
    with_kernel(
        spec_.particles.kernel, scene_.h,
        [&](const auto& k) {
          for (const BasicPressureSensor<D>& sensor : scene_.pressure_sensors)
            b.probe_pressure.push_back(read_pressure_probe(k, p, grid, sensor, spec_.particles.dp));
        },
        D);
  }
  for (BasicPlateCoupling<D>& pl : plates_) b.plate_inside.push_back(static_cast<double>(pl.fluid_inside(p, scheme_.neighbours())));
  b.motion = tank_motion();
  b.fluid_mass = fluid_mass();
  if (acc_dt_ > 0.0) {
    b.wall_force = acc_wall_force_ / acc_dt_;
    b.wall_moment = acc_wall_moment_ / acc_dt_;
    b.base_acceleration = acc_base_acceleration_ / acc_dt_;
    b.base_acceleration_y = acc_base_acceleration_y_ / acc_dt_;
  }
  for (std::size_t i = 0; i < p.n_fluid; ++i) {
    b.kinetic_energy += 0.5 * p.mass * norm2(p.velocity[i]);
    b.potential_energy += p.mass * spec_.fluid.gravity * (component(p.position[i], D - 1) - scene_.tank->y_bottom);
    b.momentum_x += p.mass * p.velocity[i].x;
    if constexpr (D == 3) b.momentum_y += p.mass * p.velocity[i].y;
  }
  return b;
}

template <int D>
void BasicSimulation<D>::reset_interval_sums() {
  acc_dt_ = 0.0;
  acc_wall_force_ = {};
  acc_wall_moment_ = {};
  acc_base_acceleration_ = 0.0;
  acc_base_acceleration_y_ = 0.0;
  acc_tld_force_ = 0.0;
  acc_tld_force_y_ = 0.0;
  for (Vec<D>& f : acc_screen_force_) f = {};
  for (Vec2& f : acc_plate_force_) f = {};
}

template <int D>
std::vector<double> BasicSimulation<D>::sample() {
  const SampleBasis basis = sample_basis();
  std::vector<double> values;
  values.reserve(columns_.size());
  for (const Column& c : columns_) values.push_back(c.value(*this, basis));
  reset_interval_sums();
  return values;
}

template <int D>
void save_particles(StateWriter& w, const BasicParticles<D>& p) {
  w.array("particles.position", p.position);
  w.array("particles.velocity", p.velocity);
  w.array("particles.pressure", p.pressure);
  w.array("particles.pressure_back", p.pressure_back);
  w.array("particles.density", p.density);
  w.array("particles.normal", p.normal);
  w.array("particles.id", p.id);
  w.array("particles.wall_motion_velocity", p.wall_motion_velocity);
  w.array("particles.wall_motion_acceleration", p.wall_motion_acceleration);
  w.value("particles.n_fluid", static_cast<std::uint64_t>(p.n_fluid));
}

template <int D>
void load_particles(StateReader& r, BasicParticles<D>& p) {
  p.position = r.array<Vec<D>>("particles.position");
  p.velocity = r.array<Vec<D>>("particles.velocity");
  p.pressure = r.array<double>("particles.pressure");
  p.pressure_back = r.array<double>("particles.pressure_back");
  p.density = r.array<double>("particles.density");
  p.normal = r.array<Vec<D>>("particles.normal");
  p.id = r.array<std::int32_t>("particles.id");
  p.wall_motion_velocity = r.array<Vec<D>>("particles.wall_motion_velocity");
  p.wall_motion_acceleration = r.array<Vec<D>>("particles.wall_motion_acceleration");
  p.n_fluid = static_cast<std::size_t>(r.value<std::uint64_t>("particles.n_fluid"));
}

template <int D>
void BasicSimulation<D>::save_state(StateWriter& w) const {
  save_particles(w, scene_.particles);
  scheme_.save_state(w);
  w.value("sim.time", time_);
  w.value("sim.steps", static_cast<std::uint64_t>(steps_));
  w.value("sim.last_dt", last_dt_);
  w.value("sim.max_speed", max_speed_);
  w.array("sim.gauge_datum", gauge_datum_);
  w.array("sim.leaks", leaks_);
  w.value("sim.wall_contacts", static_cast<std::uint64_t>(wall_contacts_));
  w.value("sim.pair_contacts", static_cast<std::uint64_t>(pair_contacts_));
  if (spec_.scheme.shifting != ShiftingModel::none)
    w.value("sim.shifts_limited", static_cast<std::uint64_t>(shifts_limited_));
  w.value("sim.acc_dt", acc_dt_);
  w.value("sim.acc_wall_force", acc_wall_force_);
  w.value("sim.acc_wall_moment", acc_wall_moment_);
  w.value("sim.acc_base_acceleration", acc_base_acceleration_);
  w.value("sim.work_on_fluid", work_on_fluid_);
  w.array("sim.acc_screen_force", acc_screen_force_);
  w.array("sim.screen_loads", screen_loads_);
  w.value("sim.sloshing_force", sloshing_force_);
  w.value("sim.acc_tld_force", acc_tld_force_);
  w.value("sim.has_structure", static_cast<std::uint8_t>(structure_.has_value()));
  if (structure_) structure_->save_state(w);
  if constexpr (D == 3) {  // issue 31's 2-DOF structure; optional on reading (older 3D checkpoints)
    w.value("sim.acc_base_acceleration_y", acc_base_acceleration_y_);
    w.value("sim.has_structure_y", static_cast<std::uint8_t>(structure_y_.has_value()));
    if (structure_y_) {
      w.value("sim.sloshing_force_y", sloshing_force_y_);
      w.value("sim.acc_tld_force_y", acc_tld_force_y_);
      structure_y_->save_state(w);
    }
  }
  w.value("sim.plates", static_cast<std::uint64_t>(plates_.size()));
  for (std::size_t k = 0; k < plates_.size(); ++k) plates_[k].save_state(w, "plate." + std::to_string(k));
  w.array("sim.acc_plate_force", acc_plate_force_);
}

template <int D>
void BasicSimulation<D>::load_state(StateReader& r) {
  load_particles(r, scene_.particles);
  scheme_.load_state(r);
  time_ = r.value<double>("sim.time");
  steps_ = static_cast<std::size_t>(r.value<std::uint64_t>("sim.steps"));
  last_dt_ = r.value<double>("sim.last_dt");
  max_speed_ = r.value<double>("sim.max_speed");
  gauge_datum_ = r.array<double>("sim.gauge_datum");
  leaks_ = r.array<LeakRecord>("sim.leaks");
  wall_contacts_ = static_cast<std::size_t>(r.value<std::uint64_t>("sim.wall_contacts"));
  if (r.next_is("sim.pair_contacts"))  // a checkpoint from before the pair contact has none
    pair_contacts_ = static_cast<std::size_t>(r.value<std::uint64_t>("sim.pair_contacts"));
  if (spec_.scheme.shifting != ShiftingModel::none)
    shifts_limited_ = static_cast<std::size_t>(r.value<std::uint64_t>("sim.shifts_limited"));
  acc_dt_ = r.value<double>("sim.acc_dt");
  acc_wall_force_ = r.value<Vec<D>>("sim.acc_wall_force");
  if (r.next_is("sim.acc_wall_moment"))  // a checkpoint from before the moment columns has none
    acc_wall_moment_ = r.value<Moment<D>>("sim.acc_wall_moment");
  acc_base_acceleration_ = r.value<double>("sim.acc_base_acceleration");
  work_on_fluid_ = r.value<double>("sim.work_on_fluid");
  acc_screen_force_ = r.array<Vec<D>>("sim.acc_screen_force");
  screen_loads_ = r.array<BasicScreenElementLoad<D>>("sim.screen_loads");
  sloshing_force_ = r.value<double>("sim.sloshing_force");
  acc_tld_force_ = r.value<double>("sim.acc_tld_force");
  const bool has_structure = r.value<std::uint8_t>("sim.has_structure") != 0;
  if (has_structure != structure_.has_value())
    throw InputError(spec_.source, "structure", "the checkpoint and the case disagree on [structure]");
  if (structure_) structure_->load_state(r);
  if (D == 3 && r.next_is("sim.acc_base_acceleration_y")) {
    acc_base_acceleration_y_ = r.value<double>("sim.acc_base_acceleration_y");
    if ((r.value<std::uint8_t>("sim.has_structure_y") != 0) != structure_y_.has_value())
      throw InputError(spec_.source, "structure.y", "the checkpoint and the case disagree on [structure.y]");
    if (structure_y_) {
      sloshing_force_y_ = r.value<double>("sim.sloshing_force_y");
      acc_tld_force_y_ = r.value<double>("sim.acc_tld_force_y");
      structure_y_->load_state(r);
    }
  } else if (structure_y_) {
    throw InputError(spec_.source, "structure.y", "the checkpoint has no [structure.y] (written before it existed)");
  }
  if (r.value<std::uint64_t>("sim.plates") != plates_.size())
    throw InputError(spec_.source, "plates", "the checkpoint and the case disagree on the number of [[plates]]");
  for (std::size_t k = 0; k < plates_.size(); ++k) plates_[k].load_state(r, "plate." + std::to_string(k));
  acc_plate_force_ = r.array<Vec2>("sim.acc_plate_force");
}

template <int D>
double BasicSimulation<D>::container_distance(Vec<D> p) const {
  if constexpr (D == 2) return container_(p);
  else if (scene_.cylinder) return scene_.cylinder->signed_distance(p);  // exact, and as cheap
  else return std::min(container_(in_section(p)), std::min(p.y, scene_.breadth - p.y));
}

// The wall-contact step (physics/wall_contact.hpp) against the tank: in 2D its section, in 3D the
// section extruded over the breadth.
template <int D>
BasicWallContact<D> BasicSimulation<D>::wall_contact(double dt) {
  const double dp = spec_.particles.dp;
  if constexpr (D == 2) {
    return keep_fluid_in_tank(scene_.particles, container_, *scene_.tank, dp, container_grid(), dt);
  } else {
    const TankGeometry& section = *scene_.tank;
    const double breadth = scene_.breadth;
    const std::optional<CylinderTank>& cylinder = scene_.cylinder;
    return keep_fluid_in_container<3>(
        scene_.particles, [this](Vec3 q) { return container_distance(q); },
        [&section, breadth, &cylinder](Vec3 q) {
          return cylinder ? cylinder->signed_distance(q) : container_signed_distance<3>(section, breadth, q);
        },
        dp, container_grid(), dt);
  }
}

template class BasicSimulation<2>;
template class BasicSimulation<3>;

}  // namespace sloshsph
