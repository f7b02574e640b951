// Load errors and warnings are one printable line naming the file and the place: bytes from a file can not
// drive the terminal they are printed on, and a JSON error says its line and column.
#include <gtest/gtest.h>

#include "app/scene_loading.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

using test::TempFolder;

TEST(LoadMessages, PrintableTextEscapesWhatATerminalWouldObey) {
  EXPECT_EQ(printableText("plain text, 100%"), "plain text, 100%");
  EXPECT_EQ(printableText("\x1b[31mred\x1b[0m"), "\\x1b[31mred\\x1b[0m");
  EXPECT_EQ(printableText("bell\a tab\t nul" + std::string(1, '\0')), "bell\\x07 tab\\x09 nul\\x00");
  EXPECT_EQ(printableText("two\nlines\r\n"), "two lines");
  EXPECT_EQ(printableText("caf\xC3\xA9 \xE6\x97\xA5\xE6\x9C\xAC \xF0\x9F\x99\x82"),
            "caf\xC3\xA9 \xE6\x97\xA5\xE6\x9C\xAC \xF0\x9F\x99\x82");
  EXPECT_EQ(printableText("\xC2\x9B"
                          "31m"),
            "\\xc2\\x9b31m");  // C1 CSI, UTF-8 encoded
  EXPECT_EQ(printableText("\x9b"
                          "31m"),
            "\\x9b31m");  // C1 CSI, a lone byte
  EXPECT_EQ(printableText("a\xE2\x80\xAE"
                          "gnp.exe"),
            "a\\xe2\\x80\\xaegnp.exe");  // right-to-left override
  EXPECT_EQ(printableText("\xC0\xAF \xED\xA0\x80 \xF5\x80\x80\x80 \xE2\x82"),
            "\\xc0\\xaf \\xed\\xa0\\x80 \\xf5\\x80\\x80\\x80 \\xe2\\x82");
  EXPECT_EQ(printableText("\x7f"), "\\x7f");
  std::string once = printableText("\x1b]0;title\x07");
  EXPECT_EQ(printableText(once), once);
}

TEST(LoadMessages, FileContentAndNamesAreEscapedInErrorsAndWarnings) {
  LoadWarnings warnings;
  warnings.add("m\x1b.obj", "material '\x1b[2J' not found");
  EXPECT_EQ(warnings.messages[0], "m\\x1b.obj: material '\\x1b[2J' not found");
  try {
    failLoad("m.obj", 3, "unknown statement '\x1b]0;owned\x07'");
  } catch (const LoadError& e) {
    EXPECT_STREQ(e.what(), "m.obj:3: unknown statement '\\x1b]0;owned\\x07'");
  }
  TempFolder dir;
  loadObj(dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \x1b[31mred\nf 1 2 3\n"), warnings);
  ASSERT_EQ(warnings.messages.size(), 2u);
  EXPECT_NE(warnings.messages[1].find("material '\\x1b[31mred' is in no material library"), std::string::npos)
      << warnings.messages[1];
}

std::string sceneError(const TempFolder& dir, const std::string& json) {
  LoadWarnings warnings;
  try {
    loadSceneFile(
        dir.write("s.json", json),
        [](const std::string& p, LoadWarnings& w, SharedModelAssets&) { return loadObj(p, w); }, warnings);
  } catch (const LoadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a LoadError for " << json;
  return {};
}

TEST(LoadMessages, JsonErrorsSayTheLineAndColumn) {
  TempFolder dir;
  const std::string file = dir.file("s.json");
  // A number beyond double's range: nlohmann says so without a position of its own.
  EXPECT_EQ(sceneError(dir, "{\n  \"models\": [],\n  \"render\": {\"spp\": 1e400}\n}"),
            file + ":3:21: invalid JSON: number overflow parsing '1e400'");
  EXPECT_EQ(sceneError(dir, "{\"models\": [1,,]}"),
            file +
                ":1:15: invalid JSON: syntax error while parsing value - unexpected ','; expected '[', '{', or a "
                "literal");
  EXPECT_EQ(sceneError(dir, "{\"models\": \"\x1b[2J")
                .rfind(file + ":1:13: invalid JSON: syntax error while parsing "
                              "value - invalid string: control character U+001B",
                       0),
            0u);
  EXPECT_EQ(sceneError(dir, R"({"models": [{"file": "\u001b[31m.obj"}]})"),
            dir.file("\\x1b[31m.obj") + ": cannot open: No such file or directory");
}

TEST(LoadMessages, UnknownScenesAreNamedPrintably) {
  try {
    loadScene("no\x1b[2Jscene");
    ADD_FAILURE();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown scene 'no\\x1b[2Jscene'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace candela
