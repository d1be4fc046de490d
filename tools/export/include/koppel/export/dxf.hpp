// The DXF of a workshop drawing (koppel export --dxf), written with dxflib: AutoCAD 2000 ASCII
// (AC1015), one layer per link named after it (the frame's "frame"), one per traced curve
// ("curve-K"), the names made legal by DxfLayerNames. A plate is a closed LWPOLYLINE of lines
// and arcs (bulges), a hole a CIRCLE, a slot a closed LWPOLYLINE, a link's point that holds no
// joint (a coupler point) a POINT, a curve an LWPOLYLINE (closed for a full turn). Coordinates
// are the drawing's, in the mechanism's length unit; $INSUNITS says which unit that is. The
// same drawing gives the same bytes.
#pragma once

#include "koppel/plot/workshop.hpp"

#include <string>
#include <vector>

namespace koppel::plot {

// The DXF $INSUNITS code of a length unit of `metres_per_unit` metres: 1 in, 2 ft, 4 mm, 5 cm,
// 6 m, 7 km, 13 um, 14 dm; 0 (unitless) when the file names no unit or one DXF has no code for.
int DxfUnits(double metres_per_unit, bool unit_given);

// The layers of links and curves named `names` (in drawing order), legal and one to one: each
// name's characters other than printable ASCII, its spaces and the characters DXF forbids in a
// layer name (< > / \ " : ; ? * | = `) replaced by '_', cut to 255 characters; a name that
// comes out as one given before (without regard to case, as DXF compares layer names; "0" and
// "Defpoints" count as given) gets the first free suffix ~2, ~3, ... So "a<b" and "a>b" are
// "a_b" and "a_b~2", and no name can start a group of its own (a line break becomes '_').
std::vector<std::string> DxfLayerNames(const std::vector<std::string>& names);

// The DXF file's text. Precondition: drawing.status is not kFailed.
std::string WriteDxf(const WorkshopDrawing& drawing, int insunits);

}  // namespace koppel::plot
