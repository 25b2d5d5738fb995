#pragma once
// The scheme a case chose (scheme.type), behind one interface for the driver. A variant, not
// a class hierarchy: the driver dispatches once per step, never per particle.
#include <optional>
#include <variant>

#include "sloshsph/schemes/isph.hpp"
#include "sloshsph/schemes/wcsph.hpp"

namespace sloshsph {

// The ISPH or the WCSPH scheme, in 2D and 3D (issue 31).
template <int D>
using SchemeVariant = std::variant<BasicIsphScheme<D>, BasicWcsphScheme<D>>;

template <int D>
class BasicAnyScheme {
 public:
  BasicAnyScheme(const CaseSpec& spec, double h) : scheme_(make(spec, h)) {}

  void initialise(BasicParticles<D>& p, const BasicFrameForce<D>& f) {
    std::visit([&](auto& s) { s.initialise(p, f); }, scheme_);
  }
  void step(BasicParticles<D>& p, const BasicStepInput<D>& in) {
    std::visit([&](auto& s) { s.step(p, in); }, scheme_);
  }
  const BasicStepDiagnostics<D>& diagnostics() const {
    return std::visit([](const auto& s) -> const BasicStepDiagnostics<D>& { return s.diagnostics(); }, scheme_);
  }
  const BasicNeighbourList<D>& neighbours() const {
    return std::visit([](const auto& s) -> const BasicNeighbourList<D>& { return s.neighbours(); }, scheme_);
  }
  double reference_density() const {
    return std::visit([](const auto& s) { return s.reference_density(); }, scheme_);
  }
  MemoryParts memory_parts() const {
    return std::visit([](const auto& s) { return s.memory_parts(); }, scheme_);
  }
  // The largest stable step of an explicit scheme (WCSPH: the CFL condition), none for ISPH.
  std::optional<double> stable_dt(const BasicParticles<D>& p, const BasicFrameForce<D>& f) const {
    if (const auto* w = std::get_if<BasicWcsphScheme<D>>(&scheme_)) return w->stable_dt(p, f);
    return std::nullopt;
  }
  // Checkpoints (run/simulation): the scheme's state between steps.
  void save_state(StateWriter& w) const {
    std::visit([&](const auto& s) { s.save_state(w); }, scheme_);
  }
  void load_state(StateReader& r) {
    std::visit([&](auto& s) { s.load_state(r); }, scheme_);
  }
  const BasicWcsphScheme<D>* wcsph() const { return std::get_if<BasicWcsphScheme<D>>(&scheme_); }

 private:
  static SchemeVariant<D> make(const CaseSpec& spec, double h) {
    if (spec.scheme.type == "wcsph") return SchemeVariant<D>(std::in_place_type<BasicWcsphScheme<D>>, spec, h);
    return SchemeVariant<D>(std::in_place_type<BasicIsphScheme<D>>, spec, h);
  }
  SchemeVariant<D> scheme_;
};
using AnyScheme = BasicAnyScheme<2>;

}  // namespace sloshsph
