#include "hydro/confinement_coefficients.h"

#include <cmath>
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
  bool have_header = false;
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
      int version = 0;
      if (!(words >> version) || version != 1) fail("unsupported format version (expected 1)");
      have_header = true;
    } else if (first == "source") {
      std::getline(words, source);
    } else if (first == "columns") {
      continue;
    } else {
      if (!have_header) fail("missing header 'hsrod-confinement-coefficients 1'");
      Row r;
      std::istringstream values(line);
      if (!(values >> r.beta >> r.c.sphere_friction >> r.c.sphere_driving >> r.c.parallel_friction >>
            r.c.perpendicular_friction >> r.c.parallel_driving >> r.c.perpendicular_driving))
        fail("expected 7 numbers: beta sphere_friction sphere_driving parallel_friction "
             "perpendicular_friction parallel_driving perpendicular_driving");
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
