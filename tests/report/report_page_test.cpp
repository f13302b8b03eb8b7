// The report pages: a lesson's index.html shows what it made in the order it made
// it, safely escaped and with nothing fetched from elsewhere; out/index.html lists
// every lesson whose record is present, and two lessons finishing together are both
// listed.
#include "gi/report/report_page.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>
#include <vector>

#include "../support/files.hpp"
#include "gi/core/atomic_file.hpp"
#include "gi/report/lessons_index.hpp"
#include "gi/report/outputs.hpp"
#include "gi/report/page_assets.hpp"
#include "gi/report/table.hpp"

namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path folder = fs::path(testing::TempDir()) / "gi_report_page_test" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

gi::Output output(gi::OutputKind kind, const std::string& caption, const std::string& file = "") {
  gi::Output o;
  o.kind = kind, o.caption = caption, o.file = file;
  return o;
}

gi::Output text(const std::string& line) { return output(gi::OutputKind::Text, line); }

gi::Output table() {
  gi::Table t("Errors <by> method", {{"method", 0}, {"error", 3}});
  t.add_row({std::string("Jacobi"), 0.125});
  t.add_row({std::string("Gauss & Seidel"), 0.0625});
  gi::Output o = output(gi::OutputKind::Table, t.title(), "errors.csv");
  o.table = t.text();
  return o;
}

gi::Output picture() {
  gi::Output o = output(gi::OutputKind::Picture, "the box", "box.png");
  o.linear = "box.pfm";
  o.exposure = 1.5;
  o.view.width = 64, o.view.height = 48;
  o.view.pixel_samples = "4 jittered samples";
  return o;
}

// Where `needle` starts in `page`; fails the test when it is not there.
std::size_t at(const std::string& page, const std::string& needle) {
  const std::size_t where = page.find(needle);
  EXPECT_NE(where, std::string::npos) << "missing: " << needle;
  return where;
}

// A lesson's record, as Lesson writes it, in folder/name/outputs.json.
void record(const fs::path& folder, const std::string& name, const std::string& status) {
  gi::write_atomically(folder / name / "outputs.json", [&](std::ostream& out) {
    out << gi::outputs_json(name, {"./" + name, "--width", "8"}, status, {text("hello")});
  });
}

}  // namespace

TEST(ReportPage, ShowsEveryOutputInTheOrderItWasMade) {
  const gi::Output chart = output(gi::OutputKind::Chart, "error against time", "error.svg");
  const gi::Output viewer = output(gi::OutputKind::Viewer, "shots replayed", "viewer.html");
  const gi::Output script = output(gi::OutputKind::Page, "copied", "viewer_main.js");
  const std::string page = gi::report_page({"11_progressive", "Shooting.", "complete", {"./11_progressive"}, true},
                                           {text("first line"), text("second line"), table(), picture(), chart,
                                            text("last line"), viewer, script});
  // Consecutive lines are one <pre> block, as on the terminal.
  const std::size_t first = at(page, "<pre>first line\nsecond line\n</pre>");
  const std::size_t tab = at(page, "<table>");
  const std::size_t pic = at(page, "<img src=\"box.png\" alt=\"the box\" width=\"64\" height=\"48\">");
  const std::size_t svg = at(page, "<img src=\"error.svg\"");
  const std::size_t last = at(page, "<pre>last line\n</pre>");
  const std::size_t view = at(page, "<a href=\"viewer.html\">Open the interactive viewer</a>");
  EXPECT_TRUE(first < tab && tab < pic && pic < svg && svg < last && last < view);
  // The table's cells as the terminal printed them, numbers aligned right, text escaped.
  at(page, "<caption>Errors &lt;by&gt; method");
  at(page, "<tr><td>Gauss &amp; Seidel</td><td class=\"number\">0.062</td></tr>");
  at(page, "<th class=\"number\">error</th>");
  // The picture's caption says how it was made and where its linear radiance is.
  at(page, "exposure 1.5; 64 &times; 48, 4 jittered samples");
  at(page, "<a href=\"box.pfm\">box.pfm</a>");
  EXPECT_EQ(page.find("viewer_main.js"), std::string::npos) << "a viewer's script is not news on the page";
  at(page, "<a href=\"../index.html\">all lessons</a>");
  at(page, "<p class=\"status complete\">complete</p>");
}

TEST(ReportPage, IsStaticAndEscapesWhatItQuotes) {
  const std::string page = gi::report_page(
      {"01_x", "A <b>bold</b> summary.", "failed: 01_x: error: <disk full>", {"./01_x", "--out", "my out", "--note", "it's"}},
      {text("<script>alert(1)</script>")});
  EXPECT_EQ(page.find("<script"), std::string::npos) << "the page runs no script";
  EXPECT_EQ(page.find("http"), std::string::npos) << "the page fetches nothing";
  EXPECT_EQ(page.find("all lessons"), std::string::npos) << "no index above a folder given by --out";
  at(page, "&lt;script&gt;alert(1)&lt;/script&gt;");
  at(page, "A &lt;b&gt;bold&lt;/b&gt; summary.");
  at(page, "<p class=\"status failed\">failed: 01_x: error: &lt;disk full&gt;</p>");
  at(page, "<code>./01_x --out &#39;my out&#39; --note &#39;it&#39;\\&#39;&#39;s&#39;</code>");
  // The style sheet is inline: the page is one file.
  at(page, std::string(gi::page_asset("report.css")));
}

TEST(ReportPage, QuotingHelpers) {
  EXPECT_EQ(gi::html_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(gi::url_path("sub/a b#1?.png"), "sub/a%20b%231%3F.png");
  EXPECT_EQ(gi::url_path("caf\xc3\xa9.png"), "caf%C3%A9.png");
  EXPECT_EQ(gi::shell_command({"./08", "--exposure", "1.5", "--out", "/tmp/x y", ""}), "./08 --exposure 1.5 --out '/tmp/x y' ''");
  EXPECT_EQ(gi::shell_command({"a'b"}), "'a'\\''b'");
}

TEST(LessonsIndex, ListsEveryRecordInFolderOrderAndSaysWhichCannotBeRead) {
  const fs::path out = scratch("index");
  record(out, "09_b", "failed: 09_b: error: diverged");
  record(out, "08_a", "complete");
  fs::create_directories(out / "10_c");
  std::ofstream(out / "10_c" / "outputs.json") << "{ not json";
  fs::create_directories(out / "11_no_record");  // not a lesson that has run
  gi::update_lessons_index(out);
  const std::string page = gi_test::file_text(out / "index.html");
  const std::size_t a = at(page, ">08_a</td>"), b = at(page, ">09_b</td>"), c = at(page, ">10_c</td>");
  EXPECT_TRUE(a < b && b < c);
  at(page, "<td class=\"failed\">failed: 09_b: error: diverged</td>");
  at(page, "<td class=\"failed\" colspan=\"4\">outputs.json is not valid JSON</td>");
  at(page, "<code>./08_a --width 8</code>");
  EXPECT_EQ(page.find("11_no_record"), std::string::npos);
  // A lesson with its page is linked; these have none.
  EXPECT_EQ(page.find("href=\"08_a/index.html\""), std::string::npos);
  std::ofstream(out / "08_a" / "index.html") << "page";
  gi::update_lessons_index(out);
  at(gi_test::file_text(out / "index.html"), "<a href=\"08_a/index.html\">08_a</a>");
}

TEST(LessonsIndex, LessonsFinishingTogetherAreAllListed) {
  const fs::path out = scratch("together");
  constexpr int lessons = 8;
  for (int round = 0; round < 5; ++round) {
    fs::remove_all(out);
    fs::create_directories(out);
    std::vector<std::thread> threads;
    for (int k = 0; k < lessons; ++k)
      threads.emplace_back([&out, k] {
        const std::string name = "lesson_" + std::to_string(k);
        record(out, name, "complete");
        gi::update_lessons_index(out);
      });
    for (std::thread& t : threads) t.join();
    const std::string page = gi_test::file_text(out / "index.html");
    for (int k = 0; k < lessons; ++k)
      EXPECT_NE(page.find(">lesson_" + std::to_string(k) + "</td>"), std::string::npos) << "round " << round << ": lost lesson_" << k;
    for (const std::string& name : gi_test::files_in(out))
      EXPECT_FALSE(gi::is_partial_file(name)) << name;
  }
}

TEST(LessonsIndex, AnUnwritableFolderIsAWriteError) {
  EXPECT_THROW(gi::update_lessons_index(scratch("gone") / "nowhere"), gi::WriteError);
}
