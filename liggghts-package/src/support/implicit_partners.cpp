#include "implicit_partners.h"

#include "error.h"
#include "fix.h"
#include "modify.h"

#include <cstdio>

namespace LAMMPS_NS {

const char *implicit_integrator_of(Modify *modify, Error *error, const char *partner_id) {
  const char *found = nullptr;
  for (int f = 0; f < modify->nfix; f++) {
    const Fix *fix = modify->fix[f];
    const auto *integrator = dynamic_cast<const PartnerIntegrator *>(fix);
    if (!integrator || !integrator->names_partner(partner_id)) continue;
    if (found) {
      char msg[256];
      std::snprintf(msg, sizeof(msg), "fix %s is claimed by two fix rod/implicit (%s and %s); one integrator per rod fix",
                    partner_id, found, fix->id);
      error->all(FLERR, msg);
    }
    found = fix->id;
  }
  return found;
}

}  // namespace LAMMPS_NS
