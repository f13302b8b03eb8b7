// The truth a lesson scores against is checked before any work (render/truth.hpp):
// lessons 14, 15 and 16 stop in one line with status 1, having written nothing, when a
// stored truth is damaged or stale (whole, but made for another scene or other
// settings); lessons 03, 04 and 14 render again a reference they keep in
// their folder when its files are damaged, and say why.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "lesson_run.hpp"
#include "truth_damage.hpp"

namespace {

namespace fs = std::filesystem;
using gi_test::LessonRun;
using gi_test::out_dir;
using gi_test::run;

const fs::path references = fs::path(GI_SOURCE_DIR) / "lessons/references";

struct Lesson {
  std::string name, args;
  bool folder;  // --references takes the folder, --reference the stem
};
// The lessons that score against the Cornell box's stored truth, at small sizes.
const Lesson lessons[] = {{"14_path_tracing", "--width 32 --height 32 --max-spp 2", false},
                          {"15_radiosity_vs_path_tracing", "--size 64 --max-spp 2", false},
                          {"16_two_pass", "--scene cornell --width 32 --height 32", true}};

// Every lesson of `lessons`, given the truth at `copy`, stops before it writes anything,
// with status 1 and one line that says the truth cannot be used and `why`.
void expect_refused(const fs::path& copy, const std::string& why, const std::string& how) {
  for (const Lesson& lesson : lessons) {
    const std::string folder = out_dir("truth_refused");
    fs::remove_all(folder);
    const std::string where = lesson.folder ? "--references " + copy.parent_path().string() : "--reference " + copy.string();
    const LessonRun r = run(lesson.name, lesson.args + " " + where + " --out " + folder);
    EXPECT_EQ(r.status, 1) << lesson.name << ", " << how << ":\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << lesson.name << ", " << how << ":\n" << r.output;
    EXPECT_NE(r.output.find(lesson.name + ": error: the stored truth of cornell cannot be used: "), std::string::npos)
        << lesson.name << ", " << how << ":\n" << r.output;
    EXPECT_NE(r.output.find(why), std::string::npos) << lesson.name << ", " << how << ":\n" << r.output;
    EXPECT_FALSE(fs::exists(folder)) << lesson.name << ", " << how << ": work started before the truth was refused";
  }
}

TEST(StoredTruths, ADamagedOneStopsTheLessonBeforeAnyWork) {
  for (const std::string& how : gi_test::truth_damages) {
    const fs::path copy = fs::path(out_dir("truth_copies")) / "cornell_256x256";
    gi_test::copy_truth(references / "cornell_256x256", copy);
    gi_test::damage_truth(copy, how);
    expect_refused(copy, copy.filename().string(), how);  // the reason varies with the damage; the file is named
  }
}

// A stale truth is whole -- its checksums hold -- but of something else: here made by
// 14_make_reference at the Cornell box's size for the furnace, and for the Cornell box
// itself with two bounces per path, then put where the Cornell box's truth belongs.
// Trusted, it would score every picture against the wrong radiance.
TEST(StoredTruths, AStaleOneIsRefusedBeforeAnyWork) {
  for (const std::string made_as : {"--scene furnace", "--scene cornell --max-depth 2"}) {
    const std::string made_in = out_dir("truth_stale_made");
    fs::remove_all(made_in);  // a truth left by an earlier run would be extended
    const LessonRun made = run("14_make_reference", made_as + " --width 256 --height 256 --batch-spp 2 --out " + made_in);
    ASSERT_EQ(made.status, 0) << made.output;
    const std::string scene = made_as.substr(8, made_as.find(' ', 8) - 8);  // after "--scene "
    const fs::path copy = fs::path(out_dir("truth_stale_copies")) / "cornell_256x256";
    gi_test::copy_truth(fs::path(made_in) / (scene + "_256x256"), copy);
    expect_refused(copy, "cornell_256x256.txt: it was made for another scene or other settings", made_as);
  }
}

// A lesson's own reference, kept in its folder: damaged, it is rendered again (and said
// so), then read back on the next run.
void kept_reference_is_rendered_again(const std::string& lesson, const std::string& args, const std::string& read) {
  const std::string folder = out_dir("kept_" + lesson);
  fs::remove_all(folder);
  const LessonRun first = run(lesson, args + " --out " + folder);
  if (first.status == 3) GTEST_SKIP() << lesson << " stops at an exercise not written yet (a student kit)";
  ASSERT_EQ(first.status, 0) << first.output;
  fs::path stem;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().filename().string().starts_with("reference_") && entry.path().extension() == ".txt")
      stem = entry.path().parent_path() / entry.path().stem();
  ASSERT_FALSE(stem.empty()) << lesson << " kept no reference";
  for (const std::string& how : gi_test::truth_damages) {
    gi_test::damage_truth(stem, how);
    const LessonRun again = run(lesson, args + " --out " + folder);
    ASSERT_EQ(again.status, 0) << lesson << ", " << how << ":\n" << again.output;
    EXPECT_EQ(again.output.find(read), std::string::npos) << lesson << ", " << how << ": a damaged reference was used";
    EXPECT_NE(again.output.find("fails its checksum") + again.output.find("is missing or not"), 2 * std::string::npos)
        << lesson << ", " << how << ": no reason said\n" << again.output;
    EXPECT_NE(run(lesson, args + " --out " + folder).output.find(read), std::string::npos)
        << lesson << ", " << how << ": rendered again, it is read back next time";
  }
}

TEST(KeptReferences, ADamagedOneIsRenderedAgain) {
  kept_reference_is_rendered_again("03_antialiasing", "--width 32 --height 24 --depth 1 --reference-n 6",
                                   "reference: read from the cache");
  kept_reference_is_rendered_again("04_soft_shadows", "--width 32 --height 24 --reference-n 6",
                                   "reference: read from the cache");
  kept_reference_is_rendered_again("14_path_tracing", "--scene soft --width 24 --height 16 --max-spp 2 --reference-spp 16",
                                   "kept by an earlier run");
}

}  // namespace
