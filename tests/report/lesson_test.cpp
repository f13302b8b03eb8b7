#include "gi/report/lesson.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "gi/core/not_implemented.hpp"
#include "gi/report/options.hpp"

TEST(RunLesson, ExitStatusAndOneLineOnStderr) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(gi::run_lesson("01_x", [] { return 0; }), 0);
  EXPECT_EQ(gi::run_lesson("01_x", []() -> int { throw gi::OptionError("--width must be in [1, 10], got 0"); }), 2);
  EXPECT_EQ(gi::run_lesson("01_x", []() -> int { throw gi::NotImplemented("exercise 1.1 ray-sphere"); }), 3);
  EXPECT_EQ(gi::run_lesson("01_x", []() -> int { throw std::invalid_argument("sphere: bad radius"); }), 1);
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "01_x: error: --width must be in [1, 10], got 0 (try --help)\n"
            "01_x: exercise 1.1 ray-sphere is not implemented yet (see exercises/)\n"
            "01_x: error: sphere: bad radius\n");
}
