// A piece's boundary written as several entities (polylines, lines, arcs, splines), chained
// end to start into one closed outline whatever order and direction they come in
// (docs/patterns.md, AAMA DXF).
#pragma once

#include "pattern/pattern.h"

#include <string>
#include <vector>

namespace tightfit::pattern {

// One entity of a boundary: its segments end to start, in the file's units.
struct BoundaryRun {
  std::string what;  // "POLYLINE 2": how the message names it
  std::vector<Segment> segments;
  bool closed =
      false;  // flagged closed by the file (a polyline): its last segment is the closing one
};

struct ChainedBoundary {
  std::vector<Segment> segments;  // a closed loop, each starting exactly where the one before ends
  std::vector<bool> starts_run;   // per segment: it begins an entity (joints between entities)
};

// Chains `runs` into one closed loop: from the first run's end, the run whose start or end
// lies nearest is joined next (reversed when it is its end), each join closing a gap of at
// most `tolerance` (in the file's units) by moving the joined run's first point. A larger
// gap, at a join or between the last end and the first start, throws PatternError naming
// `where`, the two ends and the gap; so does a run closed on itself among others.
ChainedBoundary chain_boundary(const std::vector<BoundaryRun>& runs, double tolerance,
                               const std::string& where);

// The bounding box's diagonal of the runs' points (ends and control points), file units.
double boundary_size(const std::vector<BoundaryRun>& runs);

}  // namespace tightfit::pattern
