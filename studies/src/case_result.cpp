#include "unfurl/studies/case_result.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "unfurl/sim/summary.hpp"

namespace unfurl::studies {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kOverlayPoints = 400;

std::vector<std::string> latch_joints(const sim::Scene& scene) {
  std::vector<std::string> names;
  for (const sim::Latch* l : scene.latches()) names.push_back(scene.model.joints[l->joint].name);
  return names;
}

void record_overlay(const Study& study, const sim::Scene& scene, const sim::Trajectory& tr, CaseResult& r) {
  int joint = 0;
  while (scene.model.joints[joint].name != study.overlay_joint) ++joint;
  const int index = tr.layout.q() + scene.model.first_position[joint].value;
  const std::size_t stride = std::max<std::size_t>(1, (tr.samples.size() + kOverlayPoints - 1) / kOverlayPoints);
  for (std::size_t k = 0; k < tr.samples.size(); k += stride) {
    r.angle_t.push_back(tr.samples[k].t);
    r.angle.push_back(tr.samples[k].y[index]);
  }
}

// loads_determinate (1, 0, or NaN where not assessed), the time inside
// indeterminate spans, where the first begins, and the largest
// indeterminate hinge force (RunPeaks: the minimum-norm ones in the spans,
// the rigid ones running into and out of them).
void append_determinacy(const sim::RunPeaks& peaks, double peak_indeterminate_force, std::vector<double>& outputs) {
  const auto& spans = peaks.indeterminate_spans;
  outputs.push_back(!peaks.loads_assessed ? kNaN : spans.empty() ? 1.0 : 0.0);
  outputs.push_back(peaks.loads_assessed ? sim::total_time(spans) : kNaN);
  outputs.push_back(spans.empty() ? kNaN : spans.front()[0]);
  outputs.push_back(spans.empty() ? kNaN : peak_indeterminate_force);
}

// The nominal scene's element or sensor peaks, as the case's summary has
// them (NaN for one the case's scene lacks).
void append_named_peaks(const std::vector<sim::TrackedPeak>& nominal,
                        const std::vector<sim::RunSummary::ElementPeakValue>& in_case, std::vector<double>& outputs) {
  for (const sim::TrackedPeak& p : nominal) {
    double value = kNaN;
    for (const auto& e : in_case)
      if (e.quantity == p.quantity && e.name == p.name && !std::isnan(e.peak.t)) value = e.peak.value;
    outputs.push_back(value);
  }
}

}  // namespace

const char* case_status_name(CaseStatus status) {
  switch (status) {
    case CaseStatus::deployed: return "deployed";
    case CaseStatus::not_deployed: return "not deployed";
    case CaseStatus::failed: return "failed";
  }
  return "?";
}

const std::vector<std::string>& CaseColumns::headline() {
  static const std::vector<std::string> names{"deployment_time",   "peak_latch_torque", "peak_hinge_force",
                                              "peak_hinge_moment", "max_closure_gap",   "final_energy"};
  return names;
}

std::string output_unit(const std::string& output) {
  const std::string quantity = output.substr(0, output.find('.'));
  static const std::vector<std::pair<std::string, std::string>> units{
      {"deployment_time", "s"},     {"latch_time", "s"},          {"wall_time", "s"},
      {"peak_latch_torque", "N m"}, {"peak_hinge_moment", "N m"}, {"peak_hinge_force", "N"},
      {"max_closure_gap", "m"},     {"max_closure_angle", "rad"}, {"final_energy", "J"},
      {"indeterminate_time", "s"},  {"indeterminate_from", "s"},  {"peak_hinge_force_indeterminate", "N"},
      {"peak_bushing_force", "N"},  {"peak_bushing_moment", "N m"}, {"peak_acceleration", "m/s^2"},
      {"peak_velocity", "m/s"},     {"peak_angular_rate", "rad/s"}, {"peak_angular_acceleration", "rad/s^2"},
      {"torque_margin", ""},        {"peak_stop_torque", "N m"},  {"min_clearance", "m"},
      {"contacts", ""}};
  for (const auto& [name, unit] : units)
    if (quantity == name) return unit;
  return "";
}

CaseColumns case_columns(const Study& study, const sim::Scene& nominal) {
  CaseColumns c;
  for (const StudyVariable& v : study.variables) c.inputs.push_back(v.label());
  c.outputs = CaseColumns::headline();
  c.outputs.push_back("max_closure_angle");
  for (const char* name : {"loads_determinate", "indeterminate_time", "indeterminate_from", "peak_hinge_force_indeterminate"})
    c.outputs.push_back(name);
  for (const std::string& j : latch_joints(nominal)) c.outputs.push_back("latch_time." + j);
  for (const std::string& j : latch_joints(nominal)) c.outputs.push_back("peak_latch_torque." + j);
  for (const sim::Joint& j : nominal.model.joints)
    if (j.has_reaction()) c.outputs.push_back("peak_hinge_force." + j.name);
  for (const sim::Joint& j : nominal.model.joints)
    if (j.has_reaction()) c.outputs.push_back("peak_hinge_moment." + j.name);
  c.outputs.push_back("torque_margin");
  for (const int j : sim::driven_joints(nominal)) c.outputs.push_back("torque_margin." + nominal.model.joints[j].name);
  c.outputs.push_back("min_clearance");
  c.outputs.push_back("contacts");
  for (const std::vector<sim::TrackedPeak>& peaks : {nominal.element_peaks(), nominal.sensor_peaks()})
    for (const sim::TrackedPeak& p : peaks) c.outputs.push_back(p.quantity + "." + p.name);
  c.outputs.push_back("steps");
  c.outputs.push_back("wall_time");
  return c;
}

CaseRun simulate_case(const Study& study, const StudyCase& c, const std::atomic<bool>* cancel,
                      sim::RunThreads threads) {
  CaseRun out{case_scene(study, c), {}};
  sim::RunObserver observer;
  observer.cancel = cancel;
  out.run = sim::simulate(out.scene, out.scene.run, observer, threads);
  return out;
}

CaseResult case_result(const Study& study, const sim::Scene& nominal, const StudyCase& c, const CaseRun& run,
                       const sim::Clearance* clearance) {
  const sim::Scene& scene = run.scene;
  const sim::RunResult& rr = run.run;
  const sim::Trajectory& tr = rr.trajectory;
  // Every figure from the case's own summary (what its summary.json says),
  // by the nominal scene's joint names.
  const sim::RunSummary summary = sim::summarize(scene, rr);
  CaseResult r;
  r.id = c.id;
  r.failure = c.failure ? c.failure->describe() : "";
  r.inputs = c.inputs;

  const auto named = [](const std::vector<sim::RunSummary::NamedPeak>& peaks, const std::string& joint) {
    for (const auto& p : peaks)
      if (p.joint == joint && !std::isnan(p.peak.t)) return p.peak.value;
    return kNaN;
  };
  std::vector<double> times, torques;
  std::string unlatched;
  for (const std::string& joint : latch_joints(nominal)) {
    double t = kNaN;
    for (const auto& [j, at] : summary.latch_times)
      if (j == joint && std::isnan(t)) t = at;
    times.push_back(t);
    torques.push_back(named(summary.peak_latch_torque, joint));
    if (std::isnan(times.back())) unlatched += (unlatched.empty() ? "" : ", ") + joint;
  }
  if (rr.status == sim::RunStatus::failed) {
    r.status = CaseStatus::failed;
    r.reason = sim::describe(rr.failure);
  } else if (!unlatched.empty()) {
    r.status = CaseStatus::not_deployed;
    r.reason = "never latched: " + unlatched;
  } else {
    r.status = CaseStatus::deployed;
  }

  const auto largest = [](const std::vector<double>& x) {
    double m = kNaN;
    for (double v : x)
      if (!std::isnan(v) && !(v <= m)) m = v;
    return m;
  };
  std::vector<double> forces, moments, indeterminate_forces;
  for (const sim::Joint& j : nominal.model.joints) {
    if (!j.has_reaction()) continue;
    forces.push_back(named(summary.peak_hinge_force, j.name));
    moments.push_back(named(summary.peak_hinge_moment, j.name));
    indeterminate_forces.push_back(named(summary.peak_hinge_force_indeterminate, j.name));
  }
  const double deployment = r.status == CaseStatus::deployed && !times.empty() ? largest(times) : kNaN;
  r.outputs = {deployment,
               largest(torques),
               largest(forces),
               largest(moments),
               scene.loops.empty() ? kNaN : summary.max_closure_gap,
               tr.empty() ? kNaN : summary.energy_final,
               scene.loops.empty() ? kNaN : summary.max_closure_angle};
  append_determinacy(rr.peaks, largest(indeterminate_forces), r.outputs);
  r.outputs.insert(r.outputs.end(), times.begin(), times.end());
  r.outputs.insert(r.outputs.end(), torques.begin(), torques.end());
  r.outputs.insert(r.outputs.end(), forces.begin(), forces.end());
  r.outputs.insert(r.outputs.end(), moments.begin(), moments.end());
  // The torque margin: the smallest motorization factor less one, overall
  // and per driven joint (NaN where the case has none).
  r.outputs.push_back(summary.torque_margins.empty() ? kNaN : summary.worst_motorization_factor() - 1);
  for (const int j : sim::driven_joints(nominal)) {
    double margin = kNaN;
    for (const sim::JointTorqueMargin& m : summary.torque_margins)
      if (m.joint == nominal.model.joints[j].name) margin = m.worst() - 1;
    r.outputs.push_back(margin);
  }
  // The closest approach of two bodies not jointed together (0 where they
  // touched) and how many spans of contact.
  const sim::PairClearance* closest = clearance ? clearance->closest() : nullptr;
  r.outputs.push_back(closest ? closest->distance : kNaN);
  r.outputs.push_back(closest ? static_cast<double>(clearance->contacts.size()) : kNaN);
  append_named_peaks(nominal.element_peaks(), summary.element_peaks, r.outputs);
  append_named_peaks(nominal.sensor_peaks(), summary.sensor_peaks, r.outputs);
  r.outputs.push_back(static_cast<double>(rr.stats.steps));
  r.outputs.push_back(rr.wall_time_s);
  if (!tr.empty()) record_overlay(study, scene, tr, r);
  return r;
}

double output_value(const CaseColumns& columns, const CaseResult& r, const std::string& name) {
  const auto it = std::find(columns.outputs.begin(), columns.outputs.end(), name);
  if (it == columns.outputs.end()) return kNaN;
  const auto i = static_cast<std::size_t>(it - columns.outputs.begin());
  return i < r.outputs.size() ? r.outputs[i] : kNaN;
}

}  // namespace unfurl::studies
