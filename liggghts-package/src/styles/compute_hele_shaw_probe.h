/* ----------------------------------------------------------------------
   hsrod - compute hele_shaw/probe: the background flow of a fix
   hele_shaw/drag (gap-averaged velocity, its gradient, pressure) at given
   points and along a line, with the flow rate through the line.
   Physics in drag-models/flow/flow_probe.h. Doc: doc/compute_hele_shaw_probe.txt
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

ComputeStyle(hele_shaw/probe,ComputeHeleShawProbe)

#else

#ifndef LMP_COMPUTE_HELE_SHAW_PROBE_H
#define LMP_COMPUTE_HELE_SHAW_PROBE_H

#include "compute.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeHeleShawProbe : public Compute {
 public:
  ComputeHeleShawProbe(class LAMMPS *, int &, int, char **);
  ~ComputeHeleShawProbe();
  void init();
  void compute_array();
  void compute_vector();

  // Columns of the global array, one row per probe point (0-based here,
  // 1-based in scripts).
  enum Column { X, Y, UX, UY, SPEED, DUXDX, DUXDY, DUYDX, DUYDY, PRESSURE, IN_FLUID, N_COLUMNS };
  // Entries of the global vector (only with `line`).
  enum Entry { FLOW_RATE, FLUID_LENGTH, MEAN_PRESSURE, FLUX_PRESSURE, MAX_SPEED, MEAN_VELOCITY, N_ENTRIES };

 private:
  std::string drag_id_;
  class FixHeleShawDrag *drag_;
  std::vector<Eigen::Vector2d> points_;  // probe points [m]: `point`s, then the line's nodes
  bool has_line_;
  Eigen::Vector2d line_a_, line_b_;      // line end points [m]
  int line_pieces_;

  void find_drag();
};

}  // namespace LAMMPS_NS

#endif
#endif
