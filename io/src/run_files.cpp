#include "unfurl/io/run_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "unfurl/io/json_writer.hpp"
#include "unfurl/io/run_columns.hpp"
#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::io {

namespace {

// Writes columns of every sample as a CSV file with its header.
void write_columns(const std::vector<RunColumn>& columns, const sim::Trajectory& trajectory, const std::string& path) {
  OutputFile file(path);
  std::ostream& out = file.stream();
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << header_cell(columns[c]);
  out << '\n';
  for (const sim::Sample& s : trajectory.samples) {
    for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << sim::format_number(columns[c].value(s));
    out << '\n';
  }
  file.commit();
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
  return cells;
}

double parse(const std::string& text, const std::string& where) {
  std::size_t used = 0;
  double x = NAN;
  try {
    x = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size()) throw std::runtime_error(where + ": expected a number, got '" + text + "'");
  return x;
}

// A CSV file's header: each column's name (units and frames set aside) to
// its index.
std::map<std::string, int> header_of(const std::string& line) {
  std::map<std::string, int> index;
  const std::vector<std::string> cells = split(line);
  for (std::size_t c = 0; c < cells.size(); ++c) index[column_name(cells[c])] = static_cast<int>(c);
  return index;
}

// Reads the values of `columns` from a file's rows into samples: the
// samples already there (loads.csv beside a trajectory) or new ones.
// Columns the file lacks are an error where `required`.
void read_columns(const std::string& path, const std::vector<RunColumn>& columns, std::istream& in,
                  const std::map<std::string, int>& header, const sim::Sample& blank, std::vector<sim::Sample>& samples,
                  bool append) {
  std::vector<std::pair<const RunColumn*, int>> read;
  for (const RunColumn& c : columns) {
    if (!c.set) continue;
    const auto at = header.find(c.name);
    if (at == header.end()) throw std::runtime_error(path + ":1: no column '" + c.name + "'");
    read.emplace_back(&c, at->second);
  }
  std::string line;
  for (std::size_t k = 0; std::getline(in, line); ++k) {
    const std::string where = path + ":" + std::to_string(k + 2);
    const std::vector<std::string> cells = split(line);
    if (cells.size() != header.size())
      throw std::runtime_error(where + ": expected " + std::to_string(header.size()) + " columns");
    if (!append && k >= samples.size()) throw std::runtime_error(where + ": more rows than trajectory.csv");
    sim::Sample s = append ? blank : samples[k];
    for (const auto& [column, at] : read) column->set(s, parse(cells[at], where));
    if (append) {
      if (!samples.empty() && !(s.t > samples.back().t)) throw std::runtime_error(where + ": times must increase");
      samples.push_back(std::move(s));
    } else {
      if (std::abs(s.t - samples[k].t) > 1e-9 * std::max(1.0, std::abs(s.t)))
        throw std::runtime_error(where + ": its time is not trajectory.csv's");
      samples[k] = std::move(s);
    }
  }
}

void read_events(const sim::Scene& scene, const std::string& path, sim::Trajectory& tr) {
  std::ifstream in(path);
  if (!in) return;
  std::string line;
  std::getline(in, line);
  const std::vector<const sim::Latch*> latches = scene.latches();
  for (int n = 2; std::getline(in, line); ++n) {
    const auto cells = split(line);
    if (cells.size() != 3) throw std::runtime_error(path + ":" + std::to_string(n) + ": expected t,event,joint");
    int latch = -1;
    for (std::size_t l = 0; l < latches.size(); ++l)
      if (scene.model.joints[latches[l]->joint].name == cells[2]) latch = static_cast<int>(l);
    if (latch < 0) throw std::runtime_error(path + ":" + std::to_string(n) + ": no latch on joint '" + cells[2] + "'");
    tr.events.push_back({parse(cells[0], path + ":" + std::to_string(n)), latch, latches[latch]->joint});
  }
}

// The active loop components a loads.csv was written with, from its
// loop_force and loop_moment columns.
std::vector<sim::LoopComponent> loop_components_of(const sim::Scene& scene, const std::map<std::string, int>& header,
                                                   const std::string& path) {
  std::vector<std::pair<int, sim::LoopComponent>> found;
  for (const auto& [name, at] : header) {
    const bool force = name.rfind("loop_force.", 0) == 0, moment = name.rfind("loop_moment.", 0) == 0;
    if (!force && !moment) continue;
    const std::string rest = name.substr(force ? 11 : 12);
    const auto dot = rest.rfind('.');
    int loop = -1, axis = -1;
    for (std::size_t l = 0; l < scene.loops.size(); ++l)
      if (dot != std::string::npos && scene.loops[l].name == rest.substr(0, dot)) loop = static_cast<int>(l);
    for (int a = 0; a < 3; ++a)
      if (dot != std::string::npos && rest.substr(dot + 1) == std::string(1, "xyz"[a])) axis = force ? a : a + 3;
    if (loop < 0 || axis < 0) throw std::runtime_error(path + ":1: no loop component '" + name + "' in the scene");
    found.push_back({at, {loop, axis}});
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<sim::LoopComponent> components;
  for (const auto& f : found) components.push_back(f.second);
  return components;
}

}  // namespace

void write_trajectory_csv(const sim::Scene& scene, const sim::Trajectory& trajectory, const std::string& path) {
  write_columns(trajectory_columns(scene, trajectory), trajectory, path);
}

void write_loads_csv(const sim::Scene& scene, const sim::Trajectory& trajectory, const std::string& path) {
  write_columns(load_file_columns(scene, trajectory), trajectory, path);
}

void write_sensors_csv(const sim::Scene&, const sim::Trajectory& trajectory, const std::string& path) {
  write_columns(sensor_file_columns(trajectory), trajectory, path);
}

sim::Trajectory read_trajectory_csv(const sim::Scene& scene, const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the trajectory");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file");
  const sim::Model& model = scene.model;
  sim::Trajectory tr;
  tr.layout.nq = model.nq;
  tr.layout.nv = model.nv;
  tr.load_columns = scene.load_columns();
  tr.sensor_columns = sim::sensor_columns(scene.sensors);
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  // loads.csv beside it, when there is one, says which loop components the
  // run kept.
  std::ifstream loads((dir / "loads.csv").string());
  std::string loads_line;
  const bool with_loads = loads && std::getline(loads, loads_line);
  if (with_loads) tr.loop_components = loop_components_of(scene, header_of(loads_line), (dir / "loads.csv").string());
  try {
    read_columns(path, trajectory_columns(scene, tr), in, header_of(line), empty_sample(scene, tr), tr.samples, true);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.find(": no column '") == std::string::npos) throw;
    throw std::runtime_error(what + " (was it written for scene '" + scene.name + "'?)");
  }
  if (tr.samples.empty()) throw std::runtime_error(path + ": no samples");
  read_events(scene, (dir / "events.csv").string(), tr);
  if (with_loads)
    read_columns((dir / "loads.csv").string(), load_file_columns(scene, tr), loads, header_of(loads_line),
                 empty_sample(scene, tr), tr.samples, false);
  std::ifstream sensors((dir / "sensors.csv").string());
  std::string sensors_line;
  if (!tr.sensor_columns.empty() && sensors && std::getline(sensors, sensors_line))
    read_columns((dir / "sensors.csv").string(), sensor_file_columns(tr), sensors, header_of(sensors_line),
                 empty_sample(scene, tr), tr.samples, false);
  return tr;
}

void write_events_csv(const sim::Scene& scene, const sim::Trajectory& trajectory, const std::string& path) {
  OutputFile file(path);
  file.stream() << "t,event,joint\n";
  for (const sim::LatchEvent& e : trajectory.events)
    file.stream() << sim::format_number(e.t) << ",latch," << scene.model.joints[e.joint].name << '\n';
  file.commit();
}

namespace {

// The peaks' quantities, each once, in order.
std::vector<std::string> peak_quantities(const std::vector<sim::RunSummary::ElementPeakValue>& peaks) {
  std::vector<std::string> quantities;
  for (const auto& e : peaks)
    if (std::find(quantities.begin(), quantities.end(), e.quantity) == quantities.end())
      quantities.push_back(e.quantity);
  return quantities;
}

// "torque_margin": the factors, and per driven joint the smallest
// motorization factor along the run and quasi-statically, and where; null
// when an interrupt stopped the summary.
void write_torque_margins(JsonWriter& json, const sim::RunSummary& summary) {
  if (summary.interrupted) {
    json.null("torque_margin");
    return;
  }
  const sim::TorqueMarginFactors& f = summary.torque_margin_factors;
  json.begin_object("torque_margin");
  json.value("required_motorization_factor", f.required);
  json.begin_object("uncertainty_factors")
      .value("spring", f.spring)
      .value("friction", f.friction)
      .value("damping", f.damping)
      .value("harness", f.harness)
      .value("inertia", f.inertia)
      .end_object();
  json.value("required_acceleration", f.required_acceleration);
  const double worst = summary.worst_motorization_factor();
  json.value("motorization_factor", worst).value("torque_margin", worst - 1);
  json.value("passes", summary.torque_margins_pass());
  json.begin_object("joints");
  for (const sim::JointTorqueMargin& m : summary.torque_margins) {
    json.begin_object(m.joint);
    json.value("motorization_factor", m.worst()).value("torque_margin", m.worst() - 1);
    json.value("passes", m.passes(f));
    if (m.worst_run >= 0) {
      const sim::TorqueMarginPoint& p = m.run[m.worst_run];
      json.begin_object("run").value("motorization_factor", p.factor).value("q", p.q).value("t", p.t).end_object();
    }
    if (m.worst_quasi_static >= 0) {
      const sim::TorqueMarginPoint& p = m.quasi_static[m.worst_quasi_static];
      json.begin_object("quasi_static").value("motorization_factor", p.factor).value("q", p.q).end_object();
    }
    json.end_object();
  }
  json.end_object();
  json.end_object();
}

// "clearance": the closest pair and the measured pairs' closest approach
// (listed_within null when every pair was measured), the spans of contact,
// and what was left out; null when not checked.
void write_clearance(JsonWriter& json, const sim::RunSummary& summary) {
  if (!summary.clearance) {
    json.null("clearance");
    return;
  }
  const sim::Clearance& c = *summary.clearance;
  const auto bodies = [&](const std::string& a, const std::string& b) {
    json.begin_array("bodies").value("", a).value("", b).end_array();
  };
  json.begin_object("clearance");
  json.value("clear", c.clear());
  if (const sim::PairClearance* p = c.closest()) {
    json.begin_object("minimum");
    bodies(p->body_a, p->body_b);
    json.value("distance", p->distance).value("t", p->t).end_object();
  }
  json.begin_array("contacts");
  for (const sim::ClearanceContact& x : c.contacts) {
    json.begin_object();
    bodies(x.body_a, x.body_b);
    json.value("t_begin", x.t_begin).value("t_end", x.t_end).value("at_start", x.at_start).end_object();
  }
  json.end_array();
  json.begin_array("pairs");
  for (const sim::PairClearance& p : c.pairs) {
    json.begin_object();
    bodies(p.body_a, p.body_b);
    json.value("distance", p.distance).value("t", p.t).end_object();
  }
  json.end_array();
  if (std::isinf(c.listed_within))
    json.null("listed_within");
  else
    json.value("listed_within", c.listed_within);
  json.value("pairs_beyond", c.pairs_beyond);
  json.begin_array("without_solid");
  for (const std::string& b : c.without_solid) json.value("", b);
  json.end_array();
  json.begin_array("unread");
  for (const std::string& b : c.unread) json.value("", b);
  json.end_array();
  json.value("samples", c.samples).value("distance_queries", c.distance_queries).value("wall_time", c.wall_time_s);
  json.end_object();
}

// "units": the unit of every number above with one; per joint where
// joints differ (a slider's force is in N where a hinge's torque is in N m).
void write_summary_units(JsonWriter& json, const sim::Scene& scene, const sim::RunSummary& summary) {
  const sim::Model& m = scene.model;
  json.begin_object("units");
  for (const char* key : {"t_end", "sample", "dt", "t_reached", "wall_time", "min_step", "min_step_after_restart"})
    json.value(key, "s");
  json.value("latch_time", "s");
  if (!scene.loops.empty()) {
    json.begin_object("closure").value("length", "m").value("rate", "rad/s").value("v_max", "rad/s");
    json.begin_object("lowest_rank").value("t", "s").end_object();
    json.end_object();
  }
  json.value("max_closure_gap", "m").value("max_closure_angle", "rad");
  json.value("max_closure_gap_before_latch", "m").value("max_closure_angle_before_latch", "rad");
  const auto per_joint = [&](const char* key, const std::vector<sim::RunSummary::NamedPeak>& peaks, bool moment) {
    json.begin_object(key);
    for (const auto& [joint, peak] : peaks) {
      const std::optional<int> j = m.find_joint(joint);
      const bool slider = j && m.joints[*j].type == sim::JointType::prismatic;
      json.value(joint, moment && !slider ? "N m" : "N");
    }
    json.end_object();
  };
  per_joint("peak_latch_torque", summary.peak_latch_torque, true);
  json.value("peak_hinge_force", "N").value("peak_hinge_moment", "N m");
  json.value("peak_hinge_force_indeterminate", "N").value("peak_hinge_moment_indeterminate", "N m");
  json.value("indeterminate_spans", "s");
  for (const auto* list : {&summary.element_peaks, &summary.sensor_peaks})
    for (const std::string& quantity : peak_quantities(*list))
      for (const auto& e : *list)
        if (e.quantity == quantity) {
          json.value(quantity, e.unit);
          break;
        }
  json.value("energy_initial", "J").value("energy_final", "J").value("energy_dissipated", "J");
  if (summary.energy_driven) json.value("energy_driven", "J");
  json.value("torque_margin", "motorization factors: none; torque_margin = motorization factor - 1; q as q.J");
  json.value("clearance", "distance m, times s");
  json.begin_object("final_q");
  for (int c = 0; c < m.nq; ++c) json.value(m.position_name(c), m.position_unit(c));
  json.end_object();
  if (summary.free_bus) json.value("bus_peak_rate", "rad/s").value("bus_final_attitude_change", "rad");
  json.end_object();
}

}  // namespace

void write_summary_json(const sim::Scene& scene, const sim::RunResult& result, const sim::RunSummary& summary,
                        const std::string& path) {
  OutputFile file(path);
  file.stream() << summary_json(scene, result, summary);
  file.commit();
}

std::string summary_json(const sim::Scene& scene, const sim::RunResult& result, const sim::RunSummary& summary) {
  const sim::RunSettings& run = result.settings;
  std::ostringstream text;
  JsonWriter json(text);
  json.begin_object();
  json.value("scene", scene.name).value("scene_source", scene.source);
  json.value("integrator", sim::integrator_name(run.integrator));
  json.value("rtol", run.rtol).value("atol", run.atol);
  if (run.integrator == sim::IntegratorKind::rk4) json.value("dt", run.dt);
  json.value("t_end", run.t_end).value("sample", run.sample);
  json.value("status", sim::run_status_name(result.status));
  if (result.status == sim::RunStatus::failed) {
    json.begin_object("failure");
    json.value("t", result.failure.t).value("step", result.failure.step);
    json.value("check", result.failure.check).value("message", sim::describe(result.failure));
    json.end_object();
  }
  json.value("t_reached", summary.t_reached);
  json.value("wall_time", result.wall_time_s);
  json.value("steps", result.stats.steps).value("rhs_evals", result.rhs_calls);
  json.value("jacobian_product_evals", result.jacobian_product_evals);
  json.value("jacobian_evals", result.stats.jacobian_evals);
  json.value("linear_setups", result.stats.linear_setups);
  json.value("linear_iterations", result.stats.linear_iterations);
  json.value("nonlinear_iterations", result.stats.nonlinear_iterations);
  json.value("nonlinear_failures", result.stats.nonlinear_failures);
  json.value("error_test_failures", result.stats.error_test_failures);
  json.value("min_step", result.stats.min_step);
  json.value("min_step_after_restart", result.stats.min_step_after_restart);
  json.value("restarts", result.stats.restarts);
  json.value("grazes", result.stats.grazes);
  json.begin_object("roundoff_floor").value("start", result.roundoff_floor).value("end", result.roundoff_floor_end);
  json.end_object();
  json.begin_array("tolerance_raises");
  for (const sim::ToleranceRaise& r : result.tolerance_raises)
    json.begin_object().value("t", r.t).value("roundoff_floor", r.floor).value("rtol", r.rtol).value("atol", r.atol).end_object();
  json.end_array();
  json.value("state_size", result.trajectory.layout.size());
  json.value("loop_components", result.trajectory.layout.m);
  if (const auto& c = result.closure) {
    json.begin_object("closure");
    json.value("length", c->length).value("rate", c->rate);
    json.value("v_max", c->v_max).value("v_max_source", c->v_max_automatic ? "automatic" : "scene");
    json.value("regularization", c->regularization)
        .value("regularization_source", c->regularization_automatic ? "automatic" : "scene");
    const sim::RunPeaks& p = result.peaks;
    if (p.closure_rank_at_start >= 0) {
      json.value("rank", p.closure_rank_at_start);
      json.begin_object("lowest_rank").value("value", p.lowest_closure_rank).value("t", p.lowest_closure_rank_t);
      json.end_object();
    }
    json.end_object();
  }
  json.begin_object("latch_time");
  for (const auto& [joint, t] : summary.latch_times) json.value(joint, t);
  json.end_object();
  json.begin_array("unlatched");
  for (const std::string& joint : summary.unlatched) json.value("", joint);
  json.end_array();
  json.value("max_closure_gap", summary.max_closure_gap);
  json.value("max_closure_angle", summary.max_closure_angle);
  json.value("max_closure_gap_before_latch", summary.max_closure_gap_before_latch);
  json.value("max_closure_angle_before_latch", summary.max_closure_angle_before_latch);
  auto peaks = [&](const char* key, const std::vector<sim::RunSummary::NamedPeak>& list) {
    json.begin_object(key);
    for (const auto& [joint, peak] : list) {
      if (std::isnan(peak.t)) continue;  // never engaged
      json.begin_object(joint).value("value", peak.value).value("t", peak.t).end_object();
    }
    json.end_object();
  };
  peaks("peak_latch_torque", summary.peak_latch_torque);
  peaks("peak_hinge_force", summary.peak_hinge_force);
  peaks("peak_hinge_moment", summary.peak_hinge_moment);
  for (const auto* list : {&summary.element_peaks, &summary.sensor_peaks})
    for (const std::string& quantity : peak_quantities(*list)) {
      json.begin_object(quantity);
      for (const auto& e : *list) {
        if (e.quantity != quantity || std::isnan(e.peak.t)) continue;
        json.begin_object(e.name).value("value", e.peak.value).value("t", e.peak.t);
        if (quantity == "peak_acceleration") json.value("g", e.peak.value / sim::kStandardGravity);
        json.end_object();
      }
      json.end_object();
    }
  if (summary.loads_determinate)
    json.value("loads_determinate", *summary.loads_determinate);
  else
    json.null("loads_determinate");
  json.begin_array("indeterminate_spans");
  for (const auto& span : summary.indeterminate_spans)
    json.begin_array().value("", span[0]).value("", span[1]).end_array();
  json.end_array();
  peaks("peak_hinge_force_indeterminate", summary.peak_hinge_force_indeterminate);
  peaks("peak_hinge_moment_indeterminate", summary.peak_hinge_moment_indeterminate);
  write_torque_margins(json, summary);
  write_clearance(json, summary);
  json.value("energy_initial", summary.energy_initial);
  json.value("energy_final", summary.energy_final);
  json.value("energy_dissipated", summary.energy_dissipated);
  if (summary.energy_driven) json.value("energy_driven", *summary.energy_driven);
  json.begin_object("final_q");
  for (const auto& [joint, q] : summary.final_q) json.value(joint, q);
  json.end_object();
  if (summary.free_bus) {
    json.value("bus_peak_rate", summary.free_bus->peak_rate);
    json.value("bus_final_attitude_change", summary.free_bus->final_attitude_change);
    json.begin_object("momentum_drift");
    json.value("linear", summary.free_bus->linear_momentum_drift);
    json.value("angular", summary.free_bus->angular_momentum_drift);
    json.end_object();
  }
  write_summary_units(json, scene, summary);
  json.end_object();
  return text.str();
}

}  // namespace unfurl::io
