#include "sweep_grid.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace hsrod::sweep {
namespace {

double parse_number(const std::string &name, const std::string &item, const std::string &text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception &) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value))
    throw GridError("--var " + name + ": '" + text + "' in '" + item +
                    "' is not a number (expected value, start:stop:step or start:stop:*factor)");
  return value;
}

std::string format_value(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", value);
  return text;
}

// A range of at most this many values: a typo in a step must not start a
// sweep of billions of cases.
constexpr long max_range_values = 1000000;

void append_range(const std::string &name, const std::string &item, std::vector<std::string> &values) {
  const std::size_t first = item.find(':');
  const std::size_t second = item.find(':', first + 1);
  if (second == std::string::npos || item.find(':', second + 1) != std::string::npos)
    throw GridError("--var " + name + ": range '" + item + "' must be start:stop:step or start:stop:*factor");
  const double start = parse_number(name, item, item.substr(0, first));
  const double stop = parse_number(name, item, item.substr(first + 1, second - first - 1));
  std::string step_text = item.substr(second + 1);
  const bool geometric = !step_text.empty() && step_text[0] == '*';
  if (geometric) step_text.erase(0, 1);
  const double step = parse_number(name, item, step_text);
  // Inclusive of stop up to a relative rounding tolerance (1e-9 of a step).
  constexpr double tolerance = 1e-9;
  long count = 0;
  if (geometric) {
    if (!(step > 1.0) || !(start > 0.0) || !(stop >= start))
      throw GridError("--var " + name + ": geometric range '" + item +
                      "' needs 0 < start <= stop and factor > 1");
    count = static_cast<long>(std::floor(std::log(stop / start) / std::log(step) + tolerance)) + 1;
  } else {
    if (!(step > 0.0) || !(stop >= start))
      throw GridError("--var " + name + ": range '" + item + "' needs start <= stop and step > 0");
    count = static_cast<long>(std::floor((stop - start) / step + tolerance)) + 1;
  }
  if (count > max_range_values)
    throw GridError("--var " + name + ": range '" + item + "' has more than 1000000 values");
  for (long i = 0; i < count; ++i)
    values.push_back(format_value(geometric ? start * std::pow(step, static_cast<double>(i))
                                            : start + static_cast<double>(i) * step));
}

}  // namespace

std::vector<std::string> parse_values(const std::string &name, const std::string &spec) {
  if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
                          std::string::npos)
    throw GridError("--var '" + name + "': a LIGGGHTS variable name has only letters, digits and '_'");
  std::vector<std::string> values;
  std::stringstream items(spec);
  std::string item;
  while (std::getline(items, item, ',')) {
    if (item.empty()) throw GridError("--var " + name + ": empty item in '" + spec + "'");
    if (item.find(':') != std::string::npos) {
      append_range(name, item, values);
    } else {
      if (item.find_first_of(" \t\"'") != std::string::npos)
        throw GridError("--var " + name + ": value '" + item + "' must not contain blanks or quotes");
      values.push_back(item);  // kept as written: a value may be a word (e.g. a model name)
    }
  }
  if (values.empty()) throw GridError("--var " + name + ": no values in '" + spec + "'");
  return values;
}

CaseGrid::CaseGrid(std::vector<SweptVariable> variables) : variables_(std::move(variables)) {
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j)
      if (variables_[j].name == variables_[i].name)
        throw GridError("--var " + variables_[i].name + " given twice");
    if (variables_[i].values.empty()) throw GridError("--var " + variables_[i].name + ": no values");
    size_ *= variables_[i].values.size();
  }
}

std::vector<std::string> CaseGrid::values_of(std::size_t id) const {
  std::vector<std::string> values(variables_.size());
  for (std::size_t i = variables_.size(); i-- > 0;) {
    const std::size_t n = variables_[i].values.size();
    values[i] = variables_[i].values[id % n];
    id /= n;
  }
  return values;
}

}  // namespace hsrod::sweep
