#include "trajectory_csv.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace unfurl::app {

namespace {

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

void read_events(const Scene& scene, const std::string& path, Trajectory& tr) {
  std::ifstream in(path);
  if (!in) return;
  std::string line;
  std::getline(in, line);
  for (int n = 2; std::getline(in, line); ++n) {
    const auto cells = split(line);
    if (cells.size() != 3) throw std::runtime_error(path + ":" + std::to_string(n) + ": expected t,event,joint");
    const int joint = scene.model.find_body(cells[2]);
    int latch = -1;
    for (std::size_t l = 0; l < scene.latches.size(); ++l)
      if (scene.model.joints[scene.latches[l].joint].name == cells[2]) latch = static_cast<int>(l), (void)joint;
    if (latch < 0) throw std::runtime_error(path + ":" + std::to_string(n) + ": no latch on joint '" + cells[2] + "'");
    tr.events.push_back({parse(cells[0], path + ":" + std::to_string(n)), latch, scene.latches[latch].joint});
  }
}

}  // namespace

Trajectory read_trajectory_csv(const Scene& scene, const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the trajectory");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file");
  const auto header = split(line);
  std::map<std::string, int> column;
  for (std::size_t c = 0; c < header.size(); ++c) column[header[c]] = static_cast<int>(c);
  const Model& model = scene.model;
  auto need = [&](const std::string& name) {
    const auto it = column.find(name);
    if (it == column.end())
      throw std::runtime_error(path + ":1: no column '" + name + "' (was it written for scene '" + scene.name + "'?)");
    return it->second;
  };
  const int t_col = need("t");
  std::vector<int> q_col, dq_col, p_col, gap_m_col, gap_rad_col;
  for (int c = 0; c < model.nq; ++c) {
    const std::string& joint = model.joints[model.joint_of_coordinate[c]].name;
    q_col.push_back(need("q." + joint));
    dq_col.push_back(need("dq." + joint));
    p_col.push_back(need("p." + joint));
  }
  for (const Loop& loop : scene.loops) {
    gap_m_col.push_back(need("closure_m." + loop.name));
    gap_rad_col.push_back(need("closure_rad." + loop.name));
  }
  const int energy_col = need("energy");

  Trajectory tr;
  tr.layout.nq = model.nq;
  for (int n = 2; std::getline(in, line); ++n) {
    const auto cells = split(line);
    const std::string where = path + ":" + std::to_string(n);
    if (cells.size() != header.size()) throw std::runtime_error(where + ": expected " + std::to_string(header.size()) + " columns");
    Sample s;
    s.t = parse(cells[t_col], where);
    s.y.resize(2 * model.nq);
    s.dq.resize(model.nq);
    for (int c = 0; c < model.nq; ++c) {
      s.y[c] = parse(cells[q_col[c]], where);
      s.y[model.nq + c] = parse(cells[p_col[c]], where);
      s.dq[c] = parse(cells[dq_col[c]], where);
    }
    for (std::size_t l = 0; l < scene.loops.size(); ++l) {
      s.closure.push_back({parse(cells[gap_m_col[l]], where), parse(cells[gap_rad_col[l]], where)});
    }
    s.energy.unattributed = parse(cells[energy_col], where);
    if (!tr.samples.empty() && !(s.t > tr.samples.back().t)) throw std::runtime_error(where + ": times must increase");
    tr.samples.push_back(std::move(s));
  }
  if (tr.samples.empty()) throw std::runtime_error(path + ": no samples");
  read_events(scene, (std::filesystem::path(path).parent_path() / "events.csv").string(), tr);
  return tr;
}

}  // namespace unfurl::app
