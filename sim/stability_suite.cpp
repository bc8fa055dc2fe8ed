#include "stability_suite.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "dynamics.hpp"
#include "number_text.hpp"
#include "scene_generators.hpp"
#include "summary.hpp"

namespace unfurl {

namespace {

// Overrides that set one field of every latch (or spring) of a scene.
std::vector<Override> for_each_joint(const std::string& list, const std::string& field, double value, int joints) {
  std::vector<Override> out;
  for (int j = 0; j < joints; ++j) out.push_back({list + "." + std::to_string(j) + "." + field, format_number(value)});
  return out;
}

StabilityCase make(std::string group, std::string label, std::string scene, std::vector<Override> overrides,
                   double budget_s) {
  StabilityCase c;
  c.group = std::move(group);
  c.label = std::move(label);
  c.scene = std::move(scene);
  c.overrides = std::move(overrides);
  c.overrides.push_back({"run.max_wall_time", format_number(budget_s)});
  return c;
}

void latch_stiffness_cases(std::vector<StabilityCase>& out, double budget_s) {
  // 1e3 .. 1e7 N m/rad, then on to 1e9 to find where each integrator stops.
  for (IntegratorKind kind : all_integrators())
    for (double k : {1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9}) {
      std::vector<Override> o = for_each_joint("latches", "stiffness", k, 8);
      o.push_back({"run.integrator", integrator_name(kind)});
      // The adaptive methods at rtol 1e-8; RK4 at 2e-4 s, near its limit
      // with the regulator at v_max = 2000.
      o.push_back({"run.rtol", "1e-8"});
      o.push_back({"run.atol", "1e-10"});
      o.push_back({"run.dt", "2e-4"});
      StabilityCase c = make("latch stiffness", "k_L = " + format_number(k) + ", " + integrator_name(kind), "pantograph", o, budget_s);
      c.small = kind == IntegratorKind::cvode_bdf && k <= 1e5;
      c.probe = k > 1e7;
      out.push_back(c);
    }
}

void regulator_cases(std::vector<StabilityCase>& out, double budget_s) {
  // With the feedforward the loop forces cancel the residual's acceleration
  // in every strong mode, so even a regulator far below the mechanism's
  // frequencies holds the loops (to the weak modes' share at the branch
  // points); the PID alone does not.
  for (double v : {1.0, 10.0, 100.0, 1e3, 2e3, 1e4, 1e5}) {
    StabilityCase c = make("regulator v_max", "v_max = " + format_number(v) + " rad/s", "pantograph",
                           {{"regulator.v_max", format_number(v)}}, budget_s);
    c.small = v == 10 || v == 1e4;
    // Near the branch points the gap's curvature along the modes W loses,
    // times v_max^2, makes the Newton iterations fail step after step: the
    // limit is looked for, not assumed.
    c.probe = v >= 1e5;
    out.push_back(c);
  }
  StabilityCase bare = make("regulator v_max", "v_max = 10 rad/s without feedforward", "pantograph",
                            {{"regulator.v_max", "10"}, {"regulator.feedforward", "false"}}, budget_s);
  bare.expected_check = "closure";  // far below the latch impacts' frequencies the loops open
  bare.small = true;
  out.push_back(bare);
  StabilityCase paper = make("regulator tuning", "gains: paper (16), diagonal", "pantograph",
                             {{"regulator.gains", "paper"}}, budget_s);
  paper.expected_check = "closure";
  paper.small = true;
  out.push_back(paper);
  out.push_back(make("regulator tuning", "gains: full, from the current W", "pantograph", {}, budget_s));
}

void mass_ratio_cases(std::vector<StabilityCase>& out, double budget_s) {
  // Panel A2 of the z-fold scaled against its neighbours A1 and A3.
  for (double r : {1e-3, 1e-2, 1e-1, 10.0, 100.0, 1e3}) {
    const std::string inertia = "[" + format_number(0.4802 * r) + ", " + format_number(0.2702 * r) + ", " + format_number(0.75 * r) + "]";
    StabilityCase c = make("mass ratio", "panel A2 x " + format_number(r) + " (mass and inertia)", "zfold",
                           {{"bodies.panel_A2.mass", format_number(4.0 * r)}, {"bodies.panel_A2.inertia", inertia}}, budget_s);
    c.small = true;
    out.push_back(c);
  }
}

void singular_start_cases(std::vector<StabilityCase>& out, double budget_s) {
  StabilityCase stowed = make("singular start", "exact stowed state (a = pi/2)", "pantograph_stowed", {}, budget_s);
  stowed.branches = stowed.small = true;
  out.push_back(stowed);

  std::vector<Override> at_zero;
  for (int j = 1; j <= 11; ++j) at_zero.push_back({"initial.q.j" + std::to_string(j), "0"});
  StabilityCase deployed = make("singular start", "fully deployed state (q = 0)", "pantograph", at_zero, budget_s);
  deployed.branches = deployed.small = true;
  out.push_back(deployed);

  // The cross pivot of loop A1 turned by 1e-3 rad: the loop starts open.
  const Scene reference = load_builtin_scene("pantograph");
  StabilityCase open = make("singular start", "loop A1 open by 1e-3 rad at the start", "pantograph",
                            {{"closure_tolerance", "0.01"},
                             {"initial.q.j9", format_number(reference.q0[8] + 1e-3)},
                             {"run.sample", "1e-4"}},
                            budget_s);
  open.closing_time = open.small = true;
  out.push_back(open);
}

void long_run_cases(std::vector<StabilityCase>& out, double budget_s) {
  StabilityCase c = make("long run", "four-bar without damping, 1e4 s", "fourbar",
                         {{"run.t_end", "1e4"}, {"run.sample", "1"}}, budget_s);
  c.conservative = true;
  out.push_back(c);
  StabilityCase short_run = make("long run", "four-bar without damping, 100 s", "fourbar",
                                 {{"run.t_end", "100"}, {"run.sample", "0.1"}}, budget_s);
  short_run.conservative = short_run.small = true;
  out.push_back(short_run);
}

void large_array_cases(std::vector<StabilityCase>& out, double budget_s) {
  for (const char* kind : {"pantograph", "zfold"})
    for (int n : {3, 10, 100, 1000}) {
      // The largest are benchmarks: they get five times the budget.
      StabilityCase c = make("large array", std::string(kind) + " of " + std::to_string(n) +
                                                (std::string(kind) == "zfold" ? " panels" : " stages") + ", 1 s",
                             std::string(kind) + ":" + std::to_string(n), {{"run.t_end", "1"}},
                             n >= 1000 ? 5 * budget_s : budget_s);
      c.small = n <= 10;
      out.push_back(c);
    }
}

double largest_gap(const Sample& s);

// The first time the largest loop gap is below `level`.
double closing_time(const Trajectory& tr, double level) {
  for (const Sample& s : tr.samples)
    if (largest_gap(s) < level) return s.t;
  return std::numeric_limits<double>::quiet_NaN();
}

// The largest geometric gap of any loop, metres or radians.
double largest_gap(const Sample& s) {
  double r = 0;
  for (const ClosureError& c : s.closure) r = std::max({r, c.distance, c.angle});
  return r;
}

}  // namespace

bool StabilityResult::as_expected() const {
  if (spec.probe) return status == RunStatus::finished || (status == RunStatus::failed && !failed_check.empty());
  if (spec.expected_check.empty()) return status == RunStatus::finished;
  return status == RunStatus::failed && failed_check == spec.expected_check;
}

std::vector<StabilityCase> stability_cases(double budget_s) {
  std::vector<StabilityCase> out;
  latch_stiffness_cases(out, budget_s);
  regulator_cases(out, budget_s);
  mass_ratio_cases(out, budget_s);
  singular_start_cases(out, budget_s);
  long_run_cases(out, budget_s);
  large_array_cases(out, budget_s);
  return out;
}

Scene stability_scene(const StabilityCase& c) {
  const auto colon = c.scene.find(':');
  if (colon == std::string::npos) return load_builtin_scene(c.scene, c.overrides);
  const std::string kind = c.scene.substr(0, colon);
  const int n = std::stoi(c.scene.substr(colon + 1));
  const std::string text = kind == "pantograph" ? generate_pantograph(n) : generate_zfold(n);
  return load_scene_text(text, "generated:" + c.scene, c.overrides);
}

std::string reproduce_command(const StabilityCase& c) {
  std::string command;
  std::string scene = c.scene;
  if (const auto colon = c.scene.find(':'); colon != std::string::npos) {
    const std::string kind = c.scene.substr(0, colon), n = c.scene.substr(colon + 1);
    scene = kind + "_" + n + ".yaml";
    command = "unfurl generate " + kind + (kind == "zfold" ? " --panels " : " --stages ") + n + " -o " + scene + " && ";
  }
  command += "unfurl simulate " + scene;
  for (const Override& o : c.overrides) {
    const bool quote = o.value.find_first_of(" [,") != std::string::npos;
    command += " --set " + o.path + "=" + (quote ? "'" + o.value + "'" : o.value);
  }
  return command;
}

StabilityResult run_stability_case(const StabilityCase& c) {
  StabilityResult r;
  r.spec = c;
  const Scene scene = stability_scene(c);
  RunResult run = simulate(scene, scene.run);
  const RunSummary s = summarize(scene, run);
  r.status = run.status;
  if (run.status == RunStatus::failed) {
    r.failed_check = run.failure.check;
    r.failure = describe(run.failure);
  }
  r.t_reached = s.t_reached;
  r.wall_time_s = run.wall_time_s;
  r.min_step = run.stats.min_step;
  r.steps = run.stats.steps;
  r.rhs_calls = run.rhs_calls;
  r.bodies = scene.model.size();
  r.loop_components = run.trajectory.layout.m;
  r.energy_initial = s.energy_initial;
  r.energy_final = s.energy_final;
  r.max_closure_m = s.max_closure_m;
  r.max_closure_rad = s.max_closure_rad;
  r.latches_engaged = static_cast<int>(s.latch_times.size());
  r.latches_total = static_cast<int>(scene.latches.size());
  if (c.conservative) {
    double drift = 0;
    for (const Sample& x : run.trajectory.samples) drift = std::max(drift, std::abs(x.energy.total() - s.energy_initial));
    r.energy_drift = drift / std::abs(s.energy_initial);
  }
  if (c.branches) r.notes = describe_branches(scene, run.trajectory);
  r.energy_rose = !c.conservative && s.energy_final - s.energy_initial > 0.01 * std::abs(s.energy_initial) + 1e-9;
  if (r.energy_rose) {
    std::ostringstream note;
    note << "energy rose from " << s.energy_initial << " to " << s.energy_final
         << " J: a passive mechanism cannot gain energy, so this run is not physical";
    r.notes.push_back(note.str());
  }
  if (c.closing_time && !run.trajectory.empty()) {
    std::ostringstream note;
    note << "started open by a gap of " << largest_gap(run.trajectory.samples.front())
         << "; below 1e-3 of that at t = " << closing_time(run.trajectory, 1e-3 * largest_gap(run.trajectory.samples.front()))
         << " s, below 1e-9 at t = " << closing_time(run.trajectory, 1e-9) << " s (designed slowest pole: b0 = p0 v_max = "
         << scene.regulator.p0 * scene.regulator.v_max << " 1/s)";
    r.notes.push_back(note.str());
  }
  if (c.conservative) r.trajectory = std::move(run.trajectory);
  return r;
}

std::vector<std::string> describe_branches(const Scene& scene, const Trajectory& trajectory) {
  const Model& model = scene.model;
  std::vector<std::string> out;
  if (trajectory.empty()) return out;
  const Sample &first = trajectory.samples.front(), &last = trajectory.samples.back();
  for (const Loop& loop : scene.loops) {
    // The joints from the split body and from its image up to their common
    // ancestor: the loop's path through the tree.
    std::vector<int> a, b;
    for (int i = loop.body; i != kBase; i = model.parent[i]) a.push_back(i);
    for (int i = loop.image; i != kBase; i = model.parent[i]) b.push_back(i);
    while (!a.empty() && !b.empty() && a.back() == b.back()) a.pop_back(), b.pop_back();
    a.insert(a.end(), b.rbegin(), b.rend());
    std::string opened, held, between;
    for (int i : a) {
      const int c = model.coordinate[i];
      if (c < 0) continue;
      const double moved = std::abs(last.y[c] - first.y[c]);
      std::string& list = moved > 0.1 ? opened : moved < 0.01 ? held : between;
      list += (list.empty() ? "" : ", ") + model.joints[i].name;
    }
    std::string note = "loop " + loop.name + ": ";
    note += held.empty() ? "every joint of the loop moved (the lazy-tongs path)" : "held " + held + "; opened " + (opened.empty() ? "none" : opened);
    if (!between.empty()) note += "; moved a little " + between;
    out.push_back(note);
  }
  return out;
}

GainComparison compare_gain_tunings(double budget_s) {
  GainComparison g;
  const Scene full = load_builtin_scene("pantograph", {{"run.max_wall_time", format_number(budget_s)}});
  // The paper's run is let go past the closure check, up to loops open by
  // metres, to show where it goes.
  const Scene paper = load_builtin_scene(
      "pantograph", {{"regulator.gains", "paper"}, {"run.max_closure", "1e3"}, {"run.max_wall_time", format_number(budget_s)}});
  const RunResult run_full = simulate(full, full.run), run_paper = simulate(paper, paper.run);
  for (const Sample& s : run_full.trajectory.samples) {
    g.t_full.push_back(s.t);
    g.residual_full.push_back(largest_gap(s));
  }
  for (const Sample& s : run_paper.trajectory.samples) {
    g.t_paper.push_back(s.t);
    g.residual_paper.push_back(largest_gap(s));
  }
  g.paper_status = run_paper.status;
  if (run_paper.status == RunStatus::failed) g.paper_failure = describe(run_paper.failure);
  g.paper_latches = static_cast<int>(run_paper.trajectory.events.size());
  g.full_latches = static_cast<int>(run_full.trajectory.events.size());

  // a = eigenvalues of K = W diag(W(0))^-1 (the paper's gains come from W
  // at t = 0), similar to the symmetric diag(W(0))^-1/2 W diag(W(0))^-1/2.
  Dynamics dynamics(full);
  Regulator& regulator = *dynamics.regulator();
  Sweep sweep(full.model);
  const RegulatorSettings& r = full.regulator;
  g.routh_bound = r.p0 / ((r.p0 + 2 * r.p1) * (1 + 2 * r.p0 * r.p1));
  sweep.set_configuration(full.q0.data());
  const Eigen::VectorXd scale = regulator.mobility(sweep).diagonal().cwiseSqrt().cwiseInverse();
  for (std::size_t k = 0; k < run_full.trajectory.samples.size(); k += 5) {
    const Sample& s = run_full.trajectory.samples[k];
    sweep.set_configuration(s.y.data());
    const Eigen::MatrixXd W = regulator.mobility(sweep);
    const Eigen::MatrixXd K = scale.asDiagonal() * W * scale.asDiagonal();
    g.t_eigen.push_back(s.t);
    g.smallest_eigen.push_back(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K, Eigen::EigenvaluesOnly).eigenvalues()(0));
  }
  return g;
}

}  // namespace unfurl
