// The neighbor setting a scene needs (boxes with H <= 5 um or 40 mm long
// fail with LIGGGHTS' "Cannot use neighbor bins - box size << cutoff"
// unless the user knows to set `neighbor ... nsq`).
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hsrod {

// LIGGGHTS 3.8 (Neighbor::setup_bins) bins space with bins of half the
// largest neighbor cutoff (pair cutoff + skin; the box length when no pair
// style gives a cutoff) and refuses a box whose thinnest side is more than
// 100 times thinner than that bin: a rod scene (H of a few um, or a long
// channel without a pair style) hits this. Predicts it from the same rule
// and, if the run would fail, switches the neighbor style to nsq (a rod scene
// has few atoms) with one line naming the figures. Call from a fix's init()
// (before Neighbor::init); a no-op once nsq (or multi) is in use.
// `who` names the style in the message.
void choose_neighbor_style(LAMMPS_NS::LAMMPS *lmp, const char *who);

}  // namespace hsrod
