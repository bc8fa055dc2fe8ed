#include "compliance_files.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "unfurl/io/markdown.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/studies/study_statistics.hpp"

namespace unfurl::app {

namespace {

std::string determinate_text(const std::optional<bool>& d) {
  if (!d) return "not assessed";
  return *d ? "yes" : "no";
}

// The peaks' growth with the pins' stiffness between its two stiffest
// values, as an exponent: F ~ k^e.
double growth_exponent(const ComplianceReport& report, int deployment) {
  const studies::PinStiffnessCase *soft = nullptr, *stiff = nullptr;
  for (const auto& c : report.compliant) {
    if (c.deployment != deployment || c.loads.status != sim::RunStatus::finished) continue;
    soft = stiff;
    stiff = &c;
  }
  if (!soft || !stiff || soft->loads.peak_hinge_force <= 0) return std::nan("");
  return std::log(stiff->loads.peak_hinge_force / soft->loads.peak_hinge_force) /
         std::log(stiff->stiffness / soft->stiffness);
}

// The stiffest finished compliant case of a deployment, and its rigid one.
const studies::PinStiffnessCase* stiffest(const ComplianceReport& report, int deployment) {
  const studies::PinStiffnessCase* best = nullptr;
  for (const auto& c : report.compliant)
    if (c.deployment == deployment && c.loads.status == sim::RunStatus::finished &&
        (!best || c.stiffness > best->stiffness))
      best = &c;
  return best;
}

const studies::PinStiffnessCase* rigid_case(const ComplianceReport& report, int deployment) {
  for (const auto& c : report.rigid)
    if (c.deployment == deployment && c.loads.status == sim::RunStatus::finished) return &c;
  return nullptr;
}

void write_what_it_shows(std::ostream& out, const ComplianceReport& report) {
  const studies::PinStiffnessCase *pins = stiffest(report, 0), *rigid = rigid_case(report, 0);
  if (!pins || !rigid) return;
  char buf[1400];
  out << "## What it shows\n\n";
  std::snprintf(buf, sizeof buf,
                "- Nominal: the peak hinge force settles on the rigid pantograph's as the pins stiffen: %.1f N at "
                "%.0e N/m against the rigid %.1f N (%+.1f %%). Softer pins deploy later (%.4f s at %.0e N/m, "
                "rigid %.4f s): near the stowed and the deployed flat positions, both singular positions of the "
                "loops, a small deflection of the pins admits a large relative motion of the chains, which the "
                "rigid loops forbid; the deployment converges on the rigid one as k grows.\n",
                pins->loads.peak_hinge_force, pins->stiffness, rigid->loads.peak_hinge_force,
                100 * (pins->loads.peak_hinge_force / rigid->loads.peak_hinge_force - 1), pins->loads.deployment_time,
                pins->stiffness, rigid->loads.deployment_time);
  out << buf;
  std::snprintf(buf, sizeof buf,
                "- Off-nominal: the peak hinge force grows as k^%.2f between the two stiffest pins and has no "
                "rigid limit. Chain A latches first; at the deployed flat position the loops are redundant, so the "
                "only thing that stops chain B against chain A is the pins' deflection, and the force that does "
                "grows with their stiffness as an impact's does. The rigid model cannot give this force (its loads "
                "are flagged indeterminate there); a deployment analysis needs the pins' real stiffness, and a "
                "hinge must be sized for it.\n\n",
                growth_exponent(report, 1));
  out << buf;
}

void write_monte_carlo_comparison(std::ostream& out, const ComplianceReport& report,
                                  const std::vector<std::string>& pictures) {
  if (report.monte_carlo.empty()) return;
  out << "## Monte Carlo: the peak hinge force, rigid and compliant\n\n"
      << "The same draws (every spring's stiffness and preload within +-10 %, every panel's mass within +-5 %, "
         "every latch's stiffness within +-20 %) on the rigid pantograph and on the compliant one (pins 1e6 N/m), "
         "over their deployed cases. The rigid study's peaks are over the steps where its loads are determinate: "
         "in a case whose chains latch one after the other the loops pass their deployed branch point "
         "asymmetrically and its loads are indeterminate from there to the end, so its peaks are those of the "
         "deployment before the latch-up and miss the latch-up's. The compliant study's are determinate at every "
         "step and include it.\n\n";
  for (const std::string& p : pictures)
    if (p == "monte_carlo_hinge_force.png") out << "![" << p << "](" << p << ")\n\n";
  out << "| study | cases | min | p5 | median | p95 | max |\n|---|---:|---:|---:|---:|---:|---:|\n";
  char buf[512];
  for (const MonteCarloHingeForces& m : report.monte_carlo) {
    const std::vector<double>& x = m.peak_hinge_force;
    if (x.empty()) continue;
    std::snprintf(buf, sizeof buf, "| %s (`%s`) | %zu | %.1f N | %.1f N | %.1f N | %.1f N | %.1f N |\n", m.label.c_str(),
                  m.cases_csv.c_str(), x.size(), x.front(), studies::percentile(x, 5), studies::percentile(x, 50),
                  studies::percentile(x, 95), x.back());
    out << buf;
  }
  out << "\n";
}

}  // namespace

void write_compliance_csv(const ComplianceReport& report, const std::string& path) {
  io::OutputFile file(path);
  file.stream() << "deployment,model,pin_stiffness [N/m],status,deployment_time [s],peak_hinge_force [N],"
                   "peak_hinge_joint,peak_pin_force [N],loads_determinate,peak_hinge_force_indeterminate [N],steps,"
                   "wall_time [s]\n";
  const auto deployments = studies::pin_stiffness_deployments();
  const auto row = [&](const studies::PinStiffnessCase& c, const char* model) {
    const studies::PinLoads& p = c.loads;
    file.stream() << '"' << deployments[c.deployment].label << "\"," << model << ','
                  << (c.stiffness > 0 ? sim::format_number(c.stiffness) : "") << ','
                  << sim::run_status_name(p.status) << ',' << sim::format_number(p.deployment_time) << ','
                  << sim::format_number(p.peak_hinge_force) << ',' << p.peak_hinge_joint << ','
                  << (c.stiffness > 0 ? sim::format_number(p.peak_pin_force) : "") << ','
                  << (p.loads_determinate ? (*p.loads_determinate ? "1" : "0") : "") << ','
                  << sim::format_number(p.peak_hinge_force_indeterminate) << ',' << p.steps << ','
                  << sim::format_number(p.wall_time_s) << '\n';
  };
  for (const auto& c : report.compliant) row(c, "compliant");
  for (const auto& c : report.rigid) row(c, "rigid");
  file.commit();
}

void write_compliance_markdown(const ComplianceReport& report, const std::vector<std::string>& pictures,
                               const std::string& path) {
  io::OutputFile file(path);
  std::ostream& out = file.stream();
  char buf[512];
  const auto deployments = studies::pin_stiffness_deployments();
  out << "# Compliance: the pantograph's loads against its pins' stiffness\n\n";
  out << "Made by `" << report.command << "`. Each run: rtol " << sim::format_number(report.rtol) << ", atol rtol/100, "
      << sim::format_number(report.t_end) << " s (every latch engages by 7.6 s).\n\n"
      << "`pantograph_compliant` closes the pantograph's three cross-links by bushings between full-mass panels "
         "(assets/scenes/README.md); here every pin's stiffness along its three axes is set to the value in the "
         "first column (damping and rotational stiffness as built: 100 N s/m, 1e4 N m/rad). The rigid rows are "
         "the built-in `pantograph`, whose cross-links are split bodies closed by the regulator. The off-nominal "
         "deployment has j1's spring 2 % stiffer (`--set springs.j1.stiffness=0.102`): chain A then latches "
         "before chain B and the array passes its deployed branch point asymmetrically, where the rigid model "
         "cannot determine the hinge forces (it reports the minimum-norm ones and flags them).\n\n";
  for (const std::string& p : pictures)
    if (p == "pin_stiffness.png") out << "![" << p << "](" << p << ")\n\n";
  for (std::size_t d = 0; d < deployments.size(); ++d) {
    out << "## " << deployments[d].label << "\n\n";
    out << "| model | pin stiffness, N/m | deployed at, s | peak hinge force, N (joint) | peak pin force, N | "
           "loads determinate | steps | wall time, s |\n|---|---|---|---|---|---|---|---|\n";
    for (const auto& c : report.compliant) {
      if (c.deployment != static_cast<int>(d)) continue;
      const studies::PinLoads& p = c.loads;
      std::snprintf(buf, sizeof buf, "| compliant | %.0e | %.4f | %.1f (%s) | %.1f | %s | %ld | %.2f |\n",
                    c.stiffness, p.deployment_time, p.peak_hinge_force, p.peak_hinge_joint.c_str(), p.peak_pin_force,
                    determinate_text(p.loads_determinate).c_str(), p.steps, p.wall_time_s);
      out << buf;
    }
    for (const auto& c : report.rigid) {
      if (c.deployment != static_cast<int>(d)) continue;
      const studies::PinLoads& p = c.loads;
      std::snprintf(buf, sizeof buf, "%.1f (%s)", p.peak_hinge_force, p.peak_hinge_joint.c_str());
      std::string hinge = buf;
      if (p.loads_determinate && !*p.loads_determinate) {
        std::snprintf(buf, sizeof buf, " where determinate; indeterminate %.1f",
                      p.peak_hinge_force_indeterminate);
        hinge += buf;
      }
      std::snprintf(buf, sizeof buf, "| rigid | - | %.4f | %s | - | %s | %ld | %.2f |\n", p.deployment_time,
                    io::table_cell(hinge).c_str(), determinate_text(p.loads_determinate).c_str(), p.steps,
                    p.wall_time_s);
      out << buf;
    }
    out << "\n";
  }
  write_what_it_shows(out, report);
  write_monte_carlo_comparison(out, report, pictures);
  file.commit();
}

}  // namespace unfurl::app
