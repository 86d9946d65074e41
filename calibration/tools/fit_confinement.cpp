// hsrod_fit_confinement: confinement coefficients from resolved force runs.
//
//   hsrod_fit_confinement SAMPLES.csv OUT.txt [--source TEXT]
//
// SAMPLES.csv: beta,body,n_spheres,d,mu,u_mean,v,force (SI; see
// calibration/core/confinement_fit.h). OUT.txt: "hsrod-confinement-coefficients 1",
// the file fix hele_shaw/drag reads. Prints the fitted a, b and residual per
// (beta, body).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <map>

#include "confinement_fit.h"

int main(int argc, char** argv) {
  CLI::App app{"Fit hsrod's confinement coefficients to resolved force runs"};
  std::string samples_path, out_path, source = "hsrod_fit_confinement";
  app.add_option("samples", samples_path, "CSV of resolved force samples")->required()->check(CLI::ExistingFile);
  app.add_option("output", out_path, "coefficient file to write")->required();
  app.add_option("--source", source, "text for the file's source line");
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace hsrod::calib;
    const auto samples = read_force_samples(samples_path);
    std::map<std::pair<double, int>, std::vector<ForceSample>> groups;
    for (const auto& s : samples) groups[{s.beta, static_cast<int>(s.body)}].push_back(s);
    const char* names[] = {"sphere", "rod_parallel", "rod_perpendicular"};
    for (const auto& [key, g] : groups) {
      const LinearFit f = fit_linear(g);
      std::printf("beta %.4g %-17s runs %d: a = %.6e N s/m, b = %.6e N s/m, rms residual %.2e\n", key.first,
                  names[key.second], f.n, f.a, f.b, f.rms_residual);
    }
    const auto table = fit_table(samples, source);
    table.write(out_path);
    for (const auto& r : table.rows())
      std::printf("beta %.4g: sphere_friction %.5f sphere_driving %.5f parallel_friction %.5f "
                  "perpendicular_friction %.5f parallel_driving %.5f perpendicular_driving %.5f\n",
                  r.beta, r.c.sphere_friction, r.c.sphere_driving, r.c.parallel_friction, r.c.perpendicular_friction,
                  r.c.parallel_driving, r.c.perpendicular_driving);
    std::printf("wrote %s\n", out_path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hsrod_fit_confinement: %s\n", e.what());
    return 1;
  }
  return 0;
}
