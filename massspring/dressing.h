// Dressing a body (docs/dressing.md): the garment's panels, unsewn, start round the body
// (wherever the caller put them, outside it), the body shrunk about a centre. Zero-rest-length
// seam springs, their stiffness ramped up from zero, pull every seam vertex pair together while
// the membrane, the bending springs and the penalty contact act, and the body grows back to its
// own shape; when every seam pair is closer than the closing gap and the body is whole, the
// seams are welded (each welded vertex at the mean of its copies) and the garment is handed to
// the load steps, which settle it as usual. It is the paper's flat-panel start (Section 4.3,
// FlatPanelStart) for any body and any pattern.
#pragma once

#include "bodies/skeleton_shrink.h"
#include "core/backend.h"
#include "core/pressure_field.h"
#include "massspring/massspring_parameters.h"

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace tightfit {

// The state a dressing stopped in when it fails (seams not closed, diverged, ran away): what a
// picture needs to show which part of the body holds a seam open.
struct DressingSnapshot {
  int frame = 0;
  double body_scale = 1.0;
  std::vector<Vec3> positions_m;    // every panel vertex (unwelded), numbered as problem.mesh's
  std::vector<Triangle> triangles;  // the panels' triangles on those vertices
  // Per panel vertex: the distance to its seam partner (the widest when it has several; 0 on
  // no seam), and its signed distance to the body at body_scale (negative inside), m.
  std::vector<double> seam_gap_m;
  std::vector<int> seam_partner;  // the vertex at that widest gap, -1 on no seam
  std::vector<double> body_distance_m;
  DisplayMesh body;  // the body at body_scale
};

struct DressingSettings {
  Vec3 centre_m = Vec3::Zero();  // the point the body is scaled about, or a point on the axis
  // About an axis (lengths along it kept: heights stay, the body thins) when given.
  std::optional<Vec3> scale_axis;
  // If given, the body shrinks about these bones instead, each part about its own axis
  // (bodies/skeleton_shrink.h; the body's mesh is its display mesh); centre and axis unused.
  std::vector<SkeletonBone> skeleton;
  double skeleton_blend_m = 0.03;  // SkeletonShrink's blend width, m
  // The arms turned away from the torso by this angle at the start scale, and back as the body
  // grows (SkeletonShrink::set_arm_raise), radians; the torso's direction along skeleton[0]'s
  // bone named "torso" (z when there is none).
  double skeleton_arm_raise_rad = 0.0;
  bool skeleton_shortens_torso = false;  // SkeletonShrink::set_torso_shortening
  double start_scale = 0.7;              // the body's scale at the first frame (0, 1]
  int growth_frames = 2000;              // frames over which the scale rises linearly to 1
  // The body grows only on frames when every seam pair is closer than this fraction of the mean
  // rest edge (the growth waits for the seams); 0: it grows on every frame.
  double growth_gap_fraction = 0.0;
  int seam_ramp_frames = 500;  // frames over which the seam stiffness rises linearly to full
  // The seams are closed when every seam vertex pair is closer than this fraction of the mean
  // rest edge length (welding then moves no vertex by more than half of that).
  double closed_fraction = 0.05;
  // A welded vertex inside the whole body by at most this fraction of the mean rest edge length
  // (the penalty's own depth, p / k) is put back on the surface; a deeper one has passed
  // through the body and the dressing fails.
  double inside_fraction = 0.25;
  // The dressing's motion need not be true in time, only end where the forces balance: the
  // particles stiffer for their mass than this many times the median one are made heavier
  // (OpenSeamGarment::limit_stiffness_over_mass), so that the time step follows the typical
  // particle and the garment can move as far as the body's growth asks within the frames.
  // 0: true masses.
  double stiffness_over_mass_ratio = 0.0;
  // Each seam spring pulls no harder than the full spring does at the closing gap (a constant
  // pull beyond it), so that a seam far open draws its panel along instead of tearing its
  // vertices out of it. false: linear springs at any gap.
  bool limit_seam_pull = false;
  // With the limit, a pair drawn shut is sewn: its spring linear and this many times stiffer, so
  // that the tension of a tight garment holds it closer (its gap T h / k). The particles it
  // makes stiffer are made heavier by the mass scaling above, not the time step shorter.
  double sewn_stiffness_factor = 1.0;
  int maximum_frames = 40000;
  // Time step, damping, quasi-static frames, bending and the seam springs' stiffness factor.
  MassSpringParameters mass_spring;
  // If given, a line every this many frames: frame, body scale, seam ramp, widest gap.
  std::ostream* progress = nullptr;
  int progress_frames = 1000;
  // If given, called with the state the dressing stopped in before it throws SolverError; the
  // text it returns (say, where it wrote that state) is added to the error's message.
  std::function<std::string(const DressingSnapshot&)> on_failure;
};

// Seams that start far apart (the panels where a pattern file arranges them, decimetres from
// their partners; docs/cookbook-jumpsuit.md): heavier stiff particles (ratio 4), a limited seam
// pull, pairs sewn once drawn shut (twice as stiff), and a body that grows only while every seam
// is within a mean edge. The placements whose panels start wrapped close round the body keep
// the plain springs (the defaults above).
void draw_seams_from_afar(DressingSettings& settings);

struct DressingResult {
  std::vector<Vec3> welded_positions_m;
  int frames = 0;
  double largest_seam_gap_m = 0.0;  // at the last frame, before welding
  double closed_below_m = 0.0;      // the threshold it met
  // Welded vertices inside the whole body after welding, put back on its surface, and the
  // largest depth among them, m.
  int vertices_put_back = 0;
  double deepest_m = 0.0;
  // Start vertices found inside the shrunk body and pushed out along its normal, and the
  // deepest of them, m.
  int vertices_pushed_out = 0;
  double deepest_push_m = 0.0;
  double wall_seconds = 0.0;
};

// Dresses `problem.body` (the whole body; it must outlive the call) in `garment` (whose welded
// mesh is problem.mesh) from the unwelded positions `start_m` (panel vertices, numbered as
// problem.mesh's). A start vertex inside the shrunk body is pushed out along the body's normal
// by its depth (plus a tenth of a mean edge). Throws SolverError when the seams have not closed
// within the frames (naming the seam with the widest gap, the gap and where), when the motion
// diverges, or when a vertex ends inside the body (which, how deep, where);
// std::invalid_argument for a start of the wrong size or a vertex that starts inside the shrunk
// body deeper than half the garment's size (the square root of its rest area).
DressingResult dress(const Problem& problem, const Garment& garment,
                     const std::vector<Vec3>& start_m, const DressingSettings& settings);

// "front:3 -- back:3 mirrored": the seam of `garment` that joins unwelded vertices a and b of
// its welded mesh, or the two panels and vertices when no seam lists them both.
std::string seam_joining(const Garment& garment, const SimulationMesh& mesh, int a, int b);

}  // namespace tightfit
