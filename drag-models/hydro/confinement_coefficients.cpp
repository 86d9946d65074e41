#include "hydro/confinement_coefficients.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hsrod {

double faxen_midplane_friction(double beta) {
  // Happel & Brenner (1965), eq. 7-4.28, with s = a/l = beta.
  const double s = beta;
  const double s3 = s * s * s;
  return 1.0 / (1.0 - 1.004 * s + 0.418 * s3 + 0.21 * s3 * s - 0.169 * s3 * s * s);
}

ConfinementTable::ConfinementTable(std::vector<Row> rows, std::string source)
    : rows_(std::move(rows)), source_(std::move(source)) {
  if (rows_.size() < 2) throw std::invalid_argument("confinement table needs at least two rows");
  for (size_t k = 1; k < rows_.size(); ++k)
    if (!(rows_[k].beta > rows_[k - 1].beta))
      throw std::invalid_argument("confinement table: beta must increase strictly");
  if (rows_.front().beta < 0.0 || rows_.back().beta >= 1.0)
    throw std::invalid_argument("confinement table: beta must lie in [0, 1)");
  for (const Row& r : rows_) {
    const std::string problem = coefficient_range_problem(r.c);
    if (!problem.empty()) {
      std::ostringstream msg;
      msg << "confinement table row beta = " << r.beta << ": " << problem;
      throw std::invalid_argument(msg.str());
    }
  }
}

namespace {

// Column names of the file format, in the default order, and where each
// value goes.
struct Column {
  const char* name;
  double ConfinementCoefficients::*member;  // nullptr: beta
};
const Column kColumns[] = {
    {"beta", nullptr},
    {"sphere_friction", &ConfinementCoefficients::sphere_friction},
    {"sphere_driving", &ConfinementCoefficients::sphere_driving},
    {"parallel_friction", &ConfinementCoefficients::parallel_friction},
    {"perpendicular_friction", &ConfinementCoefficients::perpendicular_friction},
    {"parallel_driving", &ConfinementCoefficients::parallel_driving},
    {"perpendicular_driving", &ConfinementCoefficients::perpendicular_driving},
};
constexpr int kColumnCount = sizeof(kColumns) / sizeof(kColumns[0]);

std::string column_list() {
  std::string s;
  for (const Column& c : kColumns) s += (s.empty() ? "" : " ") + std::string(c.name);
  return s;
}

// The whole token must be a finite number ("1.2junk", "nan", "inf" refused).
bool parse_number(const std::string& token, double& value) {
  if (token.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && errno != ERANGE && std::isfinite(value);
}

}  // namespace

std::string coefficient_range_problem(const ConfinementCoefficients& c) {
  std::ostringstream msg;
  auto check = [&](const char* name, double v, double lo, bool lo_open, double hi) {
    if (!msg.str().empty()) return;
    const bool ok = std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi;
    if (!ok)
      msg << name << " = " << v << " outside its physical range " << (lo_open ? "(" : "[") << lo
          << ", " << hi << "]";
  };
  const double big = 1e6;
  // Walls only add friction: a confined sphere's friction is at least Stokes'.
  check("sphere_friction", c.sphere_friction, 1.0, false, big);
  // A force-free sphere or rod is carried downstream, physically at most
  // with the mid-plane velocity 3/2 of the gap average; fitted tables may
  // exceed that slightly (calibration noise), twice that is nonsense.
  const double fastest = 3.0;
  check("sphere_driving", c.sphere_driving, 0.0, true, fastest);
  check("parallel_friction", c.parallel_friction, 0.0, true, big);
  check("perpendicular_friction", c.perpendicular_friction, 0.0, true, big);
  check("parallel_driving", c.parallel_driving, 0.0, true, fastest);
  check("perpendicular_driving", c.perpendicular_driving, 0.0, true, fastest);
  return msg.str();
}

ConfinementCoefficients ConfinementTable::at(double beta) const {
  if (!(beta >= rows_.front().beta && beta <= rows_.back().beta)) {
    std::ostringstream msg;
    msg << "confinement beta = d/H = " << beta << " outside the coefficient table's range [" << rows_.front().beta
        << ", " << rows_.back().beta << "]";
    throw std::invalid_argument(msg.str());
  }
  size_t k = 1;
  while (k + 1 < rows_.size() && rows_[k].beta < beta) ++k;
  const Row& a = rows_[k - 1];
  const Row& b = rows_[k];
  const double w = (beta - a.beta) / (b.beta - a.beta);
  auto mix = [w](double p, double q) { return (1.0 - w) * p + w * q; };
  ConfinementCoefficients c;
  c.sphere_friction = mix(a.c.sphere_friction, b.c.sphere_friction);
  c.sphere_driving = mix(a.c.sphere_driving, b.c.sphere_driving);
  c.parallel_friction = mix(a.c.parallel_friction, b.c.parallel_friction);
  c.perpendicular_friction = mix(a.c.perpendicular_friction, b.c.perpendicular_friction);
  c.parallel_driving = mix(a.c.parallel_driving, b.c.parallel_driving);
  c.perpendicular_driving = mix(a.c.perpendicular_driving, b.c.perpendicular_driving);
  return c;
}

ConfinementTable ConfinementTable::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open confinement coefficient file '" + path + "'");
  std::string line, source;
  int line_number = 0;
  bool have_header = false, have_columns = false;
  // order[k]: index into kColumns of the k-th column of the file.
  std::vector<int> order(kColumnCount);
  for (int k = 0; k < kColumnCount; ++k) order[k] = k;
  std::vector<Row> rows;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(path + ":" + std::to_string(line_number) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_number;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (first == "hsrod-confinement-coefficients") {
      std::string version, extra;
      if (!(words >> version) || version != "1") fail("unsupported format version (expected 1)");
      if (words >> extra) fail("unexpected '" + extra + "' after the format version");
      if (have_header) fail("second header line");
      have_header = true;
      continue;
    }
    if (!have_header) fail("missing header 'hsrod-confinement-coefficients 1' before '" + first + "'");
    if (first == "source") {
      std::getline(words, source);
    } else if (first == "columns") {
      if (have_columns) fail("second 'columns' line");
      if (!rows.empty()) fail("'columns' must come before the data rows");
      std::vector<std::string> names;
      for (std::string name; words >> name;) names.push_back(name);
      if (static_cast<int>(names.size()) != kColumnCount)
        fail("'columns' names " + std::to_string(names.size()) + " columns; expected the " +
             std::to_string(kColumnCount) + " columns " + column_list() + " (in any order)");
      std::vector<char> seen(kColumnCount, 0);
      for (int k = 0; k < kColumnCount; ++k) {
        int found = -1;
        for (int c = 0; c < kColumnCount; ++c)
          if (names[k] == kColumns[c].name) found = c;
        if (found < 0) fail("unknown column '" + names[k] + "' (expected " + column_list() + ")");
        if (seen[found]) fail("column '" + names[k] + "' named twice");
        seen[found] = 1;
        order[k] = found;
      }
      have_columns = true;
    } else {
      std::vector<std::string> tokens;
      std::istringstream values(line);
      for (std::string t; values >> t;) tokens.push_back(t);
      if (static_cast<int>(tokens.size()) != kColumnCount)
        fail("expected " + std::to_string(kColumnCount) + " numbers (" + column_list() +
             "), found " + std::to_string(tokens.size()) + " fields");
      Row r{};
      for (int k = 0; k < kColumnCount; ++k) {
        double v = 0.0;
        if (!parse_number(tokens[k], v))
          fail("'" + tokens[k] + "' in column " + kColumns[order[k]].name + " is not a finite number");
        if (kColumns[order[k]].member == nullptr)
          r.beta = v;
        else
          r.c.*(kColumns[order[k]].member) = v;
      }
      const std::string problem = coefficient_range_problem(r.c);
      if (!problem.empty()) fail(problem);
      rows.push_back(r);
    }
  }
  if (!have_header) fail("missing header 'hsrod-confinement-coefficients 1'");
  try {
    return ConfinementTable(std::move(rows), source);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

void ConfinementTable::write(const std::string& path) const {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write confinement coefficient file '" + path + "'");
  out << "hsrod-confinement-coefficients 1\n";
  out << "source " << source_ << "\n";
  out << "columns beta sphere_friction sphere_driving parallel_friction perpendicular_friction "
         "parallel_driving perpendicular_driving\n";
  out << std::setprecision(10);
  for (const Row& r : rows_)
    out << r.beta << ' ' << r.c.sphere_friction << ' ' << r.c.sphere_driving << ' ' << r.c.parallel_friction << ' '
        << r.c.perpendicular_friction << ' ' << r.c.parallel_driving << ' ' << r.c.perpendicular_driving << '\n';
}

}  // namespace hsrod
