// The compliance report: COMPLIANCE.md, pin_stiffness.csv and its plot (the
// peak hinge and pin forces against the pins' stiffness, nominal and
// off-nominal, beside the rigid pantograph's).
#pragma once

#include <string>
#include <vector>

#include "unfurl/studies/pin_stiffness.hpp"

namespace unfurl::app {

// A Monte Carlo study's peak hinge forces over its deployed cases.
struct MonteCarloHingeForces {
  std::string label, cases_csv;
  std::vector<double> peak_hinge_force;  // N, sorted
};

struct ComplianceReport {
  std::vector<studies::PinStiffnessCase> compliant;  // by deployment, then stiffness
  std::vector<studies::PinStiffnessCase> rigid;      // one per deployment
  std::vector<MonteCarloHingeForces> monte_carlo;  // rigid and compliant, when the studies were given
  double rtol = 0, t_end = 0;
  std::string command;
};

std::vector<std::string> write_compliance_plots(const ComplianceReport& report, const std::string& dir);
void write_compliance_csv(const ComplianceReport& report, const std::string& path);
void write_compliance_markdown(const ComplianceReport& report, const std::vector<std::string>& pictures,
                               const std::string& path);

}  // namespace unfurl::app
