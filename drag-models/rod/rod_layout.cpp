#include "rod/rod_layout.h"

#include <cmath>
#include <stdexcept>

namespace hsrod {

void RodSpec::validate() const {
  if (number_of_sections < 2)
    throw std::invalid_argument("number of spheres N = " + std::to_string(number_of_sections) +
                                " must be >= 2");
  if (!(sphere_diameter > 0.0)) throw std::invalid_argument("sphere diameter must be > 0");
  if (spacing < 0.0) throw std::invalid_argument("spacing must be >= 0 (0 means one diameter)");
  if (section_rows < 1 || section_layers < 1)
    throw std::invalid_argument("section must have >= 1 sphere in each direction");
}

std::pair<int, int> parse_section(const std::string& text) {
  const auto x = text.find('x');
  try {
    if (x == std::string::npos) {
      const int n = std::stoi(text);
      if (n != 1) throw std::invalid_argument("");
      return {1, 1};
    }
    const int rows = std::stoi(text.substr(0, x));
    const int layers = std::stoi(text.substr(x + 1));
    if (rows < 1 || layers < 1 || rows > 8 || layers > 8) throw std::invalid_argument("");
    return {rows, layers};
  } catch (const std::exception&) {
    throw std::invalid_argument("section '" + text +
                                "' must be 1 or RxL with 1 <= R, L <= 8 (e.g. 2x2)");
  }
}

RodLayout make_rod_layout(const RodSpec& spec) {
  spec.validate();
  RodLayout layout;
  const double s = spec.effective_spacing();
  const double d = spec.sphere_diameter;
  // Axis from end 2 to end 1, in-plane normal, and z.
  const Eigen::Vector3d axis(std::sin(spec.angle), std::cos(spec.angle), 0.0);
  const Eigen::Vector3d normal(std::cos(spec.angle), -std::sin(spec.angle), 0.0);
  const Eigen::Vector3d up(0.0, 0.0, 1.0);
  const int n = spec.number_of_sections;
  const int rows = spec.section_rows;
  const int layers = spec.section_layers;
  auto index = [&](int section, int row, int layer) { return (section * rows + row) * layers + layer; };

  for (int k = 0; k < n; ++k) {
    const double along = (0.5 * (n - 1) - k) * s;
    for (int r = 0; r < rows; ++r) {
      for (int l = 0; l < layers; ++l) {
        const double across = (r - 0.5 * (rows - 1)) * d;
        const double height = (l - 0.5 * (layers - 1)) * d;
        layout.spheres.push_back(
            {spec.centre + along * axis + across * normal + height * up, k, r * layers + l});
      }
    }
  }
  // Bonds: along the axis between equal slots of neighbouring sections, and
  // within a section between grid neighbours.
  for (int k = 0; k < n; ++k) {
    for (int r = 0; r < rows; ++r) {
      for (int l = 0; l < layers; ++l) {
        const int i = index(k, r, l);
        if (k + 1 < n) layout.bonds.emplace_back(i, index(k + 1, r, l));
        if (r + 1 < rows) layout.bonds.emplace_back(i, index(k, r + 1, l));
        if (l + 1 < layers) layout.bonds.emplace_back(i, index(k, r, l + 1));
      }
    }
  }
  std::vector<int> count(layout.spheres.size(), 0);
  for (const auto& b : layout.bonds) {
    ++count[b.first];
    ++count[b.second];
  }
  for (int c : count) layout.max_bonds_per_sphere = std::max(layout.max_bonds_per_sphere, c);
  return layout;
}

}  // namespace hsrod
