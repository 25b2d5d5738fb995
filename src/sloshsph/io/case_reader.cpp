#include "sloshsph/io/case_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "sloshsph/core/errors.hpp"
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

// Shape-specific keys are read only for their shape, so a key of another shape is an
// "unknown key" error rather than silently ignored.
TankSpec read_tank(TableReader& r) {
  TankSpec t;
  t.shape = r.choice("shape", t.shape, {"rectangle", "sloped", "triangle", "trapezoid", "parabolic", "circular", "polyline"});
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
  p.wall_layers = static_cast<int>(r.integer("wall_layers", p.wall_layers, 1, 8));
  p.kernel = r.choice("kernel", "wendland", {"wendland", "cubic_spline"}) == "cubic_spline" ? KernelType::cubic_spline
                                                                                               : KernelType::wendland_c2;
  r.finish();
  return p;
}

SchemeSpec read_scheme(TableReader& r) {
  SchemeSpec s;
  s.type = r.choice("type", s.type, {"isph"});
  s.alpha = r.in_range("alpha", s.alpha, 0.0, 1.0);
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
  s.turbulence = r.boolean("turbulence", s.turbulence);
  s.smagorinsky = r.in_range("smagorinsky", s.smagorinsky, 0.0, 1.0);
  s.ct = r.positive("ct", s.ct);
  s.solver_tolerance = r.in_range("solver_tolerance", s.solver_tolerance, 1e-14, 1e-1);
  s.solver_max_iterations = static_cast<int>(r.integer("solver_max_iterations", s.solver_max_iterations, 1, 1000000));
  s.neighbour_skin = r.in_range("neighbour_skin", s.neighbour_skin, 0.0, 1.0);
  r.finish();
  return s;
}

TimeSpec read_time(TableReader& r) {
  TimeSpec t;
  t.end = r.positive("end");
  t.dt = r.positive("dt", t.dt);
  t.adaptive = r.boolean("adaptive", t.adaptive);
  t.cfl = r.in_range("cfl", t.cfl, 1e-3, 0.5);
  t.settle = r.non_negative("settle", t.settle);
  r.finish();
  return t;
}

ExcitationSpec read_excitation(TableReader& r) {
  ExcitationSpec e;
  const std::string type = r.choice("type", "harmonic", {"none", "harmonic"});
  if (type == "none") {
    r.finish();
    return e;
  }
  e.type = ExcitationType::harmonic;
  if (!r.has("amplitude")) r.fail("amplitude", "is required for a harmonic excitation (m)");
  e.amplitude = r.non_negative("amplitude", 0.0);
  e.frequency = r.optional_positive("frequency");
  e.beta = r.optional_positive("beta");
  if (e.frequency && e.beta) r.fail("beta", "give either 'frequency' (Hz) or 'beta', not both");
  if (!e.frequency && !e.beta) r.fail("frequency", "a harmonic excitation needs 'frequency' (Hz) or 'beta' (ratio to the first sloshing frequency)");
  if (e.beta)
    e.beta_reference = r.choice("beta_reference", "modal", {"modal", "thesis"}) == "thesis" ? BetaReference::thesis
                                                                                           : BetaReference::modal;
  e.ramp = r.non_negative("ramp", e.ramp);
  e.phase = r.number("phase", e.phase);
  e.stop = r.number("stop", e.stop);
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
    g.finish();
    spec.gauges.push_back(gs);
  }
  names.clear();
  for (TableReader& p : r.array_of_tables("pressure")) {
    PressureProbeSpec ps;
    ps.name = p.string("name");
    check_name(p, "name", ps.name, names);
    ps.position = {p.number("x"), p.number("y")};
    p.finish();
    spec.pressure_probes.push_back(ps);
  }
  r.finish();
}

OutputSpec read_output(TableReader& r) {
  OutputSpec o;
  o.sample_interval = r.positive("sample_interval", o.sample_interval);
  o.snapshot_interval = r.non_negative("snapshot_interval", o.snapshot_interval);
  o.snapshot_walls = r.boolean("snapshot_walls", o.snapshot_walls);
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

// Checks that involve several sections.
void check_consistency(const CaseSpec& s, TableReader& root) {
  auto fail = [&](const std::string& key, const std::string& what) {
    throw InputError(s.where(key), key, what);
  };
  (void)root;
  if (s.fill.depth >= s.tank.height)
    fail("fill.depth", "the fluid (" + std::to_string(s.fill.depth) + " m) is deeper than the tank is high (tank.height = " +
                           std::to_string(s.tank.height) + " m)");
  const double dp = s.particles.dp;
  if (s.fill.depth < 4.0 * dp)
    fail("particles.dp", "too coarse: the fill depth holds fewer than 4 particle layers (depth / dp = " +
                             std::to_string(s.fill.depth / dp) + ")");
  if (s.tank.length < 8.0 * dp)
    fail("particles.dp", "too coarse: the tank is fewer than 8 particles long");
  const double estimate = (s.tank.length + 2.0 * s.particles.wall_layers * dp) *
                          (s.tank.height + s.particles.wall_layers * dp) / (dp * dp);
  if (estimate > 2.0e7)
    fail("particles.dp", "would need about " + std::to_string(static_cast<long long>(estimate)) +
                             " particles (limit 2e7 in 2D): is dp in metres?");
  // Hard stability bound on a fixed step: CFL 0.4 on the gravity-wave speed plus the
  // base velocity, and the viscous bound 0.125 dp^2 / nu. The thesis's own bound
  // (0.1 dp / u_max, section 2.6.3.2) is the adaptive step's; see docs/case-format.md.
  const double u_ref = std::sqrt(s.fluid.gravity * s.fill.depth) + s.excitation.amplitude * 2.0 * 3.141592653589793 *
                                                                        s.excitation.frequency.value_or(0.0);
  const double dt_max = std::min(u_ref > 0.0 ? 0.4 * dp / u_ref : 1e9,
                                 s.fluid.viscosity > 0.0 ? 0.125 * dp * dp / s.fluid.viscosity : 1e9);
  if (s.time.dt > dt_max) {
    std::ostringstream m;
    m << "time step " << s.time.dt << " s is above the stability bound " << dt_max
      << " s (0.4 dp / sqrt(g depth), 0.125 dp^2 / nu)";
    fail("time.dt", m.str());
  }
  if (s.output.sample_interval > s.time.end)
    fail("output.sample_interval", "is longer than the simulation (time.end)");
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
  section(r, "fill", true, [&](TableReader& t) {
    spec.fill.depth = t.positive("depth");
    t.finish();
  });
  section(r, "particles", true, [&](TableReader& t) { spec.particles = read_particles(t); });
  section(r, "scheme", false, [&](TableReader& t) { spec.scheme = read_scheme(t); });
  section(r, "time", true, [&](TableReader& t) { spec.time = read_time(t); });
  section(r, "excitation", false, [&](TableReader& t) { spec.excitation = read_excitation(t); });
  section(r, "probes", false, [&](TableReader& t) { read_probes(t, spec); });
  section(r, "output", false, [&](TableReader& t) { spec.output = read_output(t); });
  section(r, "run", false, [&](TableReader& t) { spec.run = read_run(t); });
  r.finish();
  spec.locations = context->locations;
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

CaseSpec read_case_file(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, "", "no such case file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot read the case file");
  std::ostringstream text;
  text << in.rdbuf();
  return read_case_text(text.str(), path, overrides);
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

std::string resolved_case_toml(const CaseSpec& s) {
  toml::table root;
  if (!s.title.empty()) root.insert("title", s.title);
  root.insert("fluid", toml::table{{"density", s.fluid.density}, {"viscosity", s.fluid.viscosity}, {"gravity", s.fluid.gravity}});
  toml::table tank{{"shape", s.tank.shape}};
  if (s.tank.shape == "polyline") {
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
  root.insert("fill", toml::table{{"depth", s.fill.depth}});
  root.insert("particles", toml::table{{"dp", s.particles.dp},
                                       {"kernel_ratio", s.particles.kernel_ratio},
                                       {"wall_layers", s.particles.wall_layers},
                                       {"kernel", s.particles.kernel == KernelType::cubic_spline ? "cubic_spline" : "wendland"}});
  root.insert("scheme", toml::table{{"type", s.scheme.type},
                                    {"alpha", s.scheme.alpha},
                                    {"pressure", s.scheme.pressure == PressureSolve::implicit_krylov ? "implicit" : "explicit"},
                                    {"free_surface", s.scheme.free_surface == FreeSurfaceModel::thesis ? "thesis" : "air"},
                                    {"free_surface_threshold", s.scheme.free_surface_threshold},
                                    {"turbulence", s.scheme.turbulence},
                                    {"smagorinsky", s.scheme.smagorinsky},
                                    {"ct", s.scheme.ct},
                                    {"solver_tolerance", s.scheme.solver_tolerance},
                                    {"solver_max_iterations", s.scheme.solver_max_iterations},
                                    {"neighbour_skin", s.scheme.neighbour_skin}});
  root.insert("time", toml::table{{"end", s.time.end}, {"dt", s.time.dt}, {"adaptive", s.time.adaptive}, {"cfl", s.time.cfl},
                                  {"settle", s.time.settle}});
  if (s.excitation.type == ExcitationType::harmonic) {
    toml::table e{{"type", "harmonic"}, {"amplitude", s.excitation.amplitude}, {"ramp", s.excitation.ramp},
                  {"phase", s.excitation.phase}, {"stop", s.excitation.stop}};
    if (s.excitation.beta) {
      e.insert("beta", *s.excitation.beta);
      e.insert("beta_reference", s.excitation.beta_reference == BetaReference::thesis ? "thesis" : "modal");
    }
    if (s.excitation.frequency) e.insert("frequency", *s.excitation.frequency);
    root.insert("excitation", e);
  }
  toml::array gauges, pressures;
  for (const auto& g : s.gauges) gauges.push_back(toml::table{{"name", g.name}, {"x", g.x}});
  for (const auto& p : s.pressure_probes)
    pressures.push_back(toml::table{{"name", p.name}, {"x", p.position.x}, {"y", p.position.y}});
  toml::table probes;
  if (!gauges.empty()) probes.insert("gauge", gauges);
  if (!pressures.empty()) probes.insert("pressure", pressures);
  if (!probes.empty()) root.insert("probes", probes);
  root.insert("output", toml::table{{"sample_interval", s.output.sample_interval},
                                    {"snapshot_interval", s.output.snapshot_interval},
                                    {"snapshot_walls", s.output.snapshot_walls}});
  root.insert("run", toml::table{{"max_leaked_fraction", s.run.max_leaked_fraction},
                                 {"max_speed_factor", s.run.max_speed_factor}});
  std::ostringstream out;
  out << "# Resolved case: every key with its value in force (defaults filled in).\n";
  out << "# Source: " << s.source << "\n";
  if (s.excitation.type == ExcitationType::harmonic)
    out << "# Excitation angular frequency in force: " << s.excitation.omega << " rad/s\n";
  out << "\n" << root << "\n";
  return out.str();
}

}  // namespace sloshsph
