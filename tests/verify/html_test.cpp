// `tessref verify --merge ... --html SITE`: the index lists the failing scene first, each scene
// has a page, and headless Chromium (scripts/html-screenshot.sh) draws a page that is not blank
// and whose DOM holds the figures and the four images. Skipped without chromium.
#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../pipeline/test_util.h"
#include "campaign_test_util.h"
#include "io/image_output.h"

namespace tessref {
namespace {

using ::testing::HasSubstr;
using test::TempDir;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class VerifyHtml : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(test::kBinary)) GTEST_SKIP() << test::kBinary << " not built";
    test::write_fake_report(dir_.path() / "reports", "alpha", true, 0.25);
    test::write_fake_report(dir_.path() / "reports", "beta", false, 0.0);
    test::write_fake_report(dir_.path() / "reports", "gamma", true, 0.5);
    const test::CliRun r = test::run_cli("verify --merge " + (dir_.path() / "reports").string() + " --html " + site());
    ASSERT_EQ(r.exit_code, 1) << r.output;  // beta failed
  }
  std::string site() const { return (dir_.path() / "site").string(); }
  TempDir dir_;
};

TEST_F(VerifyHtml, IndexSortsTheFailingSceneFirst) {
  const std::string index = test::read_file(site() + "/index.html");
  EXPECT_THAT(index, HasSubstr("3 scenes, 2 passed, 1 failed"));
  const std::size_t beta = index.find("href=\"beta.html\""), gamma = index.find("href=\"gamma.html\""),
                    alpha = index.find("href=\"alpha.html\"");
  ASSERT_NE(beta, std::string::npos);
  EXPECT_LT(beta, gamma);  // severity 2, then 0.5, then 0.25
  EXPECT_LT(gamma, alpha);
  for (const char* s : {"alpha", "beta", "gamma"}) EXPECT_TRUE(std::filesystem::exists(site() + "/" + s + ".html")) << s;
}

TEST_F(VerifyHtml, ScenePageHasVerdictFiguresPatchesAndImages) {
  const std::string page = test::read_file(site() + "/beta.html");
  EXPECT_THAT(page, HasSubstr("class=\"fail\">FAIL"));
  EXPECT_THAT(page, HasSubstr("Hausdorff distance 2e-05 of the diagonal"));
  // Issue 24, defect 7: the commands keep the run's --set overrides; figures are named in words
  // (the key in the tooltip), "no such patch" is "none"; worst pixels have their distances; the
  // worst pixel is shown 8 times larger (three more copies of the images).
  EXPECT_THAT(page, HasSubstr("tessref inspect scenes/beta.json --set tessellation.inner=7 --set camera.eye=0,1,4 --patch 17"));
  EXPECT_THAT(page, HasSubstr("<td title=\"hausdorff_of_diagonal\">Hausdorff distance / diagonal</td>"));
  EXPECT_THAT(page, HasSubstr("first patch whose gl_TessCoord differ</td><td class=\"num\">none</td>"));
  EXPECT_THAT(page, HasSubstr("<td class=\"num\">12</td><td class=\"num\">40</td><td class=\"num\">0.25</td>"));
  EXPECT_THAT(page, HasSubstr("The worst coverage mismatch, 8 times larger (12, 40"));
  EXPECT_EQ(count(page, "src=\"data:image/png;base64,iVBOR"), 7u);  // PNG's signature, base64
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(page.find("http"), std::string::npos) << "no network";
}

TEST_F(VerifyHtml, ChromiumDrawsThePage) {
  if (std::system("command -v chromium >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "chromium is not installed (scripts/install-deps.sh chromium)";
  const std::string shot = (dir_.path() / "beta.png").string(), dom = (dir_.path() / "beta.dom.html").string();
  const std::string cmd = std::string(TESSREF_SOURCE_DIR) + "/scripts/html-screenshot.sh " + site() + "/beta.html " +
                          shot + " " + dom + " 1000x900 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

  // Not blank: many colours (the page's text, tables and four gradients), not one background.
  const Rgb8Image img = read_rgb8_image(shot);
  ASSERT_EQ(img.width, 1000);
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < img.pixels.size(); i += 3)
    colours.insert(img.pixels[i] << 16 | img.pixels[i + 1] << 8 | img.pixels[i + 2]);
  EXPECT_GT(colours.size(), 200u);

  // The DOM as Chromium built it: the four images and the three zoomed copies with data, the
  // figures (named in words, keys in tooltips), the verdict.
  const std::string d = test::read_file(dom);
  EXPECT_EQ(count(d, "<img alt="), 7u);
  EXPECT_EQ(count(d, "src=\"data:image/png;base64,iVBOR"), 7u);
  for (const char* figure : {"hausdorff_of_diagonal", "max_distance_px", "within_2_255", "psnr_db", "58.5",
                             "--patch 17", "FAIL", "driver (reference)", "silhouette heat map"})
    EXPECT_THAT(d, HasSubstr(figure));
}

}  // namespace
}  // namespace tessref
