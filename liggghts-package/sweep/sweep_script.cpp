#include "sweep_script.h"

#include <algorithm>
#include <sstream>

namespace hsrod::sweep {
namespace {

// The first two words of a command line (before any '#').
void first_words(const std::string &line, std::string &command, std::string &argument) {
  std::istringstream words(line.substr(0, line.find('#')));
  command.clear();
  argument.clear();
  words >> command >> argument;
}

bool continues(const std::string &line) {
  const std::string code = line.substr(0, line.find('#'));
  const std::size_t last = code.find_last_not_of(" \t\r");
  return last != std::string::npos && code[last] == '&';
}

}  // namespace

PreparedScript prepare_script(const std::string &script_text, const std::vector<std::string> &swept_names) {
  PreparedScript prepared;
  std::istringstream lines(script_text);
  std::string line, command, argument;
  bool replacing = false;  // inside the continuation lines of a replaced command
  while (std::getline(lines, line)) {
    if (replacing) {
      replacing = continues(line);
      prepared.text += "# (hsrod-sweep: continuation of a replaced definition)\n";
      continue;
    }
    first_words(line, command, argument);
    if (command == "variable" &&
        std::find(swept_names.begin(), swept_names.end(), argument) != swept_names.end()) {
      if (std::find(prepared.defined.begin(), prepared.defined.end(), argument) == prepared.defined.end())
        prepared.defined.push_back(argument);
      replacing = continues(line);
      prepared.text += "# (hsrod-sweep: " + argument + " is set by the sweep)\n";
      continue;
    }
    prepared.text += line + "\n";
  }
  for (const std::string &name : swept_names)
    if (std::find(prepared.defined.begin(), prepared.defined.end(), name) == prepared.defined.end())
      prepared.not_defined.push_back(name);
  return prepared;
}

}  // namespace hsrod::sweep
