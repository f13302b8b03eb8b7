// The report pages: a lesson's index.html shows what it made in the order it made
// it, safely escaped and with nothing fetched from elsewhere; out/index.html lists
// every lesson whose record is present, and two lessons finishing together are both
// listed.
#include "gi/report/report_page.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>
#include <vector>

#include "../support/files.hpp"
#include "../support/process.hpp"
#include "gi/core/atomic_file.hpp"
#include "gi/core/platform/process.hpp"
#include "gi/core/platform/program.hpp"
#include "gi/report/lessons_index.hpp"
#include "gi/report/outputs.hpp"
#include "gi/report/page_assets.hpp"
#include "gi/report/run_process.hpp"
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
  const std::string page = gi::report_page({"11_progressive", "Shooting.", "complete", {"./11_progressive"}, true, {}, {}},
                                           {text("first line"), text("second line"), table(), picture(), chart,
                                            text("last line"), viewer, script});
  // Consecutive lines are one <pre> block, as on the terminal.
  const std::size_t first = at(page, "<pre>first line\nsecond line\n</pre>");
  const std::size_t tab = at(page, "<table>");
  // A 64-pixel picture is shown five times as wide, pixel for pixel.
  const std::size_t pic = at(page, "<img src=\"box.png\" alt=\"the box\" width=\"320\" height=\"240\">");
  const std::size_t svg = at(page, "<img src=\"error.svg\"");
  const std::size_t last = at(page, "<pre>last line\n</pre>");
  const std::size_t view = at(page, "<a href=\"viewer.html\">Open the interactive viewer</a>");
  EXPECT_TRUE(first < tab && tab < pic && pic < svg && svg < last && last < view);
  // The viewer is also one click from the top of the page.
  EXPECT_LT(at(page, "<a class=\"viewer-link\" href=\"viewer.html\">"), first);
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

// The top of the page says what the lesson shows, from its doc, and links the doc and
// the lab from where the page is.
TEST(ReportPage, OpensWithWhatTheLessonShowsAndLinksItsChapterAndLab) {
  gi::LessonGuide guide{"07_x", "07 — The hemicube", "docs/07_x.md", "exercises/lab07/README.md",
                        "A *cube* of `cells` and [a link](other.md) & more."};
  const gi::RunSummary run{"07_x", "unused", "complete", {"./07_x"}, true, gi::source_file("out/07_x"), guide};
  const std::string page = gi::report_page(run, {text("line")});
  at(page, "<h1>07 — The hemicube</h1>");
  at(page, "<h2>What this shows</h2>\n<p>A <em>cube</em> of <code>cells</code> and a link &amp; more.</p>");
  at(page, "<a class=\"doc\" href=\"../../docs/07_x.md\">Read the chapter: docs/07_x.md</a>");
  at(page, "<a class=\"lab\" href=\"../../exercises/lab07/README.md\">The lab: exercises/lab07/README.md</a>");
  EXPECT_EQ(page.find("unused"), std::string::npos) << "the doc's opening stands in for the summary";
  // Without a lab, no lab link.
  guide.lab.clear();
  EXPECT_EQ(gi::report_page({"07_x", "", "complete", {}, false, ".", guide}, {}).find("class=\"lab\""),
            std::string::npos);
}

// Pictures made one after another sit side by side in one gallery; a false-colour
// one carries its colour bar: the ramp, the values at its ends and between, and the
// quantity with its unit.
TEST(ReportPage, PicturesSideBySideAndFalseColourOverItsBar) {
  gi::Output heat = output(gi::OutputKind::Diagram, "rays per pixel", "heat.png");
  heat.width = 200, heat.height = 100;
  heat.colour_scale = gi::ColourScale{0, 94, "eye rays per pixel"};
  gi::Output matrix = output(gi::OutputKind::Diagram, "F", "matrix.png");
  matrix.width = matrix.height = 728;
  matrix.colour_scale = gi::ColourScale{1e-6, 0.1, "form factor F_ij", true};
  gi::Output strip = output(gi::OutputKind::Diagram, "a strip", "strip.png");
  strip.width = 1400, strip.height = 128;
  const std::string page = gi::report_page({"x", "", "complete", {}, false, {}, {}}, {picture(), heat, matrix, text("then"), strip});
  const std::size_t gallery = at(page, "<div class=\"gallery\">");
  EXPECT_LT(gallery, at(page, "box.png"));
  EXPECT_LT(at(page, "matrix.png"), at(page, "</div>\n<pre>then"));
  // The heat map is shown at up to twice its width, its bar as wide as it.
  at(page, "<figure class=\"false-colour\" style=\"max-width: 400px\"><img src=\"heat.png\"");
  at(page, "width=\"400\" height=\"200\">\n<div class=\"colour-bar\" title=");
  at(page, "linear-gradient(to right, rgb(0 0 0), rgb(0 0 255), rgb(0 255 0), rgb(255 255 0), rgb(255 0 0))");
  for (const char* tick : {">0</span>", ">20</span>", ">40</span>", ">60</span>", ">94</span>"})
    at(page, tick);
  EXPECT_EQ(page.find(">80</span>"), std::string::npos) << "a value this close to the end would crowd it";
  at(page, "<div class=\"quantity\">eye rays per pixel</div>");
  // The log scale's ticks are its decades.
  for (const char* tick : {">10<sup>-6</sup>", ">10<sup>-4</sup>", ">10<sup>-1</sup>"}) at(page, tick);
  at(page, "form factor F_ij (log scale)");
  // A strip wider than the page: a row of its own, shown as it is and scaled down by
  // the style sheet; no bar.
  at(page, "<figure class=\"strip\" style=\"max-width: 1400px\"><img src=\"strip.png\" alt=\"a strip\" width=\"1400\" height=\"128\">");
  std::size_t bars = 0;
  for (std::size_t p = page.find("class=\"colour-bar\""); p != std::string::npos; p = page.find("class=\"colour-bar\"", p + 1))
    ++bars;
  EXPECT_EQ(bars, 2u);
}

TEST(ReportPage, ShownWidthEnlargesSmallPicturesByWholeFactors) {
  EXPECT_EQ(gi::shown_width(128), 384);
  EXPECT_EQ(gi::shown_width(16), 320);
  EXPECT_EQ(gi::shown_width(320), 320);
  EXPECT_EQ(gi::shown_width(640), 640);
  EXPECT_EQ(gi::shown_width(2000), 2000);  // the style sheet fits it to the page
  EXPECT_EQ(gi::shown_width(0), 0);
}

TEST(ReportPage, IsStaticAndEscapesWhatItQuotes) {
  const std::string page = gi::report_page(
      {"01_x", "A <b>bold</b> summary.", "failed: 01_x: error: <disk full>", {"./01_x", "--out", "my out", "--note", "it's"}, false, {}, {}},
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
  at(page, "<td class=\"failed\">outputs.json is not valid JSON</td>");
  at(page, "<td class=\"complete\">complete</td>");
  EXPECT_EQ(page.find("11_no_record"), std::string::npos);
  // A lesson with its page is linked; these have none.
  EXPECT_EQ(page.find("href=\"08_a/index.html\""), std::string::npos);
  std::ofstream(out / "08_a" / "index.html") << "page";
  gi::update_lessons_index(out);
  at(gi_test::file_text(out / "index.html"), "<a href=\"08_a/index.html\">08_a</a>");
}

// Where the book has made a chapter's page beside the lesson's (docs/book/make_book.py),
// the lesson's page and the index link it; elsewhere they link the Markdown, never a
// page that is not there.
TEST(ReportPage, LinksTheChapterPageWhereTheBookMadeOne) {
  const fs::path out = scratch("book");
  const gi::LessonGuide guide = gi::read_guide(gi::doc_openings().front().contents, gi::doc_openings().front().name);
  const fs::path folder = out / guide.lesson;
  fs::create_directories(folder);
  const gi::RunSummary run{guide.lesson, "", "complete", {}, true, folder, guide};
  at(gi::report_page(run, {}), "<a class=\"doc\" href=\"" + gi::source_link(folder, guide.doc) + "\">");
  EXPECT_EQ(gi::lessons_index_page(out).find(guide.lesson + "/chapter.html"), std::string::npos);
  EXPECT_EQ(gi::lessons_index_page(out).find("book/index.html"), std::string::npos);
  std::ofstream(folder / "chapter.html") << "page";
  fs::create_directories(out / "book");
  std::ofstream(out / "book" / "index.html") << "front page";
  at(gi::report_page(run, {}), "<a class=\"doc\" href=\"chapter.html\">Read the chapter: " + guide.doc + "</a>");
  const std::string index = gi::lessons_index_page(out);
  at(index, "<a class=\"doc\" href=\"" + guide.lesson + "/chapter.html\">");
  at(index, "href=\"book/index.html\"");
}

// Where the WebAssembly build has made the lesson's live page (docs/live/make_live.py),
// the lesson's page links it, and the index links the list of live pages; elsewhere
// neither is named.
TEST(ReportPage, LinksTheLivePageWhereTheWebAssemblyBuildMadeOne) {
  const fs::path out = scratch("live");
  const gi::LessonGuide guide = gi::read_guide(gi::doc_openings().front().contents, gi::doc_openings().front().name);
  const fs::path folder = out / guide.lesson;
  fs::create_directories(folder);
  const gi::RunSummary run{guide.lesson, "", "complete", {}, true, folder, guide};
  EXPECT_EQ(gi::report_page(run, {}).find("live.html"), std::string::npos);
  EXPECT_EQ(gi::lessons_index_page(out).find("live/index.html"), std::string::npos);
  std::ofstream(folder / "live.html") << "page";
  fs::create_directories(out / "live");
  std::ofstream(out / "live" / "index.html") << "list";
  at(gi::report_page(run, {}), "<a class=\"live-link\" href=\"live.html\">Run it in the browser</a>");
  at(gi::lessons_index_page(out), "<a class=\"live\" href=\"live/index.html\">");
}

// The index is the course's table of contents: every lesson with a doc has its row,
// its title, the first sentence of what it shows and links to its chapter and lab,
// whether or not it has run.
TEST(LessonsIndex, ListsEveryLessonOfTheCourseWithItsChapterAndLab) {
  const fs::path out = scratch("contents");
  record(out, "01_rays", "complete");
  std::ofstream(out / "01_rays" / "index.html") << "page";
  const std::string page = gi::lessons_index_page(out);
  for (const gi::PageAsset& doc : gi::doc_openings()) {
    const gi::LessonGuide guide = gi::read_guide(doc.contents, doc.name);
    at(page, gi::html_escape(guide.title));
    at(page, gi::html_escape(gi::first_sentence(guide.shows)));
    at(page, "href=\"" + gi::source_link(out, guide.doc) + "\"");
    if (!guide.lab.empty()) at(page, "href=\"" + gi::source_link(out, guide.lab) + "\"");
  }
  EXPECT_GE(gi::doc_openings().size(), 16u);
  const auto rays = gi::lesson_guide("01_rays");
  ASSERT_TRUE(rays);
  at(page, "<a href=\"01_rays/index.html\">" + gi::html_escape(rays->title) + "</a>");
  at(page, "<td class=\"pending\">not run yet</td>");
}

// A run killed with -9 leaves its record saying "running": the index shows it as
// running while its process lives and as killed once it is gone, never as complete.
TEST(LessonsIndex, ARunWhoseProcessIsGoneIsShownKilled) {
  const fs::path out = scratch("killed");
  const auto running = [&](const std::string& name, const gi::RunProcess& process) {
    gi::write_atomically(out / name / "outputs.json", [&](std::ostream& o) {
      o << gi::outputs_json(name, {"./" + name}, "running", {}, process);
    });
  };
  running("20_alive", gi::this_process());
  // A process that has ended: a child that exits at once, waited for.
  gi::RunProcess dead;
  {
    gi::platform::StartedProgram child(gi_test::exits_at_once());
    dead.id = static_cast<long>(child.id());
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    child.kill();
  }
  running("21_dead", dead);
  // Our own id with another start: the id of a killed run, given to a new process.
  running("22_reused", {gi::this_process().id, gi::this_process().started + "0"});
  const std::string page = gi::lessons_index_page(out);
  const std::size_t alive = at(page, ">20_alive</td>"), gone = at(page, ">21_dead</td>"), reused = at(page, ">22_reused</td>");
  EXPECT_NE(page.find("<td class=\"pending\">running</td>", alive), std::string::npos);
  EXPECT_LT(page.find("<td class=\"failed\">killed before it finished: run it again</td>", gone), reused);
  EXPECT_NE(page.find("<td class=\"failed\">killed before it finished: run it again</td>", reused), std::string::npos);
  EXPECT_EQ(page.find(">complete<"), std::string::npos);
}

TEST(RunProcess, ThisOneIsRunningAndHasAStamp) {
  const gi::RunProcess self = gi::this_process();
  EXPECT_EQ(self.id, gi::platform::current_process_id());
#if defined(__linux__) || defined(_WIN32)
  EXPECT_FALSE(self.started.empty()) << "Linux gives each process a start time in /proc, Windows a creation time";
#endif
  EXPECT_TRUE(gi::still_running(self));
  EXPECT_FALSE(gi::still_running({}));
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
