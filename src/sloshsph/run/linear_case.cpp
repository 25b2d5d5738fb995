#include "sloshsph/run/linear_case.hpp"

#include <cstdlib>
#include <memory>

#include "sloshsph/core/errors.hpp"
#include "sloshsph/geometry/tank.hpp"
#include "sloshsph/io/csv_writer.hpp"
#include "sloshsph/physics/excitation.hpp"

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

}  // namespace

LinearCase linear_case_response(const CaseSpec& spec, const LinearCaseOptions& options) {
  check_case(spec);
  const TankGeometry tank = make_tank(spec.tank, spec.where("tank.shape"));
  LinearCase out;
  out.modes = sloshing_modes(tank, spec.fill.depth, spec.fluid.gravity, options.modes);
  out.damping = modal_damping(spec, out.modes, options.damping, out.damping_model);
  if (!spec.screens.empty()) out.ignored.push_back("screens");
  if (!spec.plates.empty()) out.ignored.push_back("plates");

  auto base = std::make_shared<BaseMotionSource>(spec.excitation, spec.time.end);
  LinearResponseInput in;
  in.modes = out.modes;
  in.damping = out.damping;
  in.base_acceleration = [base](double t) { return base->at(t).acceleration.x; };
  in.density = spec.fluid.density;
  in.still_water_area = still_water_area(tank, spec.fill.depth);
  for (const GaugeSpec& g : spec.gauges) {
    in.gauge_x.push_back(g.x);
    out.gauge_names.push_back(g.name);
  }
  in.end_time = spec.time.end;
  in.sample_interval = spec.output.sample_interval;
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

}  // namespace sloshsph
