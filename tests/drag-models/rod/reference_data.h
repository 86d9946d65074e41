// Reads "name value" lines (with '#' comments) from a data file beside the tests.
#pragma once

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

inline std::map<std::string, double> read_reference_values(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open reference data " + path);
  std::map<std::string, double> values;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string name;
    double value;
    if (words >> name >> value) values[name] = value;
  }
  return values;
}
