/* ----------------------------------------------------------------------
   hsrod - who integrates a rod fix's work (a narrow, explicit interface
   between styles).

   fix rod/implicit takes over the work of two other fixes: the bond loads
   and orientation update of fix rod/bonds and the drag force of fix
   hele_shaw/drag, which it evaluates inside its implicit step. Ownership
   runs one way: the integrator names its partners by fix ID, and each
   partner asks at its own init() whether an integrator names it. No style
   switches another one off, so `unfix` of the integrator hands the work
   back to the partners at the next run, and a partner removed under an
   integrator is an error at that run, not a dangling pointer.
------------------------------------------------------------------------- */

#ifndef LMP_HSROD_IMPLICIT_PARTNERS_H
#define LMP_HSROD_IMPLICIT_PARTNERS_H

namespace LAMMPS_NS {

class Error;
class Modify;

// What an integrator that takes over other fixes' work declares (fix
// rod/implicit implements it); support code asks through this interface, so
// it needs no style's header.
class PartnerIntegrator {
 public:
  virtual ~PartnerIntegrator() = default;
  // Whether this integrator does the work of fix `fix_id`.
  virtual bool names_partner(const char *fix_id) const = 0;
};

// The ID of the fix rod/implicit that names fix `partner_id` as its bonds
// or drag fix, or null if none does; error->all if more than one does.
const char *implicit_integrator_of(Modify *modify, Error *error, const char *partner_id);

}  // namespace LAMMPS_NS

#endif
