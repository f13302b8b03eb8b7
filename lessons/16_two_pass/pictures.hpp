#pragma once
// Lesson 16: its settings, and one picture with the time of each pass.
#include <cstdint>
#include <string>

#include "gi/image/image.hpp"
#include "gi/twopass/radiosity_pass.hpp"
#include "gi/twopass/two_pass.hpp"

namespace lesson16 {

struct Settings {
  std::string scene = "both";
  std::string references = std::string(GI_SOURCE_DIR) + "/lessons/references";
  int width = 128, height = 128, threads = 0;
  std::uint64_t seed = 1;
  gi::RadiosityPassSettings radiosity;
  gi::TwoPassSettings eye;
};

struct Picture {
  std::string method;
  gi::Image radiance;
  double pass1_seconds, pass2_seconds;
};

}  // namespace lesson16
