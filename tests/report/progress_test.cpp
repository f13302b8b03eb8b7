#include "gi/report/progress.hpp"

#include <gtest/gtest.h>

#include "gi/core/parallel.hpp"

TEST(Progress, SilentWhenStderrIsNotATerminal) {
  // Under ctest stderr is a pipe: logs and CI output must stay free of bar drawing.
  testing::internal::CaptureStderr();
  {
    gi::Progress progress("work", 1000);
    gi::parallel_for(1000, 4, [&](int) { progress.advance(); });
    progress.finish();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}
