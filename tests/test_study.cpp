// Studies: the study file (its errors name file, line, column and field),
// the cases it expands to, the injected failures, and the statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "support.hpp"
#include "unfurl/sim/summary.hpp"
#include "unfurl/studies/case_result.hpp"
#include "unfurl/studies/study_statistics.hpp"

namespace unfurl {
namespace {

studies::Study study_from(const std::string& text) { return studies::read_study_text(text, "study.yaml", ""); }

std::string error_of(const std::string& text) {
  try {
    study_from(text);
  } catch (const input::InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StudyStatistics, PercentilesInterpolateBetweenRanks) {
  std::vector<double> x(101);
  std::iota(x.begin(), x.end(), 0.0);
  EXPECT_DOUBLE_EQ(studies::percentile(x, 1), 1);
  EXPECT_DOUBLE_EQ(studies::percentile(x, 50), 50);
  EXPECT_DOUBLE_EQ(studies::percentile(x, 99), 99);
  EXPECT_DOUBLE_EQ(studies::percentile({1, 2}, 50), 1.5);
}

TEST(StudyStatistics, SpearmanSeesMonotoneRelationsAndTies) {
  const std::vector<double> x{1, 2, 3, 4, 5};
  EXPECT_DOUBLE_EQ(studies::spearman(x, {1, 8, 27, 64, 125}), 1.0);  // any increasing function
  EXPECT_DOUBLE_EQ(studies::spearman(x, {5, 4, 3, 2, 1}), -1.0);
  // Ties share their rank: ranks (1, 2.5, 2.5, 4) against (1, 2, 3, 4).
  EXPECT_NEAR(studies::spearman({1, 2, 3, 4}, {1, 2, 2, 3}), 4.5 / std::sqrt(5.0 * 4.5), 1e-15);
  EXPECT_TRUE(std::isnan(studies::spearman(x, {2, 2, 2, 2, 2})));
}

TEST(StudyFile, ErrorsNameTheFileLineColumnAndField) {
  EXPECT_NE(error_of("scene: pantograph\nsurprise: 1\n").find("study.yaml:2:1"), std::string::npos);
  EXPECT_NE(error_of("scene: nowhere\n").find("study.yaml:1:8: scene"), std::string::npos);
  const std::string bad_path = error_of("scene: pantograph\nvary:\n  - {path: springs.j99.stiffness, values: [1]}\n");
  EXPECT_NE(bad_path.find("vary[0].path"), std::string::npos) << bad_path;
  const std::string mixed = error_of(
      "scene: pantograph\nruns: 3\nvary:\n  - {path: springs.j1.stiffness, values: [0.1]}\n"
      "  - {path: springs.j2.stiffness, uniform: {min: 0.09, max: 0.11}}\n");
  EXPECT_NE(mixed.find("not both"), std::string::npos) << mixed;
  const std::string invalid = error_of("scene: pantograph\nvary:\n  - {path: bodies.panel_A1.mass, values: [2, -1]}\n");
  EXPECT_NE(invalid.find("study.yaml:3:5: vary[0]"), std::string::npos) << invalid;
  EXPECT_NE(invalid.find("mass"), std::string::npos) << invalid;
  const std::string joint = error_of("scene: pantograph\nfailures:\n  - {latch_fails: j9}\n");
  EXPECT_NE(joint.find("failures[0].latch_fails"), std::string::npos) << joint;
  const std::string zip = error_of(
      "scene: pantograph\ncombine: zip\nvary:\n  - {path: springs.j1.stiffness, values: [0.1, 0.2]}\n"
      "  - {path: springs.j2.stiffness, values: [0.1]}\n");
  EXPECT_NE(zip.find("one length"), std::string::npos) << zip;
  const std::string misplaced = error_of("scene: pantograph\nfailures:\n  - {stuck: j1, coulomb: 0.1}\n");
  EXPECT_NE(misplaced.find("failures[0].coulomb: only an extra_friction has a coulomb"), std::string::npos)
      << misplaced;
  const std::string bare = error_of("scene: pantograph\nfailures:\n  - {extra_friction: j1}\n");
  EXPECT_NE(bare.find("needs coulomb (N m), viscous (N m s/rad) or both"), std::string::npos) << bare;
}

TEST(StudyCases, ProductAndZipOfLists) {
  const std::string vary =
      "vary:\n  - {path: springs.j1.stiffness, values: [0.09, 0.11]}\n"
      "  - {path: springs.j2.stiffness, grid: {from: 0.08, to: 0.12, steps: 2}}\n";
  const auto product = studies::study_cases(study_from("scene: pantograph\n" + vary));
  ASSERT_EQ(product.size(), 5u);  // nominal + 2 x 2
  EXPECT_EQ(product[0].id, "nominal");
  EXPECT_EQ(product[0].inputs, (std::vector<double>{0.1, 0.1}));
  EXPECT_EQ(product[2].inputs, (std::vector<double>{0.09, 0.12}));  // the last variable turns fastest
  EXPECT_EQ(product[3].inputs, (std::vector<double>{0.11, 0.08}));
  const auto zip = studies::study_cases(study_from("scene: pantograph\ncombine: zip\n" + vary));
  ASSERT_EQ(zip.size(), 3u);
  EXPECT_EQ(zip[2].inputs, (std::vector<double>{0.11, 0.12}));
}

// A random case's values depend on the seed and its number only: the same
// draws whatever the study's size, and always within the bounds.
TEST(StudyCases, RandomDrawsAreReproducibleAndTruncated) {
  const std::string vary =
      "vary:\n  - {path: springs.*.stiffness, scale: true, normal: {mean: 1, sigma: 0.05, min: 0.9, max: 1.1}}\n"
      "  - {path: bodies.panel_B1.mass, lognormal: {mu: 1.386, sigma: 0.1}}\n";
  const auto small = studies::study_cases(study_from("scene: pantograph\nseed: 4\nruns: 5\n" + vary));
  const auto large = studies::study_cases(study_from("scene: pantograph\nseed: 4\nruns: 400\n" + vary));
  const auto other = studies::study_cases(study_from("scene: pantograph\nseed: 5\nruns: 5\n" + vary));
  ASSERT_EQ(small.size(), 6u);
  ASSERT_EQ(small[1].inputs.size(), 9u);  // 8 springs, 1 mass
  for (std::size_t k = 0; k < small.size(); ++k) EXPECT_EQ(small[k].inputs, large[k].inputs);
  EXPECT_NE(small[1].inputs, other[1].inputs);
  EXPECT_EQ(large[1].id, "case-0001");
  double mean = 0;
  for (std::size_t k = 1; k < large.size(); ++k) {
    for (int s = 0; s < 8; ++s) {
      EXPECT_GE(large[k].inputs[s], 0.09 - 1e-15);
      EXPECT_LE(large[k].inputs[s], 0.11 + 1e-15);
      mean += large[k].inputs[s] / (8.0 * 400);
    }
  }
  EXPECT_NEAR(mean, 0.1, 0.001);
}

// The failures change the scene as they say: a latch gone, a spring without
// stiffness, half the preload, a hinge held where it starts.
TEST(StudyCases, FailuresChangeTheSceneAsNamed) {
  const studies::Study study = study_from(
      "scene: pantograph\nfailures:\n  - {latch_fails: j3}\n  - {spring_breaks: j1}\n"
      "  - {preload_loss: j2, fraction: 0.5}\n  - {stuck: \"*\"}\n"
      "  - {extra_friction: j4, coulomb: 0.05, viscous: 0.01}\n");
  const auto cases = studies::study_cases(study);
  ASSERT_EQ(cases.size(), 1u + 3 + 11 + 1);
  EXPECT_EQ(cases[1].id, "fail-latch-j3-fails");
  const sim::Scene nominal = studies::nominal_scene(study).scene;
  const sim::Scene no_latch = studies::case_scene(study, cases[1]);
  EXPECT_EQ(no_latch.latches().size(), 7u);
  for (const sim::Latch* l : no_latch.latches()) EXPECT_NE(nominal.model.joints[l->joint].name, "j3");
  EXPECT_EQ(studies::case_scene(study, cases[2]).elements_of<sim::JointSpring>()[0]->stiffness, 0.0);
  const sim::Scene half = studies::case_scene(study, cases[3]);
  const double q0 = nominal.q0[nominal.model.position_of(1).value];
  EXPECT_DOUBLE_EQ(half.elements_of<sim::JointSpring>()[1]->free_position - q0,
                   0.5 * (nominal.elements_of<sim::JointSpring>()[1]->free_position - q0));
  const sim::Scene stuck = studies::case_scene(study, cases[4]);  // j1
  // A stop, not a latch: the latches are the scene's own.
  EXPECT_EQ(stuck.latches().size(), 8u);
  ASSERT_EQ(stuck.elements_of<sim::JointStop>().size(), 1u);
  EXPECT_EQ(stuck.elements_of<sim::JointStop>()[0]->joint, 0);
  EXPECT_EQ(stuck.elements_of<sim::JointStop>()[0]->position, nominal.q0[0]);
  EXPECT_EQ(cases.back().id, "fail-hinge-j4-friction-0.05Nm-0.01Nms");
  const sim::Scene cold = studies::case_scene(study, cases.back());
  const std::vector<const sim::JointFriction*> friction = cold.elements_of<sim::JointFriction>();
  ASSERT_EQ(friction.size(), nominal.elements_of<sim::JointFriction>().size() + 1);
  EXPECT_EQ(nominal.model.joints[friction.back()->joint].name, "j4");
  EXPECT_EQ(friction.back()->coulomb, 0.05);
  EXPECT_EQ(friction.back()->viscous, 0.01);
}

// A failure applies only to joints it can act on: "*" on a free-floating
// scene leaves out the bus's free joint, and naming it is an error.
TEST(StudyCases, FailuresLeaveOutAFreeBus) {
  const auto cases = studies::study_cases(study_from("scene: zfold_free\nfailures:\n  - {stuck: \"*\"}\n"
                                                     "  - {extra_friction: \"*\", coulomb: 0.01}\n"));
  ASSERT_EQ(cases.size(), 1u + 4 + 4);
  for (const auto& c : cases) EXPECT_EQ(c.id.find("bus"), std::string::npos) << c.id;
  EXPECT_NE(error_of("scene: zfold_free\nfailures:\n  - {stuck: bus}\n").find("not a joint with a hinge or slider"),
            std::string::npos);
}

// The workbench's edits of a case go over the case's own values, its
// preload factor included: a free position typed is the one used.
TEST(StudyCases, EditsOfACaseGoOverItsValues) {
  const studies::Study study = study_from("scene: pantograph\nvary:\n  - {path: springs.j2.preload, values: [0.8]}\n");
  const auto cases = studies::study_cases(study);
  ASSERT_EQ(cases.size(), 2u);
  const sim::Scene scaled = studies::case_scene(study, cases[1]);
  const sim::Scene other_edit = studies::case_scene_file(study, cases[1], {{"springs.j1.stiffness", "0.2"}}).scene;
  EXPECT_EQ(other_edit.elements_of<sim::JointSpring>()[1]->free_position,
            scaled.elements_of<sim::JointSpring>()[1]->free_position);  // the same double
  EXPECT_EQ(other_edit.elements_of<sim::JointSpring>()[0]->stiffness, 0.2);
  const sim::Scene typed = studies::case_scene_file(study, cases[1], {{"springs.j2.free_position", "1.0"}}).scene;
  EXPECT_EQ(typed.elements_of<sim::JointSpring>()[1]->free_position, 1.0);
}

// The runs of injected failures: the array deploys without one spring; a
// stuck root hinge holds the whole (one-degree-of-freedom) array stowed; a
// failed latch leaves its joint unlatched and the case not deployed. At
// rtol 1e-7 the deployment time is within 4e-6 s of a tight run's (at
// 1e-6 it scatters by 1e-5 s with the step sequence).
TEST(StudyCases, FailedCasesReportWhatHappened) {
  const studies::Study study = study_from(
      "scene: pantograph\nset: {run.rtol: 1.0e-7, run.atol: 1.0e-9, run.t_end: 9}\n"
      "failures:\n  - {latch_fails: j3}\n  - {stuck: j1}\n  - {extra_friction: j1, coulomb: 0.05}\n");
  const sim::Scene nominal = studies::nominal_scene(study).scene;
  const studies::CaseColumns columns = studies::case_columns(study, nominal);
  const auto cases = studies::study_cases(study);
  const studies::CaseResult ok =
      studies::case_result(study, nominal, cases[0], studies::simulate_case(study, cases[0]));
  EXPECT_EQ(ok.status, studies::CaseStatus::deployed);
  EXPECT_NEAR(studies::output_value(columns, ok, "deployment_time"), 7.3921759, 1e-5);
  // Its latched loops are redundant (the deployed branch point): the case
  // says so, with the minimum-norm peak there.
  EXPECT_EQ(studies::output_value(columns, ok, "loads_determinate"), 0.0);
  EXPECT_LT(studies::output_value(columns, ok, "indeterminate_from"), 7.393);
  EXPECT_GT(studies::output_value(columns, ok, "indeterminate_time"), 1.0);
  EXPECT_GT(studies::output_value(columns, ok, "peak_hinge_force_indeterminate"), 100.0);
  const studies::CaseResult latch =
      studies::case_result(study, nominal, cases[1], studies::simulate_case(study, cases[1]));
  EXPECT_EQ(latch.status, studies::CaseStatus::not_deployed);
  EXPECT_EQ(latch.reason, "never latched: j3");
  EXPECT_TRUE(std::isnan(studies::output_value(columns, latch, "latch_time.j3")));
  EXPECT_FALSE(std::isnan(studies::output_value(columns, latch, "latch_time.j2")));
  const studies::CaseRun stuck_run = studies::simulate_case(study, cases[2]);
  const studies::CaseResult stuck = studies::case_result(study, nominal, cases[2], stuck_run);
  EXPECT_EQ(stuck.status, studies::CaseStatus::not_deployed);
  // One source of truth: the case's row says what its own summary says. Its
  // latch j1 never engaged (no time, no torque: the stop is not a latch).
  const sim::RunSummary own = sim::summarize(stuck_run.scene, stuck_run.run);
  EXPECT_TRUE(std::isnan(studies::output_value(columns, stuck, "latch_time.j1")));
  EXPECT_TRUE(std::isnan(studies::output_value(columns, stuck, "peak_latch_torque.j1")));
  for (const auto& p : own.peak_latch_torque)
    if (p.joint == "j1") {
      EXPECT_TRUE(std::isnan(p.peak.t));
    }
  for (const auto& p : own.peak_hinge_force)
    EXPECT_EQ(studies::output_value(columns, stuck, "peak_hinge_force." + p.joint), p.peak.value) << p.joint;
  bool held = false;
  for (const auto& e : own.element_peaks)
    held = held || (e.quantity == "peak_stop_torque" && e.name == "j1" && e.peak.value > 1.0);
  EXPECT_TRUE(held);
  // j1 (the overlay joint) stays stowed: its stop, as stiff as a latch
  // (1000 N m/rad), yields 0.01 rad to the other seven springs, against the
  // 1.56 rad it travels when free.
  EXPECT_LT(std::abs(stuck.angle.back() - stuck.angle.front()), 0.02);
  // Friction on the root hinge slows the whole array: it still latches, later
  // (8.05 s against 7.39 s).
  const studies::CaseResult cold =
      studies::case_result(study, nominal, cases[3], studies::simulate_case(study, cases[3]));
  EXPECT_EQ(cold.status, studies::CaseStatus::deployed) << cold.reason;
  EXPECT_GT(studies::output_value(columns, cold, "deployment_time"), 7.3921759 + 0.1);
}

// Inputs that moved together (a zip) are not ranked as one driver, and tail
// percentiles are given only where the sample reaches beyond them.
TEST(StudyStatistics, NoDriverAmongInputsThatMovedTogetherAndNoPercentileBeyondTheSample) {
  studies::CaseColumns columns;
  columns.inputs = {"springs.j1.preload_factor", "springs.j2.preload_factor", "latches.j1.stiffness"};
  columns.outputs = studies::CaseColumns::headline();
  std::vector<studies::CaseResult> results;
  for (int k = 0; k < 30; ++k) {
    studies::CaseResult r;
    r.status = studies::CaseStatus::deployed;
    const double f = 0.9 + 0.01 * k;
    r.inputs = {f, f, 1000.0 + 37 * ((k * 7) % 11)};
    r.outputs.assign(columns.outputs.size(), 8.0 - f);
    results.push_back(r);
  }
  const studies::StudyStatistics st = studies::study_statistics(columns, results, true);
  ASSERT_FALSE(st.drivers.empty());
  EXPECT_EQ(st.drivers.front().input, "springs.j1.preload_factor");
  EXPECT_EQ(st.drivers.front().together,
            (std::vector<std::string>{"springs.j2.preload_factor", "latches.j1.stiffness"}));
  EXPECT_TRUE(studies::study_statistics(columns, results, false).drivers.front().together.empty());
  // A zip of lists moved its inputs together; a product or random draws did not.
  EXPECT_TRUE(studies::inputs_moved_together(study_from(
      "scene: zfold\ncombine: zip\nvary:\n  - {path: springs.*.preload, values: [0.9, 1.1]}\n")));
  EXPECT_FALSE(studies::inputs_moved_together(study_from(
      "scene: zfold\nvary:\n  - {path: springs.*.preload, values: [0.9, 1.1]}\n")));
  // 30 cases: p5 and p95, no p1 and p99.
  EXPECT_FALSE(std::isnan(st.outputs.front().p5));
  EXPECT_TRUE(std::isnan(st.outputs.front().p1));
  EXPECT_TRUE(std::isnan(st.outputs.front().p99));
  results.resize(3);
  const studies::StudyStatistics three = studies::study_statistics(columns, results);
  EXPECT_TRUE(std::isnan(three.outputs.front().p5));
  EXPECT_FALSE(std::isnan(three.outputs.front().p50));
}

TEST(StudyStatistics, CountsAndDriversOverDeployedCasesWithoutInjectedFailures) {
  const studies::Study study =
      study_from("scene: pantograph\nvary:\n  - {path: springs.j1.stiffness, values: [1, 2, 3, 4]}\n");
  const studies::CaseColumns columns = studies::case_columns(study, studies::nominal_scene(study).scene);
  std::vector<studies::CaseResult> rows;
  for (int k = 0; k < 6; ++k) {
    studies::CaseResult r;
    r.inputs = {static_cast<double>(k)};
    r.outputs.assign(columns.outputs.size(), 1.0);
    r.outputs[0] = 10.0 - k * k;  // deployment time falls as the input grows
    r.status = k == 5 ? studies::CaseStatus::failed : studies::CaseStatus::deployed;
    if (k == 4) r.failure = "spring j1 broken";
    rows.push_back(r);
  }
  const studies::StudyStatistics st = studies::study_statistics(columns, rows);
  EXPECT_EQ(st.cases, 6);
  EXPECT_EQ(st.deployed, 5);
  EXPECT_EQ(st.failed, 1);
  EXPECT_EQ(st.outputs[0].n, 4);
  EXPECT_DOUBLE_EQ(st.outputs[0].min, 1.0);
  EXPECT_DOUBLE_EQ(st.outputs[0].max, 10.0);
  ASSERT_FALSE(st.drivers.empty());
  EXPECT_EQ(st.drivers[0].output, "deployment_time");
  EXPECT_DOUBLE_EQ(st.drivers[0].rho, -1.0);
}

}  // namespace
}  // namespace unfurl
