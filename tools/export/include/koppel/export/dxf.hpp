// The DXF of a workshop drawing (koppel export --dxf), written with dxflib: AutoCAD 2000 ASCII
// (AC1015), one layer per link named after it (the frame's "frame"), one per traced curve
// ("curve-K"). A plate is a closed LWPOLYLINE of lines and arcs (bulges), a hole a CIRCLE, a
// slot a closed LWPOLYLINE, a link's point that holds no joint (a coupler point) a POINT, a
// curve an LWPOLYLINE (closed for a full turn). Coordinates are the drawing's, in the
// mechanism's length unit; $INSUNITS says which unit that is.
#pragma once

#include "koppel/plot/workshop.hpp"

#include <string>

namespace koppel::plot {

// The DXF $INSUNITS code of a length unit of `metres_per_unit` metres: 1 in, 2 ft, 4 mm, 5 cm,
// 6 m, 7 km, 13 um, 14 dm; 0 (unitless) when the file names no unit or one DXF has no code for.
int DxfUnits(double metres_per_unit, bool unit_given);

// The layer of a link or curve: its name with the characters DXF forbids in a layer name
// (< > / \ " : ; ? * | = ` and spaces) replaced by '_'.
std::string DxfLayerName(const std::string& name);

// The DXF file's text. Precondition: drawing.status is not kFailed.
std::string WriteDxf(const WorkshopDrawing& drawing, int insunits);

}  // namespace koppel::plot
