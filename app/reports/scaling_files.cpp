#include "scaling_files.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "unfurl/io/markdown.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::app {

void write_scaling_csv(const ScalingReport& report, const std::string& dir) {
  io::OutputFile rhs(dir + "/rhs_scaling.csv");
  rhs.stream() << "family,variant,size,bodies,loop_components,states,seconds_per_call,ns_per_body\n";
  for (const studies::RhsTiming& t : report.rhs)
    rhs.stream() << t.scene.family << ',' << t.scene.variant << ',' << t.scene.size << ',' << t.bodies << ','
                 << t.loop_components << ',' << t.states << ',' << sim::format_number(t.seconds_per_call) << ','
                 << sim::format_number(t.ns_per_body) << '\n';
  rhs.commit();
  io::OutputFile runs(dir + "/run_scaling.csv");
  runs.stream() << "family,size,bodies,states,method,status,t_reached,wall_time_s,steps,rhs_calls,jacobians,"
                   "linear_iterations,max_closure_gap\n";
  for (const studies::RunTiming& t : report.runs)
    runs.stream() << t.scene.family << ',' << t.scene.size << ',' << t.bodies << ',' << t.states << ",\"" << t.method
                  << "\"," << sim::run_status_name(t.status) << ',' << sim::format_number(t.t_reached) << ','
                  << sim::format_number(t.wall_time_s) << ',' << t.steps << ',' << t.rhs_calls << ',' << t.jacobians
                  << ',' << t.linear_iterations << ',' << sim::format_number(t.max_closure_gap) << '\n';
  runs.commit();
}

void write_scaling_markdown(const ScalingReport& report, const std::vector<std::string>& pictures,
                            const std::string& path) {
  io::OutputFile file(path);
  std::ostream& out = file.stream();
  char buf[512];
  out << "# Scaling: cost against the size of the mechanism\n\n";
  out << "Made by `" << report.command << "` on this machine (one core per run).\n\n";
  out << "## The right-hand side\n\n"
      << "One call of y' = f(y) at a moving state with the loops slightly open: the O(N) sweep, the forces and, "
         "with loops, the regulator's gains from the current W. Chains hang under gravity; z-folds and pantographs "
         "are the generated scenes of `unfurl generate`. The pantograph's gains use the dense solver up to 48 loop "
         "components and the sparse one beyond; \"dense gains\" forces the dense one (forming W costs O(N m), its "
         "Cholesky O(m^3)).\n\n";
  for (const std::string& p : pictures)
    if (p == "rhs_per_body.png") out << "![" << p << "](" << p << ")\n\n";
  out << "| mechanism | size | bodies | loop components | states | time per call | per body "
         "|\n|---|---|---|---|---|---|---|\n";
  for (const studies::RhsTiming& t : report.rhs) {
    std::snprintf(buf, sizeof buf, "| %s | %d | %d | %d | %d | %.3g us | %.0f ns |\n",
                  studies::family_label(t.scene).c_str(), t.scene.size, t.bodies, t.loop_components, t.states,
                  1e6 * t.seconds_per_call, t.ns_per_body);
    out << buf;
  }
  std::snprintf(buf, sizeof buf, "%g", report.run_t_end);
  out << "\n## Whole runs\n\n"
      << "The first " << buf << " s of each mechanism at rtol 1e-8, atol 1e-10: CVODE BDF with a dense "
      << "finite-difference Jacobian and LU (n right-hand sides and O(n^3) per setup), CVODE BDF with GMRES "
         "(Jacobian-vector products by difference quotients) preconditioned by one pass of the sweep, and the "
         "explicit ARKODE ERK. Each run has a budget of "
      << report.budget_s << " s of wall time; the dense solver is not tried beyond the size where it ran out.\n\n";
  for (const std::string& p : pictures)
    if (p == "run_wall_time.png") out << "![" << p << "](" << p << ")\n\n";
  out << "| mechanism | bodies | states | method | result | wall time, s | steps | RHS calls | Jacobians | GMRES "
         "iterations | max closure, m |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const studies::RunTiming& t : report.runs) {
    const std::string result = t.status == sim::RunStatus::finished ? "finished" : t.failure;
    std::snprintf(buf, sizeof buf, "| %.3g | %ld | %ld | %ld | %ld | %.2e |\n", t.wall_time_s, t.steps, t.rhs_calls,
                  t.jacobians, t.linear_iterations, t.max_closure_gap);
    out << "| " << t.scene.family << ' ' << t.scene.size << " | " << t.bodies << " | " << t.states << " | " << t.method
        << " | " << io::table_cell(result) << ' ' << buf;
  }
  file.commit();
}

}  // namespace unfurl::app
