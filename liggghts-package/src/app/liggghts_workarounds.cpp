#include "liggghts_workarounds.h"

#include "lammps.h"
#include "universe.h"

#include <cstring>

namespace hsrod {

void avoid_dangling_error_tip(LAMMPS_NS::LAMMPS *lmp) {
  // Universe owns the string (new[] in its constructor): edited in place,
  // same length.
  char *version = lmp->universe->version;
  if (!version) return;
  if (char *found = std::strstr(version, "PUBLIC")) std::memcpy(found, "Public", 6);
}

}  // namespace hsrod
