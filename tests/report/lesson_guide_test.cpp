// What the report pages say about a lesson comes from the opening of its doc: the
// title, the lab and the paragraph of what it shows, read from the doc itself.
#include "gi/report/lesson_guide.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

namespace {

const char* const opening =
    "# 07 — The hemicube\n"
    "\n"
    "Lesson `07_hemicube` · lab [7](../exercises/lab07/README.md) · source `lib/gi/radiosity/`\n"
    "\n"
    "Nusselt's analogue made of pixels: a *cube* of cells\n"
    "around a point. Then `more`.\n"
    "\n"
    "## The idea\n";

std::string error_of(const std::string& text) {
  try {
    gi::read_guide(text, "x.md");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LessonGuide, ReadsTheTitleTheLabAndTheOpeningParagraph) {
  const gi::LessonGuide g = gi::read_guide(opening, "07_hemicube.md");
  EXPECT_EQ(g.lesson, "07_hemicube");
  EXPECT_EQ(g.title, "07 — The hemicube");
  EXPECT_EQ(g.doc, "docs/07_hemicube.md");
  EXPECT_EQ(g.lab, "exercises/lab07/README.md");
  EXPECT_EQ(g.shows, "Nusselt's analogue made of pixels: a *cube* of cells around a point. Then `more`.");
  EXPECT_EQ(gi::first_sentence(g.shows), "Nusselt's analogue made of pixels: a cube of cells around a point.");
  const gi::LessonGuide no_lab = gi::read_guide("# 12 — x\n\nLesson `12_x` · source `a`\n\nShows.\n\n", "12_x.md");
  EXPECT_EQ(no_lab.lab, "");
}

TEST(LessonGuide, ADocWithoutItsOpeningSaysWhatIsMissing) {
  EXPECT_NE(error_of("07 — no heading\n").find("docs/x.md: the first line is not its title"), std::string::npos);
  EXPECT_NE(error_of("# t\n\n## The idea\n").find("no line 'Lesson `NN_topic`"), std::string::npos);
  EXPECT_NE(error_of("# t\n\nLesson `x` · source\n\n## The idea\n").find("no opening paragraph"), std::string::npos);
  EXPECT_NE(error_of("# t\n\nLesson `x` · source\n\nA paragraph cut").find("does not end"), std::string::npos);
}

TEST(LessonGuide, InlineMarkdownBecomesHtmlOrPlainText) {
  EXPECT_EQ(gi::markdown_inline_html("**B** = *E* + `rho F B` < [lesson 06](06.md)"),
            "<strong>B</strong> = <em>E</em> + <code>rho F B</code> &lt; lesson 06");
  EXPECT_EQ(gi::first_sentence("One, e.g. two. three. Four."), "One, e.g. two. three.");
  EXPECT_EQ(gi::first_sentence("No full stop"), "No full stop");
}

// Every lesson doc compiled in opens as the pages need: a title, the lesson's line
// naming a lesson with a doc of that name, a lab that exists, and a paragraph.
TEST(LessonGuide, EveryLessonDocOpensWithWhatItShows) {
  ASSERT_GE(gi::doc_openings().size(), 16u);
  for (const gi::PageAsset& doc : gi::doc_openings()) {
    SCOPED_TRACE(doc.name);
    const gi::LessonGuide g = gi::read_guide(doc.contents, doc.name);
    EXPECT_EQ(g.lesson + ".md", doc.name);
    EXPECT_TRUE(std::filesystem::exists(gi::source_file(g.doc)));
    if (!g.lab.empty()) {
      EXPECT_TRUE(std::filesystem::exists(gi::source_file(g.lab))) << g.lab;
    }
    EXPECT_GE(g.shows.size(), 80u) << "a sentence or two of what the lesson shows";
    EXPECT_LE(gi::first_sentence(g.shows).size(), 200u) << "the index's one line: " << gi::first_sentence(g.shows);
  }
  EXPECT_TRUE(gi::lesson_guide("01_rays"));
  EXPECT_FALSE(gi::lesson_guide("14_make_reference"));
}
