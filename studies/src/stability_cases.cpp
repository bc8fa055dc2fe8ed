#include "unfurl/studies/stability_cases.hpp"

#include "unfurl/sim/number_text.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl::studies {

namespace {

// Overrides that set one field of every latch (or spring) of a scene.
std::vector<sim::Override> for_each_joint(const std::string& list, const std::string& field, double value, int joints) {
  std::vector<sim::Override> out;
  for (int j = 0; j < joints; ++j)
    out.push_back({list + "." + std::to_string(j) + "." + field, sim::format_number(value)});
  return out;
}

StabilityCase make(std::string group, std::string label, std::string scene, std::vector<sim::Override> overrides,
                   double budget_s) {
  StabilityCase c;
  c.group = std::move(group);
  c.label = std::move(label);
  c.scene = std::move(scene);
  c.overrides = std::move(overrides);
  c.overrides.push_back({"run.max_wall_time", sim::format_number(budget_s)});
  return c;
}

void latch_stiffness_cases(std::vector<StabilityCase>& out, double budget_s) {
  // 1e3 .. 1e7 N m/rad, then on to 1e9 to find where each integrator stops.
  for (sim::IntegratorKind kind : sim::all_integrators())
    for (double k : {1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9}) {
      std::vector<sim::Override> o = for_each_joint("latches", "stiffness", k, 8);
      o.push_back({"run.integrator", sim::integrator_name(kind)});
      // The adaptive methods at rtol 1e-8; RK4 at 2e-4 s, near its limit
      // with the regulator at v_max = 2000.
      o.push_back({"run.rtol", "1e-8"});
      o.push_back({"run.atol", "1e-10"});
      o.push_back({"run.dt", "2e-4"});
      StabilityCase c = make("latch stiffness", "k_L = " + sim::format_number(k) + ", " + sim::integrator_name(kind),
                             "pantograph", o, budget_s);
      c.small = kind == sim::IntegratorKind::cvode_bdf && k <= 1e5;
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
    StabilityCase c = make("regulator v_max", "v_max = " + sim::format_number(v) + " rad/s", "pantograph",
                           {{"regulator.v_max", sim::format_number(v)}}, budget_s);
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
    const std::string inertia = "[" + sim::format_number(0.4802 * r) + ", " + sim::format_number(0.2702 * r) + ", " +
                                sim::format_number(0.75 * r) + "]";
    StabilityCase c =
        make("mass ratio", "panel A2 x " + sim::format_number(r) + " (mass and inertia)", "zfold",
             {{"bodies.panel_A2.mass", sim::format_number(4.0 * r)}, {"bodies.panel_A2.inertia", inertia}}, budget_s);
    c.small = true;
    out.push_back(c);
  }
}

void singular_start_cases(std::vector<StabilityCase>& out, double budget_s) {
  StabilityCase stowed = make("singular start", "exact stowed state (a = pi/2)", "pantograph_stowed", {}, budget_s);
  stowed.branches = stowed.small = true;
  out.push_back(stowed);

  std::vector<sim::Override> at_zero;
  for (int j = 1; j <= 11; ++j) at_zero.push_back({"initial.q.j" + std::to_string(j), "0"});
  StabilityCase deployed = make("singular start", "fully deployed state (q = 0)", "pantograph", at_zero, budget_s);
  deployed.branches = deployed.small = true;
  out.push_back(deployed);

  // The cross pivot of loop A1 turned by 1e-3 rad: the loop starts open.
  const sim::Scene reference = sim::load_builtin_scene("pantograph");
  StabilityCase open = make("singular start", "loop A1 open by 1e-3 rad at the start", "pantograph",
                            {{"closure_tolerance", "0.01"},
                             {"initial.q.j9", sim::format_number(reference.q0[8] + 1e-3)},
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

}  // namespace

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

sim::Scene stability_scene(const StabilityCase& c) {
  const auto colon = c.scene.find(':');
  if (colon == std::string::npos) return sim::load_builtin_scene(c.scene, c.overrides);
  const std::string kind = c.scene.substr(0, colon);
  const int n = std::stoi(c.scene.substr(colon + 1));
  return sim::apply_overrides(kind == "pantograph" ? generate_pantograph(n) : generate_zfold(n), c.overrides).scene;
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
  for (const sim::Override& o : c.overrides) {
    const bool quote = o.value.find_first_of(" [,") != std::string::npos;
    command += " --set " + o.path + "=" + (quote ? "'" + o.value + "'" : o.value);
  }
  return command;
}

}  // namespace unfurl::studies
