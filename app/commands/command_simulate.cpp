// unfurl simulate: run a scene and write trajectory.csv, events.csv and
// summary.json.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>
#include <iostream>
#include <utility>

#include "cli.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "unfurl/io/output_file.hpp"
#include "progress.hpp"
#include "unfurl/io/run_files.hpp"
#include "scene_clearance.hpp"
#include "scene_options.hpp"
#include "unfurl/sim/elements/elasticity.hpp"
#include "unfurl/sim/summary.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl simulate [SCENE] [--out DIR] [--t-end T] [--integrator NAME] [--rtol X]\n"
    "                       [--atol X] [--dt X] [--sample DT] [--set KEY=VALUE ...]\n"
    "\n"
    "Simulates a scene and writes into DIR (default out/), each CSV header cell\n"
    "\"name [unit; frame]\" (docs/OUTPUTS.md lists every column):\n"
    "  trajectory.csv   t, then q.J, dq.J, p.J per joint, closure_gap.L and closure_angle.L\n"
    "                   (the geometric gap) per loop, and energy, every DT seconds\n"
    "  loads.csv        per joint its elements' torques (spring_torque.J, latch_torque.J,\n"
    "                   ...) and the reaction at the hinge, hinge_force.J and\n"
    "                   hinge_moment.J (child frame); per loop component the constraint\n"
    "                   force; other elements' columns (tension.NAME), at the same times\n"
    "  events.csv       latch engagements (t, event, joint)\n"
    "  summary.json     integrator, statistics, latch times, peak loads, largest loop gap,\n"
    "                   torque margins, clearance (the closest approach of bodies not\n"
    "                   jointed together, and any contact), energy, and the units of its numbers\n"
    "\n"
    "options:\n"
    "  --out DIR             output directory (default out)\n"
    "%s"
    "  --quiet               print nothing but errors\n"
    "\n"
    "Exit status: 0 done, 1 the solver failed (what it computed is written), 2 bad scene,\n"
    "64 bad usage.\n";

// The largest of the per-joint peaks, or nullptr if none was reached.
const sim::RunSummary::NamedPeak* largest(const std::vector<sim::RunSummary::NamedPeak>& peaks) {
  const sim::RunSummary::NamedPeak* best = nullptr;
  for (const auto& p : peaks)
    if (!std::isnan(p.peak.t) && (!best || p.peak.value > best->peak.value)) best = &p;
  return best;
}

// The peak hinge force where the motion determines it, and a warning where
// it does not (RunSummary::loads_determinate).
void print_hinge_force_peaks(const sim::RunSummary& s) {
  if (const auto* p = largest(s.peak_hinge_force))
    std::printf("             peak hinge force %.4g N at %s, t = %.6f s%s\n", p->peak.value, p->joint.c_str(), p->peak.t,
                s.indeterminate_spans.empty() ? "" : " (where determinate)");
  if (!s.loads_determinate.has_value()) {
    std::printf("warning      loads not checked for determinacy at some steps: the closure system could not be\n"
                "             factored there, and the regulator's loop forces stand\n");
    return;
  }
  if (*s.loads_determinate) return;
  std::printf("warning      loads indeterminate from t = %.6f s to %.6f s (%zu spans, %.4g s in all): the rigid\n"
              "             loops are redundant there, or so near it that the regulator's forces depart from\n"
              "             the rigid ones; the reactions inside them are the minimum-norm ones there, and\n"
              "             compliance in the loops determines them\n",
              s.indeterminate_spans.front()[0], s.indeterminate_spans.back()[1], s.indeterminate_spans.size(),
              sim::total_time(s.indeterminate_spans));
  if (const auto* p = largest(s.peak_hinge_force_indeterminate))
    std::printf("             indeterminate peak hinge force %.4g N at %s, t = %.6f s\n", p->peak.value,
                p->joint.c_str(), p->peak.t);
}

// Each element peak quantity's largest (a bushing's force), by name.
void print_element_peaks(const std::vector<sim::RunSummary::ElementPeakValue>& peaks, const char* label) {
  std::vector<const sim::RunSummary::ElementPeakValue*> largest_of;
  for (const auto& e : peaks) {
    if (std::isnan(e.peak.t)) continue;
    auto same = std::find_if(largest_of.begin(), largest_of.end(), [&](auto* o) { return o->quantity == e.quantity; });
    if (same == largest_of.end())
      largest_of.push_back(&e);
    else if (e.peak.value > (*same)->peak.value)
      *same = &e;
  }
  for (const auto* e : largest_of) {
    std::string what = e->quantity.substr(e->quantity.rfind("peak_", 0) == 0 ? 5 : 0);
    std::replace(what.begin(), what.end(), '_', ' ');
    std::printf("%-13speak %s %.4g %s at %s, t = %.6f s", e == largest_of.front() ? label : "", what.c_str(),
                e->peak.value, e->unit.c_str(), e->name.c_str(), e->peak.t);
    if (e->quantity == "peak_acceleration") std::printf(" (%.3g g)", e->peak.value / sim::kStandardGravity);
    std::printf("\n");
  }
}

// A flexible body bent beyond what its model is meant for.
void print_large_deflections(const sim::Scene& scene, const sim::RunSummary& s) {
  for (const auto& e : s.element_peaks) {
    if (e.quantity != "peak_deflection" || std::isnan(e.peak.t)) continue;
    const std::optional<int> body = scene.model.find_body(e.name);
    if (!body || !scene.model.bodies[*body].flexible) continue;
    const double size = scene.model.bodies[*body].flexible->size();
    if (e.peak.value > sim::Elasticity::kLargeDeflection * size)
      std::printf("warning      %s deflects %.3g m at t = %.6f s, %.0f %% of its %.3g m: a flexible body is a small\n"
                  "             deformation on a floating frame, its errors growing as the square of that\n"
                  "             share; past a tenth of its size its results are not the structure's\n",
                  e.name.c_str(), e.peak.value, e.peak.t, 100 * e.peak.value / size, size);
  }
}

// The driven joints' smallest motorization factor, and every joint short of
// the required one by name.
void print_torque_margins(const sim::RunSummary& s) {
  if (s.interrupted) std::printf("margin       not computed: interrupted (the clearance neither)\n");
  if (s.torque_margins.empty()) return;
  const double required = s.torque_margin_factors.required;
  const sim::JointTorqueMargin* worst = &s.torque_margins.front();
  for (const auto& m : s.torque_margins)
    if (m.worst() < worst->worst()) worst = &m;
  const auto where = [](const sim::JointTorqueMargin& m) {
    char text[128];
    const bool run = m.worst_run >= 0 && (m.worst_quasi_static < 0 || m.run[m.worst_run].factor <=
                                                                          m.quasi_static[m.worst_quasi_static].factor);
    const sim::TorqueMarginPoint& p = run ? m.run[m.worst_run] : m.quasi_static[m.worst_quasi_static];
    if (run)
      std::snprintf(text, sizeof text, "at q = %.4g, t = %.4g s", p.q, p.t);
    else
      std::snprintf(text, sizeof text, "at q = %.4g (quasi-static)", p.q);
    return std::string(text);
  };
  std::printf("margin       smallest motorization factor %.3g at %s, %s (required %g: %s)\n", worst->worst(),
              worst->joint.c_str(), where(*worst).c_str(), required, s.torque_margins_pass() ? "every driven joint passes" : "FAILS");
  for (const auto& m : s.torque_margins)
    if (!m.passes(s.torque_margin_factors))
      std::printf("warning      torque margin of %s fails: motorization factor %.3g %s, below %g\n", m.joint.c_str(),
                  m.worst(), where(m).c_str(), required);
}

// The closest pair, every contact by name and span, and what was left out.
void print_clearance(const sim::RunSummary& s) {
  if (!s.clearance) return;
  const sim::Clearance& c = *s.clearance;
  if (const sim::PairClearance* p = c.closest()) {
    char beyond[96] = "all measured";
    if (c.pairs_beyond > 0)
      std::snprintf(beyond, sizeof beyond, "%ld certified beyond %.3g m", c.pairs_beyond, c.listed_within);
    std::printf("clearance    closest %.4g m, %s and %s at t = %.6f s (%zu pairs, %s; %d samples, %.3g s)\n",
                p->distance, p->body_a.c_str(), p->body_b.c_str(), p->t, c.pairs.size(), beyond, c.samples,
                c.wall_time_s);
  } else
    std::printf("clearance    no two bodies that are not jointed together both have a solid\n");
  for (const sim::ClearanceContact& x : c.contacts) {
    if (x.t_begin == x.t_end)
      std::printf("warning      %s and %s touch or interpenetrate at t = %.6f s%s\n", x.body_a.c_str(),
                  x.body_b.c_str(), x.t_begin, x.at_start ? " (at the start)" : "");
    else
      std::printf("warning      %s and %s touch or interpenetrate from t = %.6f s to %.6f s%s\n", x.body_a.c_str(),
                  x.body_b.c_str(), x.t_begin, x.t_end, x.at_start ? " (from the start: the stowed solids overlap)" : "");
  }
  // A build without the renderer reads no meshes: one line says so, not a
  // warning per body.
  std::size_t unbuilt = 0;
  for (const std::string& u : c.unread) {
    if (u.find(studies::kNoMeshReader) != std::string::npos)
      ++unbuilt;
    else
      std::printf("warning      clearance left out %s\n", u.c_str());
  }
  if (unbuilt > 0)
    std::printf("clearance    %zu bodies' meshes left out (%s): declare their collision: shapes\n", unbuilt,
                studies::kNoMeshReader);
}

void print_summary(const sim::Scene& scene, const sim::RunResult& result, const sim::RunSummary& s,
                   const std::string& dir) {
  const sim::RunSettings& run = result.settings;
  std::printf("scene        %s (%s)\n", scene.name.c_str(), scene.source.c_str());
  std::printf("integrator   %s, rtol %g, atol %g", sim::integrator_name(run.integrator), run.rtol, run.atol);
  if (run.integrator == sim::IntegratorKind::rk4) std::printf(", dt %g", run.dt);
  std::printf("\nrun          0 .. %g s %s in %.3f s wall (%.1fx real time)\n", s.t_reached,
              sim::run_status_name(result.status), result.wall_time_s,
              result.wall_time_s > 0 ? s.t_reached / result.wall_time_s : 0.0);
  // A run that took no step (it failed at its start) has no smallest one.
  char min_step[32] = "none";
  if (std::isfinite(result.stats.min_step)) std::snprintf(min_step, sizeof min_step, "%.3g s", result.stats.min_step);
  std::printf("work         %ld steps, %ld right-hand sides, %ld Jacobians, min step %s\n", result.stats.steps,
              result.rhs_calls, result.stats.jacobian_evals, min_step);
  if (result.jacobian_product_evals > 0)
    std::printf("             %ld evaluations for Jacobian products (gains held, cheaper)\n",
                result.jacobian_product_evals);
  for (const sim::ToleranceRaise& r : result.tolerance_raises)
    std::printf(
        "tolerance    rtol %.2g, atol %.2g from t = %.6f s, where the Newton iteration kept failing:\n"
        "             the right-hand side's round-off there is %.2g; below it no step fits\n"
        "             its noise inside the error test (summary.json tolerance_raises)\n",
        r.rtol, r.atol, r.t, r.floor);
  if (run.integrator != sim::IntegratorKind::rk4 && result.tolerance_raises.empty()) {
    const double tolerance = std::max(run.rtol, run.atol);
    const bool at_start = tolerance < result.roundoff_floor, at_end = tolerance < result.roundoff_floor_end;
    if (at_start || at_end) {
      const double floor = std::max(result.roundoff_floor, result.roundoff_floor_end);
      std::printf("warning      rtol %g lies below the right-hand side's round-off %s, %.2g (summary.json\n"
                  "             roundoff_floor): steps shrink to fit its noise and buy no accuracy there;\n"
                  "             rtol %g costs fewer for the accuracy the round-off allows\n",
                  run.rtol, at_start ? "from the start" : "where the run ended", floor,
                  std::pow(10.0, std::ceil(std::log10(floor))));
    }
  }
  if (!scene.latches().empty()) {
    std::printf("latches      %zu of %zu engaged\n", s.latch_times.size(), scene.latches().size());
    for (const auto& [joint, t] : s.latch_times) std::printf("               %-10s t = %.9f s\n", joint.c_str(), t);
    for (const auto& joint : s.unlatched) std::printf("               %-10s never latched\n", joint.c_str());
  }
  if (!scene.loops.empty()) {
    std::printf("loop gap     max %.3g m, %.3g rad (%.3g m, %.3g rad before the first latch)\n", s.max_closure_gap,
                s.max_closure_angle, s.max_closure_gap_before_latch, s.max_closure_angle_before_latch);
    const sim::RunPeaks& p = result.peaks;
    const int m = result.trajectory.layout.m;
    if (p.closure_rank_at_start >= 0)
      std::printf("loop rank    %d of %d equations independent at the start (%d redundant), lowest %d at t = %.6f s\n",
                  p.closure_rank_at_start, m, m - p.closure_rank_at_start, p.lowest_closure_rank,
                  p.lowest_closure_rank_t);
  }
  const sim::RunSummary::NamedPeak* latch = nullptr;
  for (const auto& p : s.peak_latch_torque)
    if (!std::isnan(p.peak.t) && (!latch || p.peak.value > latch->peak.value)) latch = &p;
  if (latch)
    std::printf("loads        peak latch torque %.4g N m at %s, t = %.6f s\n", latch->peak.value, latch->joint.c_str(),
                latch->peak.t);
  print_hinge_force_peaks(s);
  print_element_peaks(s.element_peaks, "");
  print_large_deflections(scene, s);
  print_element_peaks(s.sensor_peaks, "sensors");
  print_torque_margins(s);
  print_clearance(s);
  std::printf("energy       %.9g J at t = 0, %.9g J at t = %g s, %.9g J dissipated\n", s.energy_initial, s.energy_final,
              s.t_reached, s.energy_dissipated);
  if (s.energy_driven) std::printf("             %.9g J put in by the drivers\n", *s.energy_driven);
  if (s.free_bus)
    std::printf("bus          turned %.4g rad, peak rate %.4g rad/s; momentum drift %.2g (linear), %.2g (angular)\n",
                s.free_bus->final_attitude_change, s.free_bus->peak_rate, s.free_bus->linear_momentum_drift,
                s.free_bus->angular_momentum_drift);
  std::printf("files        %s/{trajectory,loads,events%s}.csv, %s/summary.json\n", dir.c_str(),
              scene.sensors.empty() ? "" : ",sensors", dir.c_str());
}

}  // namespace

int command_simulate(const std::vector<std::string>& argv) {
  std::set<std::string> valued = scene_flags();
  valued.insert("--out");
  const Args args(argv, valued, {"--help", "-h", "--quiet"});
  if (args.has("--help") || args.has("-h")) {
    std::printf(kHelp, scene_flags_help());
    return 0;
  }
  if (args.positionals().size() > 1) throw UsageError("simulate takes one SCENE (see --help)");
  const std::optional<std::string> scene_arg =
      args.positionals().empty() ? std::nullopt : std::optional(args.positionals()[0]);
  const sim::SceneFile file = read_scene(scene_arg, args);
  const sim::Scene& scene = file.scene;
  const std::string dir = args.get("--out").value_or("out");
  io::make_directory(dir);

  Progress progress("simulating " + scene.name, scene.run.t_end);
  const InterruptScope interrupt;
  // The clearance's work runs on a second core: the meshes' import beside
  // the run, the distances beside the torque margins and the writing of
  // the files (on the pantograph here 0.16 s and 0.1 s, its run 0.1 s).
  std::vector<std::string> unread;
  std::future<studies::BodySolids> solids =
      std::async(std::launch::async, [&] { return scene_solids(scene, file.visuals, &unread); });
  sim::RunObserver observer;
  observer.cancel = &interrupt.flag();
  if (!args.has("--quiet")) observer.on_progress = [&](const sim::StepProgress& p) { progress.update(p.t); };
  const sim::RunResult result = sim::simulate(scene, scene.run, observer);
  progress.finish();
  // An interrupt stops the summary too (on a large array its torque
  // margins and clearance take minutes): its files say what is missing.
  std::future<sim::Clearance> clearance = std::async(std::launch::async, [&] {
    return run_clearance(scene, solids.get(), std::move(unread), result.trajectory, &interrupt.flag());
  });
  sim::RunSummary summary = sim::summarize(scene, result, &interrupt.flag());

  io::write_trajectory_csv(scene, result.trajectory, dir + "/trajectory.csv");
  io::write_loads_csv(scene, result.trajectory, dir + "/loads.csv");
  io::write_events_csv(scene, result.trajectory, dir + "/events.csv");
  if (!scene.sensors.empty()) io::write_sensors_csv(scene, result.trajectory, dir + "/sensors.csv");
  summary.clearance = clearance.get();
  if (interrupt.signal() != 0) {
    summary.interrupted = true;
    summary.torque_margins.clear();
    summary.clearance.reset();
  }
  io::write_summary_json(scene, result, summary, dir + "/summary.json");
  if (!args.has("--quiet")) print_summary(scene, result, summary, dir);
  if (result.status == sim::RunStatus::failed) {
    std::fprintf(stderr, "unfurl simulate: %s\n(the results up to t = %g s are written)\n",
                 sim::describe(result.failure).c_str(), summary.t_reached);
    return 1;
  }
  if (result.status == sim::RunStatus::cancelled) {
    std::fprintf(stderr, "unfurl simulate: interrupted by %s at t = %g s\n(the results up to there are written)\n",
                 interrupt.signal_name(), summary.t_reached);
    return interrupt.exit_status();
  }
  if (summary.interrupted) {
    std::fprintf(stderr,
                 "unfurl simulate: interrupted by %s after the run, in its summary\n(the results are written; the "
                 "torque margins and clearance were not computed)\n",
                 interrupt.signal_name());
    return interrupt.exit_status();
  }
  return 0;
}

}  // namespace unfurl::app
