// Records the pore passage of every level (1-4) and of a soft (15 kPa) and a
// stiff (15 MPa) rod with the implicit step as it is at this commit, as the
// reference data of test_implicit_pore_passage (which then checks later
// integrators against it). Run:
//   build/tests/drag-models/dynamics/record_pore_passage <commit> [model] > pore_passage_reference.txt
// (with a model name: that model's rows only, to replace them in the file).
#include "pore_passage_driver.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  const std::string commit = argc > 1 ? argv[1] : "unknown";
  std::printf("# Pore passage with the implicit overdamped step (pore_passage_driver.h), recorded at commit %s\n",
              commit.c_str());
  std::printf("# by: build/tests/drag-models/dynamics/record_pore_passage %s\n", commit.c_str());
  std::printf("# dt = 4e-6 s, 1100 steps; level 4 with window_cells 2. Columns: model E[Pa] step x_centre[m] "
              "angle[deg] lateral[W]\n");
  const std::string only = argc > 2 ? argv[2] : "";
  for (const char* model : {"isotropic", "local", "nonlocal", "twoway"})
    for (double e : {15e3, 15e6}) {
      if (!only.empty() && only != model) continue;
      hsrod_test::PassageCase c;
      c.model = model;
      c.youngs_modulus = e;
      for (const auto& s : hsrod_test::run_pore_passage(c, HSROD_TEST_CACHE_DIR))
        std::printf("%s %.17g %d %.17g %.17g %.17g\n", model, e, s.step, s.x_centre, s.angle_deg, s.lateral);
      std::fflush(stdout);
    }
  return 0;
}
