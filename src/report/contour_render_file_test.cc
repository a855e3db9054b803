// The text files of `hecal contour render` (contour_render_file.h): known values in the documented
// layout.
#include "hecal/report/contour_render_file.h"

#include <gtest/gtest.h>

#include <string>

#include "hecal/version.h"

namespace hecal::report {
namespace {

TEST(ContourRenderFileTest, NamesFramesWithFourDigits) {
  EXPECT_EQ(RenderedFrameName(0), "frame_0000.png");
  EXPECT_EQ(RenderedFrameName(42), "frame_0042.png");
  EXPECT_EQ(RenderedFrameName(9999), "frame_9999.png");
}

TEST(ContourRenderFileTest, InitCsvListsTheFirstViewInPixels) {
  contour::RenderedSequence rendered;
  rendered.first_view.resize(2, 2);
  rendered.first_view << 1.5, 319, -2, 0.25;
  EXPECT_EQ(RenderInitCsv(rendered),
            "# hecal contour render: control points of the first view (px)\n"
            "x,y\n"
            "1.5,-2\n"
            "319,0.25\n");
}

TEST(ContourRenderFileTest, TruthCsvHoldsTheMotionAndShapeOfEveryFrame) {
  contour::SequenceRenderOptions options;
  options.camera = {3000.0, 5000.0};
  options.seed = 7;
  contour::RenderedSequence rendered;
  rendered.principal = {159.5, 119.5};
  contour::RenderedFrame frame;
  frame.index = 1;
  frame.motion << 6, -4, -100, 3, 2, 4.5;
  frame.shape << 0.5, -1, 0.01, 0.02, 0.003, -0.004;
  rendered.frames = {frame};
  const std::string truth = RenderTruthCsv(options, rendered);
  EXPECT_EQ(truth.rfind("# hecal " + std::string(kVersion) + " contour render: ", 0), 0u);
  EXPECT_NE(truth.find("Z0 = 5000, f = 3000 px, principal point 159.5,119.5;"), std::string::npos);
  EXPECT_NE(truth.find("noise seed 7\n"), std::string::npos);
  const std::string table = truth.substr(truth.find('\n') + 1);
  EXPECT_EQ(table,
            "frame,image,Tx,Ty,Tz,Rx_deg,Ry_deg,Rz_deg,tx,ty,m11m1,m22m1,m21,m12\n"
            "1,frame_0001.png,6,-4,-100,3,2,4.5,0.5,-1,0.01,0.02,0.003,-0.004\n");
}

}  // namespace
}  // namespace hecal::report
