// Registers the hsrod styles with a prebuilt LIGGGHTS library at run time.
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
class Fix;
}

namespace hsrod {
// Inserts every style of style_hsrod.h into the LAMMPS instance's fix,
// compute and command maps. Call after `new LAMMPS(...)`, before reading
// the input. Also applies liggghts_workarounds.h.
void register_styles(LAMMPS_NS::LAMMPS *lmp);

// Registers (or replaces: LIGGGHTS' own styles too) one fix style; used by
// the screening mode (screen/screen_mode.h) for its stand-ins.
using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);
void register_fix_style(LAMMPS_NS::LAMMPS *lmp, const char *style, FixCreator creator);
}  // namespace hsrod
