#pragma once
// The scheme a case chose (scheme.type), behind one interface for the driver. A variant, not
// a class hierarchy: the driver dispatches once per step, never per particle.
#include <optional>
#include <variant>

#include "sloshsph/schemes/isph.hpp"
#include "sloshsph/schemes/wcsph.hpp"

namespace sloshsph {

class AnyScheme {
 public:
  AnyScheme(const CaseSpec& spec, double h) : scheme_(make(spec, h)) {}

  void initialise(Particles& p, const FrameForce& f) {
    std::visit([&](auto& s) { s.initialise(p, f); }, scheme_);
  }
  void step(Particles& p, const StepInput& in) {
    std::visit([&](auto& s) { s.step(p, in); }, scheme_);
  }
  const StepDiagnostics& diagnostics() const {
    return std::visit([](const auto& s) -> const StepDiagnostics& { return s.diagnostics(); }, scheme_);
  }
  const NeighbourList& neighbours() const {
    return std::visit([](const auto& s) -> const NeighbourList& { return s.neighbours(); }, scheme_);
  }
  double reference_density() const {
    return std::visit([](const auto& s) { return s.reference_density(); }, scheme_);
  }
  MemoryParts memory_parts() const {
    return std::visit([](const auto& s) { return s.memory_parts(); }, scheme_);
  }
  // The largest stable step of an explicit scheme (WCSPH: the CFL condition), none for ISPH.
  std::optional<double> stable_dt(const Particles& p, const FrameForce& f) const {
    if (const auto* w = std::get_if<WcsphScheme>(&scheme_)) return w->stable_dt(p, f);
    return std::nullopt;
  }
  // Checkpoints (run/simulation): the scheme's state between steps.
  void save_state(StateWriter& w) const {
    std::visit([&](const auto& s) { s.save_state(w); }, scheme_);
  }
  void load_state(StateReader& r) {
    std::visit([&](auto& s) { s.load_state(r); }, scheme_);
  }
  const WcsphScheme* wcsph() const { return std::get_if<WcsphScheme>(&scheme_); }

 private:
  static std::variant<IsphScheme, WcsphScheme> make(const CaseSpec& spec, double h) {
    if (spec.scheme.type == "wcsph") return std::variant<IsphScheme, WcsphScheme>(std::in_place_type<WcsphScheme>, spec, h);
    return std::variant<IsphScheme, WcsphScheme>(std::in_place_type<IsphScheme>, spec, h);
  }
  std::variant<IsphScheme, WcsphScheme> scheme_;
};

}  // namespace sloshsph
