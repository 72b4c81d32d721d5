// The dressing stage (docs/dressing.md): a garment's panels, unsewn round a body shrunk about a
// centre, an axis or its skeleton, sewn onto it while the body grows back to its own shape; the
// welded garment is the start of the load steps, on either backend. What the stage is asked
// and answers is written here, free of any backend; a backend that can dress implements
// DressingStage and hands it to the backend registry (core/backend_registry.h), through which
// the placements that dress (cases/parts/) reach it.
#pragma once

#include "core/backend.h"
#include "core/pressure_field.h"
#include "core/skeleton_bone.h"

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

// How the garment is dressed. A frame is one step of the stage's motion (an RK4 frame of the
// mass-spring backend's dressing, massspring/dressing.h).
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
  // particles stiffer for their mass than this many times the median one are made heavier, so
  // that the time step follows the typical particle and the garment can move as far as the
  // body's growth asks within the frames. 0: true masses.
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
  // Each zero-rest-length seam spring's full stiffness is this times the law's stiffness scale
  // (N/m), dimensionless. A seam vertex pair balances the hoop pull T h (T the tension, h the
  // vertex's length of seam) at a gap T h / k: the default keeps that gap a few percent of an
  // edge up to 50% strain.
  double seam_stiffness_factor = 20.0;
  // Mass-proportional damping while the seams close, 1/s; 0: the automatic one, critical for
  // the garment's slowest membrane wave.
  double damping_per_s = 0.0;
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

// A quick settle of a dressed garment, as a load step would settle it (gravity, friction) on
// the dressing backend with its default settings for the body (rough_mesh_body) but this stop
// rule: the rms residual below `relative_tolerance` times the tension scale, no contact
// multiplier updates, and the net force rule (0: the backend's default) and slide damping of
// the load steps (docs/dressing.md, "Coarse to fine").
struct CoarseSettle {
  double relative_tolerance = 0.0;   // 0: the coarse garment is carried as dressed
  double net_force_tolerance = 0.0;  // Mass spring/Net force tolerance of the settle (0: default)
  double slide_damping_per_s = 0.0;  // Mass spring/Slide damping of the settle
  // The case's body is a rough mesh body (StopRule::rough_mesh_body: flat faces, or friction):
  // the settle takes the backend's defaults for it.
  bool rough_mesh_body = false;
};

struct SettledGarment {
  std::vector<Vec3> positions_m;  // welded vertices, m
  StepReport report;
};

class DressingStage {
 public:
  virtual ~DressingStage() = default;
  // Dresses `problem.body` (the whole body; it must outlive the call) in `garment` (whose
  // welded mesh is problem.mesh) from the unwelded positions `start_m` (panel vertices,
  // numbered as problem.mesh's). A start vertex inside the shrunk body is pushed out along the
  // body's normal by its depth (plus a tenth of a mean edge). Throws SolverError when the seams
  // have not closed within the frames (naming the seam with the widest gap, the gap and
  // where), when the motion diverges, or when a vertex ends inside the body (which, how deep,
  // where); std::invalid_argument for a start of the wrong size or a vertex that starts inside
  // the shrunk body deeper than half the garment's size (the square root of its rest area).
  virtual DressingResult dress(const Problem& problem, const Garment& garment,
                               const std::vector<Vec3>& start_m,
                               const DressingSettings& settings) const = 0;
  // Settles the welded garment from `dressed_m` through the load step `step` under `rule`
  // (whose relative tolerance is above 0). Throws SolverError as Backend::solve does.
  virtual SettledGarment settle(const Problem& problem, const std::vector<Vec3>& dressed_m,
                                const LoadStep& step, const CoarseSettle& rule) const = 0;
};

}  // namespace tightfit
