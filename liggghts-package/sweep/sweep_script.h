// hsrod-sweep: the input script as each case runs it (no LIGGGHTS, no MPI).
// A swept variable is passed to LIGGGHTS as `-var NAME value` (an index
// variable defined before the script runs). An `index` definition in the
// script is then skipped by LIGGGHTS itself, but an `equal` (or any other
// style) definition would replace or clash with it, so the sweep runs a
// copy of the main script in which every `variable NAME ...` command of a
// swept NAME (with its `&` continuation lines) is replaced by a comment,
// keeping the line numbers of LIGGGHTS' messages. Included files are not
// rewritten: define swept variables in the main script.
#pragma once

#include <string>
#include <vector>

namespace hsrod::sweep {

struct PreparedScript {
  std::string text;                        // the script to run
  std::vector<std::string> defined;        // swept names whose definition was replaced
  std::vector<std::string> not_defined;    // swept names the main script never defines
};

PreparedScript prepare_script(const std::string &script_text, const std::vector<std::string> &swept_names);

}  // namespace hsrod::sweep
