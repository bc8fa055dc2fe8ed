#include "stability_files.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "unfurl/io/markdown.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::app {

namespace {

std::string sci(double x) {
  if (!std::isfinite(x)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string fixed(double x, const char* format) {
  char buf[32];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

std::string outcome(const studies::StabilityResult& r) {
  std::string s = r.status == sim::RunStatus::finished ? "finished" : r.failure;
  if (r.status == sim::RunStatus::failed) s = "failed: " + s;
  s = io::table_cell(s);
  if (r.spec.probe) return s;
  if (!r.spec.expected_check.empty())
    s += studies::as_expected(r) ? " (expected)" : " (**expected the " + r.spec.expected_check + " check to fail**)";
  else if (!studies::as_expected(r))
    s += " (**expected to finish**)";
  return s;
}

}  // namespace

void write_stability_csv(const StabilityReport& report, const std::string& path) {
  io::OutputFile file(path);
  std::ostream& out = file.stream();
  out << "group,case,scene,status,as_expected,failed_check,t_reached,wall_time_s,steps,rhs_calls,min_step,bodies,"
         "loop_components,energy_initial,energy_final,energy_drift,max_closure_gap,max_closure_angle,"
         "latches_engaged,latches_total\n";
  for (const studies::StabilityResult& r : report.results)
    out << r.spec.group << ',' << '"' << r.spec.label << '"' << ',' << r.spec.scene << ','
        << sim::run_status_name(r.status) << ',' << (studies::as_expected(r) ? "yes" : "no") << ',' << r.failed_check
        << ',' << sim::format_number(r.t_reached) << ',' << sim::format_number(r.wall_time_s) << ',' << r.steps << ','
        << r.rhs_calls << ',' << sim::format_number(r.min_step) << ',' << r.bodies << ',' << r.loop_components << ','
        << sim::format_number(r.energy_initial) << ',' << sim::format_number(r.energy_final) << ','
        << sim::format_number(r.energy_drift) << ',' << sim::format_number(r.max_closure_gap) << ','
        << sim::format_number(r.max_closure_angle) << ',' << r.latches_engaged << ',' << r.latches_total << '\n';
  file.commit();
}

void write_stability_markdown(const StabilityReport& report, const std::vector<std::string>& pictures,
                              const std::string& path) {
  io::OutputFile file(path);
  std::ostream& out = file.stream();
  int expected = 0;
  for (const studies::StabilityResult& r : report.results) expected += studies::as_expected(r) ? 1 : 0;
  out << "# Stability: stiff and extreme cases\n\n";
  out << "Made by `" << report.command << "`. Each case is a scene pushed to an extreme and run to its end or to a "
      << "clear failure (which check, at what time and step); every run has a budget of " << report.budget_s
      << " s of wall time. " << expected << " of " << report.results.size()
      << " cases ended as expected. The command under each table reproduces a case.\n\n";

  // The largest latch stiffness per integrator.
  std::map<std::string, std::pair<const studies::StabilityResult*, const studies::StabilityResult*>>
      limits;  // last ok, first failure
  for (const studies::StabilityResult& r : report.results) {
    if (r.spec.group != "latch stiffness") continue;
    auto& l = limits[r.spec.label.substr(r.spec.label.find(", ") + 2)];
    const bool handled = r.status == sim::RunStatus::finished && !r.energy_rose;
    if (handled && !l.second) l.first = &r;
    if (!handled && !l.second) l.second = &r;
  }
  if (!limits.empty()) {
    out << "## The largest latch stiffness each integrator handles\n\n"
        << "The pantograph with all eight latches at k_L = 1e3 ... 1e9 N m/rad (adaptive methods at rtol 1e-8, RK4 at "
           "dt = 2e-4 s), within the time budget. A run counts as handled when it finishes with a physical result (its "
           "energy does not rise).\n\n"
        << "| integrator | largest k_L handled | its wall time, s | beyond it |\n|---|---|---|---|\n";
    for (const auto& [name, l] : limits)
      out << "| " << name << " | "
          << (l.first ? l.first->spec.label.substr(6, l.first->spec.label.find(',') - 6) : "none") << " | "
          << (l.first ? fixed(l.first->wall_time_s, "%.3g") : "-") << " | "
          << (l.second ? l.second->spec.label.substr(0, l.second->spec.label.find(',')) + ": " +
                             io::table_cell(l.second->status == sim::RunStatus::finished ? l.second->notes.back()
                                                                                         : l.second->failure)
                       : "finished up to 1e9")
          << " |\n";
    out << "\n";
  }
  if (report.has_gains) {
    const studies::GainComparison& g = report.gains;
    out << "## The regulator's tuning on the pantograph\n\n"
        << "The paper's diagonal gains (16), from the diagonal of W at t = 0, against the full-matrix gains from the "
           "current W. The paper's run is let go past the closure check (up to loops open by 1e3) to show where it "
           "goes: "
        << (g.paper_status == sim::RunStatus::finished ? "it ran to the end" : g.paper_failure) << ", with "
        << g.paper_latches << " of 8 latches (full gains: " << g.full_latches
        << "). With diagonal gains a residual mode along an eigenvector of K = W diag(W)^-1 is stable only if its "
           "eigenvalue a exceeds the Routh bound "
        << g.routh_bound << "; along the run the smallest a stays between ";
    double lo = INFINITY, hi = 0;
    for (double a : g.smallest_eigen) lo = std::min(lo, a), hi = std::max(hi, a);
    out << sci(lo) << " and " << sci(hi) << ".\n\n";
    for (const std::string& p : pictures)
      if (p.rfind("gains_", 0) == 0) out << "![" << p << "](" << p << ")\n\n";
  }
  std::string group;
  for (const studies::StabilityResult& r : report.results) {
    if (r.spec.group != group) {
      group = r.spec.group;
      out << "## " << group << "\n\n";
      if (group == "regulator v_max")
        out << "The regulator acts on the true geometric gap, with the loop forces' feedforward of the residual's "
               "acceleration (regulator.hpp): in every strong mode of W the loop force is the constraint force, so "
               "even v_max = 1 rad/s keeps the loops within a millimetre, where the PID alone lets them open at "
               "v_max = 10. The regularization delta = 2e-6 of W's largest eigenvalue was checked again against this "
               "design: it holds every latch stiffness 1e3 .. 1e9 below 1e-8 m of gap and the angles before the "
               "latches within 3.5e-9 rad of the one-degree-of-freedom reduction (1e-5: 3.4e-8 rad, 3e-5: 7.4e-7 "
               "rad; 1e-4 lets the gap reach 3.5e-7 m at k_L = 1e7). At v_max = 1e5 the curvature of the gap along "
               "the modes W loses near the branch points, times v_max^2, makes BDF's Newton iterations fail step "
               "after step (delta = 1e-4 would pass it in 8 s, at the cost above): that case is a probe.\n\n";
      for (const std::string& p : pictures)
        if ((group == "latch stiffness" && p == "latch_stiffness.png") ||
            (group == "long run" && p == "long_run.png") || (group == "large array" && p == "large_arrays.png"))
          out << "![" << p << "](" << p << ")\n\n";
      out << "| case | result | t reached, s | steps | wall time, s | min step, s | energy E0 -> E_end, J | energy "
             "drift | max closure, m / rad | latches |\n|---|---|---|---|---|---|---|---|---|---|\n";
    }
    out << "| " << r.spec.label << " | " << outcome(r) << " | " << fixed(r.t_reached, "%g") << " | " << r.steps << " | "
        << fixed(r.wall_time_s, "%.3g") << " | " << sci(r.min_step) << " | " << fixed(r.energy_initial, "%.6g")
        << " -> " << fixed(r.energy_final, "%.6g") << " | " << sci(r.energy_drift) << " | "
        << (r.loop_components ? sci(r.max_closure_gap) + " / " + sci(r.max_closure_angle) : "no loops") << " | "
        << r.latches_engaged << " of " << r.latches_total << " |\n";
    for (const std::string& note : r.notes) out << "|  | " << io::table_cell(note) << " | | | | | | | | |\n";
    const bool last_of_group = &r == &report.results.back() || (&r + 1)->spec.group != group;
    if (last_of_group) {
      out << "\nReproduce:\n\n";
      for (const studies::StabilityResult& x : report.results)
        if (x.spec.group == group) out << "    " << studies::reproduce_command(x.spec) << "\n";
      out << "\n";
    }
  }
  file.commit();
}

}  // namespace unfurl::app
