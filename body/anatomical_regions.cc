#include "body/anatomical_regions.h"

#include <algorithm>
#include <cmath>

namespace tightfit {

namespace {

constexpr double pi = 3.14159265358979323846;

bool is_leg_region(const std::string& name) {
  return name == "B" || name == "C" || name == "G" || name == "knee" || name == "calf" ||
         name == "thigh";
}

// The torso's section at a girth line: its box across, and its centre, front and back.
struct TorsoSection {
  Vec3 min_m, max_m, centre_m;
};
TorsoSection torso_section(const BodyGirth& g) {
  TorsoSection s{g.hull_m.front(), g.hull_m.front(), g.centre_m};
  for (const Vec3& p : g.hull_m) {
    s.min_m = s.min_m.cwiseMin(p);
    s.max_m = s.max_m.cwiseMax(p);
  }
  return s;
}

// A box round the torso's section at `level` (a girth line), `width` high, 3 cm larger across
// than the section; the front (facing 1) the part of it ahead of `share` of the way from the
// centre to the front, the back (-1) likewise behind.
RegionPiece torso_box(const BodyGirth& line, double width, int facing, double share) {
  const TorsoSection s = torso_section(line);
  RegionPiece p;
  p.min_m = Vec3(s.min_m.x() - 0.03, s.min_m.y() - 0.03, line.centre_m.z() - 0.5 * width);
  p.max_m = Vec3(s.max_m.x() + 0.03, s.max_m.y() + 0.03, line.centre_m.z() + 0.5 * width);
  const double c = s.centre_m.y();
  if (facing > 0) p.max_m.y() = c - share * (c - s.min_m.y());
  if (facing < 0) p.min_m.y() = c + share * (s.max_m.y() - c);
  return p;
}

// A band round a leg's axis at heights [low, high] along it from `at`, wide enough for the
// leg's section there (its girth over pi, with a margin) and no wider.
RegionPiece leg_tube(const PartFrame& leg, const Vec3& at, double low, double high, double girth) {
  RegionPiece p;
  p.kind = RegionPiece::Kind::tube;
  p.point_m = at;
  p.axis = -leg.along;  // upwards
  p.low_m = low;
  p.high_m = high;
  p.radius_m = 0.8 * girth / pi + 0.02;
  return p;
}

}  // namespace

const std::vector<std::string>& anatomical_region_names() {
  static const std::vector<std::string> names = {
      "bust", "under-bust band", "waist band", "hip band", "scapulae", "B", "C", "G", "knee",
      "calf", "thigh",           "upper arm"};
  return names;
}

double default_region_width_m(const std::string& name) {
  if (name == "bust" || name == "waist band" || name == "hip band") return 0.05;
  if (name == "under-bust band" || name == "knee") return 0.04;
  if (name == "scapulae") return 0.09;
  if (name == "B" || name == "C" || name == "G") return 0.02;
  if (name == "upper arm") return 0.08;
  return 0.0;  // calf and thigh: from landmark to landmark
}

std::vector<RegionPiece> anatomical_region(const BodyMeasurements& body, const AnatomyRequest& r) {
  const auto& names = anatomical_region_names();
  if (std::find(names.begin(), names.end(), r.name) == names.end())
    throw BodyMeasureError("no named region '" + r.name + "'");
  const double width = r.width_m > 0 ? r.width_m : default_region_width_m(r.name);
  std::vector<RegionPiece> pieces;
  if (r.name == "upper arm") {
    // A band round each arm's axis centred on its upper-arm girth line (its largest girth from
    // 3 to 15 cm beyond the armpit), as wide as the section there with a margin.
    if (r.facing != 0)
      throw BodyMeasureError("region 'upper arm' goes round the arm: no front or back");
    for (int side = 0; side < 2; ++side) {
      if (r.side >= 0 && r.side != side) continue;
      const std::string s = side == 0 ? " left" : " right";
      const BodyGirth& line = body.girth("upper arm" + s);
      RegionPiece p;
      p.kind = RegionPiece::Kind::tube;
      p.point_m = line.centre_m;
      p.axis = body.part("arm" + s).along;
      p.low_m = -0.5 * width;
      p.high_m = 0.5 * width;
      p.radius_m = 0.8 * line.girth_m / pi + 0.02;
      pieces.push_back(p);
    }
    return pieces;
  }
  if (is_leg_region(r.name)) {
    if (r.facing != 0)
      throw BodyMeasureError("region '" + r.name + "' goes round the leg: no front or back");
    for (int side = 0; side < 2; ++side) {
      if (r.side >= 0 && r.side != side) continue;
      const std::string s = side == 0 ? " left" : " right";
      const PartFrame& leg = body.part("leg" + s);
      const Vec3 up = -leg.along;
      const auto height = [&](const std::string& landmark) {
        return up.dot(body.landmark(landmark + s).point_m);
      };
      if (r.name == "calf" || r.name == "thigh") {
        // calf: from B up to the knee; thigh: from the knee up to 2 cm above G.
        const std::string from = r.name == "calf" ? "B" : "knee";
        const Vec3 at = body.landmark(from + s).point_m;
        const double top = r.name == "calf" ? height("knee") : height("G") + 0.02;
        const double girth = body.girth((r.name == "calf" ? "C" : "G") + s).girth_m;
        pieces.push_back(leg_tube(leg, at, 0.0, top - up.dot(at), girth));
      } else {
        const Vec3 at = body.landmark(r.name + s).point_m;
        pieces.push_back(
            leg_tube(leg, at, -0.5 * width, 0.5 * width, body.girth(r.name + s).girth_m));
      }
    }
    return pieces;
  }
  if (r.side >= 0)
    throw BodyMeasureError("region '" + r.name + "' is on the torso: no left or right");
  if (r.name == "bust") {
    // The front of the torso at the bust line, ahead of 45 % of the way from the torso's
    // centre to its front: the breasts, not the sides.
    if (r.facing < 0) throw BodyMeasureError("region 'bust' is on the front");
    pieces.push_back(torso_box(body.girth("bust"), width, 1, 0.45));
  } else if (r.name == "scapulae") {
    // The back from the armpits up by the width, behind half way from the torso's centre (at
    // the bust line) to its back, between the armpits.
    if (r.facing > 0) throw BodyMeasureError("region 'scapulae' is on the back");
    const BodyGirth& bust = body.girth("bust");
    const TorsoSection s = torso_section(bust);
    const double armpit = std::min(body.landmark("armpit left").point_m.z(),
                                   body.landmark("armpit right").point_m.z());
    RegionPiece p;
    p.min_m = Vec3(body.landmark("armpit right").point_m.x(),
                   s.centre_m.y() + 0.5 * (s.max_m.y() - s.centre_m.y()), armpit);
    p.max_m = Vec3(body.landmark("armpit left").point_m.x(), s.max_m.y() + 0.1, armpit + width);
    pieces.push_back(p);
  } else {
    const std::string line = r.name == "under-bust band" ? "under-bust"
                             : r.name == "waist band"    ? "waist"
                                                         : "hips";
    // Front or back: ahead of (behind) 15 % of the way from the centre to the front (back).
    pieces.push_back(torso_box(body.girth(line), width, r.facing, 0.15));
  }
  return pieces;
}

}  // namespace tightfit
