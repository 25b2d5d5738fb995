#include "sloshsph/io/case_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/cylinder_tank.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/io/toml_reader.hpp"

namespace sloshsph {
namespace {

void check_name(TableReader& r, const std::string& key, const std::string& name, std::set<std::string>& seen) {
  if (name.empty()) r.fail(key, "must not be empty");
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      r.fail(key, "may only hold letters, digits, '_', '-' and '.' (it names a CSV column), got \"" + name + "\"");
  if (!seen.insert(name).second) r.fail(key, "duplicate name \"" + name + "\"");
}

FluidSpec read_fluid(TableReader& r) {
  FluidSpec f;
  f.density = r.positive("density", f.density);
  f.viscosity = r.non_negative("viscosity", f.viscosity);
  f.gravity = r.non_negative("gravity", f.gravity);
  r.finish();
  return f;
}

// [fill]: depth, and/or [[fill.blocks]] of water at rest. Checked against the tank in
// resolve_fill, once the particle size is known.
FillSpec read_fill(TableReader& r) {
  FillSpec f;
  for (TableReader& b : r.array_of_tables("blocks")) {
    f.blocks.push_back({b.point("from"), b.point("to")});
    b.finish();
  }
  if (f.blocks.empty()) f.depth = r.positive("depth");
  else f.depth = r.optional_positive("depth").value_or(0.0);
  r.finish();
  return f;
}

// Shape-specific keys are read only for their shape, so a key of another shape is an
// "unknown key" error rather than silently ignored.
TankSpec read_tank(TableReader& r) {
  TankSpec t;
  t.dimensions = static_cast<int>(r.integer("dimensions", t.dimensions, 2, 3));
  t.shape = r.choice("shape", t.shape,
                     {"rectangle", "sloped", "triangle", "trapezoid", "parabolic", "circular", "polyline", "cylinder"});
  if (t.shape == "cylinder") {
    // An upright circular tank (3D): radius and wall height; it spans 2 radius in x and y.
    if (t.dimensions != 3) r.fail("shape", "\"cylinder\" is an upright circular tank: set dimensions = 3");
    for (const char* key : {"length", "breadth"})
      if (r.has(key)) r.fail(key, "a cylinder is given by its radius and height");
    t.radius = r.positive("radius");
    t.height = r.positive("height");
    t.length = t.breadth = 2.0 * t.radius;
    r.finish();
    return t;
  }
  if (t.dimensions == 3) t.breadth = r.positive("breadth");
  else if (r.has("breadth"))
    r.fail("breadth", "is the breadth of a 3D tank: set dimensions = 3, or remove it (a 2D case is per metre of breadth)");
  if (t.shape == "polyline") {
    t.points = r.points("points");
    if (t.points.size() < 3) r.fail("points", "a polyline tank needs at least 3 points");
    double x_min = t.points[0].x, x_max = x_min, y_min = t.points[0].y, y_max = y_min;
    for (const Vec2& q : t.points) {
      x_min = std::min(x_min, q.x);
      x_max = std::max(x_max, q.x);
      y_min = std::min(y_min, q.y);
      y_max = std::max(y_max, q.y);
    }
    t.length = x_max - x_min;
    t.height = y_max - y_min;
  } else {
    t.length = r.positive("length");
    t.height = r.positive("height");
  }
  if (t.shape == "parabolic") t.coefficient = r.positive("coefficient", t.coefficient);
  if (t.shape == "sloped" || t.shape == "triangle" || t.shape == "trapezoid") {
    t.angle = r.in_range("angle", t.angle, 1.0, 89.0);
    if (t.shape != "triangle") t.bottom_width = r.non_negative("bottom_width", t.bottom_width);
  }
  r.finish();
  return t;
}

ParticleSpec read_particles(TableReader& r) {
  ParticleSpec p;
  p.dp = r.positive("dp");
  p.kernel_ratio = r.in_range("kernel_ratio", p.kernel_ratio, 1.0, 2.5);
  // The walls must fill the kernel of a particle at rest dp/2 from them (core/case_spec.hpp).
  const int needed = wall_layers_needed(p.kernel_ratio);
  p.wall_layers = static_cast<int>(r.integer("wall_layers", std::max(2, needed), 1, 8));
  if (p.wall_layers < needed) {
    char what[240];
    std::snprintf(what, sizeof what,
                  "is %d, but at kernel_ratio = %g the kernel of a particle dp/2 from a wall reaches %d layers into it; "
                  "set wall_layers = %d or more (or leave it out: its default follows kernel_ratio)",
                  p.wall_layers, p.kernel_ratio, needed, needed);
    r.fail("wall_layers", what);
  }
  p.kernel = r.choice("kernel", "wendland", {"wendland", "cubic_spline"}) == "cubic_spline" ? KernelType::cubic_spline
                                                                                               : KernelType::wendland_c2;
  r.finish();
  return p;
}

// Keys of one scheme are read only for that scheme: an ISPH key in a WCSPH case (or the
// other way round) is an unknown key.
void read_isph_keys(TableReader& r, SchemeSpec& s) {
  s.alpha = r.in_range("alpha", s.alpha, 0.0, 1.0);
  s.density_relaxation_time = r.non_negative("density_relaxation_time", s.density_relaxation_time);
  if (s.density_relaxation_time > 0.0 && r.has("alpha"))
    r.fail("density_relaxation_time", "sets the blending factor (alpha = dt / density_relaxation_time); leave "
                                      "alpha out, or set density_relaxation_time = 0");
  s.pressure = r.choice("pressure", "implicit", {"explicit", "implicit"}) == "explicit" ? PressureSolve::explicit_update
                                                                                         : PressureSolve::implicit_krylov;
  // The explicit update is only stable with the thesis's particle Dirichlet condition
  // (measured: with the air model the pressure of a tank at rest swings by 50%), so each
  // pressure solve has its own default and the unstable pair is refused.
  const bool explicit_solve = s.pressure == PressureSolve::explicit_update;
  s.free_surface = r.choice("free_surface", explicit_solve ? "thesis" : "air", {"air", "thesis"}) == "thesis"
                       ? FreeSurfaceModel::thesis
                       : FreeSurfaceModel::air;
  if (explicit_solve && s.free_surface == FreeSurfaceModel::air)
    r.fail("free_surface", "\"air\" needs pressure = \"implicit\" (with the explicit update it is unstable); use \"thesis\"");
  s.free_surface_threshold = r.in_range("free_surface_threshold", s.free_surface_threshold, 0.5, 0.99);
  s.predictor = r.choice("predictor", "euler", {"euler", "midpoint"}) == "midpoint" ? PositionPredictor::midpoint
                                                                                    : PositionPredictor::euler;
  if (explicit_solve && s.predictor == PositionPredictor::midpoint)
    r.fail("predictor", "\"midpoint\" needs pressure = \"implicit\" (the explicit update reads the density at the end "
                        "of the step); use \"euler\"");
  s.turbulence = r.boolean("turbulence", s.turbulence);
  s.smagorinsky = r.in_range("smagorinsky", s.smagorinsky, 0.0, 1.0);
  s.ct = r.positive("ct", s.ct);
  s.clip_negative_pressure = r.choice("negative_pressure", "clip", {"clip", "keep"}) == "clip";
  s.solver_tolerance = r.in_range("solver_tolerance", s.solver_tolerance, 1e-14, 1e-1);
  s.solver_max_iterations = static_cast<int>(r.integer("solver_max_iterations", s.solver_max_iterations, 1, 1000000));
  s.preconditioner = r.choice("preconditioner", "multigrid", {"multigrid", "jacobi"}) == "jacobi"
                         ? Preconditioner::jacobi
                         : Preconditioner::multigrid;
  s.repulsive_walls = r.boolean("repulsive_walls", s.repulsive_walls);  // thesis eq. 3.18
  s.repulsive_coefficient = r.in_range("repulsive_coefficient", s.repulsive_coefficient, 0.0, 100.0);
  s.repulsive_range = r.in_range("repulsive_range", s.repulsive_range, 0.05, 2.0);
  s.shifting = r.choice("shifting", "none", {"none", "lind"}) == "lind" ? ShiftingModel::lind : ShiftingModel::none;
  s.shifting_coefficient = r.in_range("shifting_coefficient", s.shifting_coefficient, 0.1, 10.0);
}

void read_wcsph_keys(TableReader& r, SchemeSpec& s) {
  WcsphSpec& w = s.wcsph;
  w.sound_speed = r.non_negative("sound_speed", w.sound_speed);
  w.max_density_variation = r.in_range("max_density_variation", w.max_density_variation, 1e-4, 0.1);
  w.delta = r.in_range("delta", w.delta, 0.0, 1.0);
  w.artificial_viscosity = r.in_range("artificial_viscosity", w.artificial_viscosity, 0.0, 1.0);
  w.xsph = r.in_range("xsph", w.xsph, 0.0, 1.0);
  w.kernel_gradient_correction = r.boolean("kernel_gradient_correction", w.kernel_gradient_correction);
  w.shepard_interval = static_cast<int>(r.integer("shepard_interval", w.shepard_interval, 0, 100000));
  const std::string turb = r.choice("turbulence", "none", {"none", "sps", "smagorinsky"});
  w.turbulence = turb == "sps" ? WcsphTurbulence::sps : turb == "smagorinsky" ? WcsphTurbulence::smagorinsky
                                                                             : WcsphTurbulence::none;
  w.smagorinsky = r.in_range("smagorinsky", w.smagorinsky, 0.0, 1.0);
  w.walls = r.choice("walls", "adami", {"adami", "repulsive"}) == "repulsive" ? WallTreatment::repulsive
                                                                             : WallTreatment::adami;
  w.integrator = r.choice("integrator", "symplectic", {"symplectic", "leapfrog"}) == "leapfrog" ? Integrator::leapfrog
                                                                                               : Integrator::symplectic;
  w.cfl = r.in_range("cfl", w.cfl, 0.01, 1.0);
  s.shifting = r.choice("shifting", "none", {"none", "delta_plus"}) == "delta_plus" ? ShiftingModel::delta_plus
                                                                                   : ShiftingModel::none;
}

SchemeSpec read_scheme(TableReader& r) {
  SchemeSpec s;
  s.type = r.choice("type", s.type, {"isph", "wcsph"});
  if (s.type == "isph") read_isph_keys(r, s);
  else read_wcsph_keys(r, s);
  s.neighbour_skin = r.in_range("neighbour_skin", s.neighbour_skin, 0.0, 1.0);
  s.wall_contact = r.boolean("wall_contact", s.wall_contact);
  s.pair_contact = r.boolean("pair_contact", s.pair_contact);
  s.shifting_max = r.in_range("shifting_max", s.shifting_max, 0.01, 0.5);  // both schemes' shifts
  r.finish();
  return s;
}

TimeSpec read_time(TableReader& r) {
  TimeSpec t;
  t.end = r.positive("end");
  t.dt = r.positive("dt", t.dt);
  t.adaptive = r.boolean("adaptive", t.adaptive);
  t.cfl = r.in_range("cfl", t.cfl, 1e-3, 0.5);
  t.dt_min = r.non_negative("dt_min", t.dt_min);
  t.settle = r.non_negative("settle", t.settle);
  r.finish();
  return t;
}

// Frequency of a periodic excitation: exactly one of frequency (Hz), omega (rad/s), beta.
void read_frequency(TableReader& r, ExcitationSpec& e) {
  e.frequency = r.optional_positive("frequency");
  const std::optional<double> omega = r.optional_positive("omega");
  e.beta = r.optional_positive("beta");
  const int given = (e.frequency ? 1 : 0) + (omega ? 1 : 0) + (e.beta ? 1 : 0);
  if (given > 1) r.fail(e.beta ? "beta" : "omega", "give only one of 'frequency' (Hz), 'omega' (rad/s) and 'beta'");
  if (given == 0)
    r.fail("frequency", "a periodic excitation needs 'frequency' (Hz), 'omega' (rad/s) or 'beta' (ratio to the first "
                        "sloshing frequency)");
  if (omega) e.frequency = *omega / (2.0 * 3.141592653589793238);
  if (e.beta)
    e.beta_reference = r.choice("beta_reference", "modal", {"modal", "thesis"}) == "thesis" ? BetaReference::thesis
                                                                                           : BetaReference::modal;
  e.ramp = r.non_negative("ramp", e.ramp);
  e.phase = r.number("phase", e.phase);
  e.stop = r.number("stop", e.stop);
}

// A path in the case is relative to the case file's folder.
std::string resolve_path(TableReader& r, const std::string& key) {
  const std::string given = r.string(key);
  std::filesystem::path p(given);
  if (p.is_relative() && r.file().find('<') == std::string::npos)
    p = std::filesystem::path(r.file()).parent_path() / p;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p, ec)) r.fail(key, "no such file: " + p.string());
  // Absolute, so that the case.toml written into a run directory can be run from anywhere.
  return std::filesystem::absolute(p).lexically_normal().string();
}

// A pitch from a file: the record gives theta(t), so the harmonic pitch's keys (angle, the
// frequency, ramp, phase, stop) are refused with a message that says why, not as unknown keys.
// The file's values (angle and time) are checked when the record is read (physics/excitation.cpp).
void read_pitch_file_keys(TableReader& r, ExcitationSpec& e) {
  for (const char* key : {"angle", "frequency", "omega", "beta", "beta_reference", "ramp", "phase", "stop"})
    if (r.has(key))
      r.fail(key, "belongs to the harmonic pitch; with 'file' the record gives the angle at every time "
                  "(remove '" + std::string(key) + "', or remove 'file')");
  e.file = resolve_path(r, "file");
  if (!r.has("unit")) r.fail("unit", "is required with 'file': the unit of the angle column, \"deg\" or \"rad\"");
  e.value_unit = r.choice("unit", "deg", {"deg", "rad"}) == "deg" ? 3.141592653589793238 / 180.0 : 1.0;
  e.time_scale = r.positive("time_scale", e.time_scale);
  e.start = r.number("start", e.start);
}

// [excitation], and in it [excitation.y] (`along_y` non-null: the table's own keys; null: the y
// table, whose keys are those of a translation without `direction`).
ExcitationSpec read_excitation(TableReader& r, std::optional<ExcitationSpec>* along_y, int dimensions) {
  ExcitationSpec e;
  if (!along_y) {
    if (r.has("direction"))
      r.fail("direction", "[excitation.y] moves the base along y; give the motion along x in [excitation]");
    if (r.has("type") && (r.string("type") == "pitch" || r.string("type") == "none"))
      r.fail("type", "[excitation.y] is a translation along y: harmonic, record, pulse or noise");
  }
  const std::string type = r.choice("type", "harmonic", {"none", "harmonic", "pitch", "record", "pulse", "noise"});
  if (type == "harmonic") {
    e.type = ExcitationType::harmonic;
    if (!r.has("amplitude")) r.fail("amplitude", "is required for a harmonic excitation (m)");
    e.amplitude = r.non_negative("amplitude", 0.0);
    read_frequency(r, e);
  } else if (type == "pitch") {
    e.type = ExcitationType::pitch;
    if (r.has("file")) {
      read_pitch_file_keys(r, e);
    } else {
      if (!r.has("angle")) r.fail("angle", "is required for a pitch excitation (degrees), or give 'file' (an angle record)");
      e.angle = r.in_range("angle", 0.0, 0.0, 45.0) * 3.141592653589793238 / 180.0;
      read_frequency(r, e);
    }
    if (dimensions == 2) {
      e.pivot = r.point("pivot");
    } else {  // 3D: the pivot (x, y, z) and the axis (issue 31)
      const std::optional<Vec3> pivot = r.optional_point3("pivot");
      if (!pivot) r.fail("pivot", "is required: in 3D the point [x, y, z] the axis passes through (m)");
      e.pivot = {pivot->x, pivot->z};
      e.pivot_across = pivot->y;
      if (const std::optional<Vec3> axis = r.optional_point3("axis")) {
        if (!(norm(*axis) > 1e-12) || !std::isfinite(norm(*axis))) r.fail("axis", "expected a direction [x, y, z], not zero");
        e.axis = normalized(*axis);
      }
    }
  } else if (type == "record") {
    e.type = ExcitationType::record;
    e.file = resolve_path(r, "file");
    const std::string ext = std::filesystem::path(e.file).extension().string();
    e.format = r.choice("format", ext == ".csv" || ext == ".txt" ? "csv" : "at2", {"at2", "csv"});
    e.scale = r.number("scale", e.scale);
    if (e.format == "csv") {
      e.value_unit = r.choice("unit", "m/s2", {"m/s2", "g"}) == "g" ? 9.80665 : 1.0;
      e.time_scale = r.positive("time_scale", e.time_scale);
    }
    e.baseline_correction = r.boolean("baseline_correction", e.baseline_correction);
    e.start = r.non_negative("start", e.start);
  } else if (type == "pulse") {
    e.type = ExcitationType::pulse;
    e.shape = r.choice("shape", e.shape, {"sine", "cosine"});
    e.acceleration = r.number("acceleration");
    e.period = r.positive("period");
    e.start = r.non_negative("start", e.start);
  } else if (type == "noise") {
    e.type = ExcitationType::noise;
    e.seed = static_cast<std::uint64_t>(r.integer("seed", 1, 0, 9007199254740991LL));
    const std::vector<Vec2> band = r.has("band") ? std::vector<Vec2>{r.point("band")} : std::vector<Vec2>{{0.05, 0.5}};
    e.band_low = band[0].x;
    e.band_high = band[0].y;
    if (!(e.band_low > 0.0 && e.band_high > e.band_low)) r.fail("band", "expected [f_low, f_high] with 0 < f_low < f_high (Hz)");
    e.rms = r.positive("rms");
  }
  if (r.has("direction")) {
    const Vec2 d = r.point("direction");
    if (!(norm(d) > 1e-12) || !std::isfinite(norm(d))) r.fail("direction", "expected a horizontal vector [x, y], not zero");
    e.direction = normalized(d);
  }
  if (along_y) {
    if (auto y = r.table("y")) {
      *along_y = read_excitation(*y, nullptr, dimensions);
      (*along_y)->direction = {0.0, 1.0};
      (*along_y)->table = "excitation.y";
    }
  }
  r.finish();
  return e;
}

void read_probes(TableReader& r, CaseSpec& spec) {
  std::set<std::string> names;
  for (TableReader& g : r.array_of_tables("gauge")) {
    GaugeSpec gs;
    gs.name = g.string("name");
    check_name(g, "name", gs.name, names);
    gs.x = g.number("x");
    if (spec.tank.dimensions == 3) gs.across = g.number("y");
    g.finish();
    spec.gauges.push_back(gs);
  }
  names.clear();
  for (TableReader& p : r.array_of_tables("pressure")) {
    PressureProbeSpec ps;
    ps.name = p.string("name");
    check_name(p, "name", ps.name, names);
    if (spec.tank.dimensions == 3) {
      // 3D: y across the breadth, z up (issue 31); a sensor face is not available in 3D yet.
      ps.position = {p.number("x"), p.number("z")};
      ps.across = p.number("y");
      for (const char* key : {"to", "size"})
        if (p.has(key)) p.fail(key, "a sensor face is not available in 3D yet: the probe reads at the point (x, y, z)");
    } else {
      ps.position = {p.number("x"), p.number("y")};
    }
    ps.face_end = p.optional_point("to");
    ps.size = p.non_negative("size", 0.0);
    if (ps.size > 0.0 && ps.face_end)
      p.fail("size", "give either 'to' (the other end of the face) or 'size' (a face centred on x, y along the "
                     "wall), not both");
    p.finish();
    spec.pressure_probes.push_back(ps);
  }
  names.clear();
  for (TableReader& f : r.array_of_tables("front")) {
    FrontProbeSpec fs;
    fs.name = f.string("name");
    check_name(f, "name", fs.name, names);
    fs.band = f.non_negative("band", 0.0);
    fs.rightward = f.choice("direction", "right", {"right", "left"}) == "right";
    f.finish();
    spec.fronts.push_back(fs);
  }
  r.finish();
}

// [[screens]]: porous elements (thesis 2.5, 4.2.2) or explicit slat screens.
void read_screens(TableReader& root, CaseSpec& spec) {
  std::set<std::string> names;
  for (TableReader& r : root.array_of_tables("screens")) {
    ScreenSpec sc;
    sc.name = r.string("name");
    check_name(r, "name", sc.name, names);
    if (r.has("y") && spec.tank.dimensions == 2)
      r.fail("y", "a screen in the plane y = const is for 3D tanks (tank.dimensions = 3); a 2D screen takes 'x' or "
                  "'from' and 'to'");
    if ((r.has("plan_from") || r.has("plan_to")) && spec.tank.dimensions == 2)
      r.fail(r.has("plan_from") ? "plan_from" : "plan_to",
             "a screen in a vertical plane through a segment of the plan is for 3D tanks (tank.dimensions = 3)");
    if (r.has("plan_from") || r.has("plan_to")) {  // 3D (issue 31): a vertical plane at any angle
      for (const char* other : {"x", "y", "from", "to"})
        if (r.has(other)) r.fail(other, "give either 'plan_from' and 'plan_to' or one of 'x', 'y', 'from' and 'to'");
      if (!r.has("plan_from") || !r.has("plan_to"))
        r.fail(r.has("plan_from") ? "plan_to" : "plan_from", "a screen in a plane through the plan needs both "
                                                             "'plan_from' and 'plan_to' ([x, y] in m)");
      sc.plan = std::make_pair(r.point("plan_from"), r.point("plan_to"));
      sc.full_height = true;
      sc.from = {0.5 * (sc.plan->first.x + sc.plan->second.x), 0.0};
      sc.to = sc.from;
    } else if (r.has("y")) {  // 3D (issue 31): a screen across the breadth
      for (const char* other : {"x", "from", "to"})
        if (r.has(other)) r.fail(other, "give either 'y' (a screen in the plane y = const) or 'x' or 'from' and 'to'");
      sc.plane_y = r.number("y");
      if (!(*sc.plane_y > 0.0 && *sc.plane_y < spec.tank.breadth))
        r.fail("y", "the screen's plane must lie inside the tank: 0 < y < tank.breadth");
      sc.full_height = true;
      sc.from = {0.5 * spec.tank.length, 0.0};
      sc.to = sc.from;
    } else if (r.has("x")) {
      if (r.has("from") || r.has("to")) r.fail("x", "give either 'x' (a vertical screen) or 'from' and 'to', not both");
      sc.full_height = true;
      sc.from = {r.number("x"), 0.0};
      sc.to = sc.from;
    } else {
      if (!r.has("from") || !r.has("to")) r.fail("x", "a screen needs 'x' (vertical, full height) or 'from' and 'to' ([x, y] in m)");
      sc.from = r.point("from");
      sc.to = r.point("to");
    }
    const std::string model = r.choice("model", "ergun", {"ergun", "morison", "explicit"});
    sc.model = model == "morison" ? ScreenModel::morison : model == "explicit" ? ScreenModel::explicit_slats
                                                                                : ScreenModel::ergun;
    sc.slat_height = r.non_negative("slat_height", 0.0);
    sc.slat_gap = r.non_negative("slat_gap", 0.0);
    if (r.has("solidity")) sc.solidity = r.in_range("solidity", 0.0, 0.0, 0.999);
    else if (sc.slat_height > 0.0 && sc.slat_gap > 0.0) sc.solidity = sc.slat_height / (sc.slat_height + sc.slat_gap);
    else r.fail("solidity", "a screen needs 'solidity' (0 to 1) or 'slat_height' and 'slat_gap' (m)");
    if (sc.model == ScreenModel::explicit_slats && !(sc.slat_height > 0.0 && sc.slat_gap > 0.0))
      r.fail("slat_height", "an explicit screen needs 'slat_height' and 'slat_gap' (m)");
    sc.thickness = r.positive("thickness", sc.thickness);
    sc.spacing = r.non_negative("spacing", sc.spacing);
    sc.interaction_radius = r.non_negative("interaction_radius", sc.interaction_radius);
    if (sc.model == ScreenModel::morison) sc.loss_coefficient = r.non_negative("loss_coefficient", 0.0);
    if (sc.model != ScreenModel::explicit_slats)
      sc.shepard_velocity = r.choice("velocity", "thesis", {"thesis", "shepard"}) == "shepard";
    r.finish();
    spec.screens.push_back(sc);
  }
}

// [[plates]]: elastic plates coupled with the fluid (run/plate_coupling.hpp).
PlateSupport read_support(TableReader& r, const std::string& key, const std::string& fallback) {
  const std::string v = r.choice(key, fallback, {"clamped", "pinned", "free"});
  return v == "clamped" ? PlateSupport::clamped : v == "pinned" ? PlateSupport::pinned : PlateSupport::free;
}

void read_plates(TableReader& root, CaseSpec& spec) {
  std::set<std::string> names;
  for (TableReader& r : root.array_of_tables("plates")) {
    PlateSpec pl;
    pl.name = r.string("name");
    check_name(r, "name", pl.name, names);
    if (r.has("x")) {
      if (r.has("from") || r.has("to"))
        r.fail("x", "give either 'x' and 'height' (a plate standing on the bottom) or 'from' and 'to', not both");
      pl.from = {r.number("x"), 0.0};
      pl.standing_height = r.positive("height");
    } else {
      if (!r.has("from") || !r.has("to"))
        r.fail("x", "a plate needs 'x' and 'height' (standing on the bottom) or 'from' and 'to' ([x, y] in m)");
      pl.from = r.point("from");
      pl.to = r.point("to");
      if (norm(pl.to - pl.from) <= 0.0) r.fail("to", "the plate has zero length ('from' and 'to' coincide)");
    }
    pl.thickness = r.positive("thickness");
    pl.youngs_modulus = r.positive("youngs_modulus");
    pl.density = r.positive("density");
    pl.poisson_ratio = r.in_range("poisson_ratio", pl.poisson_ratio, 0.0, 0.4999);
    pl.elements = static_cast<int>(r.integer("elements", pl.elements, 1, 2000));
    pl.from_support = read_support(r, "from_support", "clamped");
    pl.to_support = read_support(r, "to_support", "free");
    if (pl.from_support == PlateSupport::free && pl.to_support == PlateSupport::free)
      r.fail("from_support", "a plate with two free ends floats away: support at least one end");
    pl.rayleigh_mass = r.non_negative("rayleigh_mass", 0.0);
    pl.rayleigh_stiffness = r.non_negative("rayleigh_stiffness", 0.0);
    pl.hht_alpha = r.in_range("hht_alpha", pl.hht_alpha, -1.0 / 3.0, 0.0);
    r.finish();
    spec.plates.push_back(pl);
  }
}

// [structure.load]: the external force on the structure. Keys of one load type are read only
// for that type, so a key of another type is an unknown key.
StructureLoadSpec read_structure_load(TableReader& r) {
  StructureLoadSpec l;
  const std::string type = r.choice("type", "harmonic", {"none", "harmonic", "noise", "record", "pulse"});
  if (type == "harmonic") {
    l.type = StructureLoadType::harmonic;
    if (!r.has("amplitude")) r.fail("amplitude", "is required for a harmonic load (N)");
    l.amplitude = r.non_negative("amplitude", 0.0);
    l.frequency = r.positive("frequency");
    l.ramp = r.non_negative("ramp", l.ramp);
  } else if (type == "noise") {
    l.type = StructureLoadType::noise;
    l.seed = static_cast<std::uint64_t>(r.integer("seed", 1, 0, 9007199254740991LL));
    if (r.has("band")) {
      const Vec2 band = r.point("band");
      l.band_low = band.x;
      l.band_high = band.y;
    }
    if (!(l.band_low > 0.0 && l.band_high > l.band_low))
      r.fail("band", "expected [f_low, f_high] with 0 < f_low < f_high (Hz)");
    l.target_peak_mg = r.optional_positive("target_peak_mg");
    l.rms = r.optional_positive("rms");
    if (l.target_peak_mg && l.rms) r.fail("rms", "give only one of 'target_peak_mg' (milli-g) and 'rms' (N)");
    if (!l.target_peak_mg && !l.rms)
      r.fail("target_peak_mg", "a noise load needs 'target_peak_mg' (mean peak acceleration of the structure "
                               "without TLD, milli-g) or 'rms' (N)");
    l.peak_duration = r.positive("peak_duration", l.peak_duration);
  } else if (type == "record") {
    l.type = StructureLoadType::record;
    l.file = resolve_path(r, "file");
    l.scale = r.number("scale", l.scale);
    l.time_scale = r.positive("time_scale", l.time_scale);
    l.start = r.non_negative("start", l.start);
  } else if (type == "pulse") {
    l.type = StructureLoadType::pulse;
    l.shape = r.choice("shape", l.shape, {"sine", "cosine"});
    l.amplitude = r.number("amplitude");
    l.period = r.positive("period");
    l.start = r.non_negative("start", l.start);
  }
  r.finish();
  return l;
}

// One sway mode of the structure given by (mass, stiffness, damping) or (mass, frequency,
// damping_ratio), resolved here to M, K, C (K = M w^2, C = 2 zeta M w, w = 2 pi f), with its
// initial state and its load: the keys [structure] and [structure.y] have in common.
void read_sway_mode(TableReader& r, StructureSpec& s) {
  s.mass = r.positive("mass");
  const std::optional<double> stiffness = r.optional_positive("stiffness");
  const std::optional<double> frequency = r.optional_positive("frequency");
  if (stiffness && frequency) r.fail("frequency", "give only one of 'stiffness' (N/m) and 'frequency' (Hz)");
  if (!stiffness && !frequency) r.fail("stiffness", "the structure needs 'stiffness' (N/m) or 'frequency' (Hz)");
  const double omega = frequency ? 2.0 * 3.141592653589793238 * *frequency : std::sqrt(*stiffness / s.mass);
  s.stiffness = stiffness ? *stiffness : s.mass * omega * omega;
  const bool has_damping = r.has("damping"), has_ratio = r.has("damping_ratio");
  if (has_damping && has_ratio) r.fail("damping_ratio", "give only one of 'damping' (N s/m) and 'damping_ratio'");
  if (!has_damping && !has_ratio)
    r.fail("damping", "the structure needs 'damping' (N s/m) or 'damping_ratio' (fraction of critical)");
  if (has_damping) s.damping = r.non_negative("damping", 0.0);
  else s.damping = 2.0 * r.in_range("damping_ratio", 0.0, 0.0, 1.0) * s.mass * omega;
  // Finite inputs can still overflow here (mass 1e300, frequency 1e300).
  if (!(std::isfinite(s.stiffness) && s.stiffness > 0.0))
    r.fail(frequency ? "frequency" : "stiffness", "gives a stiffness M (2 pi f)^2 that is not a finite number > 0");
  if (!std::isfinite(s.damping)) r.fail(has_damping ? "damping" : "damping_ratio", "gives an infinite damping");
  s.initial_displacement = r.number("initial_displacement", s.initial_displacement);
  s.initial_velocity = r.number("initial_velocity", s.initial_velocity);
  if (auto load = r.table("load")) s.load = read_structure_load(*load);
}

// [structure]: the SDOF structure (its sway along x), and in 3D [structure.y], the second sway
// mode along y (issue 31: the building as a 2-DOF structure). The tanks, their rigid mass and the
// ground motion are the structure's, so [structure.y] takes them from [structure].
StructureSpec read_structure(TableReader& r, std::optional<StructureSpec>& sway_y) {
  StructureSpec s;
  read_sway_mode(r, s);
  s.tank_width = r.positive("tank_width", s.tank_width);
  s.tanks = static_cast<int>(r.integer("tanks", s.tanks, 0, 1000000));
  s.rigid_mass = r.non_negative("rigid_mass", s.rigid_mass);
  s.ground_from_excitation = r.choice("ground", "none", {"none", "excitation"}) == "excitation";
  if (auto y = r.table("y")) {
    for (const char* shared : {"tank_width", "tanks", "rigid_mass", "ground"})
      if (y->has(shared))
        y->fail(shared, "belongs in [structure]: the tanks and the ground motion are the structure's, the same for "
                        "both sway modes");
    StructureSpec sy;
    read_sway_mode(*y, sy);
    sy.tank_width = s.tank_width;
    sy.tanks = s.tanks;
    sy.rigid_mass = s.rigid_mass;
    sy.ground_from_excitation = s.ground_from_excitation;
    y->finish();
    sway_y = sy;
  }
  r.finish();
  return s;
}

OutputSpec read_output(TableReader& r, int dimensions) {
  OutputSpec o;
  if (r.has("moment_point")) {
    if (dimensions == 3) {
      o.moment_point = r.optional_point3("moment_point");
      if (!o.moment_point) r.fail("moment_point", "is the point [x, y, z] the moments are taken about (m)");
    } else {
      const std::optional<Vec2> q = r.optional_point("moment_point");
      if (!q) r.fail("moment_point", "is the point [x, y] the moments are taken about (m)");
      o.moment_point = Vec3{q->x, q->y, 0.0};
    }
  }
  o.sample_interval = r.positive("sample_interval", o.sample_interval);
  o.snapshot_interval = r.non_negative("snapshot_interval", o.snapshot_interval);
  o.snapshot_walls = r.boolean("snapshot_walls", o.snapshot_walls);
  o.response_cycles = static_cast<int>(r.integer("response_cycles", o.response_cycles, 1, 100000));
  o.lowpass_hz = r.non_negative("lowpass_hz", o.lowpass_hz);
  r.finish();
  return o;
}

RunSpec read_run(TableReader& r) {
  RunSpec s;
  s.max_leaked_fraction = r.in_range("max_leaked_fraction", s.max_leaked_fraction, 0.0, 1.0);
  s.max_speed_factor = r.positive("max_speed_factor", s.max_speed_factor);
  r.finish();
  return s;
}

template <class F>
void section(TableReader& root, const std::string& key, bool required, F&& read) {
  auto t = root.table(key);
  if (!t) {
    if (required) root.fail(key, "the table [" + key + "] is required");
    return;
  }
  read(*t);
}

// Caps on the number of steps, rows and snapshots. Below the resolution of the clock a step no
// longer advances the time and an output interval never passes it, so such a case would hang
// (not interruptibly in the settling phase); far above any real run, far below that point.
template <class Fail>
void check_counts(const CaseSpec& s, Fail&& fail) {
  auto count = [](const char* ratio, double n, const char* what, const char* limit) {
    std::ostringstream m;
    m << ratio << " = " << std::setprecision(3) << n << " " << what << " (limit " << limit << ")";
    return m.str();
  };
  const double steps = s.time.end / s.time.dt, settle_steps = s.time.settle / s.time.dt;
  if (!(steps <= 1e10)) fail("time.dt", count("too small: time.end / dt", steps, "time steps", "1e10"));
  if (!(settle_steps <= 1e10))
    fail("time.settle", count("too long: time.settle / time.dt", settle_steps, "settling steps", "1e10"));
  const double rows = s.time.end / s.output.sample_interval;
  if (!(rows <= 1e8))
    fail("output.sample_interval", count("too small: time.end / sample_interval", rows, "rows of timeseries.csv", "1e8"));
  if (s.output.snapshot_interval > 0.0) {
    const double files = s.time.end / s.output.snapshot_interval;
    if (!(files <= 1e6))
      fail("output.snapshot_interval",
           count("too small: time.end / snapshot_interval", files, "snapshot files", "1e6; 0 writes none"));
  }
}

// With [structure] the tank moves with the structure: [excitation] can only be the ground
// motion under the structure (structure.ground = "excitation"), a horizontal translation.
void check_structure_consistency(const CaseSpec& s) {
  if (!s.structure) return;
  auto fail = [&](const std::string& key, const std::string& what) { throw InputError(s.where(key), key, what); };
  for (const auto& [mode, prefix] : {std::pair{&s.structure, "structure."}, std::pair{&s.structure_y, "structure.y."}}) {
    if (!*mode) continue;
    const StructureLoadSpec& load = (*mode)->load;
    if (load.type == StructureLoadType::noise && load.target_peak_mg && !((*mode)->damping > 0.0))
      fail(std::string(prefix) + "load.target_peak_mg",
           "scales the noise by the response of the damped structure alone; an undamped structure has no finite "
           "response to white noise: give damping > 0 or 'rms'");
  }
  const bool excited = s.excitation.type != ExcitationType::none || s.excitation_y;
  if (s.structure->ground_from_excitation) {
    if (!excited)
      fail("structure.ground", "is \"excitation\" but the case has no [excitation] to be the ground motion");
    if (s.excitation.type == ExcitationType::pitch)
      fail("excitation.type", "a pitch cannot be the ground motion of the structure (a horizontal translation); "
                              "use harmonic, record, pulse or noise");
  } else if (excited) {
    fail("excitation.type", "with [structure] the tank moves with the structure, so [excitation] cannot also move it: "
                            "remove [excitation], or set structure.ground = \"excitation\" to make it the ground "
                            "motion under the structure (seismic), or load the structure through [structure.load]");
  }
}

// The particle count a case would need, bounded before anything is generated (a fine dp with
// fill blocks made the reader lay out 1e18 lattice points: the mutation test's hang).
void check_particle_estimate(const CaseSpec& s) {
  const double dp = s.particles.dp;
  const double walls = s.particles.wall_layers * dp;
  double estimate = (s.tank.length + 2.0 * walls) * (s.tank.height + walls) / (dp * dp);
  if (s.tank.dimensions == 3) estimate *= (s.tank.breadth + 2.0 * walls) / dp;
  if (estimate > 2.0e7) {
    // Printed as a double: a huge tank gives an estimate beyond long long (or inf), and that
    // conversion would be undefined behaviour.
    std::ostringstream m;
    m << "would need about " << std::setprecision(3) << estimate << " particles (limit 2e7 in "
      << s.tank.dimensions << "D): is dp in metres?";
    throw InputError(s.where("particles.dp"), "particles.dp", m.str());
  }
}

// A screen through a segment of the plan (plan_from, plan_to): in a box or a cylinder (flat
// bottoms: the screen stands full height), porous or explicit, both ends inside the tank's plan
// (on its wall allowed), at least dp long.
void check_plan_screen(const CaseSpec& s, const ScreenSpec& sc, const std::string& key) {
  auto fail = [&](const std::string& sub, const std::string& what) {
    throw InputError(s.where(key + "." + sub), key + "." + sub, what);
  };
  if (s.tank.shape != "rectangle" && s.tank.shape != "cylinder")
    fail("plan_from", "a screen through a segment of the plan stands in a box (shape = \"rectangle\") or a cylinder");
  const double tol = 1e-9;
  for (const auto& [sub, q] : {std::pair<const char*, Vec2>{"plan_from", sc.plan->first}, {"plan_to", sc.plan->second}}) {
    const bool inside = s.tank.shape == "cylinder"
                            ? cylinder_of(s.tank).from_axis({q.x, q.y, 0.0}) <= s.tank.radius + tol
                            : q.x >= -tol && q.x <= s.tank.length + tol && q.y >= -tol && q.y <= s.tank.breadth + tol;
    if (!inside) fail(sub, "the end of the screen must lie inside the tank's plan (on its wall at most)");
  }
  if (norm(sc.plan->second - sc.plan->first) < s.particles.dp)
    fail("plan_to", "the screen is shorter than dp in the plan");
}

// What a 3D case (tank.dimensions = 3, issue 31) can hold so far: the ISPH scheme in a tank
// extruded over its breadth or an upright cylinder, moved by a translation along
// excitation.direction, with gauges and point pressure probes. Everything else is refused by name
// rather than run as if it were 2D.
// In 2D, excitation.direction can only be the x axis.
void check_dimensions(const CaseSpec& s) {
  auto fail = [&](const std::string& key, const std::string& what) { throw InputError(s.where(key), key, what); };
  if (s.tank.dimensions == 2) {
    if (s.excitation.direction.x != 1.0 || s.excitation.direction.y != 0.0)
      fail("excitation.direction", "is for 3D tanks (tank.dimensions = 3): a 2D tank moves along x only");
    if (s.structure_y)
      fail("structure.y", "is the structure's sway along y, for 3D tanks (tank.dimensions = 3): a 2D tank moves "
                          "along x only");
    if (s.excitation_y)
      fail("excitation.y", "moves the base along y, for 3D tanks (tank.dimensions = 3): a 2D tank moves along x only");
    return;
  }
  if (s.excitation_y && (s.excitation.direction.x != 1.0 || s.excitation.direction.y != 0.0))
    fail("excitation.direction", "with [excitation.y] (the motion along y) [excitation] is the motion along x: remove "
                                 "'direction'");
  if (s.structure && s.locations.count("structure.tank_width"))
    fail("structure.tank_width", "is the width of a 2D section; a 3D tank's forces are the whole tank's (its breadth "
                                 "is tank.breadth): remove it");
  if (s.excitation.type == ExcitationType::pitch && (s.excitation.direction.x != 1.0 || s.excitation.direction.y != 0.0))
    fail("excitation.direction", "is the direction of a translation; a rotation turns about 'axis'");
  for (std::size_t k = 0; k < s.screens.size(); ++k) {  // extruded over the breadth, a cylinder's chord or a plan segment
    const std::string key = "screens." + std::to_string(k);
    const ScreenSpec& sc = s.screens[k];
    if (sc.plan) {  // in a box or a cylinder alike
      check_plan_screen(s, sc, key);
      continue;
    }
    if (sc.plane_y && s.tank.shape != "rectangle" && s.tank.shape != "cylinder")
      fail(key + ".y", "a screen across the breadth (y) is available in a box (shape = \"rectangle\") or a cylinder "
                       "only");
    if (s.tank.shape != "cylinder") continue;
    // In a cylinder: a vertical plane x = c or y = c, over the chord it cuts from the circle.
    if (!sc.plane_y && sc.from.x != sc.to.x)
      fail(key + ".from", "a screen in a cylinder is a vertical plane: give 'x' (the plane x = const) or 'y' (y = "
                          "const), or 'from' and 'to' with the same x");
    const double R = s.tank.radius, plane = sc.plane_y ? *sc.plane_y : sc.from.x;
    if (!(std::abs(plane - R) < R - s.particles.dp)) {
      const std::string axis = sc.plane_y ? "y" : "x";
      fail(key + (sc.plane_y ? ".y" : sc.full_height ? ".x" : ".from"),
           "the screen's plane must cut the cylinder at least dp inside its wall: |" + axis +
               " - radius| < radius - dp (the axis stands at x = y = radius)");
    }
  }
  // A plate spans the breadth of a box or prism (run/plate_coupling.hpp); a cylinder's chords differ.
  if (!s.plates.empty() && s.tank.shape == "cylinder")
    fail("plates", "an elastic plate spans the breadth of a box or prism (its beam bends in the plane (x, z)); a "
                   "cylinder has no plates");
  if (s.tank.breadth < 4.0 * s.particles.dp)
    fail("particles.dp", "too coarse: the tank is fewer than 4 particles across its breadth (tank.breadth = " +
                             std::to_string(s.tank.breadth) + " m)");
}

// Fluid blocks: each inside the tank's extent, at least one particle across, below the wall
// tops; the settled depth (when not given) from the blocks' area, the head from their tops.
// The area counted is that of the lattice particles the blocks will hold (geometry/scene), so
// the settled depth is that of the water actually simulated.
void resolve_fill(CaseSpec& s) {
  FillSpec& f = s.fill;
  if (f.blocks.empty()) return;
  check_particle_estimate(s);
  // A cylinder's blocks are checked against the rectangle 2R x height it stands in (its section
  // in the plane (x, z)), and hold the lattice nodes inside the circle (geometry/cylinder_tank.hpp).
  const bool cylinder = s.tank.shape == "cylinder";
  const TankGeometry tank = make_tank(plane_section(s.tank), s.where("tank.shape"));
  const double dp = s.particles.dp;
  const double top = std::min(tank.wall.front().y, tank.wall.back().y);
  for (std::size_t k = 0; k < f.blocks.size(); ++k) {
    const FluidBlock& b = f.blocks[k];
    const std::string key = "fill.blocks." + std::to_string(k);
    auto fail = [&](const std::string& sub, const std::string& what) {
      throw InputError(s.where(key + "." + sub), key + "." + sub, what);
    };
    std::ostringstream box;
    box << "[" << b.from.x << ", " << b.from.y << "] to [" << b.to.x << ", " << b.to.y << "]";
    if (!(b.to.x > b.from.x && b.to.y > b.from.y))
      fail("to", "must lie above and to the right of `from` (the block is " + box.str() + ")");
    if (b.to.x - b.from.x < dp || b.to.y - b.from.y < dp)
      fail("to", "the block " + box.str() + " is thinner than one particle (dp = " + std::to_string(dp) + " m)");
    if (b.from.x < tank.x_min - 1e-12 || b.to.x > tank.x_max + 1e-12 || b.from.y < tank.y_bottom - 1e-12)
      fail("from", "the block " + box.str() + " reaches outside the tank");
    if (b.to.y >= top)
      fail("to", "the block " + box.str() + " reaches the top of the walls (y = " + std::to_string(top) + " m)");
  }
  const CylinderTank circle = cylinder_of(s.tank);
  const std::size_t count = cylinder ? fill_blocks(circle, dp, f.blocks).size() : fill_blocks(tank, dp, f.blocks).size();
  if (count == 0) throw InputError(s.where("fill.blocks"), "fill.blocks", "no fluid particle fits in the blocks");
  f.block_head = 0.0;
  for (const FluidBlock& b : f.blocks) f.block_head = std::max(f.block_head, b.to.y - tank.y_bottom);
  if (f.depth > 0.0) return;
  if (cylinder) {  // the blocks' water over the circle: below their tops, as the lattice inside it holds less
    f.depth = cylinder_settled_level(circle, count, dp);
    return;
  }
  // Settled depth: section_area(depth) = the blocks' water, by bisection (the area grows with
  // the depth); the wall top bounds it (beyond it, there is more water than the tank holds).
  const double water = static_cast<double>(count) * dp * dp;
  double lo = 0.0, hi = top - tank.y_bottom;
  if (section_area(tank, hi * (1.0 - 1e-9)) < water)
    throw InputError(s.where("fill.blocks"), "fill.blocks", "the blocks hold more water than the tank");
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (section_area(tank, mid) < water ? lo : hi) = mid;
  }
  f.depth = 0.5 * (lo + hi);
}

// time.dt_min, the floor of the adaptive ISPH step: where it binds, the step no longer follows the
// flow's speed and is in effect a fixed one, so it is held to the fixed step's bound `fixed_bound`
// (s). A floor on WCSPH's own CFL step would lift it above its stability limit.
template <class Fail>
void check_step_floor(const CaseSpec& s, double fixed_bound, Fail&& fail) {
  std::ostringstream m;
  if (!s.time.adaptive || s.scheme.type != "isph")
    fail("time.dt_min", "is the floor of the adaptive step of the ISPH scheme: it needs time.adaptive = true and "
                        "scheme.type = \"isph\" (or leave it out)");
  if (s.time.dt_min > s.time.dt) {
    m << s.time.dt_min << " s is above the step's ceiling time.dt = " << s.time.dt << " s";
    fail("time.dt_min", m.str());
  }
  if (s.time.dt_min > fixed_bound) {
    m << s.time.dt_min << " s is above the bound of a fixed step, " << fixed_bound
      << " s (0.4 dp / (sqrt(g depth) + X0 omega), with fill blocks sqrt(2 g head) for sqrt(g depth); 0.125 dp^2 / nu): where the "
         "floor binds, the step is a fixed one";
    fail("time.dt_min", m.str());
  }
}

// Checks that involve several sections.
void check_consistency(const CaseSpec& s, TableReader& root) {
  auto fail = [&](const std::string& key, const std::string& what) {
    throw InputError(s.where(key), key, what);
  };
  (void)root;
  if (s.fill.depth >= s.tank.height)
    fail("fill.depth", "the fluid (" + std::to_string(s.fill.depth) + " m) is deeper than the tank is high (tank.height = " +
                           std::to_string(s.tank.height) + " m)");
  if (s.tank.shape == "polyline" && !s.tank.points.empty()) {
    // tank.height of a polyline is its full extent; the water must stay below the lower of
    // the two wall tops (its first and last points). A wall whose end is its lowest point
    // (top <= 0) is malformed: the tank geometry reports that with a better message.
    double y_min = s.tank.points.front().y;
    for (const Vec2& q : s.tank.points) y_min = std::min(y_min, q.y);
    const double top = std::min(s.tank.points.front().y, s.tank.points.back().y) - y_min;
    if (top > 0.0 && s.fill.depth >= top)
      fail("fill.depth", "the fluid (" + std::to_string(s.fill.depth) + " m) is deeper than the lower wall top of "
                         "tank.points (" + std::to_string(top) + " m above the lowest point)");
    // One pool: the still level crosses the wall exactly twice (counted as the still-water
    // polygon of geometry/tank.cpp counts them, a vertex on the level being above it). Found
    // only at the end of a run otherwise, by the linear modes of the summary.
    const double level = y_min + s.fill.depth;
    int crossings = 0;
    for (std::size_t k = 0; k + 1 < s.tank.points.size(); ++k)
      crossings += (s.tank.points[k].y < level) != (s.tank.points[k + 1].y < level);
    if (top > 0.0 && crossings != 2)
      fail("fill.depth", "the still level (depth " + std::to_string(s.fill.depth) + " m) meets the wall of tank.points " +
                             std::to_string(crossings) + " times: only a single pool with one free surface is supported");
  }
  const double dp = s.particles.dp;
  if (s.fill.blocks.empty() && s.fill.depth < 4.0 * dp)
    fail("particles.dp", "too coarse: the fill depth holds fewer than 4 particle layers (depth / dp = " +
                             std::to_string(s.fill.depth / dp) + ")");
  if (s.tank.length < 8.0 * dp)
    fail("particles.dp", "too coarse: the tank is fewer than 8 particles long");
  check_particle_estimate(s);
  check_dimensions(s);
  // Hard stability bound on a fixed step: CFL 0.4 on the gravity-wave speed plus the
  // base velocity, and the viscous bound 0.125 dp^2 / nu. The thesis's own bound
  // (0.1 dp / u_max, section 2.6.3.2) is the adaptive step's; see docs/case-format.md.
  // With `beta` the frequency is resolved later (it needs the modal solver); beta times the
  // deep-water frequency sqrt(pi g / L), an upper bound of a rectangle's omega1, stands in.
  const double pi = 3.141592653589793;
  const double omega_bound = s.excitation.frequency ? 2.0 * pi * *s.excitation.frequency
                             : s.excitation.beta    ? *s.excitation.beta * std::sqrt(pi * s.fluid.gravity / s.tank.length)
                                                    : 0.0;
  const double base_speed = s.excitation.type == ExcitationType::harmonic ? s.excitation.amplitude * omega_bound : 0.0;
  const double u_ref = fill_speed_scale(s.fill, s.fluid.gravity) + base_speed;
  const double viscous_bound = s.fluid.viscosity > 0.0 ? 0.125 * dp * dp / s.fluid.viscosity : 1e9;
  if (s.time.adaptive && s.scheme.type == "isph") {
    // The adaptive step bounds itself each step by the flow's own speed (cfl dp / u_max) and
    // body force; what can be checked here is the ceiling against the body-force bound with
    // gravity alone, 0.25 sqrt(h / g) (thesis eq. 3.26), so that the first step is not above it.
    const double h = s.particles.kernel_ratio * dp;
    const double force_bound = s.fluid.gravity > 0.0 ? 0.25 * std::sqrt(h / s.fluid.gravity) : 1e9;
    const double dt_max = std::min(force_bound, viscous_bound);
    if (s.time.dt > dt_max) {
      std::ostringstream m;
      m << "time step ceiling " << s.time.dt << " s (adaptive) is above the bound " << dt_max
        << " s (0.25 sqrt(h / g); 0.125 dp^2 / nu)";
      fail("time.dt", m.str());
    }
  } else {
    const double dt_max = std::min(u_ref > 0.0 ? 0.4 * dp / u_ref : 1e9, viscous_bound);
    if (s.time.dt > dt_max) {
      std::ostringstream m;
      m << "time step " << s.time.dt << " s is above the stability bound " << dt_max
        << " s (0.4 dp / (sqrt(g depth) + X0 omega), with fill blocks sqrt(2 g head) for sqrt(g depth); 0.125 dp^2 / nu)";
      fail("time.dt", m.str());
    }
  }
  if (s.time.dt_min > 0.0) check_step_floor(s, std::min(u_ref > 0.0 ? 0.4 * dp / u_ref : 1e9, viscous_bound), fail);
  if (s.output.sample_interval > s.time.end)
    fail("output.sample_interval", "is longer than the simulation (time.end)");
  check_counts(s, fail);
  check_structure_consistency(s);
  if (!s.plates.empty() && s.scheme.type == "wcsph" && s.scheme.wcsph.walls == WallTreatment::repulsive)
    fail("plates", "elastic plates need the Adami wall model (scheme.walls = \"adami\"): Shao's repulsive "
                   "walls do not carry the motion of a moving wall");
  if (!s.plates.empty() && s.structure)
    fail("plates", "elastic plates and [structure] cannot be combined yet");
}

CaseSpec read_root(toml::table& root, const std::string& source, const std::vector<std::string>& overrides) {
  auto context = std::make_shared<TomlContext>();
  context->file = source;
  for (const auto& o : overrides) apply_override(root, o, *context);

  CaseSpec spec;
  spec.source = source;
  spec.name = std::filesystem::path(source).stem().string();
  TableReader r(root, "", context);
  spec.title = r.string("title", "");
  section(r, "fluid", false, [&](TableReader& t) { spec.fluid = read_fluid(t); });
  section(r, "tank", true, [&](TableReader& t) { spec.tank = read_tank(t); });
  section(r, "fill", true, [&](TableReader& t) { spec.fill = read_fill(t); });
  section(r, "particles", true, [&](TableReader& t) { spec.particles = read_particles(t); });
  section(r, "scheme", false, [&](TableReader& t) { spec.scheme = read_scheme(t); });
  section(r, "time", true, [&](TableReader& t) { spec.time = read_time(t); });
  section(r, "excitation", false,
          [&](TableReader& t) { spec.excitation = read_excitation(t, &spec.excitation_y, spec.tank.dimensions); });
  section(r, "probes", false, [&](TableReader& t) { read_probes(t, spec); });
  read_screens(r, spec);
  read_plates(r, spec);
  section(r, "structure", false, [&](TableReader& t) { spec.structure = read_structure(t, spec.structure_y); });
  section(r, "output", false, [&](TableReader& t) { spec.output = read_output(t, spec.tank.dimensions); });
  section(r, "run", false, [&](TableReader& t) { spec.run = read_run(t); });
  r.finish();
  spec.locations = context->locations;
  resolve_fill(spec);
  check_consistency(spec, r);
  return spec;
}

toml::table parse_or_throw(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto line = e.source().begin.line;
    std::string where = source + (line > 0 ? ":" + std::to_string(line) : "");
    throw InputError(where, "", "TOML syntax error: " + std::string(e.description()));
  }
}

}  // namespace

CaseSpec read_case_text(const std::string& text, const std::string& source, const std::vector<std::string>& overrides) {
  toml::table root = parse_or_throw(text, source);
  return read_root(root, source, overrides);
}

std::string case_text_with_overrides(const std::string& text, const std::string& source,
                                     const std::vector<std::string>& overrides) {
  toml::table root = parse_or_throw(text, source);
  TomlContext context;
  context.file = source;
  for (const auto& o : overrides) apply_override(root, o, context);
  std::ostringstream out;
  out << toml::toml_formatter(root) << "\n";
  return out.str();
}

std::string read_case_file_text(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, "", "no such case file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot read the case file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

CaseSpec read_case_file(const std::string& path, const std::vector<std::string>& overrides) {
  return read_case_text(read_case_file_text(path), path, overrides);
}

const std::string& default_case_text() {
  // Liu & Lin (2008) tank as in thesis 2.6.2, shortened: the quick-start case.
  static const std::string text = R"(title = "Built-in default: Liu & Lin (2008) tank at resonance (thesis 2.6.2), 7 s"

[fluid]
density = 1000.0
viscosity = 1.0e-6
gravity = 9.81

[tank]
shape = "rectangle"
length = 0.57
height = 0.3

[fill]
depth = 0.15

[particles]
dp = 0.005
kernel_ratio = 1.4
wall_layers = 2

[scheme]
type = "isph"
alpha = 0.01
pressure = "explicit"

[time]
end = 7.0
dt = 5.0e-4

[excitation]
type = "harmonic"
amplitude = 0.005016   # X0/L = 0.0088
beta = 1.0

[[probes.gauge]]
name = "left"
x = 0.02

[[probes.pressure]]
name = "bottom_centre"
x = 0.285
y = 0.01

[output]
sample_interval = 0.01
snapshot_interval = 0.1
)";
  return text;
}

static toml::table scheme_table(const SchemeSpec& x) {
  toml::table t{{"type", x.type},
                {"neighbour_skin", x.neighbour_skin},
                {"wall_contact", x.wall_contact},
                {"pair_contact", x.pair_contact},
                {"shifting_max", x.shifting_max}};
  if (x.type == "isph") {
    if (x.density_relaxation_time > 0.0) t.insert("density_relaxation_time", x.density_relaxation_time);
    else t.insert("alpha", x.alpha);  // the two exclude each other (read_isph_keys)
    t.insert("pressure", x.pressure == PressureSolve::implicit_krylov ? "implicit" : "explicit");
    t.insert("free_surface", x.free_surface == FreeSurfaceModel::thesis ? "thesis" : "air");
    t.insert("free_surface_threshold", x.free_surface_threshold);
    t.insert("predictor", x.predictor == PositionPredictor::midpoint ? "midpoint" : "euler");
    t.insert("turbulence", x.turbulence);
    t.insert("negative_pressure", x.clip_negative_pressure ? "clip" : "keep");
    t.insert("smagorinsky", x.smagorinsky);
    t.insert("ct", x.ct);
    t.insert("solver_tolerance", x.solver_tolerance);
    t.insert("solver_max_iterations", x.solver_max_iterations);
    t.insert("preconditioner", x.preconditioner == Preconditioner::jacobi ? "jacobi" : "multigrid");
    t.insert("repulsive_walls", x.repulsive_walls);
    t.insert("repulsive_coefficient", x.repulsive_coefficient);
    t.insert("repulsive_range", x.repulsive_range);
    t.insert("shifting", x.shifting == ShiftingModel::lind ? "lind" : "none");
    t.insert("shifting_coefficient", x.shifting_coefficient);
    return t;
  }
  const WcsphSpec& w = x.wcsph;
  t.insert("sound_speed", w.sound_speed);
  t.insert("max_density_variation", w.max_density_variation);
  t.insert("delta", w.delta);
  t.insert("artificial_viscosity", w.artificial_viscosity);
  t.insert("xsph", w.xsph);
  t.insert("kernel_gradient_correction", w.kernel_gradient_correction);
  t.insert("shepard_interval", w.shepard_interval);
  t.insert("turbulence", w.turbulence == WcsphTurbulence::sps           ? "sps"
                         : w.turbulence == WcsphTurbulence::smagorinsky ? "smagorinsky"
                                                                        : "none");
  t.insert("smagorinsky", w.smagorinsky);
  t.insert("walls", w.walls == WallTreatment::repulsive ? "repulsive" : "adami");
  t.insert("integrator", w.integrator == Integrator::leapfrog ? "leapfrog" : "symplectic");
  t.insert("cfl", w.cfl);
  t.insert("shifting", x.shifting == ShiftingModel::delta_plus ? "delta_plus" : "none");
  return t;
}

static toml::table excitation_table(const ExcitationSpec& x) {
  toml::table e;
  auto periodic = [&]() {
    if (x.beta) {
      e.insert("beta", *x.beta);
      e.insert("beta_reference", x.beta_reference == BetaReference::thesis ? "thesis" : "modal");
    } else if (x.frequency) {
      e.insert("frequency", *x.frequency);
    }
    e.insert("ramp", x.ramp);
    e.insert("phase", x.phase);
    e.insert("stop", x.stop);
  };
  switch (x.type) {
    case ExcitationType::harmonic:
      e.insert("type", "harmonic");
      e.insert("amplitude", x.amplitude);
      periodic();
      break;
    case ExcitationType::pitch:
      e.insert("type", "pitch");
      e.insert("pivot", toml::array{x.pivot.x, x.pivot.y});
      if (is_pitch_record(x)) {
        e.insert("file", x.file);
        e.insert("unit", x.value_unit == 1.0 ? "rad" : "deg");
        e.insert("time_scale", x.time_scale);
        e.insert("start", x.start);
        break;
      }
      e.insert("angle", x.angle * 180.0 / 3.141592653589793238);
      periodic();
      break;
    case ExcitationType::record:
      e.insert("type", "record");
      e.insert("file", x.file);
      e.insert("format", x.format);
      e.insert("scale", x.scale);
      if (x.format == "csv") {
        e.insert("unit", x.value_unit == 1.0 ? "m/s2" : "g");
        e.insert("time_scale", x.time_scale);
      }
      e.insert("baseline_correction", x.baseline_correction);
      e.insert("start", x.start);
      break;
    case ExcitationType::pulse:
      e.insert("type", "pulse");
      e.insert("shape", x.shape);
      e.insert("acceleration", x.acceleration);
      e.insert("period", x.period);
      e.insert("start", x.start);
      break;
    case ExcitationType::noise:
      e.insert("type", "noise");
      e.insert("seed", static_cast<std::int64_t>(x.seed));
      e.insert("band", toml::array{x.band_low, x.band_high});
      e.insert("rms", x.rms);
      break;
    case ExcitationType::none:
      e.insert("type", "none");
      break;
  }
  return e;
}

// One sway mode's keys (read_sway_mode).
static toml::table sway_mode_table(const StructureSpec& x) {
  toml::table t{{"mass", x.mass},
                {"stiffness", x.stiffness},
                {"damping", x.damping},
                {"initial_displacement", x.initial_displacement},
                {"initial_velocity", x.initial_velocity}};
  const StructureLoadSpec& l = x.load;
  toml::table load;
  switch (l.type) {
    case StructureLoadType::none:
      load.insert("type", "none");
      break;
    case StructureLoadType::harmonic:
      load.insert("type", "harmonic");
      load.insert("amplitude", l.amplitude);
      load.insert("frequency", l.frequency);
      load.insert("ramp", l.ramp);
      break;
    case StructureLoadType::noise:
      load.insert("type", "noise");
      load.insert("seed", static_cast<std::int64_t>(l.seed));
      load.insert("band", toml::array{l.band_low, l.band_high});
      if (l.target_peak_mg) load.insert("target_peak_mg", *l.target_peak_mg);
      if (l.rms) load.insert("rms", *l.rms);
      load.insert("peak_duration", l.peak_duration);
      break;
    case StructureLoadType::record:
      load.insert("type", "record");
      load.insert("file", l.file);
      load.insert("scale", l.scale);
      load.insert("time_scale", l.time_scale);
      load.insert("start", l.start);
      break;
    case StructureLoadType::pulse:
      load.insert("type", "pulse");
      load.insert("shape", l.shape);
      load.insert("amplitude", l.amplitude);
      load.insert("period", l.period);
      load.insert("start", l.start);
      break;
  }
  t.insert("load", load);
  return t;
}

// [structure] and, in 3D, [structure.y]; a 3D structure has no tank_width (read_structure).
static toml::table structure_table(const CaseSpec& s) {
  const StructureSpec& x = *s.structure;
  toml::table t = sway_mode_table(x);
  if (s.tank.dimensions == 2) t.insert("tank_width", x.tank_width);
  t.insert("tanks", x.tanks);
  t.insert("rigid_mass", x.rigid_mass);
  t.insert("ground", x.ground_from_excitation ? "excitation" : "none");
  if (s.structure_y) t.insert("y", sway_mode_table(*s.structure_y));
  return t;
}

std::string resolved_case_toml(const CaseSpec& s) {
  toml::table root;
  if (!s.title.empty()) root.insert("title", s.title);
  root.insert("fluid", toml::table{{"density", s.fluid.density}, {"viscosity", s.fluid.viscosity}, {"gravity", s.fluid.gravity}});
  toml::table tank{{"shape", s.tank.shape}};
  const bool three_d = s.tank.dimensions == 3;  // 2D cases keep the case.toml they had before issue 31
  if (three_d) tank.insert("dimensions", 3);
  if (three_d && s.tank.shape != "cylinder") tank.insert("breadth", s.tank.breadth);
  if (s.tank.shape == "cylinder") {
    tank.insert("radius", s.tank.radius);
    tank.insert("height", s.tank.height);
  } else if (s.tank.shape == "polyline") {
    toml::array pts;
    for (const Vec2& q : s.tank.points) pts.push_back(toml::array{q.x, q.y});
    tank.insert("points", pts);
  } else {
    tank.insert("length", s.tank.length);
    tank.insert("height", s.tank.height);
  }
  if (s.tank.shape == "parabolic") tank.insert("coefficient", s.tank.coefficient);
  if (s.tank.shape == "sloped" || s.tank.shape == "triangle" || s.tank.shape == "trapezoid") tank.insert("angle", s.tank.angle);
  if (s.tank.shape == "sloped" || s.tank.shape == "trapezoid") tank.insert("bottom_width", s.tank.bottom_width);
  root.insert("tank", tank);
  toml::table fill{{"depth", s.fill.depth}};
  if (!s.fill.blocks.empty()) {
    toml::array blocks;
    for (const FluidBlock& b : s.fill.blocks)
      blocks.push_back(toml::table{{"from", toml::array{b.from.x, b.from.y}}, {"to", toml::array{b.to.x, b.to.y}}});
    fill.insert("blocks", blocks);
  }
  root.insert("fill", fill);
  root.insert("particles", toml::table{{"dp", s.particles.dp},
                                       {"kernel_ratio", s.particles.kernel_ratio},
                                       {"wall_layers", s.particles.wall_layers},
                                       {"kernel", s.particles.kernel == KernelType::cubic_spline ? "cubic_spline" : "wendland"}});
  root.insert("scheme", scheme_table(s.scheme));
  toml::table time{{"end", s.time.end}, {"dt", s.time.dt}, {"adaptive", s.time.adaptive}, {"cfl", s.time.cfl},
                   {"settle", s.time.settle}};
  // Only when set: the resolved case of a case without it stays as before (the committed run
  // records' case.toml are compared with it as text).
  if (s.time.dt_min > 0.0) time.insert("dt_min", s.time.dt_min);
  root.insert("time", std::move(time));
  if (s.excitation.type != ExcitationType::none || s.excitation_y) {
    toml::table excitation = excitation_table(s.excitation);
    if (three_d) excitation.insert("direction", toml::array{s.excitation.direction.x, s.excitation.direction.y});
    if (three_d && s.excitation.type == ExcitationType::pitch) {  // the 3D pivot (x, y, z) and axis
      const ExcitationSpec& x = s.excitation;
      excitation.insert_or_assign("pivot", toml::array{x.pivot.x, x.pivot_across, x.pivot.y});
      excitation.insert("axis", toml::array{x.axis.x, x.axis.y, x.axis.z});
    }
    if (s.excitation_y) excitation.insert("y", excitation_table(*s.excitation_y));
    root.insert("excitation", excitation);
  }
  toml::array gauges, pressures;
  for (const auto& g : s.gauges) {
    toml::table gauge{{"name", g.name}, {"x", g.x}};
    if (three_d) gauge.insert("y", g.across);
    gauges.push_back(gauge);
  }
  for (const auto& p : s.pressure_probes) {
    toml::table probe = three_d ? toml::table{{"name", p.name}, {"x", p.position.x}, {"y", p.across}, {"z", p.position.y}}
                                : toml::table{{"name", p.name}, {"x", p.position.x}, {"y", p.position.y}};
    if (p.face_end) probe.insert("to", toml::array{p.face_end->x, p.face_end->y});
    if (p.size > 0.0) probe.insert("size", p.size);
    pressures.push_back(probe);
  }
  toml::array fronts;
  for (const auto& f : s.fronts)
    fronts.push_back(toml::table{{"name", f.name}, {"band", f.band}, {"direction", f.rightward ? "right" : "left"}});
  toml::table probes;
  if (!gauges.empty()) probes.insert("gauge", gauges);
  if (!pressures.empty()) probes.insert("pressure", pressures);
  if (!fronts.empty()) probes.insert("front", fronts);
  if (!probes.empty()) root.insert("probes", probes);
  toml::array screens;
  for (const ScreenSpec& sc : s.screens) {
    toml::table t{{"name", sc.name}};
    if (sc.plan) {
      t.insert("plan_from", toml::array{sc.plan->first.x, sc.plan->first.y});
      t.insert("plan_to", toml::array{sc.plan->second.x, sc.plan->second.y});
    } else if (sc.plane_y) {
      t.insert("y", *sc.plane_y);
    } else if (sc.full_height) {
      t.insert("x", sc.from.x);
    } else {
      t.insert("from", toml::array{sc.from.x, sc.from.y});
      t.insert("to", toml::array{sc.to.x, sc.to.y});
    }
    t.insert("model", screen_model_name(sc.model));
    // A solidity derived from the slats is left to be derived again: written out, it would be
    // range-checked as a given solidity (< 0.999) and a solid baffle's copy would be refused.
    const bool derived = sc.slat_height > 0.0 && sc.slat_gap > 0.0 &&
                         sc.solidity == sc.slat_height / (sc.slat_height + sc.slat_gap);
    if (!derived) t.insert("solidity", sc.solidity);
    if (sc.slat_height > 0.0) t.insert("slat_height", sc.slat_height);
    if (sc.slat_gap > 0.0) t.insert("slat_gap", sc.slat_gap);
    t.insert("thickness", sc.thickness);
    t.insert("spacing", sc.spacing);
    t.insert("interaction_radius", sc.interaction_radius);
    if (sc.model != ScreenModel::explicit_slats) t.insert("velocity", sc.shepard_velocity ? "shepard" : "thesis");
    if (sc.model == ScreenModel::morison) t.insert("loss_coefficient", sc.loss_coefficient);
    screens.push_back(t);
  }
  if (!screens.empty()) root.insert("screens", screens);
  toml::array plates;
  auto support_name = [](PlateSupport v) {
    return v == PlateSupport::clamped ? "clamped" : v == PlateSupport::pinned ? "pinned" : "free";
  };
  for (const PlateSpec& pl : s.plates) {
    toml::table t{{"name", pl.name}};
    if (pl.standing_height > 0.0) {
      t.insert("x", pl.from.x);
      t.insert("height", pl.standing_height);
    } else {
      t.insert("from", toml::array{pl.from.x, pl.from.y});
      t.insert("to", toml::array{pl.to.x, pl.to.y});
    }
    t.insert("thickness", pl.thickness);
    t.insert("youngs_modulus", pl.youngs_modulus);
    t.insert("density", pl.density);
    t.insert("poisson_ratio", pl.poisson_ratio);
    t.insert("elements", pl.elements);
    t.insert("from_support", support_name(pl.from_support));
    t.insert("to_support", support_name(pl.to_support));
    t.insert("rayleigh_mass", pl.rayleigh_mass);
    t.insert("rayleigh_stiffness", pl.rayleigh_stiffness);
    t.insert("hht_alpha", pl.hht_alpha);
    plates.push_back(t);
  }
  if (!plates.empty()) root.insert("plates", plates);
  if (s.structure) root.insert("structure", structure_table(s));
  toml::table output{{"sample_interval", s.output.sample_interval},
                     {"snapshot_interval", s.output.snapshot_interval},
                     {"snapshot_walls", s.output.snapshot_walls},
                     {"response_cycles", s.output.response_cycles},
                     {"lowpass_hz", s.output.lowpass_hz}};
  if (const std::optional<Vec3>& m = s.output.moment_point)
    output.insert("moment_point", three_d ? toml::array{m->x, m->y, m->z} : toml::array{m->x, m->y});
  root.insert("output", output);
  root.insert("run", toml::table{{"max_leaked_fraction", s.run.max_leaked_fraction},
                                 {"max_speed_factor", s.run.max_speed_factor}});
  std::ostringstream out;
  out << "# Resolved case: every key with its value in force (defaults filled in).\n";
  out << "# Source: " << s.source << "\n";
  if (s.excitation.omega > 0.0) out << "# Excitation angular frequency in force: " << s.excitation.omega << " rad/s\n";
  out << "\n" << root << "\n";
  return out.str();
}

}  // namespace sloshsph
