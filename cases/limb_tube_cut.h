// A tube cut to a limb from the body's landmarks (docs/stocking.md, "Cut to the leg"): its
// extent along the limb's axis between two measuring points with offsets ("from 2 cm below B
// to 4 cm above G"), the limb's tape girths on sections normal to the axis at heights along
// it, and a negative ease stated at measuring points. Garment/Kind = limb tube builds its
// tapered tube (core/tapered_tube_garment.h) from this; `tightfit design` reads its points.
#pragma once

#include "body/body_measurements.h"
#include "core/tapered_tube_garment.h"

#include <string>
#include <vector>

namespace tightfit {

// "B - 0.02": a measuring point and an offset up the limb's axis (m).
struct LimbTubeEnd {
  std::string point = "B";
  double offset_m = 0.0;
};
// Throws std::invalid_argument naming `entry` for text that is not POINT [+|- METRES] with a
// point of leg_point_names().
LimbTubeEnd parse_limb_tube_end(const std::string& text, const std::string& entry);

struct PointValue {
  std::string point;
  double value = 0.0;
};
// "B: 0.25, G: 0.18". Throws std::invalid_argument naming `entry`, the piece and why.
std::vector<PointValue> parse_point_values(const std::string& text, const std::string& entry);

struct LimbTubeSpec {
  int side = 0;  // leg left (0), leg right (1)
  LimbTubeEnd from{"B", -0.02}, to{"G", 0.04};
  double girth_step_m = 0.05;             // the girth table's spacing along the tube
  std::vector<PointValue> negative_ease;  // at measuring points; empty: none
};

// The spec from the entries of Garment/Limb tube as written (Limb, From, To, Girth step,
// Negative ease). Throws std::invalid_argument naming the entry at fault.
LimbTubeSpec parse_limb_tube_spec(const std::string& limb, const std::string& from,
                                  const std::string& to, double girth_step_m,
                                  const std::string& negative_ease);

struct LimbTubeCut {
  Vec3 bottom_m = Vec3::Zero();  // the axis's point at the tube's bottom edge
  Vec3 up = Vec3::UnitZ();       // the limb's axis, unit, up the limb
  double length_m = 0.0;
  PiecewiseLinear girths_m;        // the limb's tape girths at heights H along the tube
  PiecewiseLinear negative_ease;   // at the heights of its points; no points: none
  std::vector<PointValue> points;  // the measuring points within the tube: name, H (m)
  Vec3 middle_m() const { return bottom_m + 0.5 * length_m * up; }
  // The height of a measuring point along the tube; throws std::invalid_argument if it is not
  // within the tube.
  double height_of(const std::string& point) const;
};

// The cut along the axis through `axis_point_m` along `up`, the measuring points given by their
// axial coordinates (up . x, in order up the limb). Girths at the tube's ends, every
// girth_step_m from its bottom edge and at every point within it (a step knot within 5 mm of
// a point gives way to it). Throws std::invalid_argument naming the entry (From, To, Negative
// ease) at fault: an unknown or missing point, a tube of no length, an ease point outside the
// tube or an ease outside (-1, 1); BodyMeasureError when a section misses the limb.
LimbTubeCut cut_tube_along_axis(const TriangleSurface& surface, const Vec3& axis_point_m,
                                const Vec3& up, const std::vector<PointValue>& axial_points,
                                const LimbTubeSpec& spec);

// A line along a leg of a body: through the centroids of the leg's sections (normal to its own
// axis, body_measurements.h's PartFrame) at two of its measuring points (body/
// leg_measuring_points.h), and every measuring point's axial coordinate along it.
struct LegLine {
  Vec3 point_m = Vec3::Zero();    // the centroid at the lower point
  Vec3 up = Vec3::UnitZ();        // unit, up the leg
  std::vector<PointValue> axial;  // up . x of each measuring point's place on the leg's axis
  // The axial coordinate of a point and offset; throws std::invalid_argument naming `entry`
  // when the point is not found on the leg.
  double axial_at(const LimbTubeEnd& end, const std::string& entry) const;
  Vec3 at(double axial_m) const { return point_m + (axial_m - up.dot(point_m)) * up; }
};
// Leg `side` (0 left, 1 right) through its points `low` and `high` (B and G span a stocking).
// Throws BodyMeasureError when a section it needs misses the leg.
LegLine leg_line(const TriangleSurface& surface, const BodyMeasurements& body, int side,
                 const std::string& low, const std::string& high);

// The same on a body's leg, along leg_line through the From and To points. Throws
// BodyMeasureError saying what cannot be found.
LimbTubeCut cut_tube_to_leg(const TriangleSurface& surface, const BodyMeasurements& body,
                            const LimbTubeSpec& spec);

}  // namespace tightfit
