#include "work_precision_files.hpp"

#include <cmath>
#include <cstdio>

#include "unfurl/io/markdown.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::app {

namespace {

std::string setting(const studies::PrecisionPoint& p) {
  char buf[64];
  if (p.integrator == sim::IntegratorKind::rk4)
    std::snprintf(buf, sizeof buf, "dt %g", p.dt);
  else
    std::snprintf(buf, sizeof buf, "rtol %g", p.rtol);
  return buf;
}

std::string sci(double x) {
  if (!std::isfinite(x)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", s);
  return buf;
}

std::string status_text(const studies::PrecisionPoint& p) {
  if (p.status == sim::RunStatus::finished)
    return p.latches_missing ? std::to_string(p.latches_missing) + " latch(es) differ" : "ok";
  return std::string(sim::run_status_name(p.status)) + (p.failure.empty() ? "" : ": " + p.failure);
}

}  // namespace

void write_work_precision_csv(const studies::WorkPrecision& report, const std::string& path) {
  io::OutputFile file(path);
  std::ostream& out = file.stream();
  out << "scene,integrator,rtol,atol,dt,status,runs,wall_time_s,steps,rhs_calls,jacobian_evals,linear_setups,"
         "linear_iterations,nonlinear_iterations,error_test_failures,min_step,angle_error,angle_error_whole_run,"
         "final_error,latch_time_error,latches_missing,max_loop_gap_m,failure\n";
  for (const studies::PrecisionPoint& p : report.points) {
    std::string failure = p.failure;
    for (char& c : failure)
      if (c == ',' || c == '\n' || c == '"') c = ';';
    out << report.scene << ',' << sim::integrator_name(p.integrator) << ',' << sim::format_number(p.rtol) << ','
        << sim::format_number(p.atol) << ',' << sim::format_number(p.dt) << ',' << sim::run_status_name(p.status) << ','
        << p.runs << ',' << sim::format_number(p.wall_time_s) << ',' << p.stats.steps << ',' << p.rhs_calls << ','
        << p.stats.jacobian_evals << ',' << p.stats.linear_setups << ',' << p.stats.linear_iterations << ','
        << p.stats.nonlinear_iterations << ',' << p.stats.error_test_failures << ','
        << sim::format_number(p.stats.min_step) << ',' << sim::format_number(p.angle_error) << ','
        << sim::format_number(p.angle_error_whole_run) << ',' << sim::format_number(p.final_error) << ','
        << sim::format_number(p.latch_time_error) << ',' << p.latches_missing << ','
        << sim::format_number(p.max_loop_gap) << ',' << failure << '\n';
  }
  file.commit();
}

void write_work_precision_markdown(const sim::Scene& scene, const studies::WorkPrecision& report,
                                   const std::vector<std::string>& pictures, const std::string& command,
                                   const std::string& path) {
  io::OutputFile file(path);
  std::ostream& out = file.stream();
  char buf[256];
  out << "# Work-precision: " << report.scene << "\n\n";
  out << "Made by `" << command << "`.\n\n";
  out << "- Scene: " << scene.description << " (" << scene.source << "), t = 0 .. " << scene.run.t_end
      << " s, sampled every " << scene.run.sample << " s.\n";
  out << "- Reference: " << report.reference << ".\n";
  std::snprintf(buf, sizeof buf, "%g", report.compared_until);
  out << "- Angle error: the largest |q - q_ref| over the joints and the samples with t <= " << buf << " s";
  if (!scene.latches().empty() && !scene.loops.empty())
    out << " (the reference's first latch: after it the deployed state can be a branch point where exact runs "
           "part, so the final state and the latch times are compared instead)";
  out << ". Adaptive integrators run at rtol as given and atol = rtol / 100 (for a joint angle; the other states "
         "in the mechanism's own sizes, Dynamics::state_scale); RK4 at a fixed step. Wall time: the median of up to 3 runs on "
         "this machine.\n\n";
  for (const std::string& picture : pictures) out << "![" << picture << "](" << picture << ")\n\n";

  out << "## Cheapest integrator for each accuracy\n\n";
  out << "| angle error at most | integrator | setting | wall time, s | RHS calls |\n|---|---|---|---|---|\n";
  for (const studies::CheapestRun& c : studies::cheapest_by_accuracy(report)) {
    if (!c.point) continue;
    std::snprintf(buf, sizeof buf, "%.0e", c.accuracy);
    out << "| " << buf << " rad | " << sim::integrator_name(c.point->integrator) << " | " << setting(*c.point) << " | "
        << seconds(c.point->wall_time_s) << " | " << c.point->rhs_calls << " |\n";
  }
  out << "\n## Every run\n\n";
  out << "| integrator | setting | status | wall time, s | steps | RHS calls | Jacobians | linear iterations | angle "
         "error, rad | final-state error, rad |";
  if (!scene.latches().empty()) out << " latch-time error, s |";
  if (!scene.loops.empty()) out << " max loop gap, m |";
  out << "\n|---|---|---|---|---|---|---|---|---|---|" << (scene.latches().empty() ? "" : "---|")
      << (scene.loops.empty() ? "" : "---|") << "\n";
  for (const studies::PrecisionPoint& p : report.points) {
    out << "| " << sim::integrator_name(p.integrator) << " | " << setting(p) << " | " << io::table_cell(status_text(p))
        << " | " << seconds(p.wall_time_s) << " | " << p.stats.steps << " | " << p.rhs_calls << " | "
        << p.stats.jacobian_evals << " | " << p.stats.linear_iterations << " | " << sci(p.angle_error) << " | "
        << sci(p.final_error) << " |";
    if (!scene.latches().empty()) out << ' ' << sci(p.latch_time_error) << " |";
    if (!scene.loops.empty()) out << ' ' << sci(p.max_loop_gap) << " |";
    out << '\n';
  }
  file.commit();
}

}  // namespace unfurl::app
