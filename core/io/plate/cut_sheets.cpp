// SPDX-License-Identifier: GPL-3.0-or-later
// Cut files for plate structures (see desia/export.h). Flattening, the kerf offset and the
// unions are Clipper's (integer coordinates, the same natively and in WebAssembly); numbers are
// printed from integers of 1e-3 mm, so the files are byte for byte the same everywhere.
#include "desia/export.h"

#include <nlohmann/json.hpp>
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "io/json_input.h"
#include "plate/plane_frame.h"

namespace desia {
namespace {

using Point2 = std::array<double, 2>;
using Ring = std::vector<Point2>;

// A plate laid flat: its cut loops (outline first, then holes) and its engraving.
struct Mark {
  Point2 at;
  double size;
  std::string text;
};

struct FlatPlate {
  int id = 0;
  std::vector<Ring> outlines;  // outer cuts (one per piece; one for a plate)
  std::vector<Ring> holes;     // inner cuts
  std::vector<Mark> marks;     // engraving
  double width = 0, height = 0;
};

constexpr double kScale = kClipperScale;

Point2 toPoint(const ClipperLib::IntPoint& p) {
  return {static_cast<double>(p.X) / kScale, static_cast<double>(p.Y) / kScale};
}

// The region to cut: both faces' regions united (the first face alone for a prism plate).
ClipperLib::Paths blankOf(const Plate& plate, const PlaneFrame& frame) {
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clipperPaths(plate.bottom, frame), ClipperLib::ptSubject, true);
  clipper.AddPaths(clipperPaths(plate.top, frame), ClipperLib::ptClip, true);
  ClipperLib::Paths blank;
  clipper.Execute(ClipperLib::ctUnion, blank, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
  return blank;
}

ClipperLib::Paths withKerf(const ClipperLib::Paths& region, double kerf) {
  if (kerf <= 0) return region;
  ClipperLib::ClipperOffset offset;
  offset.AddPaths(region, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths grown;
  offset.Execute(grown, kerf / 2 * kScale);
  return grown;
}

std::string mm(double value);

// The kerf offset must not erase a cut: an opening of the blank (a mortise, a slot, a notch)
// narrower than the kerf closes when the blank is grown by half the kerf and shrunk back (a
// morphological closing). Refused, with the opening's width (about: its area over half its
// perimeter, exact for a long slot) and the kerf named.
void requireOpeningsWiderThanKerf(const Plate& plate, const ClipperLib::Paths& blank, double kerf,
                                  const std::string& source) {
  if (kerf <= 0) return;
  ClipperLib::ClipperOffset shrink;
  shrink.AddPaths(withKerf(blank, kerf), ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  ClipperLib::Paths closed;
  shrink.Execute(closed, -kerf / 2 * kScale);
  ClipperLib::Clipper clipper;
  clipper.AddPaths(closed, ClipperLib::ptSubject, true);
  clipper.AddPaths(blank, ClipperLib::ptClip, true);
  ClipperLib::Paths filled;
  clipper.Execute(ClipperLib::ctDifference, filled, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  double widest = 0, narrowest = HUGE_VAL;
  for (const ClipperLib::Path& piece : filled) {
    const double area = std::abs(ClipperLib::Area(piece)) / (kScale * kScale);
    if (area <= tolerance::kSheetSliverMm2) continue;  // Clipper's rounding at a corner, not an opening
    double perimeter = 0;
    for (size_t k = 0; k < piece.size(); ++k) {
      const ClipperLib::IntPoint& a = piece[k];
      const ClipperLib::IntPoint& b = piece[(k + 1) % piece.size()];
      perimeter += std::hypot(static_cast<double>(b.X - a.X), static_cast<double>(b.Y - a.Y)) / kScale;
    }
    narrowest = std::min(narrowest, 2 * area / perimeter);
    widest = std::max(widest, area);
  }
  if (widest > 0) {
    throwBadInput(source, "plate " + std::to_string(plate.id) + ": an opening about " + mm(narrowest) +
                          " mm wide (a mortise, slot or notch) is narrower than the kerf (" + mm(kerf) +
                          " mm): the cut would erase it; give a smaller kerf");
  }
}

bool insideRings(const std::vector<Ring>& rings, const Point2& q) {
  bool inside = false;
  for (const Ring& ring : rings) {
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const Point2& a = ring[i];
      const Point2& b = ring[j];
      if ((a[1] > q[1]) != (b[1] > q[1]) && q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0])
        inside = !inside;
    }
  }
  return inside;
}

void transform(FlatPlate* plate, double angle, const Point2& shift) {
  const double c = std::cos(angle), s = std::sin(angle);
  auto move = [&](Point2& p) { p = {c * p[0] - s * p[1] + shift[0], s * p[0] + c * p[1] + shift[1]}; };
  for (auto* rings : {&plate->outlines, &plate->holes}) {
    for (Ring& ring : *rings) {
      for (Point2& p : ring) move(p);
    }
  }
  for (Mark& mark : plate->marks) move(mark.at);
}

std::array<double, 4> boundsOf(const FlatPlate& plate, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  std::array<double, 4> box{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Ring& ring : plate.outlines) {
    for (const Point2& p : ring) {
      const double x = c * p[0] - s * p[1], y = s * p[0] + c * p[1];
      box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
    }
  }
  return box;
}

// Turns the plate to its smallest bounding box (the best of its edges' directions), wider than
// tall, with its lower left corner at the origin.
void layFlat(FlatPlate* plate) {
  double bestAngle = 0, bestArea = HUGE_VAL;
  for (const Ring& ring : plate->outlines) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point2& p = ring[i];
      const Point2& q = ring[(i + 1) % ring.size()];
      if (std::hypot(q[0] - p[0], q[1] - p[1]) < tolerance::kSamePointMm) continue;
      const double angle = -std::atan2(q[1] - p[1], q[0] - p[0]);
      const std::array<double, 4> box = boundsOf(*plate, angle);
      const double area = (box[2] - box[0]) * (box[3] - box[1]);
      if (area < bestArea - tolerance::kSameAreaMm2) {
        bestArea = area;
        bestAngle = angle;
      }
    }
  }
  std::array<double, 4> box = boundsOf(*plate, bestAngle);
  if (box[3] - box[1] > box[2] - box[0]) {
    bestAngle += M_PI / 2;
    box = boundsOf(*plate, bestAngle);
  }
  transform(plate, bestAngle, {0, 0});
  transform(plate, 0, {-box[0], -box[1]});
  plate->width = box[2] - box[0];
  plate->height = box[3] - box[1];
}

// A point well inside the plate for its id: the middle of the widest inside run of the scan line
// through the bounding box's middle (or a little above or below).
std::optional<Point2> labelPoint(const std::vector<Ring>& rings, double width, double height) {
  for (double fraction : {0.5, 0.35, 0.65, 0.2, 0.8}) {
    const double y = height * fraction;
    std::vector<double> crossings;
    for (const Ring& ring : rings) {
      for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Point2& a = ring[i];
        const Point2& b = ring[j];
        if ((a[1] > y) != (b[1] > y)) crossings.push_back(a[0] + (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    double best = 0;
    std::optional<Point2> at;
    for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
      if (crossings[k + 1] - crossings[k] > best) {
        best = crossings[k + 1] - crossings[k];
        at = Point2{(crossings[k] + crossings[k + 1]) / 2, y};
      }
    }
    if (at && best > std::min(width, height) * 0.1) return at;
  }
  return std::nullopt;
}

// The plates of other ids standing on this plate's faces: their contact regions' middles, in the
// plate's frame, beside which their ids are engraved (where the joints go together).
std::vector<Mark> matingMarks(const std::vector<Plate>& plates, size_t index, const std::vector<PlateContact>& contacts,
                              const PlaneFrame& frame) {
  // Each touching pair's largest contact: the shoulder of a joint, not a tenon's cheek.
  std::map<int, const PlateContact*> largest;
  for (const PlateContact& contact : contacts) {
    if (contact.a != static_cast<int>(index) && contact.b != static_cast<int>(index)) continue;
    const int other = contact.a == static_cast<int>(index) ? contact.b : contact.a;
    if (!largest.count(other) || contact.area > largest[other]->area) largest[other] = &contact;
  }
  const Vec3 axis = plateThicknessAxis(plates[index]);
  for (auto it = largest.begin(); it != largest.end();) {
    const bool onThisFace = std::abs(dot(it->second->normal, axis)) > 1 - tolerance::kFacingCosine;
    const bool onTheirEdge =
        std::abs(dot(it->second->normal, plateThicknessAxis(plates[it->first]))) < 1 - tolerance::kFacingCosine;
    it = onThisFace && onTheirEdge ? std::next(it) : largest.erase(it);
  }
  std::vector<Mark> marks;
  for (const auto& [other, contact] : largest) {
    Point2 lo{HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL};
    for (const Vec3& p : contact->region) {
      const Point2 q = toPoint(frame.toClipper(p));
      lo = {std::min(lo[0], q[0]), std::min(lo[1], q[1])};
      hi = {std::max(hi[0], q[0]), std::max(hi[1], q[1])};
    }
    const bool wide = hi[0] - lo[0] >= hi[1] - lo[1];
    const double size = 5;
    // Beside the joint on its longer side, 4 mm clear of it.
    const Point2 middle{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2};
    const double reach = (wide ? hi[1] - lo[1] : hi[0] - lo[0]) / 2 + 4 + size / 2;
    marks.push_back({wide ? Point2{middle[0], middle[1] + reach} : Point2{middle[0] + reach, middle[1]}, size,
                     std::to_string(plates[other].id)});
    marks.push_back({wide ? Point2{middle[0], middle[1] - reach} : Point2{middle[0] - reach, middle[1]}, size,
                     std::to_string(plates[other].id)});
  }
  return marks;
}

FlatPlate flatten(const std::vector<Plate>& plates, size_t index, const std::vector<PlateContact>& contacts,
                  double kerf, const std::string& source) {
  const Plate& plate = plates[index];
  const PlaneFrame frame(plate.bottom[0][0], plateThicknessAxis(plate));
  FlatPlate flat;
  flat.id = plate.id;
  const ClipperLib::Paths blank = blankOf(plate, frame);
  requireOpeningsWiderThanKerf(plate, blank, kerf, source);
  for (const ClipperLib::Path& path : withKerf(blank, kerf)) {
    Ring ring;
    for (const ClipperLib::IntPoint& p : path) ring.push_back(toPoint(p));
    (ClipperLib::Orientation(path) ? flat.outlines : flat.holes).push_back(ring);
  }
  std::vector<Ring> rings = flat.outlines;
  rings.insert(rings.end(), flat.holes.begin(), flat.holes.end());
  for (const Mark& mark : matingMarks(plates, index, contacts, frame)) {
    if (insideRings(rings, mark.at)) flat.marks.push_back(mark);
  }
  // Keep one mark per mating plate (the first that landed on the plate).
  std::vector<Mark> unique;
  for (const Mark& mark : flat.marks) {
    if (std::none_of(unique.begin(), unique.end(), [&](const Mark& m) { return m.text == mark.text; }))
      unique.push_back(mark);
  }
  flat.marks = unique;
  layFlat(&flat);
  rings = flat.outlines;
  rings.insert(rings.end(), flat.holes.begin(), flat.holes.end());
  if (const std::optional<Point2> at = labelPoint(rings, flat.width, flat.height)) {
    const double size = std::clamp(std::min(flat.width, flat.height) / 4, 3.0, 12.0);
    flat.marks.insert(flat.marks.begin(), {*at, size, std::to_string(plate.id)});
  }
  return flat;
}

struct Placement {
  size_t plate;
  int sheet;
  Point2 at;
  bool turned;
};

struct Sheet {
  double width = 0, height = 0;
};

// Shelf packing: the plates in order of height, left to right along rows, a new row when the row
// is full, a new sheet when the sheet is.
std::vector<Placement> pack(std::vector<FlatPlate>& flats, const CutSheetOptions& options, std::vector<Sheet>* sheets) {
  const double gap = options.spacing;
  const bool fixed = options.sheetWidth > 0;
  double totalArea = 0, widest = 0;
  for (const FlatPlate& flat : flats) {
    totalArea += (flat.width + gap) * (flat.height + gap);
    widest = std::max(widest, flat.width);
  }
  const double usableWidth =
      fixed ? options.sheetWidth - 2 * gap : std::max(widest, std::ceil(std::sqrt(totalArea) * 1.2));
  const double usableHeight = fixed ? options.sheetHeight - 2 * gap : HUGE_VAL;
  std::vector<size_t> order(flats.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::vector<Placement> placements(flats.size());
  std::vector<bool> turned(flats.size(), false);
  for (size_t k : order) {
    // A plate too long for the sheet's width may fit turned a quarter.
    if (flats[k].width > usableWidth && flats[k].height <= usableWidth && flats[k].width <= usableHeight)
      turned[k] = true;
    const double w = turned[k] ? flats[k].height : flats[k].width, h = turned[k] ? flats[k].width : flats[k].height;
    if (w > usableWidth + tolerance::kZeroLengthMm || h > usableHeight + tolerance::kZeroLengthMm) {
      std::ostringstream size;
      size.precision(6);
      size << flats[k].width << " x " << flats[k].height << " mm";
      throwBadInput(options.source,
                    "plate " + std::to_string(flats[k].id) + " (" + size.str() + ") does not fit on a " +
                        std::to_string(static_cast<long long>(options.sheetWidth)) + " x " +
                        std::to_string(static_cast<long long>(options.sheetHeight)) + " mm sheet with " +
                        std::to_string(static_cast<long long>(gap)) + " mm margins");
    }
  }
  auto heightOf = [&](size_t k) { return turned[k] ? flats[k].width : flats[k].height; };
  auto widthOf = [&](size_t k) { return turned[k] ? flats[k].height : flats[k].width; };
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return heightOf(a) > heightOf(b); });
  int sheet = 0;
  double x = 0, rowY = 0, rowHeight = 0, usedWidth = 0;
  std::vector<double> sheetHeights{0};
  for (size_t k : order) {
    if (x > 0 && x + widthOf(k) > usableWidth + tolerance::kZeroLengthMm) {  // next row
      rowY += rowHeight + gap;
      x = 0;
      rowHeight = 0;
    }
    if (rowY + heightOf(k) > usableHeight + tolerance::kZeroLengthMm) {  // next sheet
      ++sheet;
      sheetHeights.push_back(0);
      x = rowY = rowHeight = 0;
    }
    placements[k] = {k, sheet, {gap + x, gap + rowY}, turned[k]};
    x += widthOf(k) + gap;
    rowHeight = std::max(rowHeight, heightOf(k));
    usedWidth = std::max(usedWidth, x - gap);
    sheetHeights.back() = std::max(sheetHeights.back(), rowY + rowHeight);
  }
  for (double used : sheetHeights) {
    sheets->push_back(fixed ? Sheet{options.sheetWidth, options.sheetHeight}
                            : Sheet{usedWidth + 2 * gap, used + 2 * gap});
  }
  for (Placement& placement : placements) {
    FlatPlate& flat = flats[placement.plate];
    if (placement.turned) {
      transform(&flat, M_PI / 2, {flat.height, 0});  // a quarter turn, back into x >= 0
      std::swap(flat.width, flat.height);
    }
    transform(&flat, 0, placement.at);
  }
  return placements;
}

// Millimetres printed from an integer count of micrometres: exact, the same on every platform.
std::string mm(double value) {
  const long long micro = std::llround(value * 1000);
  const long long whole = std::llabs(micro) / 1000, fraction = std::llabs(micro) % 1000;
  std::string text = (micro < 0 ? "-" : "") + std::to_string(whole);
  if (fraction != 0) {
    char digits[8];
    std::snprintf(digits, sizeof digits, ".%03lld", fraction);
    std::string tail = digits;
    while (tail.back() == '0') tail.pop_back();
    text += tail;
  }
  return text;
}

std::string svgPath(const Ring& ring, double sheetHeight) {
  std::string d;
  for (size_t i = 0; i < ring.size(); ++i) d += (i ? " L" : "M") + mm(ring[i][0]) + " " + mm(sheetHeight - ring[i][1]);
  return d + " Z";
}

std::string svgSheet(const std::vector<FlatPlate>& flats, const std::vector<Placement>& placements, int sheet,
                     const Sheet& size, const CutSheetOptions& options, int sheetCount) {
  const std::string stroke = options.hairline ? "0.01" : "0.1";
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << mm(size.width) << "mm\" height=\"" << mm(size.height)
      << "mm\" viewBox=\"0 0 " << mm(size.width) << " " << mm(size.height) << "\">\n"
      << "<title>desia cut sheet " << sheet + 1 << " of " << sheetCount
      << " (mm; red: outer cuts, blue: inner cuts, black: engrave"
      << (options.kerf > 0 ? "; kerf " + mm(options.kerf) + " mm compensated" : std::string()) << ")</title>\n"
      << "<style>.outer{fill:none;stroke:#ff0000;stroke-width:" << stroke
      << "}.inner{fill:none;stroke:#0000ff;stroke-width:" << stroke
      << "}.engrave{fill:none;stroke:#000000;stroke-width:" << stroke
      << ";font-family:sans-serif;text-anchor:middle;dominant-baseline:central}</style>\n";
  for (const Placement& placement : placements) {
    if (placement.sheet != sheet) continue;
    const FlatPlate& flat = flats[placement.plate];
    out << "<g id=\"plate-" << flat.id << "\">\n";
    for (const Ring& ring : flat.outlines)
      out << "<path class=\"outer\" stroke=\"#ff0000\" fill=\"none\" d=\"" << svgPath(ring, size.height) << "\"/>\n";
    for (const Ring& ring : flat.holes)
      out << "<path class=\"inner\" stroke=\"#0000ff\" fill=\"none\" d=\"" << svgPath(ring, size.height) << "\"/>\n";
    for (const Mark& mark : flat.marks) {
      out << "<text class=\"engrave\" stroke=\"#000000\" fill=\"none\" x=\"" << mm(mark.at[0]) << "\" y=\""
          << mm(size.height - mark.at[1]) << "\" font-size=\"" << mm(mark.size) << "\">" << mark.text << "</text>\n";
    }
    out << "</g>\n";
  }
  out << "</svg>\n";
  return out.str();
}

void dxfPair(std::ostringstream& out, int code, const std::string& value) { out << code << "\n" << value << "\n"; }

std::string dxfSheet(const std::vector<FlatPlate>& flats, const std::vector<Placement>& placements, int sheet) {
  std::ostringstream out;
  dxfPair(out, 0, "SECTION");
  dxfPair(out, 2, "HEADER");
  dxfPair(out, 9, "$ACADVER");
  dxfPair(out, 1, "AC1009");
  dxfPair(out, 9, "$INSUNITS");
  dxfPair(out, 70, "4");  // millimetres
  dxfPair(out, 0, "ENDSEC");
  dxfPair(out, 0, "SECTION");
  dxfPair(out, 2, "TABLES");
  dxfPair(out, 0, "TABLE");
  dxfPair(out, 2, "LAYER");
  dxfPair(out, 70, "3");
  for (const auto& [name, colour] :
       std::vector<std::pair<std::string, int>>{{"CUT_OUTER", 1}, {"CUT_INNER", 5}, {"ENGRAVE", 7}}) {
    dxfPair(out, 0, "LAYER");
    dxfPair(out, 2, name);
    dxfPair(out, 70, "0");
    dxfPair(out, 62, std::to_string(colour));
    dxfPair(out, 6, "CONTINUOUS");
  }
  dxfPair(out, 0, "ENDTAB");
  dxfPair(out, 0, "ENDSEC");
  dxfPair(out, 0, "SECTION");
  dxfPair(out, 2, "ENTITIES");
  auto polyline = [&](const Ring& ring, const char* layer) {
    dxfPair(out, 0, "POLYLINE");
    dxfPair(out, 8, layer);
    dxfPair(out, 66, "1");
    dxfPair(out, 70, "1");  // closed
    for (const Point2& p : ring) {
      dxfPair(out, 0, "VERTEX");
      dxfPair(out, 8, layer);
      dxfPair(out, 10, mm(p[0]));
      dxfPair(out, 20, mm(p[1]));
    }
    dxfPair(out, 0, "SEQEND");
    dxfPair(out, 8, layer);
  };
  for (const Placement& placement : placements) {
    if (placement.sheet != sheet) continue;
    const FlatPlate& flat = flats[placement.plate];
    for (const Ring& ring : flat.outlines) polyline(ring, "CUT_OUTER");
    for (const Ring& ring : flat.holes) polyline(ring, "CUT_INNER");
    for (const Mark& mark : flat.marks) {
      dxfPair(out, 0, "TEXT");
      dxfPair(out, 8, "ENGRAVE");
      dxfPair(out, 10, mm(mark.at[0] - mark.size * 0.3 * static_cast<double>(mark.text.size())));
      dxfPair(out, 20, mm(mark.at[1] - mark.size / 2));
      dxfPair(out, 40, mm(mark.size));
      dxfPair(out, 1, mark.text);
    }
  }
  dxfPair(out, 0, "ENDSEC");
  dxfPair(out, 0, "EOF");
  return out.str();
}

}  // namespace

CutFileFormat parseCutFileFormat(const std::string& name) {
  if (name == "svg") return CutFileFormat::Svg;
  if (name == "dxf") return CutFileFormat::Dxf;
  throwBadInput("", "unknown cut file format '" + name + "' (expected svg or dxf)");
}

void parseSheetSize(const std::string& text, CutSheetOptions* options) {
  const size_t x = text.find('x');
  double width = 0, height = 0;
  size_t usedW = 0, usedH = 0;
  try {
    if (x != std::string::npos) {
      width = std::stod(text.substr(0, x), &usedW);
      height = std::stod(text.substr(x + 1), &usedH);
    }
  } catch (const std::exception&) {
    usedW = 0;
  }
  if (x == std::string::npos || usedW != x || usedH != text.size() - x - 1 || !(width >= 10 && width <= 100000) ||
      !(height >= 10 && height <= 100000)) {
    throwBadInput("",
                  "the sheet size must be WIDTHxHEIGHT in mm, each 10 to 100000 (e.g. 600x400), got '" + text + "'");
  }
  options->sheetWidth = width;
  options->sheetHeight = height;
}

CutSheetOptions parseCutSheetOptionsJson(const std::string& text) {
  const nlohmann::json root = parseJsonText(text, "cut sheet options");
  if (!root.is_object()) throwBadInput("", "cut sheet options must be an object");
  CutSheetOptions options;
  auto number = [](const nlohmann::json& value, const std::string& name) {
    if (!value.is_number())
      throwBadInput("", "cut sheet option '" + name + "' must be a number of mm, got " + value.dump());
    return value.get<double>();
  };
  for (const auto& [name, value] : root.items()) {
    if (name == "sheet") {
      if (!value.is_string())
        throwBadInput("", "cut sheet option 'sheet' must be text such as \"600x400\", got " + value.dump());
      parseSheetSize(value.get<std::string>(), &options);
    } else if (name == "kerf") {
      options.kerf = number(value, name);
    } else if (name == "spacing") {
      options.spacing = number(value, name);
    } else if (name == "hairline") {
      if (!value.is_boolean())
        throwBadInput("", "cut sheet option 'hairline' must be true or false, got " + value.dump());
      options.hairline = value.get<bool>();
    } else if (name == "source") {
      if (!value.is_string()) throwBadInput("", "cut sheet option 'source' must be text");
      options.source = value.get<std::string>();
    } else {
      throwBadInput("", "unknown cut sheet option '" + name + "' (expected sheet, kerf, spacing, hairline or source)");
    }
  }
  return options;
}

std::vector<std::string> plateCutSheets(const AssemblyDocument& document, CutFileFormat format,
                                        const CutSheetOptions& options) {
  if (document.kind != AssemblyKind::Plate || document.plates.empty()) {
    throwBadInput(options.source, "cut files are made of plate structures (kind \"plate\" with \"plates\")");
  }
  if (!(options.kerf >= 0 && options.kerf <= 5)) throwBadInput(options.source, "the kerf must be 0 to 5 mm");
  if (!(options.spacing >= 0 && options.spacing <= 1000))
    throwBadInput(options.source, "the spacing must be 0 to 1000 mm");
  if ((options.sheetWidth > 0) != (options.sheetHeight > 0))
    throwBadInput(options.source, "a sheet needs a width and a height");
  const std::vector<Plate>& plates = document.fabricationPlates.empty() ? document.plates : document.fabricationPlates;
  for (const Plate& plate : plates) {
    if (!plate.attached.empty()) {
      // Milled joints (dovetails, mitre tenons and slides, face tenons): their solids are not 2D cuts.
      throwBadInput(options.source, "plate " + std::to_string(plate.id) + " carries " + std::to_string(plate.attached.size()) +
                                        " solid(s) of milled joints (its \"attached\": tongues, tenons, housing walls), "
                                        "which cut sheets cannot hold: export stl or obj for the CNC, or design with "
                                        "joints 'cut'");
    }
  }
  // A design read from its plates has them; a result's plates (its contacts are its joints') do not.
  const std::vector<PlateContact> contacts = document.contactsFromGeometry
                                                 ? document.plateContacts
                                                 : computePlateContacts(document.plates, document.plateOptions);
  std::vector<FlatPlate> flats;
  for (size_t k = 0; k < plates.size(); ++k) flats.push_back(flatten(plates, k, contacts, options.kerf, options.source));
  std::vector<Sheet> sheets;
  const std::vector<Placement> placements = pack(flats, options, &sheets);
  std::vector<std::string> files;
  for (size_t s = 0; s < sheets.size(); ++s) {
    files.push_back(format == CutFileFormat::Svg ? svgSheet(flats, placements, static_cast<int>(s), sheets[s], options,
                                                            static_cast<int>(sheets.size()))
                                                 : dxfSheet(flats, placements, static_cast<int>(s)));
  }
  return files;
}

}  // namespace desia
