// The record of a lesson's outputs as JSON: exact text for one of each kind.
#include "gi/report/outputs.hpp"

#include <gtest/gtest.h>

#include <cmath>

TEST(Outputs, JsonOfEachKind) {
  gi::Output text;
  text.caption = "say \"hi\"\\\n\t";
  gi::Output picture;
  picture.kind = gi::OutputKind::Picture;
  picture.caption = "solution";
  picture.file = "solution.png";
  picture.bytes = 120;
  picture.linear = "solution.pfm";
  picture.linear_bytes = 780;
  picture.exposure = 1.5;
  picture.view.camera.eye = {278, 273, -800};
  picture.view.camera.look_at = {278, 273, 0};
  picture.view.camera.vertical_fov = 39.3077;
  picture.view.width = 16;
  picture.view.height = 8;
  picture.view.pixel_samples = "2 x 2 jittered eye rays, box filter";
  gi::Output nan_exposure = picture;
  nan_exposure.exposure = NAN;
  EXPECT_EQ(gi::outputs_json("08_x", {"08_x", "--out", "a b"}, "complete", {text, picture}),
            "{\n"
            "  \"lesson\": \"08_x\",\n"
            "  \"command\": [\"08_x\", \"--out\", \"a b\"],\n"
            "  \"status\": \"complete\",\n"
            "  \"outputs\": [\n"
            "    {\"kind\": \"text\", \"caption\": \"say \\\"hi\\\"\\\\\\n\\u0009\"},\n"
            "    {\"kind\": \"picture\", \"caption\": \"solution\", \"file\": \"solution.png\", \"bytes\": 120, "
            "\"linear\": \"solution.pfm\", \"exposure\": 1.5, \"view\": {\"eye\": [278, 273, -800], "
            "\"look_at\": [278, 273, 0], \"up\": [0, 1, 0], \"vertical_fov_degrees\": 39.307699999999997, "
            "\"width\": 16, \"height\": 8, \"pixel_samples\": \"2 x 2 jittered eye rays, box filter\", "
            "\"projection\": \"pinhole; pixel (x, y) spans [x, x+1] x [y, y+1] of the image plane, row 0 at the "
            "top\"}}\n"
            "  ]\n"
            "}\n");
  EXPECT_NE(gi::outputs_json("x", {}, "complete", {nan_exposure}).find("\"exposure\": null"), std::string::npos);
  EXPECT_EQ(gi::kind_name(gi::OutputKind::Cache), "cache");
}

// A false-colour diagram records its size and what its colours mean; a record made
// while the lesson runs names the process.
TEST(Outputs, ColourScaleAndProcess) {
  gi::Output heat;
  heat.kind = gi::OutputKind::Diagram;
  heat.caption = "F";
  heat.file = "f.png";
  heat.bytes = 10;
  heat.width = 728, heat.height = 728;
  heat.colour_scale = gi::ColourScale{1e-6, 0.5, "form factor F_ij", true};
  EXPECT_EQ(gi::outputs_json("07_x", {}, "running", {heat}, {4242, "boot:99"}),
            "{\n"
            "  \"lesson\": \"07_x\",\n"
            "  \"command\": [],\n"
            "  \"status\": \"running\",\n"
            "  \"process\": {\"id\": 4242, \"started\": \"boot:99\"},\n"
            "  \"outputs\": [\n"
            "    {\"kind\": \"diagram\", \"caption\": \"F\", \"file\": \"f.png\", \"bytes\": 10, \"width\": 728, "
            "\"height\": 728, \"colour_scale\": {\"map\": \"black, blue, green, yellow, red\", \"lo\": 9.9999999999999995e-07, "
            "\"hi\": 0.5, \"log10\": true, \"quantity\": \"form factor F_ij\"}}\n"
            "  ]\n"
            "}\n");
}
