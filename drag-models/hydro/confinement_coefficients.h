// Confinement coefficients of the reduced hydrodynamic models, as functions
// of the confinement beta = d / H (sphere diameter over gap height).
//
// A table of rows (beta, values...) interpolated linearly in beta, read from
// a versioned text file (format below) so that the calibration tools
// (calibration/) can replace the defaults with coefficients fitted to
// resolved runs. The defaults (default_table()) come from published
// correlations, cited at each column in default_coefficients.cpp (Faxen's
// series itself: confinement_coefficients.cpp).
//
// File format (version 1), '#' starts a comment:
//   hsrod-confinement-coefficients 1
//   source <free text: what produced this table>
//   columns beta sphere_friction sphere_driving parallel_friction perpendicular_friction parallel_driving perpendicular_driving
//   <one row of 7 numbers per beta, beta strictly increasing, 0 <= beta < 1>
// Read strictly: the header first; the optional `columns` line names all
// seven columns once, in any order, and the rows follow that order; each row
// has exactly seven whole finite numbers; every row is in the physical
// ranges of coefficient_range_problem(). Anything else is refused with the
// file, line and problem.
#pragma once

#include <string>
#include <vector>

namespace hsrod {

struct ConfinementCoefficients {
  // Friction of an isolated sphere at the mid-plane, moving parallel to the
  // walls, over the free-space Stokes value 3 pi mu d [-] (>= 1).
  double sphere_friction = 1.0;
  // Velocity of a force-free sphere at the mid-plane over the local
  // gap-averaged fluid velocity [-] (3/2 as beta -> 0).
  double sphere_driving = 1.5;
  // Friction per sphere of a rod moving along / across its axis, over the
  // isolated sphere friction [-] (shielding along the chain: < 1).
  double parallel_friction = 1.0;
  double perpendicular_friction = 1.0;
  // Force-free rod velocity along / across its axis over the gap-averaged
  // fluid velocity [-].
  double parallel_driving = 1.5;
  double perpendicular_driving = 1.5;
};

class ConfinementTable {
 public:
  struct Row {
    double beta;
    ConfinementCoefficients c;
  };

  // Built-in defaults from published correlations (see the .cpp).
  static ConfinementTable default_table();
  // Reads the versioned text format; throws std::runtime_error naming the
  // file, the line and the problem (missing file, bad version, bad row).
  static ConfinementTable read(const std::string& path);
  void write(const std::string& path) const;

  // Linear interpolation in beta; throws std::invalid_argument outside
  // [first beta, last beta] (beta >= 1 means the sphere does not fit).
  ConfinementCoefficients at(double beta) const;

  const std::vector<Row>& rows() const { return rows_; }
  const std::string& source() const { return source_; }
  double max_beta() const { return rows_.empty() ? 0.0 : rows_.back().beta; }

  ConfinementTable(std::vector<Row> rows, std::string source);

 private:
  std::vector<Row> rows_;
  std::string source_;
};

// "" if the coefficients are physical, else the first problem: friction
// coefficients > 0 (sphere_friction >= 1: walls only add friction), driving
// coefficients in (0, 3] (carried downstream; physically at most the
// mid-plane velocity 3/2, with room for fitted values); all finite.
std::string coefficient_range_problem(const ConfinementCoefficients& c);

// The rod-length law of level 2 (hydro/confinement_forms.h: rod_n_law,
// rod_velocity), fitted to the resolved campaign together with the built-in
// table (default_coefficients.cpp); level 2 uses them to scale the table's
// 10-sphere rod columns to other rod lengths. All dimensionless, functions
// of beta = d / H:
// growth g = beta^2 k(beta) of the per-sphere friction of a rod moving
// across its axis with the rod's length [-];
double perpendicular_growth(double beta);
// growth g_held = beta^2 k_held(beta) of the held-in-flow load per sphere of
// a rod across the flow (confinement_form::rod_velocity), fitted to the
// resolved r = U_perp / U_par [-];
double perpendicular_held_growth(double beta);
// the 3-D shielding e of the per-sphere friction along the axis (the e
// ln(n)/n term of rod_n_law) [-].
double parallel_shielding(double beta);

// Faxen's series for a sphere midway between two parallel walls moving
// parallel to them (Happel & Brenner 1965, eq. 7-4.28): friction over
// 3 pi mu d as a function of a / l = beta (l = H/2 the distance to each wall).
double faxen_midplane_friction(double beta);

}  // namespace hsrod
