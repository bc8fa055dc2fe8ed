#include "unfurl/sim/flexible/fem_model.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace unfurl::sim::flexible {
namespace {

struct Token {
  std::string text;
  int line = 0;
};

// A record group's words, in order, and the line of its heading.
struct Group {
  int heading_line = 0;
  std::vector<Token> tokens;
};

bool starts_with(const std::string& line, const char* prefix) { return line.rfind(prefix, 0) == 0; }

// Every record group of the file by number; "**" lines other than the
// headings are comments.
std::map<int, Group> record_groups(const std::string& text, const std::string& path) {
  std::map<int, Group> groups;
  std::istringstream in(text);
  Group* current = nullptr;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (starts_with(line, "** END OF FILE")) break;
    if (starts_with(line, "** RECORD GROUP ")) {
      char* end = nullptr;
      const char* number = line.c_str() + std::string("** RECORD GROUP ").size();
      const long n = std::strtol(number, &end, 10);
      if (end == number) throw FemFileError(path, line_number, "a RECORD GROUP heading without its number");
      if (groups.count(static_cast<int>(n)))
        throw FemFileError(path, line_number, "RECORD GROUP " + std::to_string(n) + " appears twice");
      current = &groups[static_cast<int>(n)];
      current->heading_line = line_number;
      continue;
    }
    if (starts_with(line, "**")) continue;
    std::istringstream words(line);
    if (!current) {
      std::string word;
      if (words >> word) throw FemFileError(path, line_number, "'" + word + "' before the first RECORD GROUP heading");
      continue;
    }
    for (std::string word; words >> word;) current->tokens.push_back({word, line_number});
  }
  return groups;
}

// Reads one group's words as numbers, `count` of them, as it says.
class GroupReader {
 public:
  GroupReader(const std::string& path, int number, const Group& group, const std::string& what)
      : path_(path), number_(number), group_(group), what_(what) {}

  std::vector<double> numbers(std::size_t count, std::size_t first = 0) const {
    expect(first + count);
    std::vector<double> out(count);
    for (std::size_t k = 0; k < count; ++k) out[k] = number(group_.tokens[first + k]);
    return out;
  }
  void expect(std::size_t count) const {
    const std::vector<Token>& t = group_.tokens;
    if (t.size() < count)
      throw FemFileError(path_, t.empty() ? group_.heading_line : t.back().line,
                         name() + " ends after " + std::to_string(t.size()) + " of its " + std::to_string(count) +
                             " entries (" + what_ + ")");
    if (t.size() > count)
      throw FemFileError(path_, t[count].line,
                         name() + " holds more than its " + std::to_string(count) + " entries (" + what_ + ")");
  }
  const Group& group() const { return group_; }
  [[noreturn]] void fail(int line, const std::string& what) const { throw FemFileError(path_, line, name() + ": " + what); }

  // Word k as a count (of nodes or modes).
  int count(std::size_t k) const {
    const Token& token = group_.tokens[k];
    const double x = number(token);
    if (x < 0 || x != std::floor(x) || x > 1e7)
      throw FemFileError(path_, token.line, name() + ": '" + token.text + "' is not a count");
    return static_cast<int>(x);
  }

  double number(const Token& token) const {
    std::string text = token.text;
    for (char& c : text)
      if (c == 'D' || c == 'd') c = 'E';  // Fortran's double-precision exponent
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(x))
      throw FemFileError(path_, token.line, name() + ": '" + token.text + "' is not a finite number");
    return x;
  }

 private:
  std::string name() const { return "RECORD GROUP " + std::to_string(number_); }
  const std::string& path_;
  int number_;
  const Group& group_;
  std::string what_;
};

Eigen::MatrixXd square(const std::vector<double>& values, std::size_t n) {
  Eigen::MatrixXd out(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) out(i, j) = values[i * n + j];
  return out;
}

// A node carries one mass (the same along x, y and z) and no negative
// inertia: refused at the node's line.
void check_lumped_masses(const FemModel& fem, const GroupReader& lumped) {
  for (int k = 0; k < fem.nodes(); ++k) {
    const Eigen::Matrix<double, 6, 1> m = fem.lumped.col(k);
    const int line = lumped.group().tokens[6 * k].line;
    if (m.minCoeff() < 0)
      lumped.fail(line, "node " + fem.labels[k] + " has a negative lumped mass or moment of inertia");
    if (std::abs(m[1] - m[0]) > 1e-9 * m[0] || std::abs(m[2] - m[0]) > 1e-9 * m[0])
      lumped.fail(line, "node " + fem.labels[k] + "'s masses along x, y and z differ; a node carries one mass");
  }
}

// The rigid body's mass and centre are the lumped masses' (1 % of the mass,
// and of the model's size): a unit or axis slip between the two shows.
void check_rigid_body(const FemModel& fem, const GroupReader& rigid) {
  const std::vector<double> r = rigid.numbers(13);
  const double lumped_mass = fem.lumped.row(0).sum();
  const int line = rigid.group().tokens[0].line;
  if (std::abs(r[0] - lumped_mass) > 0.01 * r[0])
    rigid.fail(line, "the rigid body's mass is " + std::to_string(r[0]) + " kg, the lumped masses sum to " +
                         std::to_string(lumped_mass) + " kg");
  const Eigen::Vector3d centre = fem.points * fem.lumped.row(0).transpose() / lumped_mass;
  if ((Eigen::Vector3d(r[1], r[2], r[3]) - centre).norm() > 0.01 * fem.size())
    rigid.fail(rigid.group().tokens[1].line, "the rigid body's centre of mass is not the lumped masses'");
}

}  // namespace

FemModel read_fem_text(const std::string& text, const std::string& path) {
  const std::map<int, Group> groups = record_groups(text, path);
  const auto group = [&](int n, const char* what) -> const Group& {
    const auto found = groups.find(n);
    if (found == groups.end())
      throw FemFileError(path, 0, "no RECORD GROUP " + std::to_string(n) + " (" + what + ")");
    return found->second;
  };
  const GroupReader header(path, 1, group(1, "the header"),
                           "revision, nodes, normal, attachment, constraint and rejected modes");
  header.expect(6);
  // Group 8 holds every mode, the rejected ones first; the others hold the
  // modes kept.
  const std::size_t nodes = header.count(1), all_modes = header.count(2) + header.count(3) + header.count(4),
                    rejected = header.count(5);
  if (nodes == 0) throw FemFileError(path, header.group().tokens[1].line, "RECORD GROUP 1: the model has no nodes");
  if (rejected >= all_modes)
    throw FemFileError(path, header.group().tokens[5].line,
                       "RECORD GROUP 1: " + std::to_string(rejected) + " of its " + std::to_string(all_modes) +
                           " modes rejected, none left");
  const std::size_t modes = all_modes - rejected;

  FemModel fem;
  const Group& labels = group(2, "the node labels");
  GroupReader(path, 2, labels, std::to_string(nodes) + " node labels").expect(nodes);
  for (const Token& t : labels.tokens) fem.labels.push_back(t.text);
  const std::string per_mode = "one per mode, " + std::to_string(modes);
  for (int n : {3, 4})
    if (groups.count(n)) GroupReader(path, n, groups.at(n), per_mode).numbers(modes);

  fem.points.resize(3, nodes);
  const char* axes[] = {"the nodes' x", "the nodes' y", "the nodes' z"};
  for (int c = 0; c < 3; ++c) {
    const std::vector<double> x = GroupReader(path, 5 + c, group(5 + c, axes[c]), axes[c]).numbers(nodes);
    for (std::size_t k = 0; k < nodes; ++k) fem.points(c, k) = x[k];
  }

  const GroupReader shapes(path, 8, group(8, "the mode shapes"),
                           "6 per node for each of " + std::to_string(all_modes) + " modes, the rejected ones first");
  const std::vector<double> phi = shapes.numbers(all_modes * nodes * 6);
  fem.shapes.resize(6 * nodes, modes);
  for (std::size_t j = 0; j < modes; ++j)
    for (std::size_t r = 0; r < 6 * nodes; ++r) fem.shapes(r, j) = phi[(j + rejected) * 6 * nodes + r];

  const std::string matrix = std::to_string(modes) + " x " + std::to_string(modes) + ", row by row";
  fem.mass = square(GroupReader(path, 9, group(9, "the modal mass matrix"), matrix).numbers(modes * modes), modes);
  fem.stiffness =
      square(GroupReader(path, 10, group(10, "the modal stiffness matrix"), matrix).numbers(modes * modes), modes);
  if (groups.count(13)) fem.damping = square(GroupReader(path, 13, groups.at(13), matrix).numbers(modes * modes), modes);

  const GroupReader lumped(path, 11, group(11, "the lumped masses, which the body's inertia is summed from"),
                           "3 masses and 3 moments of inertia per node");
  const std::vector<double> m = lumped.numbers(6 * nodes);
  fem.lumped = Eigen::Map<const Eigen::Matrix<double, 6, Eigen::Dynamic>>(m.data(), 6, nodes);
  check_lumped_masses(fem, lumped);
  if (groups.count(12))
    check_rigid_body(fem, GroupReader(path, 12, groups.at(12), "the mass, the centre of mass and the 3 x 3 inertia "
                                                               "about it"));
  return fem;
}

double FemModel::size() const { return (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).maxCoeff(); }

int FemModel::node_at(const Eigen::Vector3d& point) const {
  const double tolerance = 1e-6 * std::max(size(), point.norm());
  for (int k = 0; k < nodes(); ++k)
    if ((points.col(k) - point).norm() <= tolerance) return k;
  return -1;
}

bool FemModel::attaches(const Eigen::Vector3d& point) const {
  return node_at(point) >= 0 || point.norm() <= 1e-6 * size();
}

FemModel read_fem(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FemFileError(path, 0, "cannot open the modal data file");
  std::stringstream text;
  text << in.rdbuf();
  return read_fem_text(text.str(), path);
}

}  // namespace unfurl::sim::flexible
