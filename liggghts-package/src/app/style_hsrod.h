// The styles of the hsrod package, in the form of LIGGGHTS' style_*.h files:
// included with FIX_CLASS / COMPUTE_CLASS / COMMAND_CLASS defined it yields
// the FixStyle(...) lines, otherwise the class declarations. Add new style
// headers here.
#include "compute_hele_shaw_pressure_drop.h"
#include "compute_hele_shaw_probe.h"
#include "compute_hele_shaw_rod_load.h"
#include "compute_rod_shape.h"
#include "create_rod.h"
#include "create_rods.h"
#include "fix_cfd_torque_implicit.h"
#include "fix_hele_shaw_drag.h"
#include "fix_hele_shaw_field.h"
#include "fix_rod_bonds.h"
#include "fix_rod_implicit.h"
#include "fix_rod_inflow.h"
#include "fix_rod_outcome.h"
#include "fix_rod_outflow.h"
