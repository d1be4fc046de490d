// koppel catalog show ID --format html: the entry's page with its kinematic scheme and the plots
// of its Abtrieb outputs (transfer functions, or the path of a guided point), drawn from the same
// solver as the checks; the text page below them.
#include "catalog_command.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/plot/plots.hpp"
#include "koppel/plot/sampled_run.hpp"
#include "koppel/plot/scheme.hpp"
#include "koppel/plot/svg.hpp"

namespace koppel::cli {
namespace catalog_page {  // this file's own names, apart from the other commands' in a unity build
namespace {

// the card's sweep (its units: deg for an R drive) as the plots' range
SweepOptions CardRange(const CatalogPage& e, int order) {
  const bool angle = e.input_is_angle;
  SweepOptions range;
  range.from = angle ? DegToRad(e.from) : e.from;
  range.to = angle ? DegToRad(e.to) : e.to;
  range.step = angle ? DegToRad(e.step) : e.step;
  range.order = order;
  return range;
}

// the scheme at the assembly's input, scaled to hold every pose of the card's sweep
std::string Scheme(const CatalogPage& e, std::vector<std::string>* problems) {
  const Mechanism& m = e.mechanism;
  const plot::SampledRun run = plot::SampleMechanism(m, CardRange(e, 0));
  if (!run.complete) problems->push_back("scheme: " + run.message);
  if (run.size() == 0) return "";
  plot::SchemeScene scene;
  const Expected<Eigen::VectorXd> pose = plot::PoseAt(m, run, m.hint.input);
  if (!pose) {
    problems->push_back("scheme: " + pose.error());
    return "";
  }
  scene.q = *pose;
  for (int i = 0; i < run.size(); ++i) scene.extent.push_back(run.poses.row(i).transpose());
  scene.caption = e.entry.id;
  return plot::DrawScheme(m, scene);
}

// one plot per Abtrieb output: a guided point's path, otherwise its transfer functions
std::string OutputPlot(const CatalogPage& e, const std::string& name, std::vector<std::string>* problems) {
  const Mechanism& m = e.mechanism;
  const int output = m.FindOutput(name);
  plot::PlotResult result;
  if (m.outputs[output].kind == OutputKind::kPoint) {
    plot::CurvePlotOptions options;
    options.point = m.outputs[output].p;
    options.range = CardRange(e, 2);
    result = plot::CurvePlot(m, options);
  } else {
    plot::TransferPlotOptions options;
    options.output = output;
    options.order = 2;
    options.range = CardRange(e, 2);
    options.length_unit = e.length_unit;
    result = plot::TransferPlot(m, options);
  }
  if (result.status != plot::PlotStatus::kComplete) problems->push_back(name + ": " + result.Brief());
  return result.svg;
}

}  // namespace
}  // namespace catalog_page

std::string EntryHtml(const CatalogPage& e, const std::string& text_page, std::vector<std::string>* problems) {
  using namespace catalog_page;
  const CatalogHit& c = e.entry;
  std::string figures = Scheme(e, problems);
  for (const std::string& o : e.outputs) figures += OutputPlot(e, o, problems);
  std::string notes;
  for (const std::string& p : *problems) notes += "<li>" + plot::EscapeXml(p) + "</li>";
  return "<!DOCTYPE html>\n<html lang=\"de\"><head><meta charset=\"utf-8\"><title>" + plot::EscapeXml(c.id) +
         "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}svg{max-width:100%;height:auto;"
         "display:block;margin:1em 0}pre{white-space:pre-wrap}</style></head><body>\n<h1>" + plot::EscapeXml(c.title_de) + "</h1>\n<h2>" +
         plot::EscapeXml(c.title_en) + "</h2>\n" + (notes.empty() ? "" : "<p>Not everything could be drawn:</p><ul>" + notes + "</ul>\n") +
         figures + "\n<pre>" + plot::EscapeXml(text_page) + "</pre>\n</body></html>\n";
}

}  // namespace koppel::cli
