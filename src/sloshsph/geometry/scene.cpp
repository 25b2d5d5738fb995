#include "sloshsph/geometry/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/prism_tank.hpp"
#include "sloshsph/geometry/screens.hpp"
#include "sloshsph/sph/neighbours.hpp"

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

// The square of the distance a fluid particle is kept from a slat or plate particle, (0.9 dp)^2
// (written 0.81 dp^2, as the fills have always had it).
double clearance2(double dp) { return 0.81 * dp * dp; }

// Where the slat walls of an explicit screen stand in 3D (issue 31). explicit_slat_layout gives them
// in the section (x, z) as the walls of a vertical screen at x = x_line; a sample at (x, z) goes to
// origin + s along + (x - x_ref) across + z e_z on each of the plane's lines s (horizontal unit
// vectors along and across the screen's plane), its normal (n_x, n_z) to n_x across + n_z e_z.
struct SlatPlane {
  Vec3 origin, along, across;
  double x_ref = 0.0;
  std::vector<double> lines;  // s of each line along the plane
};

// Lines s = (k + 1/2) spacing, k < count.
std::vector<double> lines_at(int count, double spacing) {
  std::vector<double> s;
  for (int k = 0; k < count; ++k) s.push_back((k + 0.5) * spacing);
  return s;
}

// The plane of explicit screen `sc` (resolved: a vertical screen at x_line = sc.from.x in the
// section): across the breadth (plane_y) on the fill's lattice lines along x; through a segment of
// the plan, on lines about dp apart along it; otherwise the plane x = x_line, on the lattice lines
// along y, and its section samples keep their x.
SlatPlane slat_plane(const ScreenSpec& sc, const TankGeometry& section, double breadth, double dp) {
  const Vec3 x_axis{1.0, 0.0, 0.0}, y_axis{0.0, 1.0, 0.0};
  if (sc.plane_y) {
    const int n_x = static_cast<int>(std::floor((section.x_max - section.x_min) / dp + 1e-9));
    return {{section.x_min, *sc.plane_y, 0.0}, x_axis, y_axis, sc.from.x, lines_at(n_x, dp)};
  }
  if (sc.plan) {
    const Vec2 a = sc.plan->first, b = sc.plan->second;
    const double length = norm(b - a);
    const Vec2 t = (b - a) / length, n = perp(t);
    const int count = std::max(1, static_cast<int>(std::lround(length / dp)));
    return {{a.x, a.y, 0.0}, {t.x, t.y, 0.0}, {n.x, n.y, 0.0}, sc.from.x, lines_at(count, length / count)};
  }
  return {{}, y_axis, x_axis, 0.0, lines_at(static_cast<int>(std::floor(breadth / dp + 1e-9)), dp)};
}

// The slat walls of `section_walls` on `plane`'s lines, those for which `inside` holds.
template <class Inside>
void add_slat_walls(const std::vector<WallSample>& section_walls, const SlatPlane& plane, Inside inside,
                    std::vector<WallSample3>& walls) {
  const Vec3 up{0.0, 0.0, 1.0};
  for (const WallSample& w : section_walls)
    for (double s : plane.lines) {
      const Vec3 at = plane.origin + s * plane.along + (w.position.x - plane.x_ref) * plane.across + w.position.y * up;
      if (inside(at)) walls.push_back({at, w.normal.x * plane.across + w.normal.y * up});
    }
}

// The fluid kept clear of the slats: no particle closer than 0.9 dp to one of walls[first, end).
void keep_clear_of_slats(const std::vector<WallSample3>& walls, std::size_t first, double dp, std::vector<Vec3>& fluid) {
  if (first == walls.size()) return;
  std::vector<Vec3> slats;
  for (std::size_t k = first; k < walls.size(); ++k) slats.push_back(walls[k].position);
  const double reach = 0.9 * dp, reach2 = clearance2(dp);
  BasicCellGrid<3> grid;
  grid.build(slats, 0, slats.size(), reach);
  std::vector<Vec3> kept;
  for (const Vec3& f : fluid) {
    bool clear = true;
    grid.for_each_candidate(f, reach, [&](std::uint32_t k) { clear = clear && norm2(f - slats[k]) >= reach2; });
    if (clear) kept.push_back(f);
  }
  fluid.swap(kept);
}

// The case's screens, resolved (ergun and morison elements are extruded by the driver,
// physics/porous.hpp), with the slat walls of the explicit ones added to `walls` (those for which
// inside(q, screen) holds) and the fluid kept clear of them; their layouts' warnings in `warnings`.
template <class Inside>
std::vector<ScreenSpec> place_screens(const CaseSpec& spec, const TankGeometry& section, double breadth, Inside inside,
                                      std::vector<Vec3>& fluid, std::vector<WallSample3>& walls,
                                      std::vector<std::string>& warnings) {
  const double dp = spec.particles.dp;
  std::vector<ScreenSpec> screens;
  const std::size_t tank_walls = walls.size();
  for (std::size_t k = 0; k < spec.screens.size(); ++k) {
    const ScreenSpec sc = resolved_screen(spec, section, k);
    const std::string key = "screens." + std::to_string(k);
    if (sc.model == ScreenModel::explicit_slats) {
      SlatLayout layout = explicit_slat_layout(sc, dp, section, spec.where(key + ".model"), key);
      add_slat_walls(layout.walls, slat_plane(sc, section, breadth, dp), [&](Vec3 q) { return inside(q, sc); }, walls);
      for (const std::string& w : layout.warnings) warnings.push_back("screen '" + sc.name + "': " + w);
    }
    screens.push_back(sc);
  }
  keep_clear_of_slats(walls, tank_walls, dp, fluid);
  return screens;
}

// Fill blocks in 3D: each fluid particle at the hydrostatic pressure below the top of its block, as
// in 2D (the block's section (x, z) holds it).
void start_blocks_at_rest(const CaseSpec& spec, Particles3& p) {
  const double rho_g = spec.fluid.density * spec.fluid.gravity;
  for (std::size_t i = 0; i < p.n_fluid; ++i)
    p.pressure[i] = rho_g * (block_surface(spec.fill.blocks, in_section(p.position[i])) - p.position[i].z);
}

// An upright cylinder: the fluid on the cubic lattice inside it (or in its fill blocks), its side and bottom walls; the
// scene's section is the rectangle 2R x height it stands in. Porous screens (vertical planes) are
// extruded over the chord their plane cuts by the driver; explicit slats stand on it (place_screens).
Scene3 build_cylinder_scene(const CaseSpec& spec) {
  const CylinderTank cylinder = cylinder_of(spec.tank);
  auto tank = std::make_shared<TankGeometry>(make_tank(plane_section(spec.tank), spec.where("tank.radius")));
  check_probes_3d(spec, [&cylinder](Vec3 p) { return cylinder.signed_distance(p); }, tank->y_top);
  const double dp = spec.particles.dp;
  const std::vector<FluidBlock>& blocks = spec.fill.blocks;  // each over the chords of the circle
  std::vector<Vec3> fluid = blocks.empty() ? fill_fluid(cylinder, dp, spec.fill.depth) : fill_blocks(cylinder, dp, blocks);
  std::vector<WallSample3> walls = sample_walls(cylinder, dp, spec.particles.wall_layers);
  // Explicit slats over the chord of their plane: the lines of the plane inside the circle.
  std::vector<std::string> warnings;
  auto inside = [&cylinder](Vec3 q, const ScreenSpec&) { return cylinder.from_axis(q) < cylinder.radius; };
  std::vector<ScreenSpec> screens = place_screens(spec, *tank, 2.0 * cylinder.radius, inside, fluid, walls, warnings);
  Scene3 scene = three_d_scene(spec, tank, 2.0 * cylinder.radius, spec.fill.depth, fluid, walls);
  scene.cylinder = cylinder;
  scene.screens = std::move(screens);
  scene.warnings.insert(scene.warnings.end(), warnings.begin(), warnings.end());
  // The fill holds the water of fill.depth (fill_fluid): above the depth at first, it settles into
  // the ring of gaps the square lattice leaves along the round wall. Blocks: fill.depth is their
  // water's settled level (the case reader's).
  if (!blocks.empty()) start_blocks_at_rest(spec, scene.particles);
  return scene;
}

}  // namespace

// The y of the lattice planes across a prism's breadth, (m + 1/2) dp (on_planes_across's).
static std::vector<double> plate_planes(const PrismTank& prism, double dp) {
  std::vector<double> y;
  for (const Vec3& q : on_planes_across(prism, dp, {Vec2{}})) y.push_back(q.y);
  return y;
}

// A fluid particle is kept clear of slats and plates: no closer than 0.9 dp to one of their particles.
static bool clear_of(Vec2 f, const std::vector<WallSample>& solids, double dp) {
  for (const WallSample& w : solids)
    if (norm2(f - w.position) < clearance2(dp)) return false;
  return true;
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
  // Explicit slats: the section's slat walls on every plane across the breadth, or turned into the
  // plane y = plane_y or a plane through the plan (slat_plane); a slat of a plane through the plan
  // may reach past the box's wall at an end of the segment.
  std::vector<std::string> warnings;
  auto inside = [&prism](Vec3 q, const ScreenSpec& sc) { return !sc.plan || prism.signed_distance(q) > 0.0; };
  std::vector<ScreenSpec> screens = place_screens(spec, *tank, prism.breadth, inside, fluid, walls, warnings);
  // Elastic plates across the breadth: the section's plate particles on every lattice plane across
  // it (run/plate_coupling.hpp), the last wall particles, the fluid kept clear of them.
  const std::size_t first_plate_wall = walls.size();
  std::vector<PlateLayout> plates;
  std::vector<std::size_t> plate_offsets;
  const std::vector<double> planes = plate_planes(prism, dp);
  for (std::size_t k = 0; k < spec.plates.size(); ++k) {
    const KeyLocation where = [&spec](const std::string& key) { return spec.where(key); };
    PlateLayout layout = plate_layout(spec.plates[k], dp, 2.0 * spec.particles.kernel_ratio * dp, *tank, where,
                                      "plates." + std::to_string(k));
    plate_offsets.push_back(walls.size());
    for (const WallSample& w : layout.walls)
      for (double y : planes) walls.push_back({at_breadth(w.position, y), at_breadth(w.normal, 0.0)});
    plates.push_back(std::move(layout));
  }
  keep_clear_of_slats(walls, first_plate_wall, dp, fluid);
  Scene3 scene = three_d_scene(spec, tank, prism.breadth, tank->y_bottom + spec.fill.depth, fluid, walls);
  scene.plates = std::move(plates);
  for (std::size_t offset : plate_offsets) scene.plate_first.push_back(fluid.size() + offset);
  if (!scene.plates.empty()) scene.plate_planes = planes;
  if (blocks.empty()) add_fill_warning(spec, *tank, section_fluid.size(), scene.warnings);
  else start_blocks_at_rest(spec, scene.particles);
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
