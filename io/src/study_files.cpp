#include "unfurl/io/study_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "unfurl/io/json_writer.hpp"
#include "unfurl/io/output_file.hpp"

namespace unfurl::io {

namespace {

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        fields.back() += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        fields.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::string number(double x) {
  if (!std::isfinite(x)) return "";
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

double parse_number(const std::string& s) {
  if (s.empty()) return std::nan("");
  return std::stod(s);
}

std::optional<studies::CaseStatus> parse_status(const std::string& s) {
  for (studies::CaseStatus status :
       {studies::CaseStatus::deployed, studies::CaseStatus::not_deployed, studies::CaseStatus::failed})
    if (s == studies::case_status_name(status)) return status;
  return std::nullopt;
}

std::string angle_csv(const studies::CaseResult& r) {
  std::string out = "t,q\n";
  for (std::size_t k = 0; k < r.angle_t.size(); ++k) out += number(r.angle_t[k]) + "," + number(r.angle[k]) + "\n";
  return out;
}

void parse_angle_csv(const std::string& text, studies::CaseResult& r) {
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    const auto f = split_csv_line(line);
    if (f.size() != 2) continue;
    r.angle_t.push_back(parse_number(f[0]));
    r.angle.push_back(parse_number(f[1]));
  }
}

void write_text(const std::string& path, const std::string& text) {
  OutputFile out(path);
  out.stream() << text;
  out.commit();
}

const char* kNumberFormat = "%.6g";

// A table cell's text: '|' would end the cell.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string fmt(double x) {
  if (!std::isfinite(x)) return "-";
  char text[40];
  std::snprintf(text, sizeof text, kNumberFormat, x);
  return text;
}

}  // namespace

std::string read_text_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<double> read_cases_column(const std::string& path, const std::string& name, const std::string& status) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read it");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file");
  const std::vector<std::string> header = split_csv_line(line);
  const auto named = [&](const std::string& cell) { return cell == name || cell.rfind(name + " [", 0) == 0; };
  const auto column = std::find_if(header.begin(), header.end(), named);
  const auto status_column = std::find(header.begin(), header.end(), "status");
  if (column == header.end() || status_column == header.end())
    throw std::runtime_error(path + ": no column '" + name + "' (or no status column)");
  const std::size_t c = column - header.begin(), st = status_column - header.begin();
  std::vector<double> values;
  while (std::getline(in, line)) {
    const std::vector<std::string> row = split_csv_line(line);
    if (row.size() != header.size() || row[st] != status || row[c].empty()) continue;
    values.push_back(parse_number(row[c]));
  }
  return values;
}

std::string cases_header(const studies::CaseColumns& columns) {
  std::string h = "case,failure,status,reason";
  for (const std::string& c : columns.inputs) h += "," + csv_field(c);
  for (const std::string& c : columns.outputs) {
    const std::string unit = studies::output_unit(c);
    h += "," + csv_field(unit.empty() ? c : c + " [" + unit + "]");
  }
  return h;
}

std::string case_row(const studies::CaseResult& r) {
  std::string row = csv_field(r.id) + "," + csv_field(r.failure) + "," + studies::case_status_name(r.status) + "," +
                    csv_field(r.reason);
  for (double x : r.inputs) row += "," + number(x);
  for (double x : r.outputs) row += "," + number(x);
  return row;
}

std::string case_record(const studies::CaseColumns& columns, const studies::CaseResult& r) {
  return cases_header(columns) + "\n" + case_row(r) + "\n\f" + angle_csv(r);
}

std::optional<studies::CaseResult> parse_case_record(const studies::CaseColumns& columns, const std::string& record) {
  const auto split = record.find('\f');
  std::istringstream lines(record.substr(0, split));
  std::string header, row;
  if (!std::getline(lines, header) || header != cases_header(columns) || !std::getline(lines, row)) return std::nullopt;
  const auto f = split_csv_line(row);
  const std::size_t n_in = columns.inputs.size(), n_out = columns.outputs.size();
  if (f.size() != 4 + n_in + n_out) return std::nullopt;
  studies::CaseResult r;
  r.id = f[0];
  r.failure = f[1];
  const auto status = parse_status(f[2]);
  if (!status) return std::nullopt;
  r.status = *status;
  r.reason = f[3];
  try {
    for (std::size_t i = 0; i < n_in; ++i) r.inputs.push_back(parse_number(f[4 + i]));
    for (std::size_t i = 0; i < n_out; ++i) r.outputs.push_back(parse_number(f[4 + n_in + i]));
    if (split != std::string::npos) parse_angle_csv(record.substr(split + 1), r);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  return r;
}

void write_case_record(const std::string& dir, const std::string& id, const std::string& record) {
  const std::string case_dir = dir + "/cases/" + id;
  make_directory(case_dir);
  const auto split = record.find('\f');
  // The angles first: a case counts as finished once case.csv exists.
  write_text(case_dir + "/angle.csv", split == std::string::npos ? "t,q\n" : record.substr(split + 1));
  write_text(case_dir + "/case.csv", record.substr(0, split));
}

std::optional<studies::CaseResult> read_case_record(const studies::CaseColumns& columns, const std::string& dir,
                                                    const std::string& id) {
  const std::string case_dir = dir + "/cases/" + id;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(case_dir + "/case.csv", ec)) return std::nullopt;
  return parse_case_record(columns,
                           read_text_file(case_dir + "/case.csv") + "\f" + read_text_file(case_dir + "/angle.csv"));
}

void write_cases_csv(const StudyReport& report, const std::string& path) {
  OutputFile out(path);
  out.stream() << cases_header(report.columns) << "\n";
  for (const studies::CaseResult& r : report.results) out.stream() << case_row(r) << "\n";
  out.commit();
}

void write_study_summary_json(const StudyReport& report, const std::string& path) {
  OutputFile file(path);
  JsonWriter json(file.stream());
  const studies::StudyStatistics& st = report.statistics;
  json.begin_object();
  json.value("study", report.study.source).value("scene", report.study.scene_source);
  json.value("cases", static_cast<long>(report.total_cases)).value("finished", st.cases);
  json.begin_object("status")
      .value("deployed", st.deployed)
      .value("not_deployed", st.not_deployed)
      .value("failed", st.failed)
      .end_object();
  json.value("fraction_deployed", st.cases ? static_cast<double>(st.deployed) / static_cast<double>(st.cases) : 0.0);
  json.value("resumed", report.resumed)
      .value("wall_time", report.wall_time_s)
      .value("processes", report.processes)
      .value("jobs", report.jobs);
  json.begin_object("outputs");
  for (const studies::OutputStatistics& o : st.outputs) {
    json.begin_object(o.output).value("n", o.n).value("min", o.min).value("max", o.max).value("mean", o.mean);
    json.value("sd", o.sd)
        .value("p1", o.p1)
        .value("p5", o.p5)
        .value("p50", o.p50)
        .value("p95", o.p95)
        .value("p99", o.p99);
    json.end_object();
  }
  json.end_object();
  json.begin_object("drivers");
  for (const studies::Driver& d : st.drivers) {
    json.begin_object(d.output).value("input", d.input).value("spearman_rho", d.rho);
    json.begin_array("moved_with");
    for (const std::string& other : d.together) json.value("", other);
    json.end_array().end_object();
  }
  json.end_object();
  json.begin_array("correlations");
  for (const studies::Driver& d : st.correlations)
    json.begin_object().value("output", d.output).value("input", d.input).value("spearman_rho", d.rho).end_object();
  json.end_array();
  json.end_object();
  file.stream() << "\n";
  file.commit();
}

namespace {

// The cases whose loads rigid mechanics cannot determine somewhere
// (CaseResult's loads_determinate = 0), counted and listed.
// Cases whose torque margin (the smallest motorization factor less one)
// falls below the required one, counted and listed with their joints.
void write_torque_margins(const StudyReport& report, std::ostream& md) {
  const double required = studies::nominal_scene(report.study).scene.torque_margin.required;
  std::vector<std::string> rows;
  long assessed = 0;
  for (const studies::CaseResult& r : report.results) {
    const double margin = studies::output_value(report.columns, r, "torque_margin");
    if (std::isnan(margin)) continue;
    ++assessed;
    if (margin + 1 >= required) continue;
    std::string joints;
    for (std::size_t o = 0; o < report.columns.outputs.size(); ++o) {
      const std::string& name = report.columns.outputs[o];
      if (name.rfind("torque_margin.", 0) != 0 || o >= r.outputs.size() || !(r.outputs[o] + 1 < required)) continue;
      joints += (joints.empty() ? "" : ", ") + name.substr(14) + " " + fmt(r.outputs[o] + 1);
    }
    rows.push_back("| " + r.id + " | " + (r.failure.empty() ? "-" : cell(r.failure)) + " | " + fmt(margin + 1) + " | " +
                   joints + " |\n");
  }
  if (assessed == 0) return;
  md << "\n## Torque margins\n\n";
  if (rows.empty()) {
    md << "Every driven joint of every case reaches the required motorization factor (" << fmt(required) << ").\n";
    return;
  }
  md << "**Warning:** in " << rows.size() << " of " << assessed
     << " cases a driven joint's motorization factor (its driving torque over its resistive torques, each with its "
        "uncertainty factor; torque_margin = the factor less one) falls below the required "
     << fmt(required) << ":\n\n| case | failure | smallest motorization factor | joints below |\n|---|---|---:|---|\n";
  for (const std::string& row : rows) md << row;
}

// The closest approach of two bodies not jointed together over the study,
// and the cases in which two touched or went through each other.
void write_clearance(const StudyReport& report, std::ostream& md) {
  std::vector<std::string> rows;
  long assessed = 0;
  double closest = std::numeric_limits<double>::infinity();
  std::string closest_case;
  for (const studies::CaseResult& r : report.results) {
    const double distance = studies::output_value(report.columns, r, "min_clearance");
    if (std::isnan(distance)) continue;
    ++assessed;
    if (distance < closest) closest = distance, closest_case = r.id;
    const double contacts = studies::output_value(report.columns, r, "contacts");
    if (contacts > 0)
      rows.push_back("| " + r.id + " | " + (r.failure.empty() ? "-" : cell(r.failure)) + " | " + fmt(contacts) + " |\n");
  }
  if (assessed == 0) return;
  md << "\n## Clearance\n\n";
  if (rows.empty()) {
    md << "No two bodies that are not jointed together touch in any case; the closest approach is " << fmt(closest)
       << " m (case " << closest_case << ").\n";
    return;
  }
  md << "**Warning:** in " << rows.size() << " of " << assessed
     << " cases two bodies that are not jointed together touch or interpenetrate (unfurl computes no contact "
        "forces: they pass through each other). The case's summary.json (`--keep-runs`) or the workbench names "
        "the bodies and when.\n\n| case | failure | spans of contact |\n|---|---|---:|\n";
  for (const std::string& row : rows) md << row;
}

void write_indeterminate_loads(const StudyReport& report, std::ostream& md) {
  const auto value = [&](const studies::CaseResult& r, const char* name) {
    return studies::output_value(report.columns, r, name);
  };
  long indeterminate = 0, assessed = 0;
  for (const studies::CaseResult& r : report.results) {
    const double determinate = value(r, "loads_determinate");
    assessed += !std::isnan(determinate);
    indeterminate += determinate == 0;
  }
  if (indeterminate == 0) return;
  md << "\n## Loads that rigid mechanics cannot determine\n\n**Warning:** in " << indeterminate << " of " << assessed
     << " cases the hinge loads are indeterminate over part of the run: the rigid loops are redundant there (as at "
        "a deployed branch point), or so near it that the regulator's forces depart from the rigid ones. The "
        "peak hinge forces and moments above and in cases.csv cover only the determinate steps, and only maxima "
        "the rigid model reaches there (a load still rising into a span, as a toggle's does, has no rigid bound, "
        "unless a latch engages where it ends); "
        "inside the spans the reactions are the minimum-norm ones (peak_hinge_force_indeterminate, with the rigid "
        "loads running into and out of the spans), and compliance in the loops determines them.\n\n| case | status "
        "| indeterminate for, s | first from, s | indeterminate peak hinge force, N |\n|---|---|---:|---:|---:|\n";
  for (const studies::CaseResult& r : report.results) {
    if (value(r, "loads_determinate") != 0) continue;
    md << "| " << r.id << " | " << studies::case_status_name(r.status) << " | " << fmt(value(r, "indeterminate_time"))
       << " | " << fmt(value(r, "indeterminate_from")) << " | " << fmt(value(r, "peak_hinge_force_indeterminate"))
       << " |\n";
  }
}

}  // namespace

void write_study_markdown(const StudyReport& report, const std::vector<std::string>& pictures,
                          const std::string& path) {
  const studies::StudyStatistics& st = report.statistics;
  OutputFile file(path);
  std::ostream& md = file.stream();
  md << "# Study: " << std::filesystem::path(report.study.source).filename().string() << "\n\n";
  md << "Scene `" << report.study.scene << "`, " << report.total_cases << " cases";
  if (report.study.runs > 0)
    md << " (the nominal case and " << report.study.runs << " random draws, seed " << report.study.seed << ")";
  if (!report.study.failures.empty()) md << ", " << report.study.failures.size() << " of them injected failures";
  md << ". Made by `" << report.command << "` in " << fmt(report.wall_time_s) << " s (" << report.processes
     << (report.processes == 1 ? " process, " : " processes, ") << report.jobs << (report.jobs == 1 ? " job" : " jobs")
     << (report.processes == 1 ? "" : " each") << ")";
  if (report.resumed > 0)
    md << "; " << report.resumed << " cases were read back from an earlier run of the same command";
  md << ".\n\n";
  if (st.cases < report.total_cases)
    md << "**Incomplete:** " << st.cases << " of " << report.total_cases << " cases finished.\n\n";
  md << "| status | cases | fraction |\n|---|---:|---:|\n";
  const auto row = [&](const char* name, long n) {
    md << "| " << name << " | " << n << " | "
       << fmt(st.cases ? 100.0 * static_cast<double>(n) / static_cast<double>(st.cases) : 0.0) << " % |\n";
  };
  row("deployed", st.deployed);
  row("not deployed", st.not_deployed);
  row("failed", st.failed);
  md << "\n## Outputs over the deployed cases\n\nInjected failures are left out here (they are listed below).\n\n";
  md << "| output | n | min | p1 | p5 | median | p95 | p99 | max | mean | sd "
        "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const studies::OutputStatistics& o : st.outputs) {
    if (std::find(studies::CaseColumns::headline().begin(), studies::CaseColumns::headline().end(), o.output) ==
            studies::CaseColumns::headline().end() ||
        o.n == 0)  // a gap for a scene without loops
      continue;
    md << "| " << o.output << " | " << o.n << " | " << fmt(o.min) << " | " << fmt(o.p1) << " | " << fmt(o.p5) << " | "
       << fmt(o.p50) << " | " << fmt(o.p95) << " | " << fmt(o.p99) << " | " << fmt(o.max) << " | " << fmt(o.mean)
       << " | " << fmt(o.sd) << " |\n";
  }
  md << "\nEvery output column (per latch and per joint) is summarized in summary.json. A tail percentile is "
        "given only where the sample reaches beyond it (p1 and p99 from 100 cases, p5 and p95 from 20; \"-\" "
        "otherwise).\n";
  if (!st.drivers.empty()) {
    md << "\n## What drives the spread\n\nSpearman's rank correlation of each output with each varied input, over the "
          "deployed cases; the strongest per output:\n\n| output | strongest input | rho |\n|---|---|---:|\n";
    for (const studies::Driver& d : st.drivers)
      md << "| " << d.output << " | " << d.input
         << (d.together.empty() ? "" : " and the " + std::to_string(d.together.size()) + " inputs that moved with it")
         << " | " << fmt(d.rho) << " |\n";
    const studies::Driver& d = st.drivers.front();
    if (d.together.empty())
      md << "\nThe deployment time is driven most by `" << d.input << "` (rho = " << fmt(d.rho) << ": "
         << (d.rho < 0 ? "a larger value deploys sooner" : "a larger value deploys later") << ").\n";
    else
      md << "\n`" << d.input << "` moved together with " << d.together.size()
         << " other inputs over these cases (a zip, or one variable applied to many): their effects cannot be "
            "told apart, and none of them is named the driver.\n";
  }
  write_indeterminate_loads(report, md);
  write_torque_margins(report, md);
  write_clearance(report, md);
  bool any_failure = false;
  for (const studies::CaseResult& r : report.results)
    any_failure = any_failure || !r.failure.empty() || r.status != studies::CaseStatus::deployed;
  if (any_failure) {
    md << "\n## Cases that did not deploy, and injected failures\n\n| case | failure | status | reason | deployment "
          "time, s | peak latch torque, N m |\n|---|---|---|---|---:|---:|\n";
    for (const studies::CaseResult& r : report.results) {
      if (r.failure.empty() && r.status == studies::CaseStatus::deployed) continue;
      md << "| " << r.id << " | " << (r.failure.empty() ? "-" : r.failure) << " | "
         << studies::case_status_name(r.status) << " | " << (r.reason.empty() ? "-" : cell(r.reason)) << " | "
         << fmt(studies::output_value(report.columns, r, "deployment_time")) << " | "
         << fmt(studies::output_value(report.columns, r, "peak_latch_torque")) << " |\n";
    }
  }
  if (!pictures.empty()) {
    md << "\n## Plots\n\n";
    for (const std::string& p : pictures) md << "![" << p << "](" << p << ")\n\n";
  }
  md << "\nThe table of every case: cases.csv (one row per case; empty where a value does not exist).\n";
  file.commit();
}

}  // namespace unfurl::io
