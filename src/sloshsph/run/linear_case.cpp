#include "sloshsph/run/linear_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/io/csv_writer.hpp"
#include "sloshsph/linear/screen_drag.hpp"
#include "sloshsph/physics/excitation.hpp"
#include "sloshsph/physics/porous.hpp"
#include "sloshsph/run/simulation.hpp"
#include "sloshsph/run/sweep.hpp"

namespace sloshsph {
namespace {

void check_case(const CaseSpec& spec) {
  if (spec.excitation.type == ExcitationType::pitch)
    throw InputError(spec.where("excitation.type"), "excitation.type",
                     "the linear modal solution takes a horizontal base motion; a pitch is not implemented");
  if (spec.structure)
    throw InputError(spec.where("structure"), "structure",
                     "the linear modal solution imposes the base motion; a tank on a [structure] moves with it");
  if (!spec.fill.blocks.empty())
    throw InputError(spec.where("fill.blocks"), "fill.blocks",
                     "the linear modal solution starts from still water; blocks of water are not still");
}

// zeta per mode and the name of the model, from the --damping option.
std::vector<double> modal_damping(const CaseSpec& spec, const std::vector<SloshingMode>& modes,
                                  const std::string& option, std::string& model) {
  const bool rectangle = spec.tank.shape == "rectangle";
  std::vector<double> zeta(modes.size(), 0.0);
  if (option == "none" || (option == "auto" && !rectangle)) {
    model = "none";
    return zeta;
  }
  if (option == "boundary-layer" || option == "auto") {
    if (!rectangle)
      throw InputError("--damping", "damping",
                       "boundary-layer damping is known for a rectangular tank only (this one is \"" +
                           spec.tank.shape + "\"); give a damping ratio or none");
    model = "boundary-layer";
    // Mode n of the rectangle is the n-th of the modal solver (the modes alternate odd, even).
    for (std::size_t n = 0; n < modes.size(); ++n)
      zeta[n] = rectangular_boundary_layer_damping(spec.tank.length, spec.fill.depth, spec.fluid.gravity,
                                                   spec.fluid.viscosity, static_cast<int>(n + 1));
    return zeta;
  }
  char* end = nullptr;
  const double value = std::strtod(option.c_str(), &end);
  if (end == option.c_str() || *end != '\0' || !(value >= 0.0 && value < 1.0))
    throw InputError("--damping", "damping",
                     "'" + option + "' is not auto, none, boundary-layer or a damping ratio in [0, 1)");
  model = "given";
  zeta.assign(modes.size(), value);
  return zeta;
}

// The pressure-loss law of a screen of the case (physics/porous.hpp): morison its C_l (given, or
// from the solidity by Baines & Peterson), explicit slats the C_l of their solidity, ergun the
// inertial coefficient of its Ergun equation and its Darcy term t mu / K (grain diameter dp_sc).
void set_loss_law(const CaseSpec& spec, const ScreenSpec& sc, LinearScreen& out) {
  if (sc.model == ScreenModel::ergun) {
    const double porosity = 1.0 - sc.solidity;
    const double grain = sc.spacing > 0.0 ? sc.spacing : spec.particles.dp;
    const double permeability = kozeny_carman_permeability(porosity, grain);
    out.loss_coefficient = ergun_inertial_loss_coefficient(permeability, porosity, sc.thickness);
    out.linear_resistance = sc.thickness * spec.fluid.density * spec.fluid.viscosity / permeability;
  } else if (sc.model == ScreenModel::morison && sc.loss_coefficient > 0.0) {
    out.loss_coefficient = sc.loss_coefficient;
  } else {
    out.loss_coefficient = slat_screen_loss_coefficient(sc.solidity);
  }
}

// The case's vertical screens in the still water of a rectangle, as the linear model takes them
// (linear/screen_drag.hpp); what it cannot take is named in `ignored`.
std::vector<LinearScreen> linear_screens(const CaseSpec& spec, const TankGeometry& tank,
                                         std::vector<std::string>& ignored) {
  std::vector<LinearScreen> out;
  for (const ScreenSpec& sc : spec.screens) {
    const std::string name = "screen '" + sc.name + "'";
    if (spec.tank.shape != "rectangle") {
      ignored.push_back(name + " (the screens' drag is modelled in a rectangular tank only)");
      continue;
    }
    if (!sc.full_height && sc.from.x != sc.to.x) {
      ignored.push_back(name + " (not vertical)");
      continue;
    }
    LinearScreen ls;
    ls.x = sc.from.x - tank.x_min;
    const double low = sc.full_height ? 0.0 : std::min(sc.from.y, sc.to.y) - tank.y_bottom;
    const double high = sc.full_height ? spec.fill.depth : std::max(sc.from.y, sc.to.y) - tank.y_bottom;
    ls.z_from = std::max(low, 0.0);
    ls.z_to = std::min(high, spec.fill.depth);
    if (!(ls.z_to > ls.z_from) || !(ls.x > 0.0 && ls.x < spec.tank.length)) {
      ignored.push_back(name + " (not in the still water)");
      continue;
    }
    set_loss_law(spec, sc, ls);
    out.push_back(ls);
  }
  return out;
}

}  // namespace

LinearCase linear_case_response(const CaseSpec& spec, const LinearCaseOptions& options) {
  check_case(spec);
  const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
  LinearCase out;
  out.modes = sloshing_modes(tank, spec.fill.depth, spec.fluid.gravity, options.modes);
  out.damping = modal_damping(spec, out.modes, options.damping, out.damping_model);
  if (!spec.plates.empty()) out.ignored.push_back("plates");
  std::shared_ptr<const RectangularScreenDrag> drag;
  if (!spec.screens.empty() && !options.screens) {
    out.ignored.push_back("screens (--screens none)");
  } else if (!spec.screens.empty()) {
    out.screens = linear_screens(spec, tank, out.ignored);
    if (!out.screens.empty())
      drag = std::make_shared<const RectangularScreenDrag>(spec.tank.length, spec.fill.depth, spec.fluid.density,
                                                           out.screens, static_cast<int>(out.modes.size()));
  }

  auto base = std::make_shared<BaseMotionSource>(spec.excitation, spec.time.end);
  LinearResponseInput in;
  in.modes = out.modes;
  in.damping = out.damping;
  in.base_acceleration = [base](double t) { return base->at(t).acceleration.x; };
  in.density = spec.fluid.density;
  in.still_water_area = still_water_area(tank, spec.fill.depth);
  out.still_water_area = in.still_water_area;
  for (const GaugeSpec& g : spec.gauges) {
    in.gauge_x.push_back(g.x);
    out.gauge_names.push_back(g.name);
  }
  in.end_time = spec.time.end;
  in.sample_interval = spec.output.sample_interval;
  if (drag)
    in.modal_drag = [drag](const std::vector<double>& v, std::vector<double>& acc) { drag->add_accelerations(v, acc); };
  out.response = linear_response_from_rest(in);
  for (double t : out.response.time) out.base_displacement.push_back(base->at(t).displacement.x);
  return out;
}

void write_linear_csv(const std::string& path, const LinearCase& result) {
  std::vector<std::string> columns{"time", "x_base"};
  for (const std::string& name : result.gauge_names) columns.push_back("eta:" + name);
  columns.push_back("F_w");
  columns.push_back("F_sw");
  CsvWriter csv(path, columns);
  const LinearResponse& r = result.response;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    std::vector<double> row{r.time[k], result.base_displacement[k]};
    for (const std::vector<double>& eta : r.elevation) row.push_back(eta[k]);
    row.push_back(r.wall_force[k]);
    row.push_back(r.sloshing_force[k]);
    csv.write_row(row);
  }
}

namespace {

// The steady-state response of one linear solution, as run_case analyses a run's.
Response linear_steady_state(const CaseSpec& spec, const LinearCase& r) {
  std::vector<std::string> names{"time", "x_base"}, units{"s", "m"};
  std::vector<std::vector<double>> columns{r.response.time, r.base_displacement};
  for (std::size_t g = 0; g < r.gauge_names.size(); ++g) {
    names.push_back("eta:" + r.gauge_names[g]);
    units.push_back("m");
    columns.push_back(r.response.elevation[g]);
  }
  names.insert(names.end(), {"F_w", "F_sw"});
  units.insert(units.end(), {"N/m", "N/m"});
  columns.push_back(r.response.wall_force);
  columns.push_back(r.response.sloshing_force);
  return steady_state_response(names, units, columns,
                               response_options(spec, spec.fluid.density * r.still_water_area, false));
}

}  // namespace

LinearFrequencyResponse linear_frequency_response(const std::string& case_path, const std::vector<std::string>& sets,
                                                  const std::vector<double>& betas, const LinearCaseOptions& options) {
  const CaseSpec spec = read_case_file(case_path, sets);
  if (spec.excitation.type != ExcitationType::harmonic)
    throw InputError(spec.where("excitation.type"), "excitation.type",
                     "a linear frequency response needs a harmonic excitation");
  LinearFrequencyResponse out;
  for (const SweepPoint& point : plan_sweep(spec, betas, {}, ".")) {
    std::vector<std::string> point_sets = sets;
    point_sets.insert(point_sets.end(), point.overrides.begin(), point.overrides.end());
    const CaseSpec at = resolve_case(read_case_file(case_path, point_sets));
    LinearCase r = linear_case_response(at, options);
    out.points.push_back({point.beta, at.excitation.omega, linear_steady_state(at, r)});
    if (out.points.size() == 1) {
      r.response = {};
      r.base_displacement.clear();
      out.model = std::move(r);
    }
  }
  return out;
}

void write_linear_frequency_csv(const std::string& path, const std::vector<LinearFrequencyPoint>& points,
                                const std::vector<std::string>& gauge_names) {
  std::vector<std::string> columns{"beta", "omega", "eta_max", "eta_min", "F_sw_max", "F_sw_min", "energy_per_cycle",
                                   "F_w_max", "F_w_min"};
  for (const std::string& g : gauge_names) columns.insert(columns.end(), {"eta_max:" + g, "eta_min:" + g});
  CsvWriter csv(path, columns);
  for (const LinearFrequencyPoint& p : points) {
    auto extremes = [&p](const std::string& name, std::vector<double>& row) {
      const ResponseValue* v = p.response.find(name);
      row.push_back(v ? v->avg_max : NAN);
      row.push_back(v ? v->avg_min : NAN);
    };
    std::vector<double> row{p.beta, p.omega};
    extremes(gauge_names.empty() ? std::string() : "eta:" + gauge_names.front(), row);
    extremes("F_sw", row);
    row.push_back(p.response.energy_per_cycle.value_or(NAN));
    extremes("F_w", row);
    for (const std::string& g : gauge_names) extremes("eta:" + g, row);
    csv.write_row(row);
  }
}

}  // namespace sloshsph
