// SPDX-License-Identifier: GPL-3.0-or-later
// The contacts between plates (computePlateContacts): faces lying on one another with opposite
// outward normals and an overlap of positive area, and the crossings of plates that pass through
// each other; the overlap of two coplanar faces is a 2D polygon intersection by Clipper.
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include "analysis/vec3.h"
#include "desia/error.h"
#include "desia/plate.h"
#include "desia/tolerances.h"
#include "plate/normal_classes.h"
#include "plate/plane_frame.h"
#include "plate/plate_overlaps.h"
#include "plate/plate_shape.h"
#include "plate/plate_solid.h"

namespace desia {
namespace {

using geometry::Box;
using geometry::boxOf;
using geometry::maxDistanceToPlane;
using geometry::SolidFace;
using geometry::solidFaces;
using geometry::plateCrossing;
using geometry::requireMitredPerpendicularApart;
using geometry::requireNoSlantedOverlap;

std::vector<PlateContact> contactsOfSolids(const std::vector<Plate>& plates, const std::vector<int>& owner,
                                           size_t firstAttached, const PlateOptions& options);
}  // namespace

// Plates with attached solids (milled joints): every solid on its own, solids of one plate never
// in contact with each other, each contact then given to the solids' plates.
std::vector<PlateContact> computePlateContacts(const std::vector<Plate>& plates, const PlateOptions& options) {
  std::vector<Plate> solids;
  std::vector<int> owner;
  for (size_t p = 0; p < plates.size(); ++p) {
    solids.push_back(plates[p]);
    solids.back().attached.clear();
    owner.push_back(static_cast<int>(p));
  }
  for (size_t p = 0; p < plates.size(); ++p) {
    for (const Plate& solid : plates[p].attached) {
      solids.push_back(solid);
      solids.back().id = plates[p].id;
      solids.back().name = plates[p].name;
      owner.push_back(static_cast<int>(p));
    }
  }
  std::vector<PlateContact> contacts = contactsOfSolids(solids, owner, plates.size(), options);
  snapContactNormals(&contacts);
  if (solids.size() == plates.size()) return contacts;
  for (PlateContact& contact : contacts) {
    contact.a = owner[contact.a];
    contact.b = owner[contact.b];
    if (contact.a > contact.b) {  // pairs in plate order, the normal from a into b
      std::swap(contact.a, contact.b);
      contact.normal = negated(contact.normal);
      std::swap(contact.aOpens, contact.bOpens);
      std::swap(contact.aOverhang, contact.bOverhang);
    }
  }
  // In a fixed order: by plate pair, then as found.
  std::stable_sort(contacts.begin(), contacts.end(), [](const PlateContact& x, const PlateContact& y) {
    return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return contacts;
}

namespace {

// A face's loops in a frame's integer coordinates, with their bounds: a face with hundreds of holes
// (a long table's top, a mortise for each panel) meets each panel at a few of them. Loops whose
// bounds miss the other face's change nothing in the even-odd intersection with it and are left
// out (the top of a LONG TABLE of 1,002 plates gave Clipper all 2,000 of its loops for each panel).
struct FlatLoops {
  struct Bounds {
    ClipperLib::cInt loX = 0, loY = 0, hiX = -1, hiY = -1;
    bool meets(const Bounds& o) const { return loX <= o.hiX && o.loX <= hiX && loY <= o.hiY && o.loY <= hiY; }
  };
  FlatLoops(const std::vector<Loop>& loops, const PlaneFrame& frame) : paths(clipperPaths(loops, frame)) {
    for (const ClipperLib::Path& path : paths) {
      Bounds b{path[0].X, path[0].Y, path[0].X, path[0].Y};
      for (const ClipperLib::IntPoint& point : path) {
        b.loX = std::min(b.loX, point.X), b.hiX = std::max(b.hiX, point.X);
        b.loY = std::min(b.loY, point.Y), b.hiY = std::max(b.hiY, point.Y);
      }
      loopBounds.push_back(b);
      bounds = loopBounds.size() == 1 ? b : Bounds{std::min(bounds.loX, b.loX), std::min(bounds.loY, b.loY),
                                                   std::max(bounds.hiX, b.hiX), std::max(bounds.hiY, b.hiY)};
    }
  }
  // The loops whose bounds meet `other`, in their order.
  ClipperLib::Paths near(const Bounds& other) const {
    ClipperLib::Paths kept;
    for (size_t k = 0; k < paths.size(); ++k) {
      if (loopBounds[k].meets(other)) kept.push_back(paths[k]);
    }
    return kept;
  }
  ClipperLib::Paths paths;
  std::vector<Bounds> loopBounds;
  Bounds bounds;
};

// Solids from `firstAttached` on are attached solids (milled joint pieces, built from the joint's
// exact directions); a cut plate's faces come from a 2D boolean on a 1e-4 mm grid. Where the two
// meet, the attached solid's face gives the contact's normal: a wall the grid turned by 1e-5 rad
// would otherwise block a tenon sliding along it (a mitre tenon leaving its pocket).
std::vector<PlateContact> contactsOfSolids(const std::vector<Plate>& plates, const std::vector<int>& owner,
                                           size_t firstAttached, const PlateOptions& options) {
  const double tolerance = options.contactTolerance;
  std::vector<std::vector<SolidFace>> faces;
  std::vector<Box> boxes;
  std::vector<Vec3> axes;
  for (const Plate& plate : plates) {
    faces.push_back(solidFaces(plate));
    boxes.push_back(boxOf(plate));
    axes.push_back(plateThicknessAxis(plate));
  }
  std::vector<PlateContact> contacts;
  for (size_t p = 0; p < plates.size(); ++p) {
    for (size_t q = p + 1; q < plates.size(); ++q) {
      if (owner[p] == owner[q] || !boxes[p].touches(boxes[q], tolerance)) continue;
      for (const SolidFace& f : faces[p]) {
        const PlaneFrame frame(f.loops[0][0], f.normal);
        std::optional<FlatLoops> fFlat;
        for (const SolidFace& g : faces[q]) {
          if (dot(f.normal, g.normal) > -0.999) continue;                // not facing each other
          if (maxDistanceToPlane(g.loops, frame) > tolerance) continue;  // not in one plane
          if (!fFlat) fFlat = FlatLoops(f.loops, frame);
          const FlatLoops gFlat(g.loops, frame);
          ClipperLib::Clipper clipper;
          clipper.AddPaths(fFlat->near(gFlat.bounds), ClipperLib::ptSubject, true);
          clipper.AddPaths(gFlat.near(fFlat->bounds), ClipperLib::ptClip, true);
          ClipperLib::Paths overlap;
          clipper.Execute(ClipperLib::ctIntersection, overlap, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
          double area = 0;
          const ClipperLib::Path* largest = nullptr;
          for (const ClipperLib::Path& path : overlap) {
            const double a = ClipperLib::Area(path) / (kClipperScale * kClipperScale);
            area += a;
            if (!largest || std::abs(a) > std::abs(ClipperLib::Area(*largest)) / (kClipperScale * kClipperScale))
              largest = &path;
          }
          if (area <= tolerance * tolerance) continue;
          PlateContact contact;
          contact.a = static_cast<int>(p);
          contact.b = static_cast<int>(q);
          const bool otherIsExact = p < firstAttached && q >= firstAttached;
          contact.normal = *cleanedNormal(otherIsExact ? negated(g.normal) : f.normal);
          contact.area = area;
          for (const ClipperLib::IntPoint& point : *largest) contact.region.push_back(frame.fromClipper(point));
          Vec3 edge = cross(axes[p], axes[q]);
          if (norm(edge) < tolerance::kParallelSine) {
            // Parallel plates meet edge to edge: the shared edge runs along the contact's longest side.
            for (size_t i = 0; i < contact.region.size(); ++i) {
              const Vec3 side = minus(contact.region[(i + 1) % contact.region.size()], contact.region[i]);
              if (norm(side) > norm(edge)) edge = side;
            }
          }
          contact.edgeDirection = canonicalSign(normalized(edge));
          contacts.push_back(contact);
        }
      }
      if (std::optional<PlateContact> crossing =
              plateCrossing(plates, static_cast<int>(p), static_cast<int>(q), tolerance)) {
        contacts.push_back(*crossing);
        continue;  // plates crossing at any angle share the volume of their crossing, and only that
      }
      requireNoSlantedOverlap(plates[p], plates[q], tolerance);
      requireMitredPerpendicularApart(plates[p], plates[q], tolerance);
    }
  }
  return contacts;
}

}  // namespace

}  // namespace desia
