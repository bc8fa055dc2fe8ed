#include "unfurl/sim/run_settings.hpp"

namespace unfurl::sim {

const char* integrator_name(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::cvode_bdf: return "cvode-bdf";
    case IntegratorKind::cvode_adams: return "cvode-adams";
    case IntegratorKind::arkode_erk: return "arkode-erk";
    case IntegratorKind::arkode_dirk: return "arkode-dirk";
    case IntegratorKind::rk4: return "rk4";
  }
  return "?";
}

const std::vector<IntegratorKind>& all_integrators() {
  static const std::vector<IntegratorKind> kinds{IntegratorKind::cvode_bdf, IntegratorKind::cvode_adams,
                                                 IntegratorKind::arkode_erk, IntegratorKind::arkode_dirk,
                                                 IntegratorKind::rk4};
  return kinds;
}

std::optional<IntegratorKind> parse_integrator(const std::string& name) {
  for (IntegratorKind kind : all_integrators())
    if (name == integrator_name(kind)) return kind;
  return std::nullopt;
}

const char* stability_limit_detection_name(StabilityLimitDetection detection) {
  switch (detection) {
    case StabilityLimitDetection::off: return "false";
    case StabilityLimitDetection::on: return "true";
    case StabilityLimitDetection::after_latch: return "after_latch";
  }
  return "?";
}

std::optional<StabilityLimitDetection> parse_stability_limit_detection(const std::string& name) {
  for (StabilityLimitDetection detection :
       {StabilityLimitDetection::off, StabilityLimitDetection::on, StabilityLimitDetection::after_latch})
    if (name == stability_limit_detection_name(detection)) return detection;
  return std::nullopt;
}

}  // namespace unfurl::sim
