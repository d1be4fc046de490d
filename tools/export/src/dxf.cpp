#include "koppel/export/dxf.hpp"

#include <dl_dxf.h>
#include <dl_writer_ascii.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

namespace koppel::plot {
namespace {

// dxflib's writer, into a string instead of a file: the CLI writes the file atomically itself.
// DL_WriterA opens no file for an empty name; every write goes through these overrides.
class StringWriter final : public DL_WriterA {
 public:
  StringWriter() : DL_WriterA("", DL_Codes::AC1015) {}
  std::string Text() const { return out_.str(); }

  void dxfReal(int gc, double value) const override {
    // 15 significant digits: a length read back within 1e-15 of its size, no noise digits
    char text[64];
    std::snprintf(text, sizeof text, "%.15g", value);
    Pair(gc, text);
  }
  void dxfInt(int gc, int value) const override { Pair(gc, std::to_string(value)); }
  void dxfHex(int gc, int value) const override {
    char text[32];
    std::snprintf(text, sizeof text, "%0X", static_cast<unsigned>(value));
    Pair(gc, text);
  }
  void dxfString(int gc, const char* value) const override { Pair(gc, value); }
  void dxfString(int gc, const std::string& value) const override { Pair(gc, value); }

 private:
  void Pair(int gc, const std::string& value) const {
    // a line break in a value would end it and start a group of the value's making: the names
    // are made legal before (DxfLayerNames), so this is a bug, never the user's input
    for (const char c : value)
      if (static_cast<unsigned char>(c) < ' ') throw std::logic_error("WriteDxf: a control character in group " + std::to_string(gc));
    out_ << (gc < 10 ? "  " : gc < 100 ? " " : "") << gc << "\n" << value << "\n";
  }
  mutable std::ostringstream out_;
};

// Colours of the layers (AutoCAD colour index): the frame in the drawing's foreground colour,
// the links in turn, the curves red.
constexpr int kFrameColour = 7, kCurveColour = 1;
constexpr int kLinkColours[] = {5, 3, 6, 4, 30, 2};

struct Layer {
  std::string name;
  int colour;
};

// The layer of each part, then of each curve ("curve-K"), in the drawing's order.
std::vector<std::string> LayerNamesOf(const WorkshopDrawing& drawing) {
  std::vector<std::string> names;
  for (const Part& part : drawing.parts) names.push_back(part.link);
  for (const TracedCurve& curve : drawing.curves) names.push_back("curve-" + curve.name);
  return DxfLayerNames(names);
}

std::vector<Layer> LayersOf(const WorkshopDrawing& drawing, const std::vector<std::string>& names) {
  std::vector<Layer> layers = {{"0", kFrameColour}};
  int next = 0;
  for (size_t i = 0; i < drawing.parts.size(); ++i)
    layers.push_back({names[i], drawing.parts[i].frame ? kFrameColour : kLinkColours[next++ % std::size(kLinkColours)]});
  for (size_t i = drawing.parts.size(); i < names.size(); ++i) layers.push_back({names[i], kCurveColour});
  return layers;
}

DL_Attributes On(const std::string& layer) { return DL_Attributes(layer, 256, -1, "BYLAYER", 1.0); }  // 256: colour by layer

// A contour as a closed polyline: each arc's two ends, the first with the arc's bulge
// (tan(sweep / 4), positive counter-clockwise), the second with 0: the line to the next arc.
void WriteContour(DL_Dxf& dxf, StringWriter& w, const Contour& contour, const std::string& layer) {
  dxf.writePolyline(w, DL_PolylineData(static_cast<int>(2 * contour.arcs.size()), 0, 0, 1), On(layer));
  for (const Arc& arc : contour.arcs) {
    const Eigen::Vector2d from = arc.From(), to = arc.To();
    dxf.writeVertex(w, DL_VertexData(from.x(), from.y(), 0, std::tan(arc.sweep / 4)));
    dxf.writeVertex(w, DL_VertexData(to.x(), to.y(), 0, 0));
  }
  dxf.writePolylineEnd(w);
}

void WritePart(DL_Dxf& dxf, StringWriter& w, const Part& part, const std::string& layer) {
  if (!part.outline.arcs.empty()) WriteContour(dxf, w, part.outline, layer);
  for (const Hole& h : part.holes) dxf.writeCircle(w, DL_CircleData(h.centre.x(), h.centre.y(), 0, h.diameter / 2), On(layer));
  for (const Slot& s : part.slots) WriteContour(dxf, w, s.outline, layer);
  for (const auto& [name, p] : part.marks) dxf.writePoint(w, DL_PointData(p.x(), p.y(), 0), On(layer));
}

void WriteCurve(DL_Dxf& dxf, StringWriter& w, const TracedCurve& curve, const std::string& layer) {
  for (const std::vector<Eigen::Vector2d>& run : curve.runs) {
    if (run.size() < 2) continue;  // a lone sample is no line
    dxf.writePolyline(w, DL_PolylineData(static_cast<int>(run.size()), 0, 0, curve.closed ? 1 : 0), On(layer));
    for (const Eigen::Vector2d& p : run) dxf.writeVertex(w, DL_VertexData(p.x(), p.y(), 0, 0));
    dxf.writePolylineEnd(w);
  }
}

// Header and tables as dxflib's manual lays them out for a file AutoCAD opens.
void WriteHeaderAndTables(DL_Dxf& dxf, StringWriter& w, const std::vector<Layer>& layers, int insunits) {
  dxf.writeHeader(w);
  w.dxfString(9, "$INSUNITS");
  w.dxfInt(70, insunits);
  w.sectionEnd();
  w.sectionTables();
  dxf.writeVPort(w);
  w.tableLinetypes(3);
  dxf.writeLinetype(w, DL_LinetypeData("BYBLOCK", "BYBLOCK", 0, 0, 0.0));
  dxf.writeLinetype(w, DL_LinetypeData("BYLAYER", "BYLAYER", 0, 0, 0.0));
  dxf.writeLinetype(w, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
  w.tableEnd();
  w.tableLayers(static_cast<int>(layers.size()));
  for (const Layer& l : layers) dxf.writeLayer(w, DL_LayerData(l.name, 0), DL_Attributes(l.name, l.colour, 100, "CONTINUOUS", 1.0));
  w.tableEnd();
  w.tableStyle(1);
  // "Standard", so spelt: dxflib keeps the handle of this style only for that name, and the
  // dimension style refers to it (group 340); under another name it writes an unset handle
  dxf.writeStyle(w, DL_StyleData("Standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
  w.tableEnd();
  dxf.writeView(w);
  dxf.writeUcs(w);
  w.tableAppid(1);
  dxf.writeAppid(w, "ACAD");
  w.tableEnd();
  dxf.writeDimStyle(w, 1, 1, 1, 1, 1);
  dxf.writeBlockRecord(w);
  w.tableEnd();
  w.sectionEnd();
  w.sectionBlocks();
  for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(w, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(w, block);
  }
  w.sectionEnd();
}

}  // namespace

int DxfUnits(double metres_per_unit, bool unit_given) {
  if (!unit_given) return 0;
  static const std::map<double, int> codes = {{0.0254, 1}, {0.3048, 2}, {0.001, 4}, {0.01, 5},
                                              {1.0, 6},    {1000.0, 7}, {1e-6, 13}, {0.1, 14}};
  const auto it = codes.find(metres_per_unit);
  return it == codes.end() ? 0 : it->second;
}

std::string WriteDxf(const WorkshopDrawing& drawing, int insunits) {
  if (drawing.status == PlotStatus::kFailed) throw std::invalid_argument("WriteDxf: a failed drawing has nothing to write");
  DL_Dxf dxf;
  StringWriter w;
  const std::vector<std::string> layers = LayerNamesOf(drawing);
  WriteHeaderAndTables(dxf, w, LayersOf(drawing, layers), insunits);
  w.sectionEntities();
  for (size_t i = 0; i < drawing.parts.size(); ++i) WritePart(dxf, w, drawing.parts[i], layers[i]);
  for (size_t i = 0; i < drawing.curves.size(); ++i) WriteCurve(dxf, w, drawing.curves[i], layers[drawing.parts.size() + i]);
  w.sectionEnd();
  dxf.writeObjects(w);
  dxf.writeObjectsEnd(w);
  w.dxfEOF();
  return w.Text();
}

}  // namespace koppel::plot
