// unfurl report: error against run time for a scene (work-precision), and
// the stability suite of stiff and extreme cases.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli.hpp"
#include "commands.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/io/study_files.hpp"
#include "compliance_files.hpp"
#include "progress.hpp"
#include "scaling_files.hpp"
#include "stability_files.hpp"
#include "scene_options.hpp"
#include "unfurl/sim/number_text.hpp"
#include "work_precision_files.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl report [SCENE] [--out DIR] [--integrators LIST] [--tolerances LIST]\n"
    "                     [--steps LIST] [--repeats N] [--set KEY=VALUE ...] [--t-end T]\n"
    "       unfurl report --suite stiff [--out DIR] [--quick] [--budget S]\n"
    "       unfurl report --suite scaling [--out DIR] [--quick] [--budget S]\n"
    "       unfurl report --suite compliance [--out DIR] [--quick] [--studies DIR]\n"
    "\n"
    "Error against run time (work-precision): runs SCENE with each integrator over a range of\n"
    "tolerances (rk4 over a range of fixed steps), compares every run with a reference (the\n"
    "exact solution where the scene has one, else CVODE BDF at the tightest tolerance that\n"
    "runs) and writes into DIR (default report/):\n"
    "  work_precision.csv        every run: wall time (median of up to 3), steps, RHS calls,\n"
    "                            Jacobians, linear iterations, errors, loop gap, latches\n"
    "  work_precision.png        joint-angle error against wall time, one curve per integrator\n"
    "  work_precision_latch.png  latch-time error against wall time (scenes with latches)\n"
    "  work_precision_final.png  final-state error against wall time (scenes with latches)\n"
    "  WORK_PRECISION.md         the reference, the cheapest integrator for each accuracy, all runs\n"
    "\n"
    "options:\n"
    "  --out DIR             output directory (default report)\n"
    "  --integrators LIST    comma-separated (default: cvode-bdf,cvode-adams,arkode-erk,arkode-dirk,rk4)\n"
    "  --tolerances LIST     rtol values of the adaptive integrators, atol = rtol / 100\n"
    "                        (default 1e-3,1e-4,...,1e-10)\n"
    "  --steps LIST          fixed steps of rk4 in seconds (default 1e-2,5e-3,...,5e-5)\n"
    "  --repeats N           runs per setting for the median wall time (default 3)\n"
    "%s"
    "  --quiet               print nothing but errors\n"
    "\n"
    "\n"
    "--suite stiff: the stability suite. Latch stiffness 1e3 .. 1e7 per integrator (and on to\n"
    "1e9 to find each integrator's limit), regulator\n"
    "v_max 10 .. 1e5 and the paper's tuning against the full-matrix gains, mass ratios 1e-3 .. 1e3\n"
    "between neighbours, the exact stowed and deployed states and an open start, a four-bar\n"
    "without damping for 1e4 s, and generated arrays of 3 .. 1000 stages or panels. Writes\n"
    "STABILITY.md, stability.csv and plots into DIR (default stability/).\n"
    "\n"
    "--suite scaling: the right-hand side's time per body for chains, z-folds and pantographs of\n"
    "10 to 10,000 bodies, and the wall time of 1 s runs against size with CVODE BDF (dense and\n"
    "GMRES Newton solvers) and ARKODE ERK. Writes SCALING.md, rhs_scaling.csv, run_scaling.csv\n"
    "and plots into DIR (default scaling/).\n"
    "--suite compliance: the compliant pantograph's peak hinge and pin forces against its pins'\n"
    "stiffness (1e5 .. 1e8 N/m), nominal and with j1's spring 2 % stiffer, beside the rigid\n"
    "pantograph's. Writes COMPLIANCE.md, pin_stiffness.csv and pin_stiffness.png into DIR\n"
    "(default compliance/). --studies DIR: also compares the peak hinge forces of the Monte Carlo\n"
    "studies in DIR/pantograph_monte_carlo and DIR/pantograph_compliant_monte_carlo (cases.csv).\n"
    "  --quick               the small cases only\n"
    "  --budget S            wall-time budget of each run in seconds (default 120; scaling 300)\n"
    "\n"
    "Exit status: 0 done (for the suite: every case ended as expected), 1 no reference could be\n"
    "computed or a case did not end as expected, 2 bad scene, 64 bad usage.\n";

std::vector<double> number_list(const std::string& flag, const std::string& text) {
  std::vector<double> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !(x > 0) || !std::isfinite(x))
      throw UsageError(flag + " expects positive numbers separated by commas, got '" + item + "'");
    out.push_back(x);
  }
  if (out.empty()) throw UsageError(flag + " needs at least one value");
  return out;
}

std::vector<sim::IntegratorKind> integrator_list(const std::string& text) {
  std::vector<sim::IntegratorKind> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    const auto kind = sim::parse_integrator(item);
    if (!kind)
      throw UsageError("unknown integrator '" + item + "' (cvode-bdf, cvode-adams, arkode-erk, arkode-dirk, rk4)");
    out.push_back(*kind);
  }
  if (out.empty()) throw UsageError("--integrators needs at least one integrator");
  return out;
}

double budget(const Args& args, double fallback) {
  const double s = args.number("--budget", fallback);
  if (!(s > 0)) throw UsageError("--budget expects a positive number of seconds");
  return s;
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string s = "unfurl report";
  for (const std::string& a : argv) s += " " + a;
  return s;
}

int work_precision_report(const std::vector<std::string>& argv, const Args& args) {
  if (args.positionals().size() > 1) throw UsageError("report takes one SCENE (see --help)");
  const std::optional<std::string> scene_arg =
      args.positionals().empty() ? std::nullopt : std::optional(args.positionals()[0]);
  const sim::Scene scene = load_scene(scene_arg, args);
  studies::WorkPrecisionSettings settings;
  if (const auto v = args.get("--integrators")) settings.integrators = integrator_list(*v);
  if (const auto v = args.get("--tolerances")) settings.tolerances = number_list("--tolerances", *v);
  if (const auto v = args.get("--steps")) settings.rk4_steps = number_list("--steps", *v);
  if (const auto n = args.number("--repeats")) {
    if (*n != std::floor(*n) || *n < 1 || *n > 100) throw UsageError("--repeats expects a whole number from 1 to 100");
    settings.repeats = static_cast<int>(*n);
  }
  const std::string dir = args.get("--out").value_or("report");
  io::make_directory(dir);
  const bool quiet = args.has("--quiet");

  Progress progress("report " + scene.name, 1);
  const studies::ReportProgress on_progress = [&](const std::string& what, int done, int total) {
    if (!quiet) progress.update(static_cast<double>(done) / total, what);
  };
  const studies::WorkPrecision report = studies::measure_work_precision(scene, settings, on_progress);
  progress.finish();

  write_work_precision_csv(report, dir + "/work_precision.csv");
  const std::vector<std::string> pictures = write_work_precision_plots(scene, report, dir);
  write_work_precision_markdown(scene, report, pictures, command_line(argv), dir + "/WORK_PRECISION.md");
  if (quiet) return 0;
  std::printf("scene        %s (%s)\n", scene.name.c_str(), scene.source.c_str());
  std::printf("reference    %s\n", report.reference.c_str());
  std::printf("runs         %zu\n", report.points.size());
  std::printf("cheapest     angle error   integrator    setting        wall time\n");
  for (const studies::CheapestRun& c : studies::cheapest_by_accuracy(report)) {
    if (!c.point) continue;
    char setting[32];
    if (c.point->integrator == sim::IntegratorKind::rk4)
      std::snprintf(setting, sizeof setting, "dt %g", c.point->dt);
    else
      std::snprintf(setting, sizeof setting, "rtol %g", c.point->rtol);
    std::printf("             <= %-10.0e %-13s %-14s %.4g s\n", c.accuracy, sim::integrator_name(c.point->integrator),
                setting, c.point->wall_time_s);
  }
  std::printf("files        %s/work_precision.csv, %s/WORK_PRECISION.md", dir.c_str(), dir.c_str());
  for (const std::string& p : pictures) std::printf(", %s/%s", dir.c_str(), p.c_str());
  std::printf("\n");
  return 0;
}

// Sizes (links, panels, stages) of each family, about 10 .. 10,000 bodies.
const std::vector<std::pair<std::string, std::vector<int>>>& rhs_sizes() {
  static const std::vector<std::pair<std::string, std::vector<int>>> sizes{
      {"chain", {10, 30, 100, 300, 1000, 3000, 10000}},
      {"zfold", {9, 29, 99, 299, 999, 2999, 9999}},
      {"pantograph", {3, 10, 33, 100, 333, 1000, 3333}}};
  return sizes;
}

int scaling_report(const std::vector<std::string>& argv, const Args& args) {
  ScalingReport report;
  report.command = command_line(argv);
  report.budget_s = budget(args, 300);
  const bool quick = args.has("--quick"), quiet = args.has("--quiet");
  const int largest = quick ? 300 : 1'000'000;
  const std::string dir = args.get("--out").value_or("scaling");
  io::make_directory(dir);

  std::vector<studies::ScalingScene> rhs_scenes;
  for (const auto& [family, sizes] : rhs_sizes())
    for (int n : sizes)
      if (n <= largest) rhs_scenes.push_back({family, n, "", {}});
  for (int n : {3, 5, 8, 12, 16})
    rhs_scenes.push_back({"pantograph", n, "dense gains", {{"regulator.solver", "dense"}}});
  struct RunPlan {
    studies::ScalingScene scene;
    sim::IntegratorKind integrator;
    sim::LinearSolverKind solver;
  };
  std::vector<RunPlan> plans;
  const std::pair<const char*, std::vector<int>> run_sizes[] = {{"pantograph", {3, 10, 30, 100, 300, 1000}},
                                                                {"zfold", {3, 10, 100, 1000, 3000}}};
  for (const auto& [family, sizes] : run_sizes)
    for (const auto& [integrator, solver] :
         {std::pair{sim::IntegratorKind::cvode_bdf, sim::LinearSolverKind::dense},
          std::pair{sim::IntegratorKind::cvode_bdf, sim::LinearSolverKind::krylov},
          std::pair{sim::IntegratorKind::arkode_erk, sim::LinearSolverKind::automatic}})
      for (int n : sizes)
        if (n <= (quick ? 10 : largest)) plans.push_back({{family, n, "", {}}, integrator, solver});

  Progress progress("scaling suite", static_cast<double>(rhs_scenes.size() + plans.size()));
  double done = 0;
  for (const studies::ScalingScene& s : rhs_scenes) {
    if (!quiet) progress.update(done++, "rhs " + s.family + " " + std::to_string(s.size));
    report.rhs.push_back(studies::time_right_hand_side(s, quick ? 0.2 : 1.0));
  }
  std::string gave_up;  // family and method that ran out of budget: larger sizes are skipped
  for (const RunPlan& p : plans) {
    if (!quiet) progress.update(done++, "run " + p.scene.family + " " + std::to_string(p.scene.size));
    const std::string key =
        p.scene.family + sim::integrator_name(p.integrator) + std::to_string(static_cast<int>(p.solver));
    if (key == gave_up) continue;
    report.runs.push_back(studies::time_whole_run(p.scene, p.integrator, p.solver, report.run_t_end, report.budget_s));
    if (report.runs.back().status != sim::RunStatus::finished) gave_up = key;
  }
  progress.finish();
  write_scaling_csv(report, dir);
  const std::vector<std::string> pictures = write_scaling_plots(report, dir);
  write_scaling_markdown(report, pictures, dir + "/SCALING.md");
  if (!quiet)
    std::printf(
        "scaling      %zu right-hand sides, %zu runs\nfiles        %s/SCALING.md, %s/rhs_scaling.csv, "
        "%s/run_scaling.csv and %zu plots\n",
        report.rhs.size(), report.runs.size(), dir.c_str(), dir.c_str(), dir.c_str(), pictures.size());
  return 0;
}

int compliance_report(const std::vector<std::string>& argv, const Args& args) {
  if (!args.positionals().empty()) throw UsageError("--suite runs its own scenes: give no SCENE");
  ComplianceReport report;
  report.command = command_line(argv);
  report.rtol = 1e-8;
  report.t_end = 9;
  const bool quick = args.has("--quick"), quiet = args.has("--quiet");
  const std::string dir = args.get("--out").value_or("compliance");
  io::make_directory(dir);
  const std::vector<double> stiffnesses =
      quick ? std::vector<double>{1e5, 1e6, 1e7} : std::vector<double>{1e5, 3e5, 1e6, 3e6, 1e7, 3e7, 1e8};
  const int deployments = static_cast<int>(studies::pin_stiffness_deployments().size());
  Progress progress("compliance suite", static_cast<double>(deployments * (stiffnesses.size() + 1)));
  double done = 0;
  for (int d = 0; d < deployments; ++d) {
    for (const double k : stiffnesses) {
      if (!quiet) progress.update(done++, "pins " + sim::format_number(k) + " N/m");
      report.compliant.push_back(studies::run_compliant_pins(d, k, report.rtol, report.t_end));
    }
    if (!quiet) progress.update(done++, "rigid");
    report.rigid.push_back(studies::run_rigid_pins(d, report.rtol, report.t_end));
  }
  progress.finish();
  if (const auto studies_dir = args.get("--studies")) {
    for (const auto& [label, study] : {std::pair{"rigid", "pantograph_monte_carlo"},
                                       std::pair{"compliant", "pantograph_compliant_monte_carlo"}}) {
      MonteCarloHingeForces m{label, std::string(study) + "/cases.csv", {}};
      m.peak_hinge_force = io::read_cases_column(*studies_dir + "/" + m.cases_csv, "peak_hinge_force");
      std::sort(m.peak_hinge_force.begin(), m.peak_hinge_force.end());
      report.monte_carlo.push_back(std::move(m));
    }
  }
  write_compliance_csv(report, dir + "/pin_stiffness.csv");
  const std::vector<std::string> pictures = write_compliance_plots(report, dir);
  write_compliance_markdown(report, pictures, dir + "/COMPLIANCE.md");
  int failed = 0;
  for (const auto* cases : {&report.compliant, &report.rigid})
    for (const studies::PinStiffnessCase& c : *cases)
      if (c.loads.status != sim::RunStatus::finished) {
        ++failed;
        std::fprintf(stderr, "unfurl report: pins %g N/m did not finish: %s\n", c.stiffness, c.loads.failure.c_str());
      }
  if (!quiet)
    std::printf("compliance   %zu runs\nfiles        %s/COMPLIANCE.md, %s/pin_stiffness.csv and %zu plots\n",
                report.compliant.size() + report.rigid.size(), dir.c_str(), dir.c_str(), pictures.size());
  return failed == 0 ? 0 : 1;
}

int stability_report(const std::vector<std::string>& argv, const Args& args) {
  if (args.get("--suite") == "scaling") return scaling_report(argv, args);
  if (args.get("--suite") == "compliance") return compliance_report(argv, args);
  if (args.get("--suite") != "stiff")
    throw UsageError("unknown suite '" + *args.get("--suite") + "' (stiff, scaling, compliance)");
  if (!args.positionals().empty()) throw UsageError("--suite runs its own scenes: give no SCENE");
  StabilityReport report;
  report.command = command_line(argv);
  report.budget_s = budget(args, 120);
  const bool quick = args.has("--quick"), quiet = args.has("--quiet");
  const std::string dir = args.get("--out").value_or("stability");
  io::make_directory(dir);
  std::vector<studies::StabilityCase> cases = studies::stability_cases(report.budget_s);
  if (quick)
    cases.erase(std::remove_if(cases.begin(), cases.end(), [](const studies::StabilityCase& c) { return !c.small; }),
                cases.end());
  Progress progress("stability suite", static_cast<double>(cases.size() + 1));
  for (std::size_t k = 0; k < cases.size(); ++k) {
    if (!quiet) progress.update(static_cast<double>(k), cases[k].label);
    report.results.push_back(studies::run_stability_case(cases[k]));
  }
  if (!quick) {
    if (!quiet) progress.update(static_cast<double>(cases.size()), "regulator tunings");
    report.gains = studies::compare_gain_tunings(report.budget_s);
    report.has_gains = true;
  }
  progress.finish();
  write_stability_csv(report, dir + "/stability.csv");
  const std::vector<std::string> pictures = write_stability_plots(report, dir);
  write_stability_markdown(report, pictures, dir + "/STABILITY.md");
  int unexpected = 0;
  for (const studies::StabilityResult& r : report.results) {
    if (studies::as_expected(r)) continue;
    ++unexpected;
    std::fprintf(stderr, "unfurl report: %s / %s did not end as expected: %s\n", r.spec.group.c_str(),
                 r.spec.label.c_str(), r.status == sim::RunStatus::finished ? "it finished" : r.failure.c_str());
  }
  if (!quiet)
    std::printf(
        "stability    %zu cases, %zu ended as expected\nfiles        %s/STABILITY.md, %s/stability.csv and %zu plots\n",
        report.results.size(), report.results.size() - unexpected, dir.c_str(), dir.c_str(), pictures.size());
  return unexpected == 0 ? 0 : 1;
}

}  // namespace

int command_report(const std::vector<std::string>& argv) {
  const Args args(argv,
                  {"--out", "--integrators", "--tolerances", "--steps", "--repeats", "--set", "--t-end", "--sample",
                   "--suite", "--budget", "--studies"},
                  {"--help", "-h", "--quiet", "--quick"});
  if (args.has("--help") || args.has("-h")) {
    std::printf(kHelp,
                "  --set KEY=VALUE       override a value of the scene (repeatable)\n"
                "  --t-end T             simulate from 0 to T seconds\n"
                "  --sample DT           compare every DT seconds (default: the scene's sample)\n");
    return 0;
  }
  try {
    return args.has("--suite") ? stability_report(argv, args) : work_precision_report(argv, args);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const UsageError*>(&e) || dynamic_cast<const input::InputError*>(&e)) throw;
    std::fprintf(stderr, "unfurl report: %s\n", e.what());
    return 1;
  }
}

}  // namespace unfurl::app
