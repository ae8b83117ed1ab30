#include "engine/pipeline/stage_timer.h"

#include <gtest/gtest.h>

namespace linesurf {
namespace {

TEST(StageTimer, RecordsStagesInOrder) {
  StageTimer timer;
  timer.Start("a");
  timer.Start("b");
  timer.Stop();
  ASSERT_EQ(timer.Stages().size(), 2u);
  EXPECT_EQ(timer.Stages()[0].first, "a");
  EXPECT_EQ(timer.Stages()[1].first, "b");
  EXPECT_GE(timer.TotalSeconds(), 0.0);
}

TEST(StageTimer, PeakRssIsPositive) { EXPECT_GT(PeakRssBytes(), 0u); }

}  // namespace
}  // namespace linesurf
