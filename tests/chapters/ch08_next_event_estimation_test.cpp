// Chapter 08 as a student runs it: a tiny run and its outputs (images, the reference cache, the
// shoot-out's table and figures), the cache reused and rebuilt, reproducibility across thread
// counts, and bad input.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "io/image_file.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch08_next_event_estimation";
const std::string k_tiny = "--width 12 --height 9 --spp 2 --reference-spp 4 --ray-budgets 8,16 ";

TEST(Ch08Test, TinyRunWritesImagesReferencesAndTheShootout) {
  const auto dir = fresh_dir("ch08_smoke");
  const auto refs = dir.parent_path() / "ch08_smoke_cache";
  std::filesystem::remove_all(refs);
  const ProgramRun run = run_program(k_program, k_tiny + "--threads 2 --reference-dir " +
                                                    refs.string() + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;

  for (const char* stem : {"nee", "mis"}) {
    const mcrt::Image image = mcrt::read_pfm(dir / (std::string(stem) + ".pfm"));
    EXPECT_EQ(image.width, 12);
    EXPECT_EQ(image.height, 9);
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(stem) + ".png")));
  }
  // One cached reference per scene of the shoot-out but the furnace (a closed form).
  for (const char* stem : {"cornell_ls0.1_12x9", "cornell_ls1_12x9", "cornell_ls3_12x9",
                           "cornell-spheres_ls1_12x9", "smallpt_ls1_12x9"}) {
    EXPECT_TRUE(std::filesystem::exists(refs / (std::string(stem) + ".pfm"))) << stem;
    const auto info = read_json(refs / (std::string(stem) + ".json"));
    EXPECT_EQ(info["spp"], 4);
    EXPECT_EQ(info["seed"], 1);
    EXPECT_GT(info["seconds"].get<double>(), 0.0);
    EXPECT_GE(info["standard_error_rms"].get<double>(), 0.0);
  }
  const CsvFile csv(dir / "efficiency.csv");
  const std::vector<std::string>& header = csv.header();
  for (const char* column :
       {"scene", "light_scale", "estimator", "budget_rays_per_pixel", "spp", "rays_per_pixel",
        "rel_mse", "efficiency", "efficiency_vs_uniform", "mean", "mean_ci_low", "mean_ci_high"})
    EXPECT_NE(std::find(header.begin(), header.end(), column), header.end()) << column;
  for (const char* column : {"seconds", "rays_per_second"})  // timings.json's, not the CSV's
    EXPECT_EQ(std::find(header.begin(), header.end(), column), header.end()) << column;
  EXPECT_EQ(csv.size(), 6u * 6u * 2u);  // scenes x estimators x budgets
  for (std::size_t i = 0; i < csv.size(); ++i) {
    EXPECT_GE(csv.number(i, "spp"), 1.0);
    // photographed at the first pass that reaches the budget: past it by less than one pass
    // (at most 65 rays a pixel: the depth-64 baselines)
    EXPECT_GE(csv.number(i, "rays_per_pixel"), csv.number(i, "budget_rays_per_pixel"));
    EXPECT_LT(csv.number(i, "rays_per_pixel"), csv.number(i, "budget_rays_per_pixel") + 66.0);
    if (csv.number(i, "rel_mse") == 0.0) continue;  // exact (cosine in the furnace): infinite
    EXPECT_NEAR(csv.number(i, "efficiency"),
                1.0 / (csv.number(i, "rel_mse") * csv.number(i, "rays_per_pixel")),
                1e-5 * csv.number(i, "efficiency"));  // the CSV's 6 significant digits
  }
  EXPECT_EQ(read_json(dir / "timings.json")["shootout"].size(), 72u);
  EXPECT_TRUE(std::filesystem::exists(dir / "contact_sheet.png"));
  for (const char* scene :
       {"furnace", "cornell_x0.1", "cornell_x1", "cornell_x3", "cornell-spheres", "smallpt"})
    EXPECT_TRUE(std::filesystem::exists(dir / fmt::format("relmse_vs_rays_{}.gp", scene))) << scene;
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["scene"], "cornell");
  EXPECT_EQ(summary["shootout"].size(), 72u);

  // A second run reuses the cache; other settings rebuild it.
  const auto pfm = refs / "cornell_ls1_12x9.pfm";
  const auto written = std::filesystem::last_write_time(pfm);
  ASSERT_EQ(run_program(k_program, k_tiny + "--quiet --reference-dir " + refs.string() + " --out " +
                                       dir.string())
                .exit_code,
            0);
  EXPECT_EQ(std::filesystem::last_write_time(pfm), written);
  ASSERT_EQ(run_program(k_program,
                        "--width 12 --height 9 --spp 2 --reference-spp 6 --ray-budgets "
                        "8 --quiet --reference-dir " +
                            refs.string() + " --out " + dir.string())
                .exit_code,
            0);
  EXPECT_EQ(read_json(refs / "cornell_ls1_12x9.json")["spp"], 6);
}

TEST(Ch08Test, SameSeedGivesByteIdenticalImagesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch08_threads1"), two = fresh_dir("ch08_threads2");
  const auto refs1 = one.parent_path() / "ch08_threads1_cache";
  const auto refs2 = one.parent_path() / "ch08_threads2_cache";
  std::filesystem::remove_all(refs1);
  std::filesystem::remove_all(refs2);
  const std::string flags = k_tiny + "--scene cornell-spheres --seed 5 --quiet";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --reference-dir " + refs1.string() +
                                       " --out " + one.string())
                .exit_code,
            0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --reference-dir " + refs2.string() +
                                       " --out " + two.string())
                .exit_code,
            0);
  // every output but timings.json: the shoot-out counts rays, not seconds
  for (const char* file :
       {"nee.pfm", "nee.png", "mis.pfm", "mis.png", "images.csv", "efficiency.csv", "summary.json",
        "contact_sheet.png", "relmse_vs_rays_cornell_x0.1.gp", "relmse_vs_rays_cornell_x0.1.svg"})
    EXPECT_EQ(read_text(one / file), read_text(two / file)) << file;
  EXPECT_EQ(read_text(refs1 / "cornell-spheres_ls1_12x9.pfm"),
            read_text(refs2 / "cornell-spheres_ls1_12x9.pfm"));
  const CsvFile a(one / "images.csv"), b(two / "images.csv");
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.number(i, "rays"), b.number(i, "rays"));
    EXPECT_EQ(a.number(i, "rel_mse"), b.number(i, "rel_mse"));
  }
}

class Ch08BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch08BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch08BadInputTest,
    ::testing::Values(
        BadInput{"--spp 0", "--spp"}, BadInput{"--light-scale 5", "--light-scale"},
        BadInput{"--light-scale 0", "--light-scale"}, BadInput{"--ray-budgets 0", "--ray-budgets"},
        BadInput{"--ray-budgets 1,x", "--ray-budgets"},
        BadInput{"--ray-budgets 1e7", "--ray-budgets"}, BadInput{"--budgets 1", "--budgets"},
        BadInput{"--depth -1", "--depth"}, BadInput{"--reference-spp 1", "--reference-spp"},
        BadInput{"--scene moon", "--scene"},
        BadInput{"--width 8192 --height 4096 --reference-spp 100000", "--reference-spp"}),
    bad_input_name);

}  // namespace
