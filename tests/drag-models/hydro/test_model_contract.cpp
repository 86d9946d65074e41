// The contract every registered hydrodynamic model must keep
// (hydro/hydrodynamic_model.h), run over the registry so that each model,
// including one added later, is checked by name (test names end in the
// model's name): the resistance R is symmetric positive definite; the load
// is F = d - R v with the per-sphere blocks those of R; a quiescent fluid
// loads a resting rod with nothing; an isolated sphere far from walls is
// level 1; the loads do not change when the rod is moved or mirrored in a
// uniform stream away from walls; a sphere moving at the confinement
// table's force-free velocity lambda(beta) u feels no force. Tolerances per
// model: model_contract_reference.txt.
#include "hydro/model_registry.h"

#include "flow/uniform_flow.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

using namespace hsrod;

namespace {

constexpr double kMu = 1e-3, kD = 3e-6, kBeta = 0.15, kGap = kD / kBeta;

struct Tolerances {
  double isolated = 0, moved = 0, mirrored = 0, free = 0;
};

std::map<std::string, Tolerances> reference() {
  std::ifstream in(std::string(HSROD_TEST_DATA_DIR) + "/model_contract_reference.txt");
  std::map<std::string, Tolerances> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream w(line);
    std::string name;
    Tolerances t;
    if (w >> name >> t.isolated >> t.moved >> t.mirrored >> t.free) rows[name] = t;
  }
  return rows;
}

// A uniform gap-averaged stream U along x in a slit of gap H, 1 cm wide (walls far away).
UniformFlow uniform_slit_stream(double gap, double speed) {
  return UniformFlow(ChannelGeometry(1e-2, 1e-2, gap, -5e-3, -5e-3), {speed, 0.0});
}

// A gently bent 10-sphere rod (an arc), tilted to the flow, centred at `centre`.
RodGeometry bent_rod(const Eigen::Vector3d& centre, int id) {
  RodGeometry rod;
  rod.sphere_diameter = kD;
  rod.id = id;
  for (int k = 0; k < 10; ++k) {
    const double s = (k - 4.5) * kD;
    const double tilt = 0.4;
    const Eigen::Vector3d along(std::cos(tilt), std::sin(tilt), 0.0), across(-std::sin(tilt), std::cos(tilt), 0.0);
    rod.positions.push_back(centre + s * along + 0.02 * s * s / kD * across);
  }
  return rod;
}

// The full resistance R (3n x 3n) of a load, from its blocks or the coupled matrix.
Eigen::MatrixXd full_resistance(const RodDrag& drag) {
  if (drag.coupled()) return drag.coupled_resistance;
  const int n = static_cast<int>(drag.resistance.size());
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) r.block<3, 3>(3 * i, 3 * i) = drag.resistance[i];
  return r;
}

Eigen::VectorXd stacked(const std::vector<Eigen::Vector3d>& v) {
  Eigen::VectorXd out(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out.segment<3>(3 * i) = v[i];
  return out;
}

const ConfinementTable& table() {
  static const ConfinementTable built_in = ConfinementTable::default_table();
  return built_in;
}

// Models are immutable: one instance per name serves all tests (level 4
// measures its lattice's self-mobility once, at construction).
const HydrodynamicModel* shared_model(const std::string& name) {
  static std::map<std::string, std::unique_ptr<HydrodynamicModel>> models;
  auto& m = models[name];
  if (!m) m = make_hydrodynamic_model(name, {kMu, kGap, kD}, table());
  return m.get();
}

class ModelContract : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    const auto rows = reference();
    ASSERT_EQ(rows.count(GetParam()), 1u) << "no reference row for model " << GetParam()
                                          << " in model_contract_reference.txt";
    tolerance = rows.at(GetParam());
    model = shared_model(GetParam());
    level1 = shared_model(find_model_level(1)->name);
  }
  Tolerances tolerance;
  const HydrodynamicModel* model = nullptr;
  const HydrodynamicModel* level1 = nullptr;
  const UniformFlow stream = uniform_slit_stream(kGap, 1e-3);
};

TEST_P(ModelContract, ResistanceIsSymmetricPositiveDefinite) {
  RodDrag drag;
  model->evaluate(bent_rod(Eigen::Vector3d::Zero(), 1), stream, drag);
  const Eigen::MatrixXd r = full_resistance(drag);
  EXPECT_LT((r - r.transpose()).norm(), 1e-12 * r.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (r + r.transpose()));
  EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0);
  for (double rotational : drag.rotational_resistance) EXPECT_GT(rotational, 0.0);
}

TEST_P(ModelContract, LoadIsDrivingMinusResistanceTimesVelocity) {
  RodDrag drag;
  const RodGeometry rod = bent_rod(Eigen::Vector3d::Zero(), 1);
  model->evaluate(rod, stream, drag);
  const Eigen::MatrixXd r = full_resistance(drag);
  const int n = rod.size();
  for (int i = 0; i < n; ++i)
    EXPECT_LT((drag.resistance[i] - r.block<3, 3>(3 * i, 3 * i)).norm(), 1e-12 * r.norm()) << "block " << i;
  const Eigen::VectorXd v = 1e-3 * Eigen::VectorXd::LinSpaced(3 * n, -1.0, 1.0);
  const Eigen::VectorXd expected = stacked(drag.driving_force) - r * v;
  EXPECT_LT((drag.forces(v) - expected).norm(), 1e-12 * expected.norm());
}

TEST_P(ModelContract, RestingRodInQuiescentFluidFeelsNothing) {
  const UniformFlow still = uniform_slit_stream(kGap, 0.0);
  RodDrag drag;
  const RodGeometry rod = bent_rod(Eigen::Vector3d::Zero(), 1);
  model->evaluate(rod, still, drag);
  EXPECT_EQ(drag.forces(Eigen::VectorXd::Zero(3 * rod.size())).norm(), 0.0);
  for (const auto& t : drag.driving_torque) EXPECT_EQ(t.norm(), 0.0);
}

TEST_P(ModelContract, IsolatedSphereIsLevelOne) {
  RodGeometry sphere;
  sphere.sphere_diameter = kD;
  sphere.positions = {Eigen::Vector3d(1.1e-7, -0.7e-7, 0.0)};
  RodDrag got, expected;
  model->evaluate(sphere, stream, got);
  level1->evaluate(sphere, stream, expected);
  const double zeta = expected.resistance[0](0, 0);
  EXPECT_LT((got.resistance[0] - expected.resistance[0]).norm(), tolerance.isolated * zeta);
  EXPECT_LT((got.driving_force[0] - expected.driving_force[0]).norm(),
            tolerance.isolated * expected.driving_force[0].norm());
  EXPECT_NEAR(got.rotational_resistance[0], expected.rotational_resistance[0],
              1e-12 * expected.rotational_resistance[0]);
}

TEST_P(ModelContract, LoadsUnchangedWhenTheRodIsMovedAwayFromWalls) {
  RodDrag here, there;
  model->evaluate(bent_rod(Eigen::Vector3d::Zero(), 1), stream, here);
  model->evaluate(bent_rod(Eigen::Vector3d(37.3 * kD, -21.9 * kD, 0.0), 2), stream, there);
  const Eigen::VectorXd d0 = stacked(here.driving_force), d1 = stacked(there.driving_force);
  EXPECT_LT((d1 - d0).norm(), tolerance.moved * d0.norm());
  const Eigen::MatrixXd r0 = full_resistance(here), r1 = full_resistance(there);
  EXPECT_LT((r1 - r0).norm(), tolerance.moved * r0.norm());
}

TEST_P(ModelContract, LoadsMirrorWhenTheRodIsMirroredAboutTheFlowAxis) {
  const RodGeometry rod = bent_rod(Eigen::Vector3d::Zero(), 1);
  RodGeometry mirror = rod;
  mirror.id = 2;
  for (auto& x : mirror.positions) x.y() = -x.y();
  RodDrag a, b;
  model->evaluate(rod, stream, a);
  model->evaluate(mirror, stream, b);
  const Eigen::Matrix3d m = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
  const int n = rod.size();
  Eigen::MatrixXd big = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < n; ++i) big.block<3, 3>(3 * i, 3 * i) = m;
  const Eigen::VectorXd da = stacked(a.driving_force), db = stacked(b.driving_force);
  EXPECT_LT((db - big * da).norm(), tolerance.mirrored * da.norm());
  const Eigen::MatrixXd ra = full_resistance(a), rb = full_resistance(b);
  EXPECT_LT((rb - big * ra * big).norm(), tolerance.mirrored * ra.norm());
}

TEST_P(ModelContract, SphereMovingAtTheTablesFreeVelocityFeelsNoForce) {
  RodGeometry sphere;
  sphere.sphere_diameter = kD;
  sphere.positions = {Eigen::Vector3d(0.4e-7, 0.9e-7, 0.0)};
  RodDrag drag;
  model->evaluate(sphere, stream, drag);
  const double lambda = table().at(kBeta).sphere_driving;
  const Eigen::Vector3d v(lambda * stream.mean_velocity(), 0.0, 0.0);
  const double zeta = full_resistance(drag)(0, 0);
  EXPECT_LT(drag.forces(v).norm(), tolerance.free * zeta * stream.mean_velocity());
}

std::vector<std::string> registered_names() {
  std::vector<std::string> names;
  for (const ModelEntry& m : registered_models()) names.push_back(m.name);
  return names;
}

}  // namespace

INSTANTIATE_TEST_SUITE_P(AllRegisteredModels, ModelContract, ::testing::ValuesIn(registered_names()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) { return param_info.param; });
