#include "cli.hpp"

#include <cmath>

namespace unfurl::app {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
           const std::set<std::string>& switches) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a.size() < 2 || a[0] != '-' || a == "-") {
      positionals_.push_back(a);
      continue;
    }
    std::string flag = a, value;
    bool inline_value = false;
    if (const auto eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
      flag = a.substr(0, eq);
      value = a.substr(eq + 1);
      inline_value = true;
    }
    if (switches.count(flag)) {
      if (inline_value) throw UsageError(flag + " takes no value");
      values_[flag].push_back("");
    } else if (valued.count(flag)) {
      if (!inline_value) {
        if (i + 1 >= argv.size()) throw UsageError(flag + " needs a value");
        value = argv[++i];
      }
      values_[flag].push_back(value);
    } else {
      throw UsageError("unknown option " + flag + " (see --help)");
    }
  }
}

std::optional<std::string> Args::get(const std::string& flag) const {
  const auto it = values_.find(flag);
  if (it == values_.end()) return std::nullopt;
  return it->second.back();
}

std::vector<std::string> Args::all(const std::string& flag) const {
  const auto it = values_.find(flag);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

std::optional<double> Args::number(const std::string& flag) const {
  const auto text = get(flag);
  if (!text) return std::nullopt;
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(*text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text->size() || !std::isfinite(x)) throw UsageError(flag + ": expected a number, got '" + *text + "'");
  return x;
}

double Args::number(const std::string& flag, double fallback) const {
  const auto x = number(flag);
  return x ? *x : fallback;
}

}  // namespace unfurl::app
