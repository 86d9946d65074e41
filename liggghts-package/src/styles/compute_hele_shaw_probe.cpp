/* ----------------------------------------------------------------------
   hsrod - compute hele_shaw/probe (see compute_hele_shaw_probe.h)

   compute ID group hele_shaw/probe DRAG-ID keyword values ...
     point x y            a probe point [m] (repeatable)
     line x1 y1 x2 y2 n   n probe points at the midpoints of n equal pieces
                          of the segment [m]; also the section integrals
   Global array, one row per point (points first, then the line's nodes),
   columns (1-based): 1-2 x y [m], 3-4 u_x u_y [m/s], 5 |u| [m/s],
   6-9 du_x/dx du_x/dy du_y/dx du_y/dy [1/s], 10 p [Pa], 11 in fluid (0/1).
   Global vector (with line): 1 flow rate through the line [m^3/s],
   2 fluid length of the line [m], 3 mean p along it [Pa], 4 flux-weighted
   p [Pa], 5 max |u| [m/s], 6 mean velocity Q / (H fluid length) [m/s].
------------------------------------------------------------------------- */

#include "compute_hele_shaw_probe.h"

#include "error.h"
#include "keyword_parsing.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "fix_hele_shaw_drag.h"

#include "flow/flow_probe.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;

ComputeHeleShawProbe::ComputeHeleShawProbe(LAMMPS *instance, int &iarg, int narg, char **arg)
    : Compute(instance, iarg, narg, arg), drag_(nullptr), has_line_(false), line_pieces_(0) {
  // LIGGGHTS 3.8's Compute leaves these uninitialised; the destructor frees
  // both (vector exists only with a line: delete[] of garbage crashed at exit).
  vector = nullptr;
  array = nullptr;
  const char *style_name = "compute hele_shaw/probe";
  if (iarg >= narg) error->all(FLERR, "Illegal compute hele_shaw/probe command: missing the ID of a fix hele_shaw/drag");
  drag_id_ = arg[iarg++];
  find_drag();
  std::vector<Eigen::Vector2d> single;
  while (iarg < narg) {
    const char *key = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg) {
        char msg[256];
        std::snprintf(msg, sizeof(msg), "Illegal compute hele_shaw/probe command: keyword %s needs %d value(s)", key, n);
        error->all(FLERR, msg);
      }
    };
    if (strcmp(key, "point") == 0) {
      need(2);
      single.emplace_back(parse_number(error, style_name, key, arg[iarg + 1]), parse_number(error, style_name, key, arg[iarg + 2]));
      iarg += 3;
    } else if (strcmp(key, "line") == 0) {
      need(5);
      if (has_line_) error->all(FLERR, "compute hele_shaw/probe: give at most one line");
      has_line_ = true;
      line_a_ = {parse_number(error, style_name, key, arg[iarg + 1]), parse_number(error, style_name, key, arg[iarg + 2])};
      line_b_ = {parse_number(error, style_name, key, arg[iarg + 3]), parse_number(error, style_name, key, arg[iarg + 4])};
      line_pieces_ = parse_integer(error, style_name, key, arg[iarg + 5]);
      if (line_pieces_ < 1 || line_pieces_ > 100000)
        error->all(FLERR, "compute hele_shaw/probe: line needs 1 to 100000 points");
      if (!((line_b_ - line_a_).norm() > 0.0))
        error->all(FLERR, "compute hele_shaw/probe: line end points must differ");
      iarg += 6;
    } else {
      char msg[256];
      std::snprintf(msg, sizeof(msg),
                    "Illegal compute hele_shaw/probe command: unknown keyword '%s' (expected point or line)", key);
      error->all(FLERR, msg);
    }
  }
  points_ = single;
  if (has_line_) {
    const auto nodes = hsrod::segment_midpoints(line_a_, line_b_, line_pieces_);
    points_.insert(points_.end(), nodes.begin(), nodes.end());
  }
  if (points_.empty()) error->all(FLERR, "compute hele_shaw/probe: give at least one point or a line");

  array_flag = 1;
  size_array_rows = static_cast<int>(points_.size());
  size_array_cols = N_COLUMNS;
  extarray = 0;
  memory->create(array, size_array_rows, size_array_cols, "hele_shaw/probe:array");
  if (has_line_) {
    vector_flag = 1;
    size_vector = N_ENTRIES;
    extvector = 0;
    vector = new double[N_ENTRIES];
  }
}

ComputeHeleShawProbe::~ComputeHeleShawProbe() {
  memory->destroy(array);
  delete[] vector;
}

void ComputeHeleShawProbe::find_drag() {
  const int f = modify->find_fix(drag_id_.c_str());
  drag_ = f < 0 ? nullptr : dynamic_cast<FixHeleShawDrag *>(modify->fix[f]);
  if (!drag_) {
    char msg[256];
    std::snprintf(msg, sizeof(msg), "compute hele_shaw/probe: '%s' is not the ID of a fix hele_shaw/drag defined before",
                  drag_id_.c_str());
    error->all(FLERR, msg);
  }
}

void ComputeHeleShawProbe::init() { find_drag(); }

// The background flow is steady: every processor holds it and evaluates all
// points, no communication.
void ComputeHeleShawProbe::compute_array() {
  invoked_array = update->ntimestep;
  const hsrod::BackgroundFlow &flow = drag_->flow();
  for (size_t row = 0; row < points_.size(); row++) {
    const hsrod::FlowSample s = hsrod::sample_flow(flow, points_[row]);
    double *out = array[row];
    out[X] = s.position.x();
    out[Y] = s.position.y();
    out[UX] = s.velocity.x();
    out[UY] = s.velocity.y();
    out[SPEED] = s.velocity.norm();
    out[DUXDX] = s.velocity_gradient(0, 0);
    out[DUXDY] = s.velocity_gradient(0, 1);
    out[DUYDX] = s.velocity_gradient(1, 0);
    out[DUYDY] = s.velocity_gradient(1, 1);
    out[PRESSURE] = s.pressure;
    out[IN_FLUID] = s.in_fluid ? 1.0 : 0.0;
  }
}

void ComputeHeleShawProbe::compute_vector() {
  invoked_vector = update->ntimestep;
  const hsrod::SectionIntegrals s = hsrod::integrate_section(drag_->flow(), line_a_, line_b_, line_pieces_);
  vector[FLOW_RATE] = s.flow_rate;
  vector[FLUID_LENGTH] = s.fluid_length;
  vector[MEAN_PRESSURE] = s.mean_pressure;
  vector[FLUX_PRESSURE] = s.flux_weighted_pressure;
  vector[MAX_SPEED] = s.max_speed;
  vector[MEAN_VELOCITY] =
      s.fluid_length > 0.0 ? s.flow_rate / (drag_->flow().geometry().gap_height() * s.fluid_length) : 0.0;
}
