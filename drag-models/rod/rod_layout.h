// Sphere positions and bond topology of a straight rod, as made by the
// LIGGGHTS command create_rod (and usable by tests and calibration tools).
//
// Conventions follow Braesel et al. (Soft Matter 2024): x is the flow
// direction, y the channel width, z the gap height. The in-plane angle alpha
// is measured from the y axis (alpha = 0: rod perpendicular to the flow),
// as in the paper's eq. (1). Section 0 is end "1" of eq. (1): with
// Delta = x_end1 - x_end2 the paper's angle of a rod made with angle alpha
// is alpha.
#pragma once

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace hsrod {

struct RodSpec {
  int number_of_sections = 0;             // N spheres along the axis (>= 2)
  double sphere_diameter = 0.0;           // d [m]
  double spacing = 0.0;                   // centre distance along the axis [m] (0: = d)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // centre of the rod [m]
  double angle = 0.0;                     // in-plane angle from the y axis [rad]
  int section_rows = 1;                   // spheres across the width of a section
  int section_layers = 1;                 // spheres across the height (z) of a section

  double effective_spacing() const { return spacing > 0.0 ? spacing : sphere_diameter; }
  // Length of the rod in the paper's sense, L_Rod = N d [m].
  double rod_length() const { return number_of_sections * effective_spacing(); }
  // Throws std::invalid_argument naming the bad field.
  void validate() const;
};

struct RodLayout {
  struct Sphere {
    Eigen::Vector3d position;   // [m]
    int section = 0;            // index along the axis, 0 = end 1
    int slot = 0;               // index within the section
  };
  std::vector<Sphere> spheres;                 // ordered section by section
  std::vector<std::pair<int, int>> bonds;      // indices into spheres, first < second
  int max_bonds_per_sphere = 0;                // over all spheres, counting both ends
};

RodLayout make_rod_layout(const RodSpec& spec);

// Parses "1", "2x2", "3x1" (rows x layers). Throws std::invalid_argument.
std::pair<int, int> parse_section(const std::string& text);

}  // namespace hsrod
