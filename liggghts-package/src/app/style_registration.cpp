// Run-time registration of this package's styles with Debian's prebuilt
// libliggghts, which has no plugin mechanism.
//
// LIGGGHTS looks styles up in Modify::fix_map, Modify::compute_map and
// Input::command_map, which are private/protected and filled from the
// style_*.h files compiled into the library. Without patching LIGGGHTS we
// reach those maps with the explicit-instantiation access idiom: access
// checking does not apply to the names used in an explicit template
// instantiation ([temp.spec]/6 in C++17), so a pointer-to-member of a
// private member may be passed as a template argument there and exported
// through a friend function. This is the only file that does so.

#include "style_registration.h"
#include "liggghts_workarounds.h"

#include "input.h"
#include "lammps.h"
#include "modify.h"

#include "style_hsrod.h"

#include <map>
#include <string>

namespace {

using namespace LAMMPS_NS;

// The creator signatures are spelled out: Modify's typedefs are private.
using FixCreator = Fix *(*)(LAMMPS *, int, char **);
using ComputeCreator = Compute *(*)(LAMMPS *, int, int, char **);
using CommandCreator = void (*)(LAMMPS *, int, char **);

using FixMap = std::map<std::string, FixCreator>;
using ComputeMap = std::map<std::string, ComputeCreator>;
using CommandMap = std::map<std::string, CommandCreator>;

// Tag types name the member pointer type; `get(Tag)` is defined by the
// explicit instantiation below.
struct FixMapTag {
  using type = FixMap *Modify::*;
  friend type get(FixMapTag);
};
struct ComputeMapTag {
  using type = ComputeMap *Modify::*;
  friend type get(ComputeMapTag);
};
struct CommandMapTag {
  using type = CommandMap *Input::*;
  friend type get(CommandMapTag);
};

template <typename Tag, typename Tag::type Member>
struct ExposeMember {
  friend typename Tag::type get(Tag) { return Member; }
};

template struct ExposeMember<FixMapTag, &Modify::fix_map>;
template struct ExposeMember<ComputeMapTag, &Modify::compute_map>;
template struct ExposeMember<CommandMapTag, &Input::command_map>;

template <typename T>
Fix *make_fix(LAMMPS *lmp, int narg, char **arg) {
  return new T(lmp, narg, arg);
}

template <typename T>
Compute *make_compute(LAMMPS *lmp, int iarg, int narg, char **arg) {
  return new T(lmp, iarg, narg, arg);
}

template <typename T>
void run_command(LAMMPS *lmp, int narg, char **arg) {
  T command(lmp);
  command.command(narg, arg);
}

}  // namespace

namespace hsrod {

void register_styles(LAMMPS_NS::LAMMPS *lmp) {
  // Every hsrod instance (hsrod, hsrod-sweep, the tests) also gets the
  // library workarounds (an ERROR line printed twice with garbage bytes).
  avoid_dangling_error_tip(lmp);
  FixMap &fixes = *(lmp->modify->*get(FixMapTag{}));
  ComputeMap &computes = *(lmp->modify->*get(ComputeMapTag{}));
  CommandMap &commands = *(lmp->input->*get(CommandMapTag{}));

#define FIX_CLASS
#define FixStyle(key, Class) fixes[#key] = &make_fix<Class>;
#include "style_hsrod.h"
#undef FixStyle
#undef FIX_CLASS

#define COMPUTE_CLASS
#define ComputeStyle(key, Class) computes[#key] = &make_compute<Class>;
#include "style_hsrod.h"
#undef ComputeStyle
#undef COMPUTE_CLASS

#define COMMAND_CLASS
#define CommandStyle(key, Class) commands[#key] = &run_command<Class>;
#include "style_hsrod.h"
#undef CommandStyle
#undef COMMAND_CLASS
}

void register_fix_style(LAMMPS_NS::LAMMPS *lmp, const char *style, FixCreator creator) {
  FixMap &fixes = *(lmp->modify->*get(FixMapTag{}));
  fixes[style] = creator;
}

}  // namespace hsrod
