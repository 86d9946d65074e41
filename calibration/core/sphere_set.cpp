// hsrod calibration: immersed-sphere set (see sphere_set.h).
#include "sphere_set.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace hsrod::calib {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(trim(item));
  return out;
}

// Parses a header-led CSV into rows of named doubles; comments ('#') and blank lines skipped.
struct Table {
  std::vector<std::string> cols;
  std::vector<std::vector<double>> rows;
  int col(const std::string& name) const {
    auto it = std::find(cols.begin(), cols.end(), name);
    return it == cols.end() ? -1 : static_cast<int>(it - cols.begin());
  }
};

Table parse_table(const std::string& text, const std::string& origin) {
  Table t;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    auto f = split_csv(line);
    if (t.cols.empty()) {
      t.cols = f;
      continue;
    }
    if (f.size() != t.cols.size()) {
      throw std::runtime_error(origin + ":" + std::to_string(lineno) + ": expected " +
                               std::to_string(t.cols.size()) + " columns, found " +
                               std::to_string(f.size()));
    }
    std::vector<double> row;
    for (const auto& s : f) {
      try {
        std::size_t pos = 0;
        row.push_back(std::stod(s, &pos));
        if (pos != s.size()) throw std::invalid_argument(s);
      } catch (const std::exception&) {
        throw std::runtime_error(origin + ":" + std::to_string(lineno) + ": not a number: '" + s + "'");
      }
    }
    t.rows.push_back(std::move(row));
  }
  if (t.cols.empty()) throw std::runtime_error(origin + ": empty file (a header line is required)");
  return t;
}

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot open '" + path + "'");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace

Vec3 Sphere::rigid_velocity(const Vec3& p) const {
  const Vec3 r{p[0] - x[0], p[1] - x[1], p[2] - x[2]};
  return {v[0] + omega[1] * r[2] - omega[2] * r[1],
          v[1] + omega[2] * r[0] - omega[0] * r[2],
          v[2] + omega[0] * r[1] - omega[1] * r[0]};
}

MotionMode parse_motion_mode(const std::string& name) {
  if (name == "fixed") return MotionMode::Fixed;
  if (name == "constantVelocity") return MotionMode::ConstantVelocity;
  if (name == "table") return MotionMode::Table;
  if (name == "coupled") return MotionMode::Coupled;
  throw std::invalid_argument("unknown sphere motion '" + name +
                              "' (expected fixed, constantVelocity, table or coupled)");
}

SphereSet SphereSet::read_csv(const std::string& path) { return from_text(read_file(path), path); }

SphereSet SphereSet::from_text(const std::string& text, const std::string& origin) {
  const Table t = parse_table(text, origin);
  for (const char* req : {"id", "x", "y", "z", "d"}) {
    if (t.col(req) < 0) throw std::runtime_error(origin + ": missing column '" + req + "'");
  }
  SphereSet s;
  auto get = [&](const std::vector<double>& row, const char* name) {
    const int c = t.col(name);
    return c < 0 ? 0.0 : row[c];
  };
  for (const auto& row : t.rows) {
    Sphere sp;
    sp.id = static_cast<long>(get(row, "id"));
    sp.x = {get(row, "x"), get(row, "y"), get(row, "z")};
    sp.d = get(row, "d");
    sp.v = {get(row, "vx"), get(row, "vy"), get(row, "vz")};
    sp.omega = {get(row, "wx"), get(row, "wy"), get(row, "wz")};
    if (!(sp.d > 0.0)) {
      throw std::runtime_error(origin + ": sphere " + std::to_string(sp.id) +
                               " has non-positive diameter");
    }
    s.spheres_.push_back(sp);
  }
  for (const auto& sp : s.spheres_) s.x0_.push_back(sp.x);
  return s;
}

void SphereSet::read_path_table(const std::string& path) {
  set_path_table_text(read_file(path), path);
}

void SphereSet::set_path_table_text(const std::string& text, const std::string& origin) {
  const Table t = parse_table(text, origin);
  for (const char* req : {"t", "id", "x", "y", "z"}) {
    if (t.col(req) < 0) throw std::runtime_error(origin + ": missing column '" + req + "'");
  }
  table_.clear();
  for (const auto& row : t.rows) {
    table_[static_cast<long>(row[t.col("id")])].push_back(
        {row[t.col("t")], {row[t.col("x")], row[t.col("y")], row[t.col("z")]}});
  }
  for (auto& [id, samples] : table_) {
    std::stable_sort(samples.begin(), samples.end(),
                     [](const Sample& a, const Sample& b) { return a.t < b.t; });
  }
  for (const auto& sp : spheres_) {
    if (!table_.count(sp.id)) {
      throw std::runtime_error(origin + ": no path given for sphere id " + std::to_string(sp.id));
    }
  }
}

void SphereSet::set_time(double t) {
  if (mode_ == MotionMode::ConstantVelocity) {
    for (std::size_t k = 0; k < spheres_.size(); ++k) {
      auto& sp = spheres_[k];
      for (int i = 0; i < 3; ++i) sp.x[i] = x0_[k][i] + sp.v[i] * t;
    }
  } else if (mode_ == MotionMode::Table) {
    for (auto& sp : spheres_) {
      const auto& s = table_.at(sp.id);
      if (s.size() == 1 || t <= s.front().t) {
        sp.x = s.front().x;
        sp.v = {0, 0, 0};
        continue;
      }
      if (t >= s.back().t) {
        sp.x = s.back().x;
        sp.v = {0, 0, 0};
        continue;
      }
      // first sample with time > t
      auto it = std::upper_bound(s.begin(), s.end(), t,
                                 [](double tt, const Sample& a) { return tt < a.t; });
      const Sample& b = *it;
      const Sample& a = *(it - 1);
      const double dt = b.t - a.t;
      const double w = dt > 0 ? (t - a.t) / dt : 0.0;
      for (int i = 0; i < 3; ++i) {
        sp.x[i] = a.x[i] + w * (b.x[i] - a.x[i]);
        sp.v[i] = dt > 0 ? (b.x[i] - a.x[i]) / dt : 0.0;
      }
    }
  }
}

void SphereSet::set_spheres(std::vector<Sphere> spheres) {
  spheres_ = std::move(spheres);
  x0_.clear();
  for (const auto& sp : spheres_) x0_.push_back(sp.x);
}

void SphereSet::write_force_header(std::ostream& os) {
  os << "# hydrodynamic load on each sphere (SI: s, m, m/s, N, N m)\n"
        "t,id,x,y,z,vx,vy,vz,Fx,Fy,Fz,Tx,Ty,Tz\n";
}

void SphereSet::write_forces(std::ostream& os, double t) const {
  const auto old = os.precision();
  os << std::setprecision(10);
  for (const auto& sp : spheres_) {
    os << t << ',' << sp.id;
    for (const auto* v : {&sp.x, &sp.v, &sp.force, &sp.torque}) {
      for (double c : *v) os << ',' << c;
    }
    os << '\n';
  }
  os.precision(old);
}

}  // namespace hsrod::calib
