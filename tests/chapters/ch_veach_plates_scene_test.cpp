// --scene veach-plates as a student runs it: chapters 05 to 08 list it in --help and render it
// in a tiny run (glossy plates lit, every value finite, the open background black); chapter
// 05's two engines write the same bytes on it and ignore --albedo there, as on every scene but
// the furnace; chapters 01 and 04, whose estimators see only diffuse materials, refuse it with
// exit 2 and one line naming --scene.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "chapters/run_program.hpp"
#include "io/image_file.hpp"

using namespace mcrt::testing;

namespace {

// A program, its tiny flags on veach-plates, and the images it writes of the scene.
struct GlossyRun {
  std::string program;
  std::string flags;
  std::vector<std::string> images;
  bool has_reference_cache = false;  // chapter 05: its reference is cached under --reference-dir
};

const std::vector<GlossyRun> k_runs{
    {"ch05_path_tracer",
     "--width 24 --height 18 --spp 1,4 --depth 3 --reference-spp 4",
     {"spp_0001.pfm", "spp_0004.pfm"},
     true},
    {"ch06_russian_roulette",
     "--width 16 --height 12 --spp 2 --depth 4 --paths 4000 --q 0.7,0.9",
     {"depth_cut.pfm", "roulette.pfm"}},
    {"ch07_importance_sampling",
     "--width 24 --height 18 --spp 4 --depth 3 --reference-spp 8",
     {"uniform.pfm", "cosine.pfm", "reference.pfm"}},
    // chapter 08: NEE and MIS of the chosen scene (its shoot-out keeps its own scenes)
    {"ch08_next_event_estimation",
     "--width 24 --height 18 --spp 4 --reference-spp 8 --ray-budgets 8 --plates-spp 1",
     {"nee.pfm", "mis.pfm"},
     true},
};

TEST(VeachPlatesChapterTest, HelpOfChapters05To08ListsTheScene) {
  for (const GlossyRun& r : k_runs) {
    const ProgramRun help = run_program(r.program, "--help");
    EXPECT_EQ(help.exit_code, 0) << r.program;
    EXPECT_NE(help.out.find("veach-plates"), std::string::npos) << r.program << "\n" << help.out;
  }
}

// Each run takes well under a second at these sizes (a few thousand paths); the lit plates
// show as pixels brighter than the background, which is exactly 0 where rays leave.
TEST(VeachPlatesChapterTest, Chapters05To08RenderItInATinyRun) {
  for (const GlossyRun& r : k_runs) {
    SCOPED_TRACE(r.program);
    const auto dir = fresh_dir(r.program + "_veach_plates");
    const std::string cache =
        r.has_reference_cache ? " --reference-dir " + (dir / "reference").string() : "";
    const ProgramRun run = run_program(r.program, "--scene veach-plates " + r.flags + cache +
                                                      " --quiet --out " + (dir / "out").string());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(read_json(dir / "out" / "summary.json")["flags"]["scene"], "veach-plates");
    for (const std::string& name : r.images) {
      const mcrt::Image image = mcrt::read_pfm(dir / "out" / name);
      int lit = 0, black = 0;
      for (const mcrt::Color& c : image.pixels) {
        ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) << name;
        lit += c.r > 0.0;
        black += c.r == 0.0;
      }
      EXPECT_GT(lit, 0) << name;    // some plate or light is seen and lit
      EXPECT_GT(black, 0) << name;  // and the sky above the lights is empty
    }
  }
}

// The four-lane engine weighs glossy lanes one at a time: still the loop's image, byte for
// byte. --albedo shapes the furnace only, so on veach-plates it changes nothing.
TEST(VeachPlatesChapterTest, Chapter05EnginesAgreeAndAlbedoIsIgnored) {
  const auto loop = fresh_dir("ch05_veach_loop"), lanes = fresh_dir("ch05_veach_lanes"),
             albedo = fresh_dir("ch05_veach_albedo");
  const std::string flags =
      "--scene veach-plates --width 21 --height 13 --spp 1,3 --depth 5 --seed 9 "
      "--reference-spp 0 --quiet";
  ASSERT_EQ(
      run_program("ch05_path_tracer", flags + " --engine loop --out " + loop.string()).exit_code,
      0);
  ASSERT_EQ(run_program("ch05_path_tracer", flags + " --out " + lanes.string()).exit_code, 0);
  ASSERT_EQ(
      run_program("ch05_path_tracer", flags + " --albedo 0.3 --out " + albedo.string()).exit_code,
      0);
  for (const char* name : {"spp_0001.pfm", "spp_0003.pfm", "spp_0003.png"}) {
    EXPECT_EQ(read_text(loop / name), read_text(lanes / name)) << name;
    EXPECT_EQ(read_text(albedo / name), read_text(lanes / name)) << name;
  }
}

TEST(VeachPlatesChapterTest, DiffuseOnlyChaptersRefuseIt) {
  for (const char* program : {"ch01_ray_tracing", "ch04_recursive_nk"}) {
    SCOPED_TRACE(program);
    expect_refused(program, BadInput{"--scene veach-plates", "--scene"});
  }
}

}  // namespace
