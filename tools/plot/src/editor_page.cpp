#include "koppel/plot/editor_page.hpp"

#include "plot_support.hpp"

#include "koppel/api/editor.hpp"
#include "koppel/plot/svg.hpp"

#if KOPPEL_EDITOR_PAGE
namespace koppel::plot::editor_assets {
// tools/edit/edit.cmake: the template, the page's script, the WebAssembly module, math.js
extern const char* const k_template;
extern const char* const k_script;
extern const char* const k_module;
extern const char* const k_mathjs;
extern const char* const k_mathjs_license;
}  // namespace koppel::plot::editor_assets
#endif

namespace koppel::plot {

bool EditorPageAvailable() { return KOPPEL_EDITOR_PAGE != 0; }

PlotResult EditorPage(const Model& model) {
#if KOPPEL_EDITOR_PAGE
  namespace assets = editor_assets;
  const std::string title = model.title().empty() ? model.name() : model.title() + " (" + model.name() + ")";
  PlotResult result;
  result.svg = Fill(assets::k_template, {{"TITLE", EscapeXml(title)},
                                         {"DATA", ScriptSafe(EditorDocumentJson(model))},
                                         {"UPLOT_CSS", plot::assets::k_uplot_css},
                                         {"UPLOT_LICENSE", plot::assets::k_uplot_license},
                                         {"UPLOT_JS", plot::assets::k_uplot_js},
                                         {"MATHJS_LICENSE", assets::k_mathjs_license},
                                         {"MATHJS", assets::k_mathjs},
                                         {"MODULE", assets::k_module},
                                         {"EDITOR_JS", assets::k_script}});
  return result;
#else
  (void)model;
  return {PlotStatus::kFailed, "this koppel was built without emscripten (em++), so it has no editor page: install Debian's emscripten and build again", ""};
#endif
}

}  // namespace koppel::plot
