/* ----------------------------------------------------------------------
   hsrod - fix rod/implicit (see fix_rod_implicit.h): its keywords, each
   checked against its accepted range (doc/fix_rod_implicit.txt).
------------------------------------------------------------------------- */

#include "fix_rod_implicit.h"

#include "error.h"
#include "keyword_parsing.h"

#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

void FixRodImplicit::parse_keywords(int narg, char **arg) {
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg) {
      char msg[128];
      std::snprintf(msg, sizeof(msg), "Illegal fix rod/implicit command: keyword %s needs a value", arg[iarg]);
      error->all(FLERR, msg);
    }
    const char *key = arg[iarg], *val = arg[iarg + 1];
    if (strcmp(key, "bonds") == 0) {
      bonds_id_ = val;
    } else if (strcmp(key, "drag") == 0) {
      drag_id_ = val;
    } else if (strcmp(key, "walls") == 0) {
      if (strcmp(val, "yes") != 0 && strcmp(val, "no") != 0) error->all(FLERR, "fix rod/implicit: walls expects yes or no");
      walls_ = strcmp(val, "yes") == 0;
    } else if (strcmp(key, "wall_friction") == 0) {
      wall_friction_ = parse_number(error, "fix rod/implicit", key, val);
      if (!(wall_friction_ >= 0.0)) error->all(FLERR, "fix rod/implicit: wall_friction must be >= 0 (Coulomb coefficient)");
    } else if (strcmp(key, "slip_velocity") == 0) {
      slip_velocity_ = parse_number(error, "fix rod/implicit", key, val);
      if (!(slip_velocity_ > 0.0)) error->all(FLERR, "fix rod/implicit: slip_velocity must be > 0 m/s");
    } else if (strcmp(key, "friction_iterations") == 0) {
      friction_iterations_ = parse_integer(error, "fix rod/implicit", key, val);
      if (!(friction_iterations_ >= 0 && friction_iterations_ <= 1000))
        error->all(FLERR, "fix rod/implicit: friction_iterations must be in [0, 1000] (0: friction about the "
                          "previous step's slip)");
    } else if (strcmp(key, "friction_tolerance") == 0) {
      friction_tolerance_ = parse_number(error, "fix rod/implicit", key, val);
      if (!(friction_tolerance_ > 0.0 && friction_tolerance_ <= 1.0))
        error->all(FLERR, "fix rod/implicit: friction_tolerance must be in (0, 1] (relative friction-force mismatch)");
    } else if (strcmp(key, "rod_contact") == 0) {
      if (strcmp(val, "hertz") != 0 && strcmp(val, "none") != 0)
        error->all(FLERR, "fix rod/implicit: rod_contact expects hertz or none");
      rod_contact_ = strcmp(val, "hertz") == 0;
    } else if (strcmp(key, "rod_friction") == 0) {
      rod_friction_ = parse_number(error, "fix rod/implicit", key, val);
      if (!(rod_friction_ >= 0.0 && rod_friction_ <= 10.0))
        error->all(FLERR, "fix rod/implicit: rod_friction must be in [0, 10] (Coulomb coefficient between rods)");
    } else if (strcmp(key, "rod_interaction") == 0) {
      parse_rod_interaction(narg, arg, iarg);
    } else if (strcmp(key, "rod_far_field") == 0) {
      far_field_ = parse_yes_no(error, "fix rod/implicit", key, val);
      far_field_given_ = true;
    } else if (strcmp(key, "contact_solve") == 0) {
      if (strcmp(val, "capacitance") != 0 && strcmp(val, "lu") != 0)
        error->all(FLERR, "fix rod/implicit: contact_solve expects capacitance or lu");
      contact_capacitance_ = strcmp(val, "capacitance") == 0;
    } else if (strcmp(key, "max_displacement") == 0) {
      max_displacement_ = parse_number(error, "fix rod/implicit", key, val);
      if (!(max_displacement_ > 0.0 && max_displacement_ <= 10.0))
        error->all(FLERR, "fix rod/implicit: max_displacement must be in (0, 10] sphere diameters per step");
    } else if (strcmp(key, "accuracy_guard") == 0) {
      guard_ = parse_yes_no(error, "fix rod/implicit", key, val);
    } else if (strcmp(key, "step_error") == 0) {
      limits_.max_step_error = parse_number(error, "fix rod/implicit", key, val);
      if (!(limits_.max_step_error > 0.0 && limits_.max_step_error <= 1.0))
        error->all(FLERR, "fix rod/implicit: step_error must be in (0, 1] (relative error of a step)");
    } else if (strcmp(key, "adaptive") == 0) {
      limits_.adaptive = parse_yes_no(error, "fix rod/implicit", key, val);
    } else if (strcmp(key, "tolerance") == 0) {
      limits_.displacement_tolerance = parse_number(error, "fix rod/implicit", key, val);
      if (!(limits_.displacement_tolerance > 0.0 && limits_.displacement_tolerance <= 1.0))
        error->all(FLERR, "fix rod/implicit: tolerance must be in (0, 1] (local displacement error of a substep "
                          "over its displacement)");
    } else if (strcmp(key, "max_growth") == 0) {
      limits_.max_growth = parse_number(error, "fix rod/implicit", key, val);
      if (!(limits_.max_growth >= 0.0 && limits_.max_growth <= 10.0))
        error->all(FLERR, "fix rod/implicit: max_growth must be in [0, 10] (growth rate of the rod's speed times "
                          "the substep; 0: off)");
    } else if (strcmp(key, "max_bond_strain") == 0) {
      limits_.max_bond_strain = parse_number(error, "fix rod/implicit", key, val);
      if (!(limits_.max_bond_strain > 0.0 && limits_.max_bond_strain <= 10.0))
        error->all(FLERR, "fix rod/implicit: max_bond_strain must be in (0, 10] (largest |axial strain| of a bond)");
    } else if (strcmp(key, "max_substeps") == 0) {
      limits_.max_substeps = parse_integer(error, "fix rod/implicit", key, val);
      if (!(limits_.max_substeps >= 1 && limits_.max_substeps <= 1 << 20))
        error->all(FLERR, "fix rod/implicit: max_substeps must be in [1, 1048576]");
    } else {
      char msg[704];
      std::snprintf(msg, sizeof(msg),
                    "Illegal fix rod/implicit command: unknown keyword '%s' (expected bonds, drag, walls, "
                    "wall_friction, slip_velocity, friction_iterations, friction_tolerance, rod_contact, rod_friction, rod_interaction, rod_far_field, contact_solve, max_displacement, "
                    "accuracy_guard, step_error, max_substeps, max_bond_strain, max_growth, adaptive, tolerance)", key);
      error->all(FLERR, msg);
    }
  }
}
