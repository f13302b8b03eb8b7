#include "gi/report/svg_canvas.hpp"

#include <gtest/gtest.h>

#include <clocale>
#include <string>

TEST(SvgCanvas, WritesWhatItIsGivenEscapedAndInDots) {
  gi::SvgCanvas canvas(200, 100);
  canvas.line({0, 0}, {10.5, 20.25});
  canvas.text({5, 6}, "A_j < 1 & \"F\"", "middle", 12);
  canvas.polygon({{0, 0}, {1, 0}, {0, 1}}, "fill=\"red\"");
  const std::string svg = canvas.svg();
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\"", 0), 0u);
  EXPECT_NE(svg.find("x2=\"10.50\" y2=\"20.25\""), std::string::npos);
  EXPECT_NE(svg.find(">A_j &lt; 1 &amp; &quot;F&quot;</text>"), std::string::npos);
  EXPECT_NE(svg.find("points=\"0.00,0.00 1.00,0.00 0.00,1.00 \" fill=\"red\""), std::string::npos);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
}

TEST(SvgCanvas, AnArrowEndsInAHeadAtItsPoint) {
  // A shaft along +x to (100, 50): the head's tip is the end, its base 10 px back.
  gi::SvgCanvas canvas(200, 100);
  canvas.arrow({0, 50}, {100, 50}, "#D55E00");
  const std::string svg = canvas.svg();
  EXPECT_NE(svg.find("<polygon points=\"100.00,50.00 91.34,45.00 91.34,55.00 \" fill=\"#D55E00\""), std::string::npos)
      << svg;
}

TEST(SvgCanvas, NumbersHaveADotWhateverTheLocale) {
  const char* locale = std::setlocale(LC_NUMERIC, "de_DE.UTF-8");  // a decimal comma, where installed
  EXPECT_EQ(gi::svg_number(0.5), "0.50");
  EXPECT_EQ(gi::svg_number(-12.345), "-12.35");  // 1234.5 rounds away from zero
  EXPECT_EQ(gi::svg_number(3.007), "3.01");
  EXPECT_EQ(gi::svg_number(-0.001), "0.00");
  EXPECT_EQ(gi::svg_number(720), "720.00");
  if (locale) std::setlocale(LC_NUMERIC, "C");
}
