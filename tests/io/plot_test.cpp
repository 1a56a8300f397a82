// Plot images are accepted only when whole (common/io/plot.hpp image_file_problem): a PNG
// needs its signature and a final IEND chunk, an SVG its closing </svg>.

#include "io/plot.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "io/image_file.hpp"
#include "io/output.hpp"
#include "render/image.hpp"
#include "support/temp_files.hpp"

namespace fs = std::filesystem;

namespace {

fs::path file_with(const std::string& name, const std::string& bytes) {
  const fs::path path = mcrt::testing::temp_suite_dir("plot_file_test") / name;
  mcrt::testing::write_text(path, bytes);
  return path;
}

TEST(PlotFileTest, AWholePngIsAcceptedAndATruncatedOneRejected) {
  const std::string png = mcrt::encode_png(mcrt::Image(4, 3));
  EXPECT_EQ(mcrt::image_file_problem(file_with("whole.png", png)), "");
  const std::string truncated =
      mcrt::image_file_problem(file_with("cut.png", png.substr(0, png.size() - 5)));
  EXPECT_NE(truncated.find("truncated"), std::string::npos) << truncated;
  EXPECT_NE(mcrt::image_file_problem(file_with("empty.png", "")), "");
  EXPECT_NE(mcrt::image_file_problem(file_with("text.png", "<svg></svg>")), "");
}

TEST(PlotFileTest, AWholeSvgIsAcceptedAndATruncatedOneRejected) {
  const std::string svg = "<?xml version=\"1.0\"?>\n<svg>\n<g></g>\n</svg>\n\n";
  EXPECT_EQ(mcrt::image_file_problem(file_with("whole.svg", svg)), "");
  const std::string truncated = mcrt::image_file_problem(file_with("cut.svg", svg.substr(0, 20)));
  EXPECT_NE(truncated.find("truncated"), std::string::npos) << truncated;
  EXPECT_NE(mcrt::image_file_problem(file_with("empty.svg", "")), "");
}

TEST(PlotFileTest, AMissingFileIsRejected) {
  EXPECT_NE(mcrt::image_file_problem("/nonexistent/mcrt/plot.png"), "");
}

TEST(PlotFileTest, GnuplotDrawsInAFolderWhateverItsName) {
  if (!mcrt::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = mcrt::testing::fresh_temp_dir("plot_file_test", "-it's a \"plot\" é");
  mcrt::testing::write_text(dir / "data.csv", "x,y\n1,1\n2,4\n");
  mcrt::write_plot(dir, {"square", "title", "x", "y", false, false, "",
                         "plot 'data.csv' using \"x\":\"y\" with lines"});
  EXPECT_EQ(mcrt::image_file_problem(dir / "square.png"), "");
  EXPECT_EQ(mcrt::image_file_problem(dir / "square.svg"), "");
}

TEST(PlotFileTest, AGnuplotErrorIsAnIoErrorAndLeavesNoImage) {
  if (!mcrt::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = mcrt::testing::fresh_temp_dir("plot_file_test", "error");
  std::string message;
  try {
    mcrt::write_plot(dir, {"broken", "title", "x", "y", false, false, "", "plot no_such_variable"});
  } catch (const mcrt::IoError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("broken.gp"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / "broken.png"));
  EXPECT_FALSE(fs::exists(dir / "broken.svg"));
}

TEST(PlotFileTest, ALogAxisWithNoPositiveValueIsDrawnLinear) {
  if (!mcrt::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = mcrt::testing::fresh_temp_dir("plot_file_test", "zeros");
  mcrt::testing::write_text(dir / "data.csv", "n,rmse\n1,0\n4,0\n");
  mcrt::Plot plot{"zeros", "title", "n", "rmse",
                  true,    true,    "",  "plot 'data.csv' using \"n\":\"rmse\" with lines"};
  plot.x_values = {1.0, 4.0};
  plot.y_values = {0.0, 0.0};
  mcrt::write_plot(dir, plot);  // would throw on gnuplot's "all points y value undefined"
  const std::string text = mcrt::testing::read_text(dir / "zeros.gp");
  EXPECT_NE(text.find("set logscale x"), std::string::npos);
  EXPECT_EQ(text.find("set logscale y"), std::string::npos);
  EXPECT_EQ(mcrt::image_file_problem(dir / "zeros.png"), "");
}

}  // namespace
