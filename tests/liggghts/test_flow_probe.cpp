// compute hele_shaw/probe through LIGGGHTS: the background flow at points and
// along a line, read the way a user reads it (thermo variables, fix
// ave/time, fix print). Straight channel: the closed-form Brinkman profile
// (written out here, independently of drag-models) to round-off. Pore
// scene: the throat velocity is the grid solution's node value and the flow
// rate through the throat equals the inflow.
#include "liggghts_session.h"

#include "compute.h"
#include "fix_hele_shaw_drag.h"
#include "variable.h"

#include "flow/grid_brinkman_flow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

using hsrod_test::LiggghtsSession;
using hsrod_test::num;

namespace {

constexpr double L = 600e-6, W = 200e-6, H = 20e-6, mu = 1e-3;  // scene [m], [Pa s]

// The pore-scene box with one 10-sphere rod and a drag fix `drag` (extra keywords).
void scene(LiggghtsSession &s, const std::string &drag_keywords) {
  setenv("HSROD_CACHE_DIR", HSROD_TEST_CACHE_DIR, 1);
  s.commands({"units si", "atom_style hybrid granular molecular", "atom_modify map array sort 0 0", "boundary f f f",
              "newton off", "communicate single cutoff 1e-5 vel yes",
              "region box block 0 600e-6 0 200e-6 0 20e-6 units box", "create_box 1 box",
              "create_rod spheres 10 diameter 3e-6 type 1 density 1170 centre 150e-6 100e-6 10e-6",
              "fix drag all hele_shaw/drag viscosity 1e-3 fluid_density 1170 model isotropic timestep_check no " +
                  drag_keywords,
              "timestep 1e-9"});
}

LAMMPS_NS::Compute *compute(LiggghtsSession &s, const char *id) {
  auto *modify = s.lammps()->modify;
  return modify->compute[modify->find_compute(id)];
}

double equal_variable(LiggghtsSession &s, const char *name) {
  auto *v = s.lammps()->input->variable;
  return v->compute_equal(v->find(const_cast<char *>(name)));
}

// Closed-form developed depth-averaged Brinkman profile of a straight
// channel (u'' - k^2 u = dp/dx / mu, u(0) = u(W) = 0, k = sqrt(12)/H),
// scaled to the mean U: u/U, d(u/U)/dy and dp/dx / (mu U).
struct ClosedForm {
  double k = std::sqrt(12.0) / H, a = k * W / 2, norm = 1.0 - std::tanh(a) / a;
  double u(double y) const { return (1.0 - std::cosh(k * (y - W / 2)) / std::cosh(a)) / norm; }
  double dudy(double y) const { return -k * std::sinh(k * (y - W / 2)) / std::cosh(a) / norm; }
  double dpdx() const { return -k * k / norm; }
};

}  // namespace

TEST(FlowProbe, StraightChannelReproducesClosedFormBrinkmanProfile) {
  const double U = 0.03;
  LiggghtsSession s;
  scene(s, "mean_velocity " + num(U));
  const int n = 4000;
  s.commands({"compute probe all hele_shaw/probe drag point 120e-6 37e-6 point 455e-6 1.3e-6 line 300e-6 0 300e-6 "
              "200e-6 " + std::to_string(n),
              "variable ux equal c_probe[1][3]", "variable flux equal c_probe[1]",
              "thermo_style custom step v_ux c_probe[2][3] c_probe[1][10] c_probe[1]",
              "fix profile all ave/time 1 1 1 c_probe[2] c_probe[3] c_probe[7] c_probe[10] mode vector file probe_profile.txt",
              "fix flux all print 1 \"${flux}\" file probe_flux.txt screen no", "run 1"});  // no integrator: nothing moves
  const ClosedForm exact;
  // Round-off: both evaluate the same formula (drag-models with decaying
  // exponentials, this test with cosh), so they agree to ~1e-15 U.
  const double tol = 1e-12 * U;
  LAMMPS_NS::Compute *c = compute(s, "probe");
  c->compute_array();
  for (int row = 0; row < c->size_array_rows; row++) {
    const double *r = c->array[row];
    const double x = r[0], y = r[1];
    ASSERT_EQ(r[10], 1.0) << "row " << row;
    EXPECT_NEAR(r[2], U * exact.u(y), tol) << "u_x at y = " << y;
    EXPECT_EQ(r[3], 0.0);
    EXPECT_NEAR(r[6], U * exact.dudy(y), 1e-12 * U * exact.k) << "du_x/dy at y = " << y;
    EXPECT_EQ(r[5], 0.0);
    EXPECT_EQ(r[8], 0.0);
    EXPECT_NEAR(r[9], mu * U * exact.dpdx() * (x - L), 1e-12 * std::fabs(mu * U * exact.dpdx() * L)) << "p at x = " << x;
  }
  // The same numbers through a thermo variable (as thermo and fix print read them).
  EXPECT_NEAR(equal_variable(s, "ux"), U * exact.u(37e-6), tol);
  // Flow rate: midpoint rule on n pieces; its error (h^2/24) [u']_0^W
  // = 2.3e-7 relative here, the rest is round-off.
  const double q = U * W * H;
  c->compute_vector();
  EXPECT_NEAR(c->vector[0] / q, 1.0, 1e-6);
  EXPECT_NEAR(c->vector[1], W, 1e-12 * W);            // the whole line lies in the fluid
  EXPECT_NEAR(c->vector[5], U, 1e-6 * U);             // mean velocity Q / (H W)
  EXPECT_NEAR(c->vector[2], mu * U * exact.dpdx() * (300e-6 - L), 1e-9 * mu * U * std::fabs(exact.dpdx()) * L);

  // fix ave/time wrote the profile (y, u_x, du_x/dy, p), one line per node.
  std::ifstream profile("probe_profile.txt");
  ASSERT_TRUE(profile.good());
  std::string line;
  int rows = 0;
  double worst = 0.0;
  while (std::getline(profile, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    double index, y, ux, dudy, p;
    if (!(in >> index >> y >> ux >> dudy >> p)) continue;  // the "step rows" line has 2 fields
    // The file holds LIGGGHTS' %g (6 digits) of y and u_x: rounding of both.
    const double rounding = 5e-6 * (std::fabs(ux) + std::fabs(U * exact.dudy(y) * y));
    worst = std::max(worst, std::fabs(ux - U * exact.u(y)) / rounding);
    rows++;
  }
  EXPECT_TRUE(rows >= n + 2 && rows % (n + 2) == 0) << rows << " rows";  // one block per output step
  EXPECT_LT(worst, 1.0);
  // fix print wrote the flow rate (at step 1; variables print with 15 digits).
  std::ifstream printed("probe_flux.txt");
  double q_printed = 0.0;
  while (std::getline(printed, line))
    if (!line.empty() && line[0] != '#') q_printed = std::atof(line.c_str());
  EXPECT_NEAR(q_printed / q, 1.0, 1e-5);
}

TEST(FlowProbe, PoreThroatVelocityAndFlowRateAgreeWithTheGridSolution) {
  LiggghtsSession s;
  scene(s, "channel 600e-6 200e-6 20e-6 origin 0 0 0 pore 85e-6 300e-6 reynolds 2");
  auto *drag = dynamic_cast<LAMMPS_NS::FixHeleShawDrag *>(s.fix("drag"));
  ASSERT_NE(drag, nullptr);
  const auto *grid = dynamic_cast<const hsrod::GridBrinkmanFlow *>(&drag->flow());
  ASSERT_NE(grid, nullptr) << "the pore scene must use the grid solver";
  // The u node of the solved grid nearest the throat centre (x = 300 um, y = W/2).
  const hsrod::MacGrid &g = grid->field().grid();
  const int i = static_cast<int>(std::lround(300e-6 / H / g.hx));
  const int j = static_cast<int>(std::lround(100e-6 / H / g.hy - 0.5));
  const Eigen::Vector2d node = g.u_position(i, j) * H;
  const hsrod::ExtendedLattice lat = hsrod::extended_u_lattice(g);
  const double node_u = grid->mean_velocity() * grid->field().u_ext()[lat.index(i, j)];
  const int n = 3000;
  s.commands({"compute probe all hele_shaw/probe drag point " + num(node.x()) + " " + num(node.y()) +
                  " line 300e-6 0 300e-6 200e-6 " + std::to_string(n) + "",
              "compute inlet all hele_shaw/probe drag line 0 0 0 200e-6 2000",
              "thermo_style custom step c_probe[1][3] c_probe[1] c_inlet[1]", "run 0"});
  LAMMPS_NS::Compute *c = compute(s, "probe");
  c->compute_array();
  const double U = grid->mean_velocity(), q = U * W * H;
  std::printf("throat node (%.4g, %.4g) um: probe u_x %.8g m/s, grid node %.8g m/s (%.3f U)\n", node.x() * 1e6,
              node.y() * 1e6, c->array[0][2], node_u, node_u / U);
  // At a node the interpolant returns the node value (the no-slip band does
  // not reach the throat centre, 15 um from the cylinders).
  EXPECT_NEAR(c->array[0][2], node_u, 1e-12 * node_u);
  EXPECT_GT(node_u / U, 8.0);  // the pore accelerates the flow ~9x (drag-models/flow/README.md)
  c->compute_vector();
  compute(s, "inlet")->compute_vector();
  const double q_throat = c->vector[0], q_inlet = compute(s, "inlet")->vector[0];
  std::printf("flow rate / Q: throat %.6f (fluid length %.4g um, max |u| %.4g m/s), inlet %.6f\n", q_throat / q,
              c->vector[1] * 1e6, c->vector[4], q_inlet / q);
  EXPECT_NEAR(q_throat / q, 1.0, 5e-3);
  EXPECT_NEAR(q_inlet / q, 1.0, 5e-3);
  EXPECT_NEAR(c->vector[1], W - 2 * 85e-6, 2.0 * W / n);  // open width of the pore, 30 um
}
