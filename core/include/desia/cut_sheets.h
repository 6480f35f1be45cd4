// SPDX-License-Identifier: GPL-3.0-or-later
// Cut files of a plate structure for a laser cutter or a CNC router: every plate laid flat,
// nested onto sheets, as SVG at true size (millimetres) or DXF (R12, $INSUNITS = mm). Outer cuts,
// inner cuts (mortises and holes) and engraving (plate ids, the id of the plate that stands on a
// face next to its joint) are told apart by colour in SVG and by layer in DXF.
#pragma once

#include <string>
#include <vector>

#include "desia/document.h"

namespace desia {

enum class CutFileFormat { Svg, Dxf };

// "svg" or "dxf"; BadInput naming the value else.
CutFileFormat parseCutFileFormat(const std::string& name);

struct CutSheetOptions {
  // The sheet in mm; 0 x 0 = one sheet as large as the parts need.
  double sheetWidth = 0, sheetHeight = 0;
  double kerf = 0;        // mm the beam removes: outlines move out by half of it, holes in
  double spacing = 5;     // mm between parts and from the sheet's edges
  bool hairline = false;  // SVG strokes 0.01 mm wide (lasers that cut hairlines only) instead of 0.1 mm
  std::string source = "<input>";
};

// "600x400" (mm); BadInput naming the text else.
void parseSheetSize(const std::string& text, CutSheetOptions* options);

// Options as the package passes them ({sheet: "600x400", kerf, spacing, hairline, source});
// unknown names and bad values are BadInput.
CutSheetOptions parseCutSheetOptionsJson(const std::string& text);

// One file per sheet, in order. The plates are the document's `fabricationPlates` (a result cut
// with a clearance) or its `plates`; each is laid flat on its first face (a plate with mitred
// edges: the blank holding both faces), turned to its smallest bounding box, and shelf-packed in
// order of height. Throws BadInput for a document without plates, a sheet too small for a plate
// (named, with its size), a kerf or spacing out of range.
std::vector<std::string> plateCutSheets(const AssemblyDocument& document, CutFileFormat format,
                                        const CutSheetOptions& options);

}  // namespace desia
