#include "gi/report/chart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace {
int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(Chart, LinearTicksAreOneTwoFiveSteps) {
  EXPECT_EQ(gi::axis_ticks(0, 10, false), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  EXPECT_EQ(gi::axis_ticks(0, 0.7, false).size(), 8u);  // steps of 0.1
  const auto ticks = gi::axis_ticks(13, 97, false);     // steps of 20 covering the range
  EXPECT_LE(ticks.front(), 13);
  EXPECT_GE(ticks.back(), 97);
  EXPECT_DOUBLE_EQ(ticks[1] - ticks[0], 20);
}

TEST(Chart, LogTicksAreDecades) {
  EXPECT_EQ(gi::axis_ticks(0.003, 2, true), (std::vector<double>{1e-3, 1e-2, 1e-1, 1, 10}));
}

// Every decade from 10^-22 to 10^22, the same bits as the literal
// (std::pow(10.0, -3) is a unit in the last place off on MinGW).
TEST(Chart, PowersOfTenAreTheNearestDoubles) {
  for (int e = -22; e <= 22; ++e)
    EXPECT_EQ(gi::power_of_ten(e), std::strtod(("1e" + std::to_string(e)).c_str(), nullptr)) << "10^" << e;
}

// A log axis over less than a few decades still carries several labelled ticks:
// 16 to 37 ms once had only 10 and 100.
TEST(Chart, ANarrowLogAxisGetsFinerTicks) {
  const auto near = [](const std::vector<double>& got, const std::vector<double>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-12 * want[i]) << i;
  };
  near(gi::axis_ticks(16, 37, true), {10, 20, 30, 40});
  near(gi::axis_ticks(0.02, 3, true), {0.01, 0.1, 1, 10});
  near(gi::axis_ticks(0.02, 0.7, true), {0.02, 0.05, 0.1, 0.2, 0.5, 1});
  near(gi::axis_ticks(0.0011, 0.5, true), {1e-3, 1e-2, 1e-1, 1});
  near(gi::axis_ticks(21, 24, true), {21, 21.5, 22, 22.5, 23, 23.5, 24});
  gi::Chart chart{"t", "ms", "RMSE", true, true, {}};
  chart.series.push_back({"a", {16, 37}, {0.02, 0.05}});
  const std::string svg = gi::to_svg(chart);
  for (const char* label : {">10<", ">20<", ">30<", ">40<", ">0.02<", ">0.03<", ">0.04<", ">0.05<"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
}

TEST(Chart, OneLinePerSeriesLegendEscapedAndBadPointsSkipped) {
  gi::Chart chart{"Error <vs> time", "ms", "RMSE", false, true, {}};
  chart.series.push_back({"depth & more", {1, 2, 3}, {0.1, 0.0, 0.01}});  // 0 cannot sit on a log axis
  chart.series.push_back({"threshold", {1, 2}, {NAN, 0.5}, gi::Mark::Points});
  const std::string svg = gi::to_svg(chart);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline"), 1);  // the second series has points only
  EXPECT_NE(svg.find("Error &lt;vs&gt; time"), std::string::npos);
  EXPECT_NE(svg.find("depth &amp; more"), std::string::npos);
  EXPECT_EQ(count(svg, "<circle"), 2);  // two usable points of the first series
  EXPECT_EQ(count(svg, "<rect x"), 2);  // plot frame + one usable point of the second
}

TEST(Chart, EmptyChartIsStillValid) {
  const std::string svg = gi::to_svg(gi::Chart{"empty", "x", "y", true, true, {}});
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

// The legend right of the plot is not cut off: a long name widens the picture (at
// about 7 px a character), a short one leaves the width asked for.
TEST(Chart, ALongLegendNameWidensThePicture) {
  gi::Chart chart{"t", "x", "y", false, false, {}};
  chart.series.push_back({"short", {1, 2}, {1, 2}});
  EXPECT_NE(gi::to_svg(chart, 720, 480).find("width=\"720\""), std::string::npos);
  const std::string name(60, 'm');
  chart.series.push_back({name, {1, 2}, {2, 3}});
  const std::string svg = gi::to_svg(chart, 720, 480);
  const std::size_t at = svg.find("width=\"") + 7;
  const int width = std::stoi(svg.substr(at));
  EXPECT_GE(width, 720 - 200 + 46 + 7 * 60) << "the legend's text starts 46 px right of the plot";
}

// A title longer than the plot is wide starts inside the picture: its centre is at
// least half its estimated length (8 px a character at font size 15) from the left.
TEST(Chart, ALongTitleStaysInsideThePicture) {
  const std::string title(100, 'T');
  const std::string svg = gi::to_svg(gi::Chart{title, "x", "y", false, false, {}}, 720, 480);
  const std::size_t at = svg.find("<text x=\"") + 9;
  EXPECT_GE(std::stod(svg.substr(at)), 4.0 * 100);
  EXPECT_GE(std::stoi(svg.substr(svg.find("width=\"") + 7)), 8 * 100);
}
