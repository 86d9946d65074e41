// A rod split across two MPI ranks (and across a periodic boundary) follows
// the same trajectory as on one rank, to round-off. Run under
// `mpirun -np 2`: the 2-rank run uses MPI_COMM_WORLD, rank 0 then repeats
// the run alone on MPI_COMM_SELF as the reference.
#include "liggghts_session.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

namespace {

std::vector<std::string> script(const std::string &processors) {
  // Periodic in x; the rod (along x, 20 spheres of 3 um) straddles both the
  // periodic boundary at x = +-3e-5 and the rank boundary at x = 0 as it moves.
  return {"units si",
          "atom_style hybrid granular molecular",
          "atom_modify map array sort 0 0",
          "boundary p f f",
          "newton off",
          "processors " + processors,
          "communicate single cutoff 1e-5 vel yes",
          "region box block -3e-5 3e-5 -3e-5 3e-5 -1e-5 1e-5 units box",
          "create_box 1 box",
          "create_rod spheres 20 diameter 3e-6 type 1 density 1170 centre 2.5e-5 0 0 angle 80",
          "group ends id 1 20",
          "fix bonds all rod/bonds youngs_modulus 15e6 poisson_ratio 0.3 damping 0.05",
          "fix integrate all nve/sphere",
          "velocity all set 0.5 0 0",
          "velocity ends set 0.5 0.3 0.1",
          "timestep 1e-8",
          "run 3000"};
}

}  // namespace

TEST(MpiRod, TwoRanksMatchOneRank) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  ASSERT_EQ(size, 2) << "run with mpirun -np 2";

  std::vector<Eigen::Vector3d> parallel;
  {
    hsrod_test::LiggghtsSession s(MPI_COMM_WORLD);
    s.commands(script("2 1 1"));
    parallel = s.gather("x");
  }
  int ok = 1;
  if (rank == 0) {
    hsrod_test::LiggghtsSession s(MPI_COMM_SELF);
    s.commands(script("1 1 1"));
    const auto serial = s.gather("x");
    ASSERT_EQ(serial.size(), parallel.size());
    double worst = 0.0, travelled = 0.0;
    for (size_t i = 0; i < serial.size(); i++) {
      Eigen::Vector3d diff = parallel[i] - serial[i];
      diff.x() -= 6e-5 * std::round(diff.x() / 6e-5);  // periodic image
      worst = std::max(worst, diff.norm());
    }
    travelled = 0.5 * 3000 * 1e-8;
    std::printf("2 ranks vs 1 rank: largest position difference %.3g m (rod moved %.3g m)\n", worst, travelled);
    EXPECT_LT(worst, 1e-9 * 3e-6);
    ok = worst < 1e-9 * 3e-6;
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
}

namespace {

std::vector<std::string> pore_script(const std::string &processors, const std::string &model) {
  // The pore scene with the implicit integrator; the rod crosses the rank
  // boundary at x = 300 um (the pore) during the run.
  return {"units si",
          "atom_style hybrid granular molecular",
          "atom_modify map array sort 0 0",
          "boundary f f f",
          "newton off",
          "processors " + processors,
          "communicate single cutoff 1e-5 vel yes",
          "region box block 0 600e-6 0 200e-6 0 20e-6 units box",
          "create_box 1 box",
          "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 270e-6 100e-6 10e-6 angle 10",
          "fix bonds all rod/bonds youngs_modulus 15e3 poisson_ratio 0.3",
          "fix drag all hele_shaw/drag channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 "
          "viscosity 1e-3 fluid_density 1170 reynolds 2 model " + model,
          "fix step all rod/implicit bonds bonds drag drag",
          "timestep 2e-6",
          "run 300"};
}

}  // namespace

// Every rank gathers the whole rod and evaluates the model on it, so the
// trajectory must not depend on the decomposition: level 3 (dense solve) and
// level 4 (window solves, KLU) alike.
static void expect_pore_passage_independent_of_ranks(const std::string &model) {
  setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<Eigen::Vector3d> parallel;
  {
    hsrod_test::LiggghtsSession s(MPI_COMM_WORLD);
    s.commands(pore_script("2 1 1", model));
    parallel = s.gather("x");
  }
  int ok = 1;
  if (rank == 0) {
    hsrod_test::LiggghtsSession s(MPI_COMM_SELF);
    s.commands(pore_script("1 1 1", model));
    const auto serial = s.gather("x");
    double worst = 0.0;
    for (size_t i = 0; i < serial.size(); i++) worst = std::max(worst, (parallel[i] - serial[i]).norm());
    std::printf("implicit pore passage (%s), 2 ranks vs 1 rank: largest position difference %.3g m (rod at x = %.4g m)\n",
                model.c_str(), worst, serial[0].x());
    EXPECT_LT(worst, 1e-9 * 3e-6);
    ok = worst < 1e-9 * 3e-6;
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
}

TEST(MpiRod, ImplicitPorePassageTwoRanksMatchOneRank) { expect_pore_passage_independent_of_ranks("nonlocal"); }

TEST(MpiRod, TwoWayPorePassageTwoRanksMatchOneRank) {
  expect_pore_passage_independent_of_ranks("twoway window_cells 2");
}

// Several rods: two rods, one on each rank at the start, pushed
// into contact across the rank boundary at x = 300 um, Hertz contact with
// friction and level 3's hydrodynamic interaction between them; every rank
// gathers both rods and steps them together, so 2 ranks equal 1.
TEST(MpiRod, RodsInContactOnDifferentRanksMatchOneRank) {
  const auto script = [](const std::string &processors) {
    return std::vector<std::string>{
        "units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
        "newton off", "processors " + processors, "communicate single cutoff 1e-5 vel yes",
        "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
        "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 297e-6 100e-6 10e-6 angle 0",
        "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 306e-6 104e-6 10e-6 angle 20",
        "group a molecule 1", "group b molecule 2",
        "fix bonds all rod/bonds youngs_modulus 15e3 poisson_ratio 0.3",
        "fix drag all hele_shaw/drag mean_velocity 0.03 model nonlocal",
        "fix push_a a addforce 1e-9 0 0", "fix push_b b addforce -1e-9 0 0",
        "fix step all rod/implicit bonds bonds drag drag rod_contact hertz rod_friction 0.5", "timestep 2e-6",
        "run 200"};
  };
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<Eigen::Vector3d> parallel;
  double touching = 0.0;
  {
    hsrod_test::LiggghtsSession s(MPI_COMM_WORLD);
    s.commands(script("2 1 1"));
    parallel = s.gather("x");
    touching = s.fix("step")->compute_vector(10);
  }
  int ok = 1;
  if (rank == 0) {
    hsrod_test::LiggghtsSession s(MPI_COMM_SELF);
    s.commands(script("1 1 1"));
    const auto serial = s.gather("x");
    double worst = 0.0;
    for (size_t i = 0; i < serial.size(); i++) worst = std::max(worst, (parallel[i] - serial[i]).norm());
    std::printf("two rods in contact, 2 ranks vs 1 rank: largest position difference %.3g m; rods touching %g\n",
                worst, touching);
    EXPECT_EQ(touching, 2.0);
    EXPECT_LT(worst, 1e-9 * 3e-6);
    ok = worst < 1e-9 * 3e-6 && touching == 2.0;
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
}
