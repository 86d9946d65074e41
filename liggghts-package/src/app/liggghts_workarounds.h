// Workarounds for defects of Debian's prebuilt LIGGGHTS 3.8 that hsrod
// cannot fix in the library itself.
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hsrod {

// LIGGGHTS 3.8's Error::one and Error::all append, in one of five errors of a
// build whose version string contains "PUBLIC", a "Tip of the day" or
// "Comment from the off" (SpecialMessages::generate_message, error_special.h)
// that is returned as the c_str() of a destroyed local std::string: the
// ERROR line is printed a second time with garbage bytes. The
// message is generated only when universe->version contains "PUBLIC"; this
// replaces that version string by the same text with "PUBLIC" written
// "Public" (the banner, printed before, is unchanged). Call once per
// instance, before reading input; idempotent.
void avoid_dangling_error_tip(LAMMPS_NS::LAMMPS *lmp);

}  // namespace hsrod
