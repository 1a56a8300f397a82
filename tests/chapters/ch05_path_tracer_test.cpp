// Chapter 05 as a student runs it: a tiny run and its outputs, reproducibility across thread
// counts, and bad input.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/run_folder.hpp"
#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "io/image_file.hpp"
#include "io/image_file_decoding.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch05_path_tracer";

TEST(Ch05Test, TinyRunWritesImagesErrorTableAndSummary) {
  const auto dir = fresh_dir("ch05_smoke");
  const ProgramRun run =
      run_program(k_program,
                  "--scene cornell-spheres --width 24 --height 18 --spp 1,4,16 --depth 4 "
                  "--threads 2 --out " +
                      dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("fitted slope"), std::string::npos) << run.out;

  const CsvFile csv(dir / "rmse_vs_spp.csv");
  EXPECT_EQ(csv.header(), (std::vector<std::string>{"spp", "rmse", "rmse_vs_reference", "seconds",
                                                    "rays", "rays_per_second"}));
  ASSERT_EQ(csv.size(), 3u);
  const std::vector<double> rmse = csv.numbers("rmse");
  const int pixels = 24 * 18, spp[] = {1, 4, 16};
  for (std::size_t i = 0; i < csv.size(); ++i) {
    EXPECT_EQ(csv.number(i, "spp"), spp[i]);
    EXPECT_GT(rmse[i], 0.0);
    // Two renders of spp samples per pixel, each path 1 to depth + 1 = 5 closest-hit queries.
    const double rays = csv.number(i, "rays");
    EXPECT_GE(rays, 2.0 * pixels * spp[i]);
    EXPECT_LE(rays, 2.0 * pixels * spp[i] * 5);
    EXPECT_GT(csv.number(i, "rays_per_second"), 0.0);
  }
  // 16 times the samples: a quarter of the error, here within a factor 2 either way (432
  // pixels give the RMS error to about 10% at these spp; the factor is a coarse bound for a
  // smoke run, the law itself is tested in tests/render/path_tracer_checks.cpp).
  EXPECT_GT(rmse[2], rmse[0] / 8.0);
  EXPECT_LT(rmse[2], rmse[0] / 2.0);

  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["non_finite_samples"], 0);
  EXPECT_EQ(summary["scene"], "cornell-spheres");
  EXPECT_EQ(summary["depth"], 4);
  // The rays of every render: the main pairs, the bias study's (depths 0, 1, 2) and
  // smallpt.png's (64 spp, each path 1 to depth + 1 = 5 closest-hit queries).
  const double smallpt_rays = summary["smallpt_rays"].get<double>();
  EXPECT_GE(smallpt_rays, 64.0 * pixels);
  EXPECT_LE(smallpt_rays, 64.0 * pixels * 5);
  double rays = smallpt_rays;
  for (double r : csv.numbers("rays")) rays += r;
  for (double r : CsvFile(dir / "depth_bias.csv").numbers("rays")) rays += r;
  EXPECT_EQ(summary["rays"].get<double>(), rays);
  EXPECT_EQ(summary["rmse_vs_spp"].size(), 3u);
  EXPECT_GT(read_json(dir / "timings.json")["rays_per_second"].get<double>(), 0.0);
  const double slope = summary["rmse_slope"].get<double>();
  EXPECT_LT(slope, -0.2);  // coarse, as above: -1/2 within the noise of 432 pixels
  EXPECT_GT(slope, -0.8);
  EXPECT_EQ(summary["flags"]["spp"], "1,4,16");

  for (const char* name : {"spp_0001", "spp_0004", "spp_0016"}) {
    const mcrt::Image image = mcrt::read_pfm(dir / (std::string(name) + ".pfm"));
    EXPECT_EQ(image.width, 24);
    EXPECT_EQ(image.height, 18);
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(name) + ".png")));
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "noise_strip.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "rmse_vs_spp.gp"));
  // smallpt.png as a student sees it (decoded by stb_image): the run's size, and lit: its mean
  // code value far above black (the lit walls give codes of 100 and more; 10 is a floor that
  // a black or almost black render fails).
  const DecodedPng smallpt = decode_png(read_text(dir / "smallpt.png"));
  EXPECT_EQ(smallpt.width, 24);
  EXPECT_EQ(smallpt.height, 18);
  double code_sum = 0.0;
  for (const std::uint8_t code : smallpt.bytes) code_sum += code;
  EXPECT_GT(code_sum / static_cast<double>(smallpt.bytes.size()), 10.0);
  for (const auto& entry : std::filesystem::directory_iterator(dir))  // the manifest aside
    if (entry.path().filename() != mcrt::k_manifest_name) {
      EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary file left";
    }
}

// The error against the reference sees what the two-render estimate cannot: the light a depth
// cut drops. At --depth 0 only the lamp seen directly is left, so the image misses the whole
// reflected light, and at 256 spp that bias dominates the error against the reference.
TEST(Ch05Test, ErrorAgainstTheReferenceShowsTheDepthCutsBias) {
  const auto dir = fresh_dir("ch05_reference");
  const std::string reference_dir = (dir.parent_path() / "ch05_cache").string();
  const ProgramRun run =
      run_program(k_program,
                  "--width 32 --height 24 --spp 4,256 --depth 0 --reference-spp 64 --quiet "
                  "--reference-dir " +
                      reference_dir + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CsvFile csv(dir / "rmse_vs_spp.csv");
  ASSERT_EQ(csv.size(), 2u);
  // The two-render error falls 8x from 4 to 256 spp; the error against the reference keeps
  // the bias (about 0.09 RMS here against a noise of 0.02): 2x is far from both.
  EXPECT_GT(csv.number(1, "rmse_vs_reference"), 2.0 * csv.number(1, "rmse"));
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["reference"]["settings"]["max_depth"], -1);
  EXPECT_EQ(summary["reference"]["spp"], 64);
  // The reflected light of the Cornell box is about as bright as what the lamp adds directly
  // over the image (0.117 against 0.064 at 64x48); 1.3x leaves room for a tiny image's noise.
  EXPECT_GT(summary["mean_radiance_reference"].get<double>(),
            1.3 * summary["mean_radiance"].get<double>());
  EXPECT_GT(summary["depth_cut_bias_rms"].get<double>(), csv.number(1, "rmse"));
  EXPECT_TRUE(
      std::filesystem::exists(std::filesystem::path(reference_dir) / "cornell_ls1_32x24.pfm"));
  // The bias study (--bias-depths 0,1,2) renders the same spp at each depth: at depth 0 its
  // error against the reference levels off at the bias while its two-render error falls
  // (the main run's depth 0 above, so the same 2x margin), and each depth misses less light
  // than the one before (its mean is higher, so its bias is lower; the margin of 1.3x at
  // depth 0 above leaves the gap to depth 2 far above a tiny image's noise).
  const CsvFile bias(dir / "depth_bias.csv");
  ASSERT_EQ(bias.size(), 6u);  // 3 depths x 2 spp
  EXPECT_EQ(bias.number(0, "depth"), 0);
  EXPECT_EQ(bias.number(5, "depth"), 2);
  EXPECT_EQ(bias.number(1, "rmse_vs_reference"), csv.number(1, "rmse_vs_reference"));
  EXPECT_GT(bias.number(1, "rmse_vs_reference"), 2.0 * bias.number(1, "rmse"));
  EXPECT_LT(bias.number(5, "rmse_vs_reference"), bias.number(1, "rmse_vs_reference"));
  EXPECT_EQ(summary["bias_depths"], (std::vector<int>{0, 1, 2}));

  // Without a reference the column stays, empty, and so do the summary's fields, as null.
  const auto none = fresh_dir("ch05_no_reference");
  ASSERT_EQ(run_program(k_program, "--width 8 --height 6 --spp 1 --reference-spp 0 --quiet --out " +
                                       none.string())
                .exit_code,
            0);
  EXPECT_EQ(CsvFile(none / "rmse_vs_spp.csv").text(0, "rmse_vs_reference"), "");
  EXPECT_TRUE(read_json(none / "summary.json")["reference"].is_null());
}

TEST(Ch05Test, SameSeedGivesByteIdenticalImagesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch05_threads1"), two = fresh_dir("ch05_threads2");
  const std::string flags = "--width 20 --height 16 --spp 2 --depth 6 --seed 5 --quiet";
  // Each run renders its own reference (a cache folder of its own), so a reference's render
  // seconds reaching summary.json would show here: they belong in timings.json alone.
  const auto cache_one = fresh_dir("ch05_threads1_cache"),
             cache_two = fresh_dir("ch05_threads2_cache");
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --reference-dir " + cache_one.string() +
                                       " --out " + one.string())
                .exit_code,
            0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --reference-dir " + cache_two.string() +
                                       " --out " + two.string())
                .exit_code,
            0);
  EXPECT_TRUE(read_json(one / "timings.json").contains("reference_seconds"));
  EXPECT_EQ(read_text(one / "spp_0002.pfm"), read_text(two / "spp_0002.pfm"));
  EXPECT_EQ(read_text(one / "spp_0002.png"), read_text(two / "spp_0002.png"));
  EXPECT_EQ(read_text(one / "summary.json"), read_text(two / "summary.json"));
  EXPECT_EQ(read_text(one / "rmse_vs_spp.svg"), read_text(two / "rmse_vs_spp.svg"));
  // The bias study's renders at depths 0, 1, 2 (the run has a reference): the same too.
  EXPECT_EQ(read_text(one / "depth_bias.csv"), read_text(two / "depth_bias.csv"));
}

// The lecture's loop and the four-lane engine write the same images, byte for byte, and the
// same table but for the timings.
TEST(Ch05Test, BothEnginesWriteTheSameImages) {
  const auto loop = fresh_dir("ch05_engine_loop"), lanes = fresh_dir("ch05_engine_lanes");
  const std::string flags =
      "--scene cornell --width 21 --height 13 --spp 1,3 --depth 5 --seed 9 --reference-spp 0 --quiet";
  ASSERT_EQ(run_program(k_program, flags + " --engine loop --out " + loop.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --out " + lanes.string()).exit_code, 0);
  for (const char* name : {"spp_0001.pfm", "spp_0003.pfm", "spp_0003.png", "noise_strip.png"})
    EXPECT_EQ(read_text(loop / name), read_text(lanes / name)) << name;
  const CsvFile a(loop / "rmse_vs_spp.csv"), b(lanes / "rmse_vs_spp.csv");
  EXPECT_EQ(a.numbers("rmse"), b.numbers("rmse"));
  EXPECT_EQ(a.numbers("rays"), b.numbers("rays"));
}

// --sampler jittered and sobol render the same bytes with either --engine (the four lanes take
// each sample's points as the loop does) and for any thread count; each differs from the
// independent image, and from the other.
TEST(Ch05Test, SamplersRenderTheSameImageWhateverTheEngineAndThreads) {
  const std::string flags =
      "--scene cornell --width 15 --height 11 --spp 4 --depth 4 --seed 3 --reference-spp 0 --quiet";
  const auto independent = fresh_dir("ch05_sampler_independent");
  ASSERT_EQ(run_program(k_program, flags + " --out " + independent.string()).exit_code, 0);
  std::string previous = read_text(independent / "spp_0004.pfm");
  for (const char* sampler : {"jittered", "sobol"}) {
    const auto lanes = fresh_dir(std::string("ch05_sampler_lanes_") + sampler);
    const auto loop = fresh_dir(std::string("ch05_sampler_loop_") + sampler);
    const std::string with = flags + " --sampler " + sampler;
    ASSERT_EQ(run_program(k_program, with + " --threads 1 --out " + lanes.string()).exit_code, 0);
    ASSERT_EQ(run_program(k_program, with + " --engine loop --threads 2 --out " + loop.string())
                  .exit_code,
              0);
    const std::string image = read_text(lanes / "spp_0004.pfm");
    EXPECT_EQ(image, read_text(loop / "spp_0004.pfm")) << sampler;
    EXPECT_EQ(read_text(lanes / "rmse_vs_spp.csv").size() > 0, true);
    EXPECT_EQ(read_json(lanes / "summary.json")["flags"]["sampler"], sampler);
    EXPECT_NE(image, previous) << sampler;
    previous = image;
  }
}

TEST(Ch05Test, HelpNamesEveryFlag) {
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"--scene", "--width", "--height", "--spp", "--depth", "--seed",
                           "--threads", "--out", "--quiet", "--reference-spp", "--reference-dir",
                           "--engine", "--sampler", "--bias-depths", "--print-flags"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

// --print-flags (every chapter's, from app/cli): the flags a run with these flags records in
// summary.json, printed without running; nothing is written. scripts/make-figures records them
// and the figure-drift test compares them with the program's.
TEST(Ch05Test, PrintFlagsPrintsWhatSummaryRecordsAndRunsNothing) {
  const auto dir = fresh_dir("ch05_print_flags");
  const std::string flags = "--width 8 --height 6 --spp 1,2 --depth 3 --reference-spp 0 --quiet";
  const ProgramRun printed =
      run_program(k_program, flags + " --print-flags --out " + (dir / "none").string());
  ASSERT_EQ(printed.exit_code, 0) << printed.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "none"));
  ASSERT_EQ(run_program(k_program, flags + " --out " + (dir / "run").string()).exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(printed.out), read_json(dir / "run" / "summary.json")["flags"]);
}

class Ch05BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch05BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch05BadInputTest,
    ::testing::Values(BadInput{"--spp 0", "--spp"}, BadInput{"--spp 1,0,4", "--spp"},
                      BadInput{"--spp x", "--spp"}, BadInput{"--depth -1", "--depth"},
                      BadInput{"--scene moon", "--scene"}, BadInput{"--engine simd", "--engine"},
                      BadInput{"--sampler halton", "--sampler"}, BadInput{"--sampler", "--sampler"},
                      BadInput{"--reference-spp -1", "--reference-spp"},
                      BadInput{"--reference-spp 2000000", "--reference-spp"},
                      BadInput{"--smallpt-spp -1", "--smallpt-spp"},
                      BadInput{"--smallpt-spp 70000", "--smallpt-spp"},
                      BadInput{"--width 16384 --height 16384", "--width"},
                      BadInput{"--width 8192 --height 4096 --spp 4096", "--spp"},
                      // Accepted by the albedo check, but its reference's paths would have a
                      // million vertices each (3 + 1 / (1 - a)): refused by the work estimate.
                      BadInput{"--scene furnace --albedo 0.999999 --reference-spp 1024",
                               "--albedo"},
                      BadInput{"--threads 0", "--threads"},
                      // Numbers are read as written: nothing clamped, no hex, finite reals only.
                      BadInput{"--depth 1e3", "--depth"}, BadInput{"--width 0x10", "--width"},
                      BadInput{"--emission nan", "--emission"},
                      BadInput{"--seed 18446744073709551616", "--seed"}),
    bad_input_name);

TEST(Ch05Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, "--width 8 --height 8 --spp 1");
}

}  // namespace
