// The model registry (hydro/model_registry.h): one entry per rung of the
// fidelity ladder, the factory and the error message read from it, and the
// doc page's table of models kept equal to it.
#include "hydro/model_registry.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

using namespace hsrod;

TEST(ModelRegistry, OneModelPerLevelOneToFourByIncreasingLevel) {
  const auto& models = registered_models();
  ASSERT_EQ(models.size(), 4u);
  std::set<std::string> names;
  for (std::size_t k = 0; k < models.size(); ++k) {
    EXPECT_EQ(models[k].level, static_cast<int>(k) + 1);
    EXPECT_TRUE(names.insert(models[k].name).second) << models[k].name;
    EXPECT_FALSE(models[k].description.empty());
    EXPECT_EQ(find_model(models[k].name), &models[k]);
    EXPECT_EQ(find_model_level(models[k].level), &models[k]);
  }
  EXPECT_EQ(find_model("auto"), nullptr);  // a policy, not a model
}

TEST(ModelRegistry, FactoryBuildsEachRegisteredModelWithItsNameAndLevel) {
  const ConfinementTable table = ConfinementTable::default_table();
  for (const ModelEntry& entry : registered_models()) {
    const auto model = make_hydrodynamic_model(entry.name, {1e-3, 20e-6, 3e-6}, table);
    EXPECT_EQ(model->name(), entry.name);
    EXPECT_EQ(model->level(), entry.level);
  }
}

TEST(ModelRegistry, UnknownNameListsTheRegisteredOnes) {
  EXPECT_EQ(valid_model_names("auto"), "isotropic, local, nonlocal, twoway or auto");
  try {
    make_hydrodynamic_model("slender", {1e-3, 20e-6, 3e-6}, ConfinementTable::default_table());
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("expected isotropic, local, nonlocal or twoway"), std::string::npos)
        << e.what();
  }
}

// liggghts-package/doc/fix_hele_shaw_drag.txt has one table row per model:
// "name | level | description", as registered.
TEST(ModelRegistry, DocPageTableListsEveryRegisteredModel) {
  std::ifstream in(std::string(HSROD_SOURCE_DIR) + "/liggghts-package/doc/fix_hele_shaw_drag.txt");
  ASSERT_TRUE(in) << "doc page not found";
  std::stringstream text;
  text << in.rdbuf();
  std::set<std::string> rows;
  std::string line;
  while (std::getline(text, line)) {
    const std::string tail = " :tb(s=|)";
    if (line.size() > tail.size() && line.compare(line.size() - tail.size(), tail.size(), tail) == 0)
      line.erase(line.size() - tail.size());
    rows.insert(line);
  }
  int table_rows = 0;
  for (const std::string& row : rows)
    if (row.find(" | ") != std::string::npos && row.rfind("name |", 0) != 0) ++table_rows;
  EXPECT_EQ(table_rows, static_cast<int>(registered_models().size()));
  for (const ModelEntry& entry : registered_models()) {
    const std::string expected = entry.name + " | " + std::to_string(entry.level) + " | " + entry.description;
    EXPECT_EQ(rows.count(expected), 1u) << "missing doc row: " << expected;
  }
}
