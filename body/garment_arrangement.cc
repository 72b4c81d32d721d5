#include "body/garment_arrangement.h"

#include <stdexcept>

namespace tightfit {

Vec3 ArrangementFit::operator()(const Vec3& file_point_m) const {
  const Vec3 d = frame * file_point_m - reference_origin_m;
  return body_origin_m + Vec3(across * d.x(), across * d.y(), vertical * d.z());
}

namespace {

double torso_length_m(const BodyMeasurements& body) {
  return body.landmark("neck base").point_m.z() - body.part("torso").origin_m.z();
}

}  // namespace

ArrangementFit fit_arrangement(const Mat3& frame, const BodyMeasurements& reference,
                               const BodyMeasurements& body) {
  ArrangementFit fit;
  fit.frame = frame;
  fit.reference_origin_m = reference.part("torso").origin_m;
  fit.body_origin_m = body.part("torso").origin_m;
  fit.vertical = torso_length_m(body) / torso_length_m(reference);
  double ratios = 0.0;
  const char* lines[] = {"bust", "waist", "hips"};
  for (const char* line : lines) ratios += body.girth(line).girth_m / reference.girth(line).girth_m;
  fit.across = ratios / 3.0;
  return fit;
}

ArrangementFit unfitted_arrangement(const Mat3& frame) {
  ArrangementFit fit;
  fit.frame = frame;
  return fit;
}

std::vector<Vec3> arranged_positions(const Garment& garment, const SimulationMesh& mesh,
                                     const ArrangementFit& fit) {
  std::vector<Vec3> x(mesh.n_unwelded_vertices());
  for (std::size_t p = 0; p < garment.panels.size(); ++p) {
    const Panel& panel = garment.panels[p];
    if (!panel.arrangement)
      throw std::invalid_argument("panel '" + panel.name +
                                  "' has no 3D arrangement in its pattern file (GarmentCode's "
                                  "panels give theirs as translation and rotation)");
    for (std::size_t i = 0; i < panel.rest_positions_m.size(); ++i) {
      const Vec2& r = panel.rest_positions_m[i];
      x[mesh.panel_vertex_offset[p] + i] = fit(
          panel.arrangement->rotation * Vec3(r.x(), r.y(), 0.0) + panel.arrangement->translation_m);
    }
  }
  return x;
}

std::vector<SkeletonBone> skeleton_bones(const BodyMeasurements& body) {
  std::vector<SkeletonBone> bones;
  for (const PartFrame& part : body.parts) {
    double length = part.length_m;
    if (part.name == "torso") length = torso_length_m(body);
    bones.push_back({part.name, part.origin_m, part.origin_m + length * part.along});
  }
  return bones;
}

}  // namespace tightfit
