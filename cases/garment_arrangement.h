// The automatic arrangement of a garment's panels round a body (Placement/Kind = arrangement;
// docs/arrangement.md, "Any body: the arrangement"): each panel is assigned to a side of the
// torso, by the case's short list ("front: torso front, back: torso back") or by its name, and
// wrapped on an elliptic cylinder round the torso's own axis (body/body_measurements.h's
// PartFrame) that clears the body shrunk for the dressing by a share of its girth; each panel's
// height comes from the landmarks: the top of its side seam (its most upright seam to another
// torso panel) a little below the armpits. No coordinate comes from the case.
//
// The ease against the body (docs/arrangement.md, "Ease against the body"): the pattern's width
// round the body at a girth line (the sum of its torso panels' widths at that line's height, as
// arranged) over the body's girth there, less one.
#pragma once

#include "bodies/panel_wrap.h"
#include "body/body_measurements.h"
#include "core/garment.h"

#include <map>
#include <string>
#include <vector>

namespace tightfit {

// The body parts a panel can be assigned to; the torso's four sides are where its middle goes
// round the torso's axis (front 0 degrees, left 90, back 180, right 270).
const std::vector<std::string>& arrangement_body_parts();

struct ArrangementOptions {
  // Panel name -> body part (arrangement_body_parts()); a panel not named here is assigned by
  // its name (arrangement_part_from_name), and a garment none of whose panels is assigned
  // either way goes evenly round the torso in the file's order.
  std::map<std::string, std::string> parts;
  double start_scale = 0.7;  // the body's scale about the torso's axis at the dressing's start
  // The cylinder's clearance outside the shrunk torso, a share of the largest torso girth's
  // mean radius (girth / 2 pi).
  double clearance = 0.1;
  double side_seam_below_armpit_m = 0.03;  // the side seams' tops below the lower armpit, m
};

struct ArrangementPlan {
  PanelWrap wrap;                        // round the torso's axis, one angle and hem per panel
  std::vector<std::string> panel_parts;  // the body part of each panel
  double armpit_level_m = 0.0;           // along the axis from wrap.centre_m
  std::string description;               // one line: where each panel went
};

// "front: torso front, back: torso back" (a list already split at the commas) -> by panel.
// Throws std::invalid_argument naming an entry that is not PANEL: PART or an unknown part.
std::map<std::string, std::string> parse_arrangement_parts(const std::vector<std::string>& words);

// The body part a panel's name says ("front", "back", "side left", ...), or "" if none.
std::string arrangement_part_from_name(const std::string& panel_name);

// Throws std::invalid_argument for a panel assigned to a limb (the dressing shrinks the body
// about the torso's axis alone, where no sleeve or leg finds room), a part name of `options`
// that names no panel of the garment, or a torso without the girths it needs.
ArrangementPlan plan_arrangement(const Garment& garment, const BodyMeasurements& body,
                                 const ArrangementOptions& options);

// The panel's width along pattern x at pattern height y (the sum of the intervals its
// triangles cut from that line), m.
double panel_width_at_m(const Panel& panel, double y_m);

// The ease against the body asked for at one girth line: "bust: -0.15".
struct BodyEase {
  std::string line;   // a girth of body_measurements: bust, under-bust, waist, hips
  double ease = 0.0;  // garment round the body over the body's girth, less one
};
BodyEase parse_body_ease(const std::string& text);  // throws std::invalid_argument

struct EaseAtLine {
  std::string line;
  double girth_m = 0.0;    // the body's (a tape's) girth
  double garment_m = 0.0;  // the torso panels' widths at the line's height, summed
  double ease = 0.0;       // garment / girth - 1
};

// The torso girth lines (bust, under-bust, waist, hips) that every torso panel of the arranged
// garment reaches, with the garment's width round the body there.
std::vector<EaseAtLine> ease_at_girth_lines(const Garment& garment, const ArrangementPlan& plan,
                                            const BodyMeasurements& body);

// The factor on pattern x (round the body) that gives `ease` at its line. Throws
// std::invalid_argument when the body has no such girth or the garment does not reach it.
double round_body_scale_for(const BodyEase& ease, const Garment& garment,
                            const ArrangementPlan& plan, const BodyMeasurements& body);

// Every panel's pattern x scaled by `factor` about the panel's middle.
void scale_panels_round_body(Garment& garment, double factor);

}  // namespace tightfit
