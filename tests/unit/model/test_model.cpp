// The load factors of the model (model/model.hpp, step_factor): a step's own factors or the global ones,
// and within a step (the sub-steps of an automatic step cut) linear between step − 1 and step.
#include <gtest/gtest.h>

#include <vector>

#include "symcontact/model/model.hpp"

using namespace symcontact;

TEST(ModelLoads, StepFactorsAreInterpolatedBetweenSteps) {
  const std::vector<double> global = {0.5, 1.0}, own = {0.2, 0.6};
  EXPECT_EQ(step_factor({}, global, 0, 0.5), 0.25);  // from the unloaded start
  EXPECT_EQ(step_factor({}, global, 1, 0.5), 0.75);
  EXPECT_DOUBLE_EQ(step_factor(own, global, 1, 0.25), 0.3);
  EXPECT_EQ(step_factor(own, global, 1, 1.0), 0.6);
  EXPECT_EQ(step_factor(own, global, 1), 0.6);
}
