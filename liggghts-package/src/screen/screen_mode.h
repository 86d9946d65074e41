// hsrod screening mode: `hsrod -in in.liggghts -var hsrod_screen scene.json`
// runs a resolved CFD-DEM script unchanged with the coupling replaced by the
// reduced model and prints a pre-flight report (doc:
// liggghts-package/doc/hsrod_screen.txt).
#pragma once

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace hsrod::screen {

// The scene file named by `-var hsrod_screen FILE` ("1": scene.json in the
// working directory), or "" when screening is not requested.
std::string requested_scene(int argc, char **argv);

// Before the input is read: reads the scene file and registers the
// stand-in fixes (fix_screen_standin.h). Returns false (message printed)
// on a bad scene file.
bool begin(LAMMPS_NS::LAMMPS *lmp, const std::string &scene_path);

// After the script has run: the pre-flight report and the reduced
// prediction.
void report(LAMMPS_NS::LAMMPS *lmp);

}  // namespace hsrod::screen
