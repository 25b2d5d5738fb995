// The structure without a tank acting on it (issue 5, tests 1-2): the harmonic steady state
// through the whole Simulation path (tanks = 0: the fluid rides along without acting back), and
// the effective damping of the structure alone under the thesis's band-limited noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "coupling_test_cases.hpp"
#include "sloshsph/analysis/admittance.hpp"
#include "sloshsph/analysis/stats.hpp"
#include "sloshsph/io/case_reader.hpp"
#include "sloshsph/run/simulation.hpp"
#include "sloshsph/run/structure_coupling.hpp"
#include "sloshsph/run/structure_summary.hpp"

namespace sloshsph {
namespace {

constexpr double kPi = std::numbers::pi;

std::size_t column_index(const Simulation& sim, const std::string& name) {
  for (std::size_t k = 0; k < sim.columns().size(); ++k)
    if (sim.columns()[k].name == name) return k;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST(StructureAlone, HarmonicSteadyStateMatchesClosedForm) {
  // SDOF M = 1000 kg, f_n = 1 Hz, zeta = 5%, F = F0 sin(w t), r = w / w_n = 0.9. Started on the
  // steady-state solution x = X sin(w t - phi), tan(phi) = 2 zeta r / (1 - r^2), so no transient
  // is left: the amplitude of x_s over 4 s must equal the closed form
  //   X = (F0 / K) / sqrt((1 - r^2)^2 + (2 zeta r)^2)
  // within 1% (issue 5). Expected error: Newmark period elongation (w dt)^2 / 12 = 3e-5 at
  // dt = 1 ms and the 10 ms sampling of the peak, 1 - cos(w 5 ms) = 4e-4. (The fluid, which does
  // not act back, is as coarse as the reader allows: 10 x 10 particles.)
  const double m = 1000.0, fn = 1.0, zeta = 0.05, r = 0.9, f0 = 500.0;
  const double wn = 2 * kPi * fn, k = m * wn * wn, w = r * wn;
  const double amplitude = (f0 / k) / std::sqrt(std::pow(1 - r * r, 2) + std::pow(2 * zeta * r, 2));
  const double phi = std::atan2(2 * zeta * r, 1 - r * r);
  char structure[512];
  std::snprintf(structure, sizeof structure,
                "[structure]\nmass = %.17g\nfrequency = %.17g\ndamping_ratio = %.17g\ntanks = 0\n"
                "initial_displacement = %.17g\ninitial_velocity = %.17g\n"
                "[structure.load]\ntype = \"harmonic\"\namplitude = %.17g\nfrequency = %.17g\n",
                m, fn, zeta, -amplitude * std::sin(phi), amplitude * w * std::cos(phi), f0, r * fn);
  const CaseSpec spec =
      resolve_case(read_case_text(test::small_tank_case(structure, 4.0, 1.0e-6, 0.01), "harmonic.toml"));
  Simulation sim(spec);
  const std::size_t ix = column_index(sim, "x_s"), ixb = column_index(sim, "x_base"), iF = column_index(sim, "F_e"),
                    itld = column_index(sim, "F_TLD");
  double peak = 0.0, worst_tracking = 0.0, worst_force = 0.0, worst_tld = 0.0;
  while (!sim.finished()) {
    sim.step();
    const std::vector<double> row = sim.sample();
    peak = std::max(peak, std::abs(row[ix]));
    // The tank moves with the structure, the load is F0 sin(w t), and no tank acts back.
    worst_tracking = std::max(worst_tracking, std::abs(row[ixb] - row[ix]));
    worst_force = std::max(worst_force, std::abs(row[iF] - f0 * std::sin(w * sim.time())));
    worst_tld = std::max(worst_tld, std::abs(row[itld]));
  }
  EXPECT_NEAR(peak / amplitude, 1.0, 0.01);
  EXPECT_EQ(worst_tracking, 0.0);
  EXPECT_LT(worst_force, 1e-9 * f0);
  EXPECT_EQ(worst_tld, 0.0);
  std::printf("harmonic steady state: X = %.6e m (closed form %.6e m), ratio %.5f\n", peak, amplitude,
              peak / amplitude);
}

TEST(StructureAlone, GroundMotionSteadyStateMatchesClosedForm) {
  // Ground displacement X_g sin(w t) ([excitation] as the ground motion, structure.ground =
  // "excitation"): M x'' + C x' + K x = -M a_g for x relative to the ground, so the steady-state
  // relative amplitude is X = X_g r^2 / sqrt((1 - r^2)^2 + (2 zeta r)^2) (closed form), here
  // started on it (no transient). Tolerance 1% as for the force test; the tank moves with
  // ground + structure: x_base = X_g sin(w t) + x_s and a_base = a_s to rounding.
  const double fn = 1.0, zeta = 0.05, r = 1.1, xg = 0.002;
  const double w = 2 * kPi * r * fn;
  const double amplitude = xg * r * r / std::sqrt(std::pow(1 - r * r, 2) + std::pow(2 * zeta * r, 2));
  const double phi = std::atan2(2 * zeta * r, 1 - r * r);
  char text[768];
  std::snprintf(text, sizeof text,
                "[structure]\nmass = 1000.0\nfrequency = %.17g\ndamping_ratio = %.17g\ntanks = 0\n"
                "ground = \"excitation\"\n"
                "initial_displacement = %.17g\ninitial_velocity = %.17g\n"
                "[excitation]\ntype = \"harmonic\"\namplitude = %.17g\nfrequency = %.17g\n",
                fn, zeta, -amplitude * std::sin(phi), amplitude * w * std::cos(phi), xg, r * fn);
  const CaseSpec spec = resolve_case(read_case_text(test::small_tank_case(text, 4.0, 1.0e-6, 0.01), "ground.toml"));
  Simulation sim(spec);
  const std::size_t ix = column_index(sim, "x_s"), ixb = column_index(sim, "x_base"), ia = column_index(sim, "a_s"),
                    iab = column_index(sim, "a_base");
  double peak = 0.0, worst_x = 0.0, worst_a = 0.0;
  while (!sim.finished()) {
    sim.step();
    const std::vector<double> row = sim.sample();
    peak = std::max(peak, std::abs(row[ix]));
    worst_x = std::max(worst_x, std::abs(row[ixb] - row[ix] - xg * std::sin(w * sim.time())));
    worst_a = std::max(worst_a, std::abs(row[iab] - row[ia]));
  }
  EXPECT_NEAR(peak / amplitude, 1.0, 0.01);
  EXPECT_LT(worst_x, 1e-9 * xg);
  EXPECT_EQ(worst_a, 0.0);
  std::printf("ground motion steady state: X = %.6e m (closed form %.6e m), ratio %.5f\n", peak, amplitude,
              peak / amplitude);
}

// Runs the thesis building alone under its noise load for `duration`, sampled every 0.05 s.
StructureSeries building_alone(const StructureSpec& spec, double duration, double dt) {
  StructureCoupling s(spec, duration);
  s.set_fluid_mass(0.0);
  s.start(0.0);
  StructureSeries out;
  auto record = [&] {
    out.time.push_back(s.time());
    out.x_s.push_back(s.displacement());
    out.a_s.push_back(s.absolute_acceleration());
    out.F_e.push_back(s.external_force());
  };
  record();
  const int every = static_cast<int>(std::lround(0.05 / dt));
  const auto steps = static_cast<long>(std::lround(duration / dt));
  for (long n = 1; n <= steps; ++n) {
    s.advance(dt, 0.0, 0.0);
    if (n % every == 0) record();
  }
  return out;
}

// The thesis building (4.4.2.2) with no tank under its 10 milli-g noise load (seed 2023).
StructureSpec thesis_building_alone_under_noise() {
  StructureSpec spec;
  spec.mass = 7.0e7;
  spec.damping = 1.18e6;
  spec.stiffness = 4.96e7;
  spec.tanks = 0;
  spec.load.type = StructureLoadType::noise;
  spec.load.seed = 2023;
  spec.load.target_peak_mg = 10.0;
  return spec;
}

TEST(StructureAlone, NoiseEffectiveDampingIsTheStructuralDamping) {
  // Thesis 4.4.2: M = 70,000 t, C = 1.18e6 N s/m, K = 4.96e7 N/m (zeta = 1.00%, f_n = 0.1339 Hz),
  // one hour of band-limited noise (0.05-0.5 Hz) scaled to a mean hourly peak of 10 milli-g.
  // References and tolerances:
  //  * zeta_eff from the area under the displacement admittance (eq. 4.30, Vickery et al. 1983;
  //    the area from the whole record, run/structure_summary.hpp) equals the structural 1%
  //    within 10% (issue 5). The force is a sum of equal sinusoids at the harmonics of 1/3600 s,
  //    orthogonal over the record, so the response variance has no sampling scatter of a
  //    random process; the errors are the start-up transient (the response builds up over
  //    1/(zeta w_n) = 119 s; measured over seeds 1-8: 0.981-1.051%) and the band cut-off
  //    (+0.5%, analysis/admittance.hpp).
  //  * The RMS acceleration equals the random-vibration prediction that scaled the force
  //    (signals/white_noise.hpp) within 5% (same error budget).
  //  * The largest peak of one realisation scatters about the mean peak by ~10% (Gumbel
  //    spread pi / sqrt(6) / sqrt(2 ln(nu T)) sigma over the mean 3.7 sigma): within 30%.
  const StructureSpec spec = thesis_building_alone_under_noise();
  const StructureSeries s = building_alone(spec, 3600.0, 0.01);
  const nlohmann::json j = structure_summary(s, spec);
  const double zeta = j["admittance"]["effective_damping_ratio"].get<double>();
  const double rms_ratio = j["acceleration"]["rms_normalised_by_structure_alone"].get<double>();
  const double peak_mg = j["acceleration"]["peak_milli_g"].get<double>();
  EXPECT_NEAR(zeta / 0.01, 1.0, 0.10);
  EXPECT_NEAR(rms_ratio, 1.0, 0.05);
  EXPECT_NEAR(peak_mg / 10.0, 1.0, 0.30);
  // The admittance tends to 1 below resonance (static response F / K): the bins over 0.05-0.09 Hz
  // (|H|^2 = 1.16-2.2 by the closed form) against the closed form within 10% (averaged bins).
  const auto a = structure_admittance(s, spec);
  ASSERT_TRUE(a);
  double measured = 0.0, closed = 0.0;
  for (std::size_t k = 0; k < a->displacement.f.size(); ++k)
    if (a->displacement.f[k] >= 0.05 && a->displacement.f[k] <= 0.09) {
      measured += a->displacement.value[k];
      closed += sdof_admittance(a->displacement.f[k], a->natural_frequency, 0.01);
    }
  EXPECT_NEAR(measured / closed, 1.0, 0.10);
  std::printf("building alone, 1 h noise at 10 milli-g: zeta_eff = %.5f, RMS a / predicted = %.4f, peak = %.2f "
              "milli-g, low-f MAF / closed form = %.4f, segment %.0f s\n",
              zeta, rms_ratio, peak_mg, measured / closed, a->segment_seconds);
  // The CSV has the documented header and one row per bin up to 2 f_hi.
  const std::string csv = admittance_csv(*a);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "f_Hz,H2_displacement,H2_structure_alone,S_force_N2_per_Hz,S_displacement_m2_per_Hz");
}

TEST(StructureAlone, ShortNoiseRecordHasNoAdmittanceAndNoError) {
  // A run of a few seconds under noise (a quick look at a case): its Welch bins (1 / 0.5 s = 2 Hz
  // apart) have none inside the 0.05-0.5 Hz band. The summary says so instead of failing the run
  // (before this, the effective damping threw and the run ended without its summary.json).
  const StructureSpec spec = thesis_building_alone_under_noise();
  const StructureSeries s = building_alone(spec, 2.0, 0.01);
  EXPECT_FALSE(structure_admittance(s, spec));
  nlohmann::json j;
  ASSERT_NO_THROW(j = structure_summary(s, spec));
  EXPECT_EQ(j["admittance"]["note"].get<std::string>(), "record too short for a spectrum");
  EXPECT_FALSE(j["structure_without_tank"].contains("effective_damping_ratio"));
  // 40 s: quarter-length segments of 10 s, bins 0.1 Hz apart, 4.5 bins in the band: it has one.
  EXPECT_TRUE(structure_admittance(building_alone(spec, 40.0, 0.01), spec));
}

TEST(StructureAlone, WithoutTankResponseReproducesTheStructureFromItsSampledLoad) {
  // summary.json "structure_without_tank" re-integrates the structure under the recorded F_e.
  // Reference: the same structure integrated at dt = 0.01 s with the exact load (building_alone)
  // and sampled every 0.05 s, 600 s of the thesis building's 10 milli-g noise. Tolerances: the
  // response from the sampled (linearly interpolated) load within 0.1% of the largest value,
  // the RMS and peak ratios within 0.1% of 1 (run/structure_summary.hpp); zeta_eff equal.
  const StructureSpec spec = thesis_building_alone_under_noise();
  const StructureSeries s = building_alone(spec, 600.0, 0.01);
  const StructureAloneResponse r = structure_alone_response(s, spec);
  ASSERT_EQ(r.x.size(), s.time.size());
  double worst_x = 0.0, worst_a = 0.0;
  for (std::size_t k = 0; k < r.x.size(); ++k) {
    worst_x = std::max(worst_x, std::abs(r.x[k] - s.x_s[k]));
    worst_a = std::max(worst_a, std::abs(r.a[k] - s.a_s[k]));
  }
  EXPECT_LT(worst_x, 1e-3 * peak_abs(s.x_s));
  EXPECT_LT(worst_a, 1e-3 * peak_abs(s.a_s));
  const nlohmann::json j = structure_summary(s, spec);
  for (const char* q : {"displacement", "acceleration"})
    for (const char* ratio : {"rms_ratio_to_without_tank", "peak_ratio_to_without_tank"})
      EXPECT_NEAR(j[q][ratio].get<double>(), 1.0, 1e-3) << q << " " << ratio;
  EXPECT_NEAR(j["structure_without_tank"]["effective_damping_ratio"].get<double>(),
              j["admittance"]["effective_damping_ratio"].get<double>(), 1e-3 * 0.01);
  std::printf("structure without tank from the sampled load: worst x error %.2e of the peak, worst a %.2e\n",
              worst_x / peak_abs(s.x_s), worst_a / peak_abs(s.a_s));
}

TEST(StructureAlone, WithoutTankResponseUnderGroundAccelerationMatchesClosedForm) {
  // Ground acceleration A sin(w t) sampled every 0.01 s (w dt = 0.05: the samples' largest value
  // and the interpolated load are within 0.05% of the true amplitude), no force. Reference: the SDOF steady
  // state, relative displacement X = (A / w_n^2) / D and absolute acceleration
  // A sqrt(1 + (2 zeta r)^2) / D, D = sqrt((1 - r^2)^2 + (2 zeta r)^2); measured over the last
  // 20 s of 100 s (the start-up decays as exp(-zeta w_n t): 5e-4 by 60 s). Tolerance 0.5%.
  StructureSpec spec;
  spec.mass = 1000.0;
  spec.stiffness = 4.0e4;
  const double wn = std::sqrt(spec.stiffness / spec.mass), zeta = 0.02;
  spec.damping = 2.0 * zeta * std::sqrt(spec.stiffness * spec.mass);
  const double A = 1.0, w = 5.0, r = w / wn;
  StructureSeries s;
  for (int k = 0; k <= 10000; ++k) {
    const double t = 0.01 * k;
    s.time.push_back(t);
    s.x_s.push_back(0.0);
    s.a_s.push_back(0.0);
    s.F_e.push_back(0.0);
    s.ground_acceleration.push_back(A * std::sin(w * t));
  }
  const StructureAloneResponse out = structure_alone_response(s, spec);
  double peak_x = 0.0, peak_a = 0.0;
  for (std::size_t k = 0; k < s.time.size(); ++k)
    if (s.time[k] >= 80.0) {
      peak_x = std::max(peak_x, std::abs(out.x[k]));
      peak_a = std::max(peak_a, std::abs(out.a[k]));
    }
  const double D = std::sqrt(std::pow(1.0 - r * r, 2) + std::pow(2.0 * zeta * r, 2));
  EXPECT_NEAR(peak_x / (A / (wn * wn) / D), 1.0, 0.005);
  EXPECT_NEAR(peak_a / (A * std::sqrt(1.0 + std::pow(2.0 * zeta * r, 2)) / D), 1.0, 0.005);
}

TEST(StructureAlone, LoadsAreTheDocumentedFunctions) {
  // Each load against its formula (exact to rounding).
  StructureSpec spec;
  spec.mass = 1000.0;
  spec.damping = 10.0;
  spec.stiffness = 4.0e4;
  spec.load.type = StructureLoadType::harmonic;
  spec.load.amplitude = 3.0;
  spec.load.frequency = 0.5;
  spec.load.ramp = 2.0;
  const StructureLoad harmonic(spec, 10.0);
  EXPECT_NEAR(harmonic.at(1.0), 0.5 * 3.0 * std::sin(kPi * 1.0), 1e-12);  // half-way up the ramp
  EXPECT_NEAR(harmonic.at(2.5), 3.0 * std::sin(kPi * 2.5), 1e-12);
  spec.load.type = StructureLoadType::pulse;
  spec.load.shape = "sine";
  spec.load.amplitude = 2.0;
  spec.load.period = 4.0;
  spec.load.start = 1.0;
  const StructureLoad pulse(spec, 10.0);
  EXPECT_DOUBLE_EQ(pulse.at(0.5), 0.0);
  EXPECT_NEAR(pulse.at(2.0), 2.0, 1e-12);  // a quarter period in: the peak
  EXPECT_NEAR(pulse.at(6.0), 0.0, 1e-12);
  // Noise: the same seed gives the same force; `rms` sets the PSD level S0 = rms^2 / (f_hi - f_lo)
  // and the record (harmonics of 1/1000 s in the band: N df = 0.451 Hz) has the RMS
  // sqrt(S0 N df) = 1.0011 rms exactly (orthogonal components); tolerance 0.5% (interpolation).
  spec.load = {};
  spec.load.type = StructureLoadType::noise;
  spec.load.rms = 1.0e5;
  const StructureLoad n1(spec, 1000.0), n2(spec, 1000.0);
  EXPECT_NEAR(n1.psd_level(), 1.0e10 / 0.45, 1e-6 * 1.0e10 / 0.45);
  std::vector<double> f;
  for (int i = 0; i < 100000; ++i) f.push_back(n1.at(0.01 * i));
  EXPECT_EQ(n1.at(12.345), n2.at(12.345));
  EXPECT_NEAR(rms(f) / (1.0e5 * std::sqrt(0.451 / 0.45)), 1.0, 0.005);
}

}  // namespace
}  // namespace sloshsph
