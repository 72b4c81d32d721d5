#include "pattern/boundary_chain.h"

#include "core/plain_text.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace tightfit::pattern {

namespace {

std::string length_text(double d) {
  char text[40];
  std::snprintf(text, sizeof text, "%.4g", d);
  return text;
}

std::vector<Segment> reversed_chain(const std::vector<Segment>& segments) {
  std::vector<Segment> r;
  for (auto s = segments.rbegin(); s != segments.rend(); ++s) r.push_back(reversed(*s));
  return r;
}

// The segment with its start moved to `x` (a gap within the tolerance closed). An arc keeps
// its centre and end; its sweep follows the moved start.
Segment started_at(Segment s, const Vec2& x) {
  if (s.kind == Segment::Kind::arc) {
    const Vec2 a = s.start - s.centre, b = x - s.centre;
    s.sweep_rad -= std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
  s.start = x;
  return s;
}

bool closes_on_itself(const BoundaryRun& run, double tolerance) {
  return run.closed || (run.segments.size() >= 2 &&
                        (run.segments.back().end - run.segments.front().start).norm() <= tolerance);
}

}  // namespace

double boundary_size(const std::vector<BoundaryRun>& runs) {
  Vec2 low = Vec2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const BoundaryRun& run : runs)
    for (const Segment& s : run.segments)
      for (int k = 0; k <= 8; ++k) {
        const Vec2 x = point_at(s, k / 8.0);
        low = low.cwiseMin(x);
        high = high.cwiseMax(x);
      }
  return (high - low).allFinite() ? (high - low).norm() : 0.0;
}

ChainedBoundary chain_boundary(const std::vector<BoundaryRun>& runs, double tolerance,
                               const std::string& where) {
  ChainedBoundary chain;
  if (runs.empty()) throw PatternError(where + ": no boundary");
  for (const BoundaryRun& run : runs)
    if (run.segments.empty()) throw PatternError(where + ": " + run.what + " has no segment");
  const std::string tolerance_note =
      " (joins are closed up to " + length_text(tolerance) + ", 1/1000 of the piece's size)";
  if (runs.size() > 1)
    for (const BoundaryRun& run : runs)
      if (closes_on_itself(run, tolerance))
        throw PatternError(where + ": " + run.what +
                           " is a closed loop of its own besides the other boundary entities "
                           "(one piece, one outline)");

  std::vector<bool> used(runs.size(), false);
  auto append = [&](const std::vector<Segment>& segments) {
    for (std::size_t k = 0; k < segments.size(); ++k) {
      chain.segments.push_back(k == 0 && !chain.segments.empty()
                                   ? started_at(segments[k], chain.segments.back().end)
                                   : segments[k]);
      chain.starts_run.push_back(k == 0);
    }
  };
  append(runs[0].segments);
  used[0] = true;
  std::string last_what = runs[0].what;
  for (std::size_t joined = 1; joined < runs.size(); ++joined) {
    const Vec2 end = chain.segments.back().end;
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_run = 0;
    bool best_reversed = false;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      if (used[r]) continue;
      const double to_start = (runs[r].segments.front().start - end).norm();
      const double to_end = (runs[r].segments.back().end - end).norm();
      if (to_start < best) best = to_start, best_run = r, best_reversed = false;
      if (to_end < best) best = to_end, best_run = r, best_reversed = true;
    }
    const BoundaryRun& next = runs[best_run];
    if (!(best <= tolerance)) {
      const Vec2 other = best_reversed ? next.segments.back().end : next.segments.front().start;
      throw PatternError(where + ": the boundary has a gap: " + last_what + " ends at " +
                         point_text(end) + ", the nearest free end is " + next.what + "'s " +
                         (best_reversed ? "end " : "start ") + point_text(other) + ", " +
                         length_text(best) + " away" + tolerance_note);
    }
    append(best_reversed ? reversed_chain(next.segments) : next.segments);
    used[best_run] = true;
    last_what = next.what;
  }
  const Vec2 start = chain.segments.front().start, end = chain.segments.back().end;
  const double gap = (end - start).norm();
  if (runs.size() == 1 && runs[0].closed) {
    // Flagged closed: the closing segment is already there.
  } else if (!(gap <= tolerance)) {
    throw PatternError(
        where + ": the boundary is open: " +
        (runs.size() == 1 ? "it" : "the chain of " + std::to_string(runs.size()) + " entities") +
        " starts at " + point_text(start) + " (" + runs[0].what + ") and ends at " +
        point_text(end) + " (" + last_what + "), " + length_text(gap) + " apart" + tolerance_note);
  }
  // Close exactly: the first segment starts where the last ends.
  if (gap > 0 && gap <= tolerance && chain.segments.size() > 1)
    chain.segments.front() = started_at(chain.segments.front(), end);
  else if (gap > 0 && gap <= tolerance) {
    chain.segments.push_back(line_segment(end, start));  // a single segment cannot close
    chain.starts_run.push_back(false);
  }
  return chain;
}

}  // namespace tightfit::pattern
