// Bounded work of the dense level-3 model: a rod of N = 10 000 spheres
// would need several 7 GB matrices; the prediction refuses it before
// anything is allocated.
#include "hydro/dense_model_budget.h"

#include <gtest/gtest.h>

#include <string>

using namespace hsrod;

TEST(DenseModelBudget, TenThousandSpheresAreRefusedWithTheFigures) {
  // One dense 30 000 x 30 000 matrix of doubles is 7.2 GB (the issue's
  // figure); the model holds several.
  EXPECT_GE(nonlocal_model_bytes(10000), 7.2e9);
  const std::string m = nonlocal_model_budget_problem(10000, 2e9);
  EXPECT_NE(m.find("10000 spheres"), std::string::npos) << m;
  EXPECT_NE(m.find("30000 x 30000"), std::string::npos) << m;
  EXPECT_NE(m.find("limit 2 GB"), std::string::npos) << m;
  EXPECT_NE(m.find("model local"), std::string::npos) << m;
  EXPECT_NE(m.find("memory_limit"), std::string::npos) << m;
}

TEST(DenseModelBudget, DocumentedRodsFit) {
  // The paper's rods (10-20 spheres, 2x2 sections: 80) and a 200-sphere rod
  // need a few MB at most.
  for (long n : {10L, 20L, 80L, 200L}) {
    EXPECT_EQ(nonlocal_model_budget_problem(n, 2e9), "") << n;
    EXPECT_LT(nonlocal_model_bytes(n), 2e7) << n;
  }
  // Exactly 6 (3n)^2 doubles.
  EXPECT_DOUBLE_EQ(nonlocal_model_bytes(100), 6.0 * 300 * 300 * 8);
}
