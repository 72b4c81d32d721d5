// The start frame of Placement/Kind = dressing read off the body's landmarks (docs/dressing.md,
// "The frame from the landmarks"): the elliptic cylinder the panels are wrapped on goes round
// the torso's axis (body/body_measurements.h's PartFrame "torso"), its semi-axes clear the
// torso's section at a girth line as shrunk for the dressing, and the hem stands at a height
// stated from a landmark line ("armpit - 0.35"). Every entry may instead be a number or a
// vector, for an analytic body (a cylinder) that has no landmarks.
#pragma once

#include "bodies/panel_wrap.h"
#include "body/body_measurements.h"

#include <optional>
#include <string>
#include <vector>

namespace tightfit {

// The lines along the torso's axis a height may be stated from: crotch, hips, waist,
// under-bust, bust, armpit (the lower of the two), neck base.
const std::vector<std::string>& torso_line_names();
// The girth lines a semi-axis may be read at: hips, waist, under-bust, bust.
const std::vector<std::string>& torso_girth_line_names();

// "armpit - 0.35": a line of `lines` and an offset (m); or "0.02": a number alone (line empty).
struct LineOffset {
  std::string line;
  double offset_m = 0.0;
};
// Throws std::invalid_argument naming `entry`, the text and the known lines (did you mean) for
// text that is neither NUMBER nor LINE [+|- METRES].
LineOffset parse_line_offset(const std::string& text, const std::string& entry,
                             const std::vector<std::string>& lines);

// "torso" (nothing: the torso's own) or three numbers x,y,z. Throws std::invalid_argument
// naming `entry` otherwise.
std::optional<Vec3> parse_torso_or_vector(const std::string& text, const std::string& entry);

// The dressing frame's entries as written (Placement/Dressing: Centre, Axis, Front, Semi-axis
// side, Semi-axis front, Hem height), parsed.
struct DressingFrameSpec {
  std::optional<Vec3> centre, axis, front;  // nothing: the torso's
  std::string centre_line;                  // "torso at LINE": the torso axis's point there
  bool axis_vertical = false;               // "vertical": tightfit's z, the body's up
  LineOffset semi_axis_side, semi_axis_front, hem_height;
  // Whether any entry needs the body's landmarks.
  bool needs_landmarks() const;
};
// Throws std::invalid_argument naming the entry at fault (a zero axis, a line not known, a
// semi-axis that is no positive number).
DressingFrameSpec parse_dressing_frame(const std::string& centre, const std::string& axis,
                                       const std::string& front, const std::string& semi_side,
                                       const std::string& semi_front, const std::string& hem);

// The wrap's centre, axis, front, semi-axes and hem height (angles left empty). A semi-axis
// "LINE + C" is start_scale times the torso section's largest distance from the axis along that
// direction at the girth line LINE, plus C; a hem "LINE + H" is LINE's height along the axis
// from the centre, plus H. `body` may be null when no entry needs it. Throws std::invalid_argument
// naming the entry for a line the body does not have, a semi-axis that comes out non-positive
// or a front along the axis.
PanelWrap resolve_dressing_frame(const DressingFrameSpec& spec, const BodyMeasurements* body,
                                 double start_scale);

struct Scenario;
// The same on the scenario's body, measured (body/body_measurements.h) only when an entry needs
// it. Throws BodyMeasureError naming the landmark the body lacks.
PanelWrap dressing_frame_on_body(const DressingFrameSpec& spec, const Scenario& scenario,
                                 double start_scale);

// One line saying where the frame came from, for the run's log.
std::string describe_dressing_frame(const DressingFrameSpec& spec, const PanelWrap& wrap);

}  // namespace tightfit
