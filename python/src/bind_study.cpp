// Studies: a study file, or a study's YAML text made in Python, run on the
// machine's cores (the CLI's runner: threads, a record per case), its
// cases returned as arrays; with `out` the CLI's files are written there too
// (cases.csv, summary.json, STUDY.md and the plots).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "py_types.hpp"
#include "study_plots.hpp"
#include "study_runner.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/io/study_files.hpp"
#include "unfurl/studies/study.hpp"

namespace unfurl::python {

namespace py = pybind11;

namespace {

// A scratch directory for the cases' records, removed when done.
struct Scratch {
  std::filesystem::path path;
  Scratch() {
    path = std::filesystem::temp_directory_path() /
           ("unfurl_py_study_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::filesystem::create_directories(path);
  }
  ~Scratch() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

py::array_t<double> matrix(const std::vector<studies::CaseResult>& results, bool inputs, std::size_t columns) {
  py::array_t<double> a({results.size(), columns});
  auto d = a.mutable_unchecked<2>();
  for (std::size_t k = 0; k < results.size(); ++k) {
    const std::vector<double>& row = inputs ? results[k].inputs : results[k].outputs;
    for (std::size_t c = 0; c < columns; ++c) d(k, c) = c < row.size() ? row[c] : std::nan("");
  }
  return a;
}

}  // namespace

void bind_study(py::module_& m) {
  m.def(
      "_study",
      [](const std::string& source, bool is_text, const std::string& directory, const std::optional<std::string>& out,
         std::optional<int> jobs) {
        const studies::Study study = is_text ? studies::read_study_text(source, "python", directory)
                                             : studies::read_study_file(source);
        const int threads = jobs.value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
        if (threads < 1 || threads > 1024) throw py::value_error("jobs: expected 1..1024");
        Scratch scratch;
        const std::string dir = out.value_or(scratch.path.string());
        io::make_directory(dir);
        std::atomic<bool> cancel{false};
        const auto start = std::chrono::steady_clock::now();
        app::SweepOptions options{dir, threads, false, true};
        app::StudyRun run(study, options, cancel);
        run_interruptibly(
            [&] {
              app::run_locally(run);
              return 0;
            },
            cancel, [] {});
        std::vector<studies::CaseResult> results;
        for (const auto& r : run.results())
          if (r) results.push_back(*r);
        if (out) {
          io::StudyReport report{study,
                                 run.columns(),
                                 results,
                                 static_cast<long>(run.cases().size()),
                                 0,
                                 studies::study_statistics(run.columns(), results, studies::inputs_moved_together(study)),
                                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                                 1,
                                 threads,
                                 "unfurl.study (Python)"};
          io::write_cases_csv(report, *out + "/cases.csv");
          io::write_study_summary_json(report, *out + "/summary.json");
          const std::vector<std::string> plots = app::write_study_plots(report, *out);
          io::write_study_markdown(report, plots, *out + "/STUDY.md");
        }
        std::vector<std::string> ids, failures, status, reasons, output_units;
        for (const studies::CaseResult& r : results) {
          ids.push_back(r.id), failures.push_back(r.failure), reasons.push_back(r.reason);
          status.push_back(studies::case_status_name(r.status));
        }
        for (const std::string& o : run.columns().outputs) output_units.push_back(studies::output_unit(o));
        py::dict d;
        d["case"] = ids, d["failure"] = failures, d["status"] = status, d["reason"] = reasons;
        d["inputs"] = run.columns().inputs, d["outputs"] = run.columns().outputs;
        d["output_units"] = output_units;
        d["input_data"] = matrix(results, true, run.columns().inputs.size());
        d["output_data"] = matrix(results, false, run.columns().outputs.size());
        return d;
      },
      py::arg("source"), py::arg("is_text"), py::arg("directory"), py::arg("out") = std::nullopt,
      py::arg("jobs") = std::nullopt);
}

}  // namespace unfurl::python
