#include "resolved_campaign.h"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace hsrod::calib {

namespace {
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string x; std::getline(ss, x, ',');) out.push_back(x);
  return out;
}
}  // namespace

std::vector<CsvRow> read_csv_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::string> head;
  std::vector<CsvRow> rows;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = fields(line);
    if (head.empty()) {
      head = f;
      continue;
    }
    if (f.size() != head.size())
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": " + std::to_string(f.size()) +
                               " fields where the header has " + std::to_string(head.size()));
    CsvRow r;
    for (std::size_t k = 0; k < f.size(); ++k) r[head[k]] = f[k];
    rows.push_back(std::move(r));
  }
  return rows;
}

std::vector<ResolvedRod> read_resolved_series(const std::string& path) {
  std::vector<ResolvedRod> out;
  for (const CsvRow& row : read_csv_rows(path)) {
    ResolvedRod r;
    for (const auto& [name, text] : row) {
      try {
        if (name == "role") r.role = text;
        else if (name == "meshes") continue;  // "6/8/10": the meshes of the series
        else if (name == "beta") r.beta = std::stod(text);
        else if (name == "n") r.n = std::stoi(text);
        else if (name == "spacing") r.spacing = std::stod(text);
        else r.q[name] = std::stod(text);
      } catch (const std::logic_error&) {
        throw std::runtime_error(path + ": column " + name + ": not a number: '" + text + "'");
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

bool ProfileKey::operator<(const ProfileKey& o) const {
  return std::tie(beta, n, spacing, quantity) < std::tie(o.beta, o.n, o.spacing, o.quantity);
}

std::map<ProfileKey, std::vector<double>> read_resolved_profiles(const std::string& path) {
  std::map<ProfileKey, std::vector<double>> out;
  for (const CsvRow& r : read_csv_rows(path))
    out[{r.at("beta"), r.at("n"), r.at("spacing"), r.at("load") + "_" + r.at("component")}].push_back(
        std::stod(r.at("value")));
  return out;
}

}  // namespace hsrod::calib
