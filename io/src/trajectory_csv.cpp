#include "unfurl/io/trajectory_csv.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace unfurl::io {

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
    const std::vector<const Latch*> latches = scene.latches();
    int latch = -1;
    for (std::size_t l = 0; l < latches.size(); ++l)
      if (scene.model.joints[latches[l]->joint].name == cells[2]) latch = static_cast<int>(l);
    if (latch < 0) throw std::runtime_error(path + ":" + std::to_string(n) + ": no latch on joint '" + cells[2] + "'");
    tr.events.push_back({parse(cells[0], path + ":" + std::to_string(n)), latch, latches[latch]->joint});
  }
}

// loads.csv beside the trajectory, when there is one: the same samples.
void read_loads(const Scene& scene, const std::string& path, Trajectory& tr) {
  std::ifstream in(path);
  if (!in) return;
  std::string line;
  if (!std::getline(in, line)) return;
  const auto header = split(line);
  std::map<std::string, int> column;
  for (std::size_t c = 0; c < header.size(); ++c) column[header[c]] = static_cast<int>(c);
  const Model& model = scene.model;
  auto find = [&](const std::string& name) {
    const auto it = column.find(name);
    return it == column.end() ? -1 : it->second;
  };
  tr.load_columns = scene.load_columns();
  std::vector<int> loop_columns;
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (header[c].rfind("loop_force.", 0) != 0) continue;
    loop_columns.push_back(static_cast<int>(c));
    const std::string rest = header[c].substr(11);
    const auto dot = rest.rfind('.');
    int loop = -1, axis = -1;
    for (std::size_t l = 0; l < scene.loops.size(); ++l)
      if (dot != std::string::npos && scene.loops[l].name == rest.substr(0, dot)) loop = static_cast<int>(l);
    for (int a = 0; a < 6; ++a)
      if (dot != std::string::npos && rest.substr(dot + 1) == wrench_component_name(a)) axis = a;
    if (loop < 0 || axis < 0) throw std::runtime_error(path + ":1: no loop component '" + rest + "' in the scene");
    tr.loop_components.push_back({loop, axis});
  }
  for (std::size_t k = 0; k < tr.samples.size(); ++k) {
    if (!std::getline(in, line)) throw std::runtime_error(path + ": fewer rows than trajectory.csv");
    const std::string where = path + ":" + std::to_string(k + 2);
    const auto cells = split(line);
    if (cells.size() != header.size()) throw std::runtime_error(where + ": expected " + std::to_string(header.size()) + " columns");
    Sample& s = tr.samples[k];
    if (std::abs(parse(cells[0], where) - s.t) > 1e-9 * std::max(1.0, std::abs(s.t)))
      throw std::runtime_error(where + ": its time is not trajectory.csv's");
    s.loads.element.assign(tr.load_columns.size(), 0.0);
    for (std::size_t c = 0; c < tr.load_columns.size(); ++c) {
      const int at = find(tr.load_columns[c].name);
      if (at >= 0) s.loads.element[c] = parse(cells[at], where);
    }
    s.loads.reaction.resize(model.size());
    for (int j = 0; j < model.size(); ++j) {
      const std::string& name = model.joints[j].name;
      for (int a = 0; a < 6; ++a) {
        const int c = find("reaction." + name + "." + wrench_component_name(a));
        if (c < 0) throw std::runtime_error(path + ":1: no column 'reaction." + name + "." + wrench_component_name(a) + "'");
        s.loads.reaction[j][a] = parse(cells[c], where);
      }
    }
    for (int c : loop_columns) s.loads.loop_force.push_back(parse(cells[c], where));
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
    q_col.push_back(need("q." + model.position_name(c)));
    dq_col.push_back(need("dq." + model.position_name(c)));
  }
  for (int c = 0; c < model.nv; ++c) p_col.push_back(need("p." + model.velocity_name(c)));
  for (const Loop& loop : scene.loops) {
    gap_m_col.push_back(need("closure_m." + loop.name));
    gap_rad_col.push_back(need("closure_rad." + loop.name));
  }
  const int energy_col = need("energy");
  const auto dissipated_col = column.find("energy_dissipated");

  Trajectory tr;
  tr.layout.nq = model.nq;
  tr.layout.nv = model.nv;
  for (int n = 2; std::getline(in, line); ++n) {
    const auto cells = split(line);
    const std::string where = path + ":" + std::to_string(n);
    if (cells.size() != header.size()) throw std::runtime_error(where + ": expected " + std::to_string(header.size()) + " columns");
    Sample s;
    s.t = parse(cells[t_col], where);
    s.y.resize(model.nq + model.nv);
    s.q_dot.resize(model.nq);
    for (int c = 0; c < model.nq; ++c) {
      s.y[c] = parse(cells[q_col[c]], where);
      s.q_dot[c] = parse(cells[dq_col[c]], where);
    }
    for (int c = 0; c < model.nv; ++c) s.y[model.nq + c] = parse(cells[p_col[c]], where);
    for (std::size_t l = 0; l < scene.loops.size(); ++l) {
      s.closure.push_back({parse(cells[gap_m_col[l]], where), parse(cells[gap_rad_col[l]], where)});
    }
    s.energy.unattributed = parse(cells[energy_col], where);
    if (dissipated_col != column.end()) s.energy.dissipated = parse(cells[dissipated_col->second], where);
    if (!tr.samples.empty() && !(s.t > tr.samples.back().t)) throw std::runtime_error(where + ": times must increase");
    tr.samples.push_back(std::move(s));
  }
  if (tr.samples.empty()) throw std::runtime_error(path + ": no samples");
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  read_events(scene, (dir / "events.csv").string(), tr);
  read_loads(scene, (dir / "loads.csv").string(), tr);
  return tr;
}

}  // namespace unfurl::io
