// Registers the hsrod styles with a prebuilt LIGGGHTS library at run time.
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hsrod {
// Inserts every style of style_hsrod.h into the LAMMPS instance's fix,
// compute and command maps. Call after `new LAMMPS(...)`, before reading
// the input.
void register_styles(LAMMPS_NS::LAMMPS *lmp);
}  // namespace hsrod
