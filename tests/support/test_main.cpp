// GoogleTest entry point shared by all linesurf test executables.

#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

namespace {

// Per-process temporary directories (FreshTempDir) would pile up in /tmp otherwise.
class RemovePassedTestsTempDirs : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& test) override {
    linesurf::testing::RemoveTempDirOfPassedTest(test);
  }
};

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::UnitTest::GetInstance()->listeners().Append(new RemovePassedTestsTempDirs);
  return RUN_ALL_TESTS();
}
