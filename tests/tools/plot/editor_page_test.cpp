// The page of `koppel edit` (tools/plot/src/editor_page.cpp): the document embedded in the page
// reads back, with a JSON parser, as the document the API makes; the title escaped in <title> and
// unable to end the page's script; every placeholder of the template filled; a build without the
// page says so. References: EditorDocumentJson (koppel/api/editor.hpp) parsed directly; the
// template's own placeholders (tools/edit/page.html); a page whose title is harmless.
#include "koppel/plot/editor_page.hpp"

#include "koppel/api/editor.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace koppel::editor_page_test {
namespace {

// The JSON of <script type="application/json" id="koppel-document">.
nlohmann::json EmbeddedDocument(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"koppel-document\">";
  const size_t begin = page.find(open);
  REQUIRE(begin != std::string::npos);
  const size_t from = begin + open.size(), to = page.find("</script>", from);
  REQUIRE(to != std::string::npos);
  return nlohmann::json::parse(page.substr(from, to - from));
}

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// the catalog's slider-crank with `title` as its title
Model WithTitle(const std::string& title) {
  const std::string text = test::Replace(test::ReadText(test::CatalogEntryPath("slider-crank-offset")),
                                         "title: Slider-crank with adjustable offset\n", "title: " + title + "\n");
  return Model::Parse(text, "titled.yaml", {{"e", "0.3"}});
}

}  // namespace

TEST_CASE("the page embeds the API's document and names the model in its title", "[plot][editor-page]") {
  const Model model = Model::Load(test::CatalogEntryPath("slider-crank-offset"), {{"e", "0.3"}});
  const plot::PlotResult r = plot::EditorPage(model);
  if (!plot::EditorPageAvailable()) {  // a build without em++: refused, with the reason
    CHECK(r.status == plot::PlotStatus::kFailed);
    CHECK(r.svg.empty());
    CHECK_THAT(r.message, Catch::Contains("emscripten"));
    return;
  }
  REQUIRE(r.status == plot::PlotStatus::kComplete);
  CHECK(EmbeddedDocument(r.svg) == nlohmann::json::parse(EditorDocumentJson(model)));
  CHECK(Count(r.svg, "<title>Slider-crank with adjustable offset (slider-crank-offset)</title>") == 1);
  // every placeholder of the template is filled (the page's scripts hold none of their own)
  for (const char* key : {"TITLE", "DATA", "UPLOT_CSS", "UPLOT_LICENSE", "UPLOT_JS", "MATHJS_LICENSE", "MATHJS", "MODULE", "EDITOR_JS"}) {
    INFO(key);
    CHECK(r.svg.find(std::string("{{") + key + "}}") == std::string::npos);
  }
}

TEST_CASE("a hostile title is escaped in <title> and cannot end the page's script", "[plot][editor-page]") {
  if (!plot::EditorPageAvailable()) return;  // (the refusal: the test case above)
  const std::string hostile = "\"</script><!-- <b>x</b> & y\"";  // a YAML string: the title </script><!-- <b>x</b> & y
  const std::string plain = plot::EditorPage(WithTitle("plain")).svg, page = plot::EditorPage(WithTitle(hostile)).svg;
  REQUIRE_FALSE(page.empty());
  // as many </script> and <!-- as the page of a harmless title: none came from the title
  CHECK(Count(page, "</script>") == Count(plain, "</script>"));
  CHECK(Count(page, "<!--") == Count(plain, "<!--"));
  CHECK(Count(page, "<title>&lt;/script&gt;&lt;!-- &lt;b&gt;x&lt;/b&gt; &amp; y (slider-crank-offset)</title>") == 1);
  // the document keeps the title as it is, and is the API's document
  const nlohmann::json doc = EmbeddedDocument(page);
  CHECK(doc["title"] == "</script><!-- <b>x</b> & y");
  CHECK(doc == nlohmann::json::parse(EditorDocumentJson(WithTitle(hostile))));
}

}  // namespace koppel::editor_page_test
