#include "sloshsph/geometry/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/prism_tank.hpp"
#include "sloshsph/geometry/screens.hpp"

namespace sloshsph {
namespace {

void check_gauges(const CaseSpec& spec, const TankGeometry& tank) {
  for (std::size_t k = 0; k < spec.gauges.size(); ++k) {
    const std::string key = "probes.gauge." + std::to_string(k) + ".x";
    const double x = spec.gauges[k].x;
    if (x <= tank.x_min || x >= tank.x_max) {
      std::ostringstream m;
      m << "gauge '" << spec.gauges[k].name << "' at x = " << x << " m is outside the tank (" << tank.x_min << " < x < "
        << tank.x_max << ")";
      throw InputError(spec.where(key), key, m.str());
    }
  }
}

// A face of length `size` centred on `centre`, along the wall segment nearest to it: where a
// flush-mounted transducer of that diameter sits (in 2D its face is a segment of the wall).
PressureSensor face_on_wall(const TankGeometry& tank, Vec2 centre, double size) {
  const std::size_t k = tank.nearest_segment(centre);
  const Vec2 along = normalized(tank.wall[k + 1] - tank.wall[k]);
  return {centre - 0.5 * size * along, centre + 0.5 * size * along, true};
}

// Resolves each [[probes.pressure]] to where it reads (a point, a face from `to`, or a face of
// `size` on the nearest wall) and checks that it lies in the tank.
std::vector<PressureSensor> pressure_sensors(const CaseSpec& spec, const TankGeometry& tank) {
  std::vector<PressureSensor> sensors;
  const double dp = spec.particles.dp;
  for (std::size_t k = 0; k < spec.pressure_probes.size(); ++k) {
    const auto& probe = spec.pressure_probes[k];
    const std::string prefix = "probes.pressure." + std::to_string(k) + ".";
    // A probe may sit on the wall surface or in the first wall layer (thesis 5.5.1), not beyond;
    // so may both ends of a sensor face.
    const auto outside = [&](Vec2 p) { return tank.signed_distance(p) < -dp || p.y > tank.y_top; };
    const auto fail = [&](const std::string& field, Vec2 p, const char* what) {
      std::ostringstream m;
      m << "pressure probe '" << probe.name << "'" << what << " (" << p.x << ", " << p.y << ") m is outside the tank";
      throw InputError(spec.where(prefix + field), prefix + field, m.str());
    };
    if (outside(probe.position)) fail("x", probe.position, " at");
    PressureSensor sensor{probe.position, probe.position, false};
    if (probe.face_end) {
      sensor = {probe.position, *probe.face_end, true};
      if (outside(*probe.face_end)) fail("to", *probe.face_end, ": the end of its face,");
    } else if (probe.size > 0.0) {
      const double off = std::abs(tank.signed_distance(probe.position));
      if (off > dp) {
        std::ostringstream m;
        m << "pressure probe '" << probe.name << "' at (" << probe.position.x << ", " << probe.position.y << ") m is "
          << off << " m from the nearest wall: a sensor face ('size') lies on a wall, so (x, y) must be within dp = "
          << dp << " m of the wall surface (or give the face's ends with 'to')";
        throw InputError(spec.where(prefix + "size"), prefix + "size", m.str());
      }
      sensor = face_on_wall(tank, probe.position, probe.size);
      for (const Vec2 end : {sensor.from, sensor.to})
        if (outside(end)) fail("size", end, ": an end of its face along the wall,");
    }
    sensors.push_back(sensor);
  }
  return sensors;
}

// The thesis free surface (p = 0 on flagged particles) with the implicit solve has run away
// within a few dozen steps when dt sqrt(g/dp) was 0.031 (linear_sloshing.toml at dp = 10 mm,
// dt = 1 ms: step 50-65) and 0.050 (building_sf_10mg.toml: dp = 0.1 m, dt = 5 ms, within 0.15 s of
// the settle), and ran at 0.022 (dp = 5 mm, dt = 0.5 ms) and 0.0099 (dp = 0.1 m, dt = 1 ms).
// Measured 2026-12-04 (docs/validation/notes.md); an empirical bound, not a stability theory.
void add_time_step_warnings(const CaseSpec& spec, std::vector<std::string>& warnings) {
  constexpr double kThesisImplicitBound = 0.025;
  const SchemeSpec& sc = spec.scheme;
  if (sc.type != "isph" || sc.pressure != PressureSolve::implicit_krylov || sc.free_surface != FreeSurfaceModel::thesis)
    return;
  const double rate = std::sqrt(spec.fluid.gravity / spec.particles.dp);  // 1/s
  const double ratio = spec.time.dt * rate;
  if (ratio <= kThesisImplicitBound) return;
  char text[400];
  std::snprintf(text, sizeof text,
                "scheme.free_surface = \"thesis\" with the implicit solve has run away at time.dt * sqrt(g / dp) "
                "of 0.031 and above (here %.3g); it ran at 0.022 and below: consider time.dt <= %.3g s, or the "
                "default free surface \"air\"",
                ratio, kThesisImplicitBound / rate);
  warnings.push_back(text);
}

// The particles of a fill hold n dp^2 of water, and the lattice (spacing dp from the left end of
// the section, rows from the bottom, particles at least dp/2 inside the wall) fills the section
// below fill.depth exactly only when dp divides its length and depth: otherwise a gap is left at
// the right wall and under the level, the water settles lower than fill.depth, and a start from
// rest begins with the collapse of the gap (found 2026-12-06: dp = 8 mm in the 0.5 m tank of
// linear_sloshing.toml left 4 mm at the right wall and 2 mm under the level; the gauges then read
// about -2 mm at rest and the right one dropped 3 mm in the first 0.05 s). Warned when the level
// comes out more than dp/5 low.
void add_fill_warning(const CaseSpec& spec, const TankGeometry& tank, std::size_t particles,
                      std::vector<std::string>& warnings) {
  const double dp = spec.particles.dp, depth = spec.fill.depth;
  const std::vector<Vec2> section = still_water_polygon(tank, depth);
  double x_low = section.front().x, x_high = x_low;
  for (const Vec2& v : section)
    if (v.y >= tank.y_bottom + depth - 1e-12) x_low = std::min(x_low, v.x), x_high = std::max(x_high, v.x);
  const double width = x_high - x_low;
  const double area = section_area(tank, depth);
  const double missing = area - static_cast<double>(particles) * dp * dp;
  if (!(width > 0.0) || missing <= 0.2 * dp * width) return;
  const double low = missing / width;
  char advice[200];
  if (spec.tank.shape == "rectangle")
    std::snprintf(advice, sizeof advice, "a dp that divides both the length (%.6g m) and the depth avoids it",
                  spec.tank.length);
  else
    std::snprintf(advice, sizeof advice, "a fill.depth of about %.6g m holds the water of %.6g m", depth + low,
                  depth);
  char text[600];
  std::snprintf(text, sizeof text,
                "fill.depth: the %zu particles hold %.3g%% less water than the section below %.6g m (the lattice of "
                "spacing dp = %.6g m does not reach the walls and the level): the water settles about %.3g m lower, "
                "at %.6g m, and a start from rest begins by filling the gap; %s",
                particles, 100.0 * missing / area, depth, dp, low, depth - low, advice);
  warnings.push_back(text);
}

// 3D: each gauge's vertical line (x, y) inside the tank's plan, each probe inside the tank (or in
// its first wall layer, as in 2D) and below the top of the walls. `distance` is the tank's signed
// distance.
template <class Distance>
void check_probes_3d(const CaseSpec& spec, const Distance& distance, double top) {
  for (std::size_t k = 0; k < spec.gauges.size(); ++k) {
    const GaugeSpec& g = spec.gauges[k];
    if (!(distance(Vec3{g.x, g.across, 0.5 * top}) > 0.0)) {
      const std::string key = "probes.gauge." + std::to_string(k) + ".x";
      std::ostringstream m;
      m << "gauge '" << g.name << "' at (x, y) = (" << g.x << ", " << g.across << ") m is outside the tank";
      throw InputError(spec.where(key), key, m.str());
    }
  }
  for (std::size_t k = 0; k < spec.pressure_probes.size(); ++k) {
    const PressureProbeSpec& probe = spec.pressure_probes[k];
    const Vec3 at = at_breadth(probe.position, probe.across);
    if (distance(at) < -spec.particles.dp || at.z > top) {
      const std::string key = "probes.pressure." + std::to_string(k) + ".x";
      std::ostringstream m;
      m << "pressure probe '" << probe.name << "' at (" << at.x << ", " << at.y << ", " << at.z << ") m is outside the tank";
      throw InputError(spec.where(key), key, m.str());
    }
  }
}

// 3D: the lattice across the breadth has floor(breadth / dp) planes; a remainder leaves a gap of
// water at the far end wall, as add_fill_warning's gap does in the section.
void add_breadth_warning(const CaseSpec& spec, std::vector<std::string>& warnings) {
  const double dp = spec.particles.dp, breadth = spec.tank.breadth;
  const double gap = breadth - std::floor(breadth / dp + 1e-9) * dp;
  if (gap <= 0.2 * dp) return;
  char text[300];
  std::snprintf(text, sizeof text,
                "tank.breadth: the lattice of spacing dp = %.6g m fills %.6g m of the breadth %.6g m; the water "
                "begins by filling the gap of %.3g m at the end wall y = breadth (a dp that divides the breadth avoids it)",
                dp, breadth - gap, breadth, gap);
  warnings.push_back(text);
}

// The parts of a 3D scene that do not depend on the tank's shape: the probes' points, the time-step
// warnings, and the particles at rest below `still_level` from the fluid and wall samples.
Scene3 three_d_scene(const CaseSpec& spec, std::shared_ptr<const TankGeometry> tank, double breadth, double still_level,
                     const std::vector<Vec3>& fluid, const std::vector<WallSample3>& walls) {
  if (fluid.empty()) throw InputError(spec.where("fill.depth"), "fill.depth", "no fluid particle fits in the tank");
  Scene3 scene;
  scene.tank = std::move(tank);
  scene.breadth = breadth;
  for (const PressureProbeSpec& probe : spec.pressure_probes) {
    const Vec3 at = at_breadth(probe.position, probe.across);
    scene.pressure_sensors.push_back({at, at, false});
  }
  add_time_step_warnings(spec, scene.warnings);
  scene.dp = spec.particles.dp;
  scene.h = spec.particles.kernel_ratio * spec.particles.dp;
  scene.still_level = still_level;
  scene.particles = particles_at_rest<3>(fluid, walls, scene.dp, still_level, spec.fluid.density, spec.fluid.gravity);
  scene.initial_fluid_count = scene.particles.n_fluid;
  scene.initial_fluid_mass = scene.particles.mass * static_cast<double>(scene.particles.n_fluid);
  return scene;
}

// Screen k of the case: a full-height screen runs from the bottom to the top of the walls at its x.
static ScreenSpec resolved_screen(const CaseSpec& spec, const TankGeometry& tank, std::size_t k) {
  ScreenSpec sc = spec.screens[k];
  if (sc.full_height) {
    const std::string key = "screens." + std::to_string(k);
    if (sc.from.x <= tank.x_min || sc.from.x >= tank.x_max)
      throw InputError(spec.where(key + ".x"), key + ".x", "the screen is outside the tank");
    sc.from = {sc.from.x, tank.bottom_at(sc.from.x)};
    sc.to = {sc.from.x, tank.y_top};
  }
  return sc;
}

// An upright cylinder: the fluid on the cubic lattice inside it, its side and bottom walls; the
// scene's section is the rectangle 2R x height it stands in. Screens (ergun and morison, vertical:
// the case reader refuses others) are extruded over the chord their plane cuts by the driver.
Scene3 build_cylinder_scene(const CaseSpec& spec) {
  const CylinderTank cylinder{spec.tank.radius, spec.tank.height};
  TankSpec box = spec.tank;
  box.shape = "rectangle";
  auto tank = std::make_shared<TankGeometry>(make_tank(box, spec.where("tank.radius")));
  check_probes_3d(spec, [&cylinder](Vec3 p) { return cylinder.signed_distance(p); }, tank->y_top);
  const double dp = spec.particles.dp;
  Scene3 scene = three_d_scene(spec, tank, 2.0 * cylinder.radius, spec.fill.depth, fill_fluid(cylinder, dp, spec.fill.depth),
                               sample_walls(cylinder, dp, spec.particles.wall_layers));
  scene.cylinder = cylinder;
  for (std::size_t k = 0; k < spec.screens.size(); ++k) scene.screens.push_back(resolved_screen(spec, *tank, k));
  // The fill holds the water of fill.depth (fill_fluid): above the depth at first, it settles into
  // the ring of gaps the square lattice leaves along the round wall.
  return scene;
}

}  // namespace

// A fluid particle is kept clear of slats and plates: no closer than 0.9 dp to one of their particles.
static bool clear_of(Vec2 f, const std::vector<WallSample>& solids, double dp) {
  for (const WallSample& w : solids)
    if (norm2(f - w.position) < 0.81 * dp * dp) return false;
  return true;
}

// Explicit slats across the breadth of a box (issue 31): `section_walls`, the slat walls of a vertical
// screen at x = x_line in the section (x, z), turned so that x - x_line runs along y from y = plane_y
// (normals (0, n_x, n_z)), on the fill lattice's lines x = x_min + (i + 1/2) dp along the length; the
// fluid is kept 0.9 dp clear of them in that turned plane.
static void add_slats_across(const std::vector<WallSample>& section_walls, double x_line, double plane_y,
                             const TankGeometry& section, double dp, std::vector<Vec3>& fluid,
                             std::vector<WallSample3>& walls) {
  const int n_x = static_cast<int>(std::floor((section.x_max - section.x_min) / dp + 1e-9));
  for (const WallSample& w : section_walls)
    for (int i = 0; i < n_x; ++i)
      walls.push_back({{section.x_min + (i + 0.5) * dp, plane_y + (w.position.x - x_line), w.position.y},
                       {0.0, w.normal.x, w.normal.y}});
  std::vector<Vec3> kept;
  for (const Vec3& f : fluid)
    if (clear_of({x_line + (f.y - plane_y), f.z}, section_walls, dp)) kept.push_back(f);
  fluid.swap(kept);
}

Scene3 build_scene3(const CaseSpec& spec) {
  if (spec.tank.shape == "cylinder") return build_cylinder_scene(spec);
  auto tank = std::make_shared<TankGeometry>(make_tank(spec.tank, spec.where("tank.shape")));
  const PrismTank prism{*tank, spec.tank.breadth};
  check_probes_3d(spec, [&prism](Vec3 p) { return prism.signed_distance(p); }, tank->y_top);
  const double dp = spec.particles.dp;
  const std::vector<FluidBlock>& blocks = spec.fill.blocks;  // each over the whole breadth
  const std::vector<Vec2> section_fluid =
      blocks.empty() ? fill_fluid(*tank, dp, spec.fill.depth) : fill_blocks(*tank, dp, blocks);
  std::vector<Vec3> fluid = on_planes_across(prism, dp, section_fluid);
  std::vector<WallSample3> walls = sample_walls(prism, dp, spec.particles.wall_layers);
  // Screens: ergun and morison elements are extruded over the breadth by the driver
  // (physics/porous.hpp); explicit slats are the section's slat walls on every plane across it, or,
  // across the breadth (plane_y, boxes), the slat walls of the section's vertical screen at x_line
  // turned into the plane y = plane_y and repeated along the length.
  std::vector<ScreenSpec> screens;
  std::vector<WallSample> slats;
  std::vector<std::string> warnings;
  for (std::size_t k = 0; k < spec.screens.size(); ++k) {
    const ScreenSpec sc = resolved_screen(spec, *tank, k);
    const std::string key = "screens." + std::to_string(k);
    if (sc.model == ScreenModel::explicit_slats) {
      SlatLayout layout = explicit_slat_layout(sc, dp, *tank, spec.where(key + ".model"), key);
      if (sc.plane_y) add_slats_across(layout.walls, sc.from.x, *sc.plane_y, *tank, dp, fluid, walls);
      else slats.insert(slats.end(), layout.walls.begin(), layout.walls.end());
      for (const std::string& w : layout.warnings) warnings.push_back("screen '" + sc.name + "': " + w);
    }
    screens.push_back(sc);
  }
  if (!slats.empty()) {
    const std::vector<WallSample3> extruded = extrude_inside(slats, prism, dp);
    walls.insert(walls.end(), extruded.begin(), extruded.end());
    std::vector<Vec3> kept;  // the slats stand on every plane: a particle's distance to them is its section's
    for (const Vec3& f : fluid)
      if (clear_of(in_section(f), slats, dp)) kept.push_back(f);
    fluid.swap(kept);
  }
  Scene3 scene = three_d_scene(spec, tank, prism.breadth, tank->y_bottom + spec.fill.depth, fluid, walls);
  if (blocks.empty()) {
    add_fill_warning(spec, *tank, section_fluid.size(), scene.warnings);
  } else {  // each particle at the hydrostatic pressure below the top of its block, as in 2D
    Particles3& p = scene.particles;
    const double rho_g = spec.fluid.density * spec.fluid.gravity;
    for (std::size_t i = 0; i < p.n_fluid; ++i)
      p.pressure[i] = rho_g * (block_surface(blocks, in_section(p.position[i])) - p.position[i].z);
  }
  add_breadth_warning(spec, scene.warnings);
  scene.screens = std::move(screens);
  scene.warnings.insert(scene.warnings.end(), warnings.begin(), warnings.end());
  return scene;
}

Scene build_scene(const CaseSpec& spec) {
  auto tank = std::make_shared<TankGeometry>(make_tank(spec.tank, spec.where("tank.shape")));
  check_gauges(spec, *tank);

  Scene scene;
  scene.tank = tank;
  scene.pressure_sensors = pressure_sensors(spec, *tank);
  add_time_step_warnings(spec, scene.warnings);
  scene.dp = spec.particles.dp;
  scene.h = spec.particles.kernel_ratio * spec.particles.dp;
  scene.still_level = tank->y_bottom + spec.fill.depth;

  const std::vector<FluidBlock>& blocks = spec.fill.blocks;
  std::vector<Vec2> fluid = blocks.empty() ? fill_fluid(*tank, scene.dp, spec.fill.depth) : fill_blocks(*tank, scene.dp, blocks);
  const std::string fill_key = blocks.empty() ? "fill.depth" : "fill.blocks";
  if (fluid.empty()) throw InputError(spec.where(fill_key), fill_key, "no fluid particle fits in the tank");
  if (blocks.empty()) add_fill_warning(spec, *tank, fluid.size(), scene.warnings);
  std::vector<WallSample> walls = sample_walls(*tank, scene.dp, spec.particles.wall_layers);
  const std::size_t tank_walls = walls.size();
  // Screens: explicit slat screens are rigid wall particles (thesis 4.3.2's explicit model).
  for (std::size_t k = 0; k < spec.screens.size(); ++k) {
    const ScreenSpec sc = resolved_screen(spec, *tank, k);
    const std::string key = "screens." + std::to_string(k);
    if (sc.model == ScreenModel::explicit_slats) {
      SlatLayout layout = explicit_slat_layout(sc, scene.dp, *tank, spec.where(key + ".model"), key);
      walls.insert(walls.end(), layout.walls.begin(), layout.walls.end());
      for (const std::string& w : layout.warnings) scene.warnings.push_back("screen '" + sc.name + "': " + w);
    }
    scene.screens.push_back(sc);
  }
  // Elastic plates: wall particles that the driver moves with the plate.
  std::vector<std::size_t> plate_offsets;
  for (std::size_t k = 0; k < spec.plates.size(); ++k) {
    const std::string key = "plates." + std::to_string(k);
    const KeyLocation where = [&spec](const std::string& k) { return spec.where(k); };
    PlateLayout layout = plate_layout(spec.plates[k], scene.dp, 2.0 * scene.h, *tank, where, key);
    plate_offsets.push_back(walls.size());
    walls.insert(walls.end(), layout.walls.begin(), layout.walls.end());
    scene.plates.push_back(std::move(layout));
  }
  // No fluid inside the slats and plates.
  if (walls.size() > tank_walls) {
    const std::vector<WallSample> solids(walls.begin() + static_cast<std::ptrdiff_t>(tank_walls), walls.end());
    std::vector<Vec2> kept;
    for (const Vec2& f : fluid)
      if (clear_of(f, solids, scene.dp)) kept.push_back(f);
    fluid.swap(kept);
  }

  Particles& p = scene.particles;
  p.resize(fluid.size() + walls.size());
  p.n_fluid = fluid.size();
  p.volume = scene.dp * scene.dp;
  p.mass = spec.fluid.density * p.volume;
  const double rho_g = spec.fluid.density * spec.fluid.gravity;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    p.position[i] = fluid[i];
    const double surface = blocks.empty() ? scene.still_level : block_surface(blocks, fluid[i]);
    p.pressure[i] = rho_g * (surface - fluid[i].y);
  }
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const std::size_t i = fluid.size() + k;
    p.position[i] = walls[k].position;
    p.normal[i] = walls[k].normal;
    p.pressure[i] = rho_g * std::max(0.0, scene.still_level - walls[k].position.y);
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.id[i] = static_cast<std::int32_t>(i);
    p.density[i] = spec.fluid.density;
  }
  for (std::size_t offset : plate_offsets) scene.plate_first.push_back(fluid.size() + offset);
  scene.initial_fluid_count = p.n_fluid;
  scene.initial_fluid_mass = p.mass * static_cast<double>(p.n_fluid);
  return scene;
}

}  // namespace sloshsph
