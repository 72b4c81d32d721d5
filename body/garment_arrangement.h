// A garment placed as its pattern file arranges it (GarmentCode's panels carry their 3D place
// round the file's own body), moved onto another body by the landmarks, and the skeleton the
// dressing shrinks that body about (docs/arrangement.md "Arrangement from the pattern file").
#pragma once

#include "bodies/skeleton_shrink.h"
#include "body/body_measurements.h"
#include "core/garment.h"

#include <string>
#include <vector>

namespace tightfit {

// The file's frame to the body's: p' = body_origin + S (frame (p - 0) - reference_origin),
// S = diag(across, across, vertical) in tightfit's frame (z up).
struct ArrangementFit {
  Mat3 frame = Mat3::Identity();           // the file's axes turned into tightfit's (z up)
  Vec3 reference_origin_m = Vec3::Zero();  // the reference body's torso root (at the crotch)
  Vec3 body_origin_m = Vec3::Zero();       // the case body's
  double vertical = 1.0;  // the torso's length (crotch to neck base), body over reference
  double across = 1.0;    // the mean of the bust, waist and hip girths' ratios, body over reference

  Vec3 operator()(const Vec3& file_point_m) const;
};

// The fit that puts the reference body's torso on the body's: its root on the body's, its
// length and girths scaled to the body's. Throws std::out_of_range when a measurement it reads
// is missing.
ArrangementFit fit_arrangement(const Mat3& frame, const BodyMeasurements& reference,
                               const BodyMeasurements& body);
// No reference body: the file's arrangement taken as it is, only turned into tightfit's frame.
ArrangementFit unfitted_arrangement(const Mat3& frame);

// Every panel vertex (unwelded, numbered as mesh's) at its arranged place, flat. Throws
// std::invalid_argument naming the first panel the file gives no arrangement.
std::vector<Vec3> arranged_positions(const Garment& garment, const SimulationMesh& mesh,
                                     const ArrangementFit& fit);

// The body's part axes as bones: the torso from the crotch to the neck base, each arm from the
// shoulder to the hand's end, each leg from the crotch to the floor.
std::vector<SkeletonBone> skeleton_bones(const BodyMeasurements& body);

}  // namespace tightfit
