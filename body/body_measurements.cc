// The landmarks and girths of docs/measuring-bodies.md: the definitions there are
// the ones implemented here, level by level on the torso scan (torso_scan.h) and along the
// limbs' axes (limb_track.h).
#include "body/body_measurements.h"

#include "body/body_size.h"
#include "body/limb_track.h"
#include "body/torso_scan.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

namespace tightfit {

namespace {

const char* side_name(int side) {
  return side == 0 ? "left" : "right";
}

BodyGirth girth_of(const std::string& name, const SectionLoop& loop, const Vec3& normal,
                   double floor_m) {
  BodyGirth g;
  g.name = name;
  g.girth_m = loop.hull_perimeter_m;
  g.section_m = loop.perimeter_m;
  g.centre_m = loop.centroid_m;
  g.level_m = loop.centroid_m.z() - floor_m;
  g.normal = normal;
  g.hull_m = loop.hull_m;
  return g;
}

// The level index among [first, last) whose value is smallest (or largest), -1 if none.
int extreme_level(int first, int last, const std::function<double(int)>& value, bool largest) {
  int best = -1;
  double best_value = 0.0;
  for (int k = first; k < last; ++k) {
    const double v = value(k);
    if (!std::isfinite(v)) continue;
    if (best < 0 || (largest ? v > best_value : v < best_value)) {
      best = k;
      best_value = v;
    }
  }
  return best;
}

PartFrame frame(const std::string& name, const Vec3& origin, const Vec3& along,
                const Vec3& across_hint, double length) {
  PartFrame f;
  f.name = name;
  f.origin_m = origin;
  f.along = along.normalized();
  f.lateral = (across_hint - across_hint.dot(f.along) * f.along).normalized();
  f.front = f.lateral.cross(f.along);
  // Keep the front towards -y (the body's front) where it is defined.
  if (f.front.y() > 0) f.front = -f.front;
  f.length_m = length;
  return f;
}

class Measurer {
 public:
  explicit Measurer(const TriangleSurface& surface)
      : surface_(surface), horizontal_(surface, Vec3::UnitZ()), scan_(scan_torso(horizontal_)) {
    m_.floor_m = scan_.floor_m;
    m_.top_m = scan_.top_m;
  }

  BodyMeasurements run() {
    landmark("crotch", scan_.crotch_m);
    for (int side = 0; side < 2; ++side)
      landmark(std::string("armpit ") + side_name(side), scan_.armpit_m[side]);
    legs();
    torso();
    arms();
    neck();
    lengths();
    return m_;
  }

 private:
  double height() const { return scan_.height_m(); }
  int level_at(double z) const {
    return std::clamp(
        static_cast<int>(std::lround((scan_.top_m - scan_.step_m - z) / scan_.step_m)), 0,
        static_cast<int>(scan_.levels.size()) - 1);
  }
  void landmark(const std::string& name, const Vec3& p) { m_.landmarks.push_back({name, p}); }
  void length(const std::string& name, double l) { m_.lengths.push_back({name, l}); }

  // The torso's loop at level k, or nothing below the crotch.
  const SectionLoop* torso(int k) const {
    return k < scan_.crotch_level && scan_.levels[k].core >= 0 ? &scan_.core(k) : nullptr;
  }
  double torso_value(int k, const std::function<double(const SectionLoop&)>& f) const {
    const SectionLoop* l = torso(k);
    return l ? f(*l) : std::numeric_limits<double>::quiet_NaN();
  }

  // Legs: the axis through the centroids of the horizontal sections, then girths on planes
  // normal to it; B, C, G, knee and ankle after RAL-GZ 387 and ISO 8559-1.
  void legs() {
    const double crotch = scan_.crotch_m.z();
    const double crotch_height = crotch - scan_.floor_m;
    for (int side = 0; side < 2; ++side) {
      const std::string s = side_name(side);
      std::vector<Vec3> centroids;
      double thigh = 0.0;
      int thigh_level = -1;
      for (int k = scan_.crotch_level; k < static_cast<int>(scan_.levels.size()); ++k) {
        if (scan_.levels[k].leg[side] < 0) break;
        const SectionLoop& l = scan_.leg(side, k);
        const double z = scan_.levels[k].z_m;
        if (z > scan_.floor_m + 0.12 * crotch_height && z < crotch - 0.12 * crotch_height)
          centroids.push_back(l.centroid_m);
        // Thigh: the largest horizontal girth in the 5 cm below the crotch (just below the
        // gluteal fold).
        if (z > crotch - 0.05 && l.hull_perimeter_m > thigh) {
          thigh = l.hull_perimeter_m;
          thigh_level = k;
        }
      }
      if (centroids.size() < 10)
        throw BodyMeasureError("leg " + s +
                               ": the leg cannot be followed from the crotch to the ankle in "
                               "horizontal sections (it ends or joins the other leg)");
      const FittedLine axis = fit_line(centroids, Vec3::UnitZ());
      const SectionCutter cutter(surface_, axis.direction);
      const auto section = [&](double z) -> std::optional<SectionLoop> {
        const Vec3 p = axis.at_height(z);
        std::vector<SectionLoop> loops = cutter.cut(cutter.normal().dot(p));
        const int i = follow_loop(cutter, loops, p, 0.05);
        if (i < 0) return std::nullopt;
        return loops[i];
      };
      const auto search = [&](double low, double high, bool largest, const char* what) {
        double best_z = 0.0, best = 0.0;
        bool found = false;
        for (double z = low; z <= high; z += 0.0025)
          if (const auto l = section(z))
            if (!found || (largest ? l->hull_perimeter_m > best : l->hull_perimeter_m < best)) {
              best = l->hull_perimeter_m;
              best_z = z;
              found = true;
            }
        if (!found)
          throw BodyMeasureError(std::string(what) + " " + s +
                                 ": no section of the leg normal to its axis between z = " +
                                 std::to_string(low) + " and " + std::to_string(high) + " m");
        return best_z;
      };
      const auto add_girth = [&](const std::string& name, double z) {
        const auto l = section(z);
        m_.girths.push_back(girth_of(name + " " + s, *l, axis.direction, scan_.floor_m));
        m_.girths.back().level_m = z - scan_.floor_m;
        landmark(name + " " + s, axis.at_height(z));
      };
      // B: the ankle's smallest girth, 4 to 15 % of the height above the floor.
      const double b = search(scan_.floor_m + 0.04 * height(), scan_.floor_m + 0.15 * height(),
                              false, "ankle (B)");
      // C: the calf's largest girth, from 5 cm above B to 55 % of the crotch height.
      const double c = search(b + 0.05, scan_.floor_m + 0.55 * crotch_height, true, "calf (C)");
      // The knee: halfway between the crotch and the ankle.
      const double knee = 0.5 * (crotch + b);
      // G: the upper thigh, an eighth of the crotch height below the crotch.
      const double g = crotch - crotch_height / 8;
      add_girth("B", b);
      add_girth("C", c);
      add_girth("knee", knee);
      add_girth("G", g);
      landmark("ankle " + s, axis.at_height(b));
      if (thigh_level >= 0)
        m_.girths.push_back(
            girth_of("thigh " + s, scan_.leg(side, thigh_level), Vec3::UnitZ(), scan_.floor_m));
      const Vec3 root = axis.at_height(crotch), end = axis.at_height(scan_.floor_m);
      m_.parts.push_back(frame("leg " + s, root, end - root, Vec3::UnitX(), (end - root).norm()));
    }
  }

  // Bust, under-bust, waist and hips on horizontal sections of the torso (ISO 8559-1: bust at
  // the bust points, waist the narrowest, hips the widest below it).
  void torso() {
    const double crotch = scan_.crotch_m.z();
    const double armpit = std::min(scan_.armpit_m[0].z(), scan_.armpit_m[1].z());
    const auto range = [&](double high, double low) {  // levels from z = high down to low
      return std::pair<int, int>(level_at(high), level_at(low) + 1);
    };
    // Bust: the first level down from just below the armpits (0.6 % of the height) where the
    // torso's front stands out (reaches further forward than every torso level within 1.7 % of
    // the height, 3 cm on an adult: the breasts, or a man's chest, not a belly below it),
    // searched down to 55 % of the way from the crotch to the armpits; without one, the level
    // there where the torso reaches furthest forward.
    auto [b0, b1] = range(armpit - 0.006 * height(), crotch + 0.55 * (armpit - crotch));
    const auto front_y = [&](int k) {
      return torso_value(k, [](const SectionLoop& l) { return l.min_m.y(); });
    };
    // The window scales with the body: 3 cm on a person 1.75 m tall.
    const int window = std::max(1, static_cast<int>(std::lround(0.017 * height() / scan_.step_m)));
    int bust = -1;
    for (int k = b0; k < b1 && bust < 0; ++k) {
      bool stands_out = std::isfinite(front_y(k));
      for (int j = std::max(0, k - window); j <= k + window && stands_out; ++j)
        if (front_y(j) < front_y(k)) stands_out = false;
      if (stands_out) bust = k;
    }
    if (bust < 0) bust = extreme_level(b0, b1, front_y, false);
    if (bust < 0) throw BodyMeasureError("bust: no torso section below the armpits");
    const SectionLoop& b = scan_.core(bust);
    const double cx = b.centroid_m.x();
    Vec3 points[2] = {Vec3(0, 1e9, 0), Vec3(0, 1e9, 0)};
    double midline_front = 1e9;
    for (const Vec3& p : b.points_m) {
      Vec3& q = points[p.x() > cx ? 0 : 1];
      if (p.y() < q.y()) q = p;
      if (std::abs(p.x() - cx) < 0.01) midline_front = std::min(midline_front, p.y());
    }
    // Bust points where the front dips between them (by over 5 mm) as it does between breasts.
    m_.bust_points_present = midline_front - 0.5 * (points[0].y() + points[1].y()) > 0.005;
    if (m_.bust_points_present)
      for (int side = 0; side < 2; ++side)
        landmark(std::string("bust point ") + side_name(side), points[side]);
    m_.girths.push_back(girth_of("bust", b, Vec3::UnitZ(), scan_.floor_m));
    const double bust_z = b.centroid_m.z();
    // Waist: the smallest girth between 40 % and 85 % of the way from the crotch to the bust.
    auto [w0, w1] = range(crotch + 0.85 * (bust_z - crotch), crotch + 0.4 * (bust_z - crotch));
    const auto hull = [&](int k) {
      return torso_value(k, [](const SectionLoop& l) { return l.hull_perimeter_m; });
    };
    const int waist = extreme_level(w0, w1, hull, false);
    if (waist < 0) throw BodyMeasureError("waist: no torso section between the crotch and bust");
    const double waist_z = scan_.levels[waist].z_m;
    // Hips: at the level where the buttocks reach furthest back, between the crotch and the
    // waist.
    auto [h0, h1] = range(waist_z, crotch);
    const int hips = extreme_level(
        h0, h1,
        [&](int k) { return torso_value(k, [](const SectionLoop& l) { return l.max_m.y(); }); },
        true);
    if (hips < 0) throw BodyMeasureError("hips: no torso section between the crotch and waist");
    // Under-bust: below the bust, where the breast's underside (the front receding by more than
    // half a metre per metre of height) turns into the ribcage; without such an underside, 35 %
    // of the way from the bust down to the waist.
    int under = -1;
    {
      const auto front = [&](int k) {
        double y = 1e9;
        for (const Vec3& p : scan_.core(k).points_m)
          for (int side = 0; side < 2; ++side)
            if (std::abs(p.x() - points[side].x()) < 0.02) y = std::min(y, p.y());
        return y;
      };
      const int span = std::max(1, static_cast<int>(std::lround(0.01 / scan_.step_m)));
      bool underside = false;
      for (int k = bust + span; k < waist; ++k) {
        const double recede = (front(k) - front(k - span)) / (span * scan_.step_m);
        if (recede > 0.5) underside = true;
        if (underside && recede < 0.5) {
          under = k;
          break;
        }
      }
      if (under < 0) under = level_at(bust_z - 0.35 * (bust_z - waist_z));
    }
    m_.girths.push_back(girth_of("under-bust", scan_.core(under), Vec3::UnitZ(), scan_.floor_m));
    m_.girths.push_back(girth_of("waist", scan_.core(waist), Vec3::UnitZ(), scan_.floor_m));
    m_.girths.push_back(girth_of("hips", scan_.core(hips), Vec3::UnitZ(), scan_.floor_m));
    // The torso's axis through the centroids from 5 cm above the crotch to 3 cm below the
    // armpits.
    std::vector<Vec3> centroids;
    auto [t0, t1] = range(armpit - 0.03, crotch + 0.05);
    for (int k = t0; k < t1; ++k)
      if (const SectionLoop* l = torso(k)) centroids.push_back(l->centroid_m);
    const FittedLine axis = fit_line(centroids, Vec3::UnitZ());
    const Vec3 root = axis.at_height(crotch);
    torso_axis_ = axis;
    m_.parts.push_back(frame("torso", root, axis.direction, Vec3::UnitX(), 0.0));
  }

  // Arms: followed from the armpit along the principal direction of the arm's surface, then
  // along the axis through the sections' centroids; the shoulder point (acromion) the highest
  // point of the body within 4 cm outside the armpit, the wrist the arm's smallest girth
  // between 60 % and 90 % of the way from the shoulder to the fingertips, the upper arm its
  // largest girth from 3 to 15 cm beyond the armpit.
  void arms() {
    const double crotch = scan_.crotch_m.z();
    for (int side = 0; side < 2; ++side) {
      const std::string s = side_name(side);
      const double sign = side == 0 ? 1.0 : -1.0;
      const Vec3& armpit = scan_.armpit_m[side];
      // The arm's points: along every edge (every 1 cm, so that long faces count by their
      // length), above the crotch and 1 cm outside the torso's side at their level (outside the
      // armpit above it).
      std::vector<Vec3> arm;
      const auto outside = [&](const Vec3& x) {
        if (x.z() <= crotch) return false;
        const int k = level_at(x.z());
        const double side_x = x.z() >= armpit.z() || !torso(k)
                                  ? sign * armpit.x()
                                  : (side == 0 ? torso(k)->max_m.x() : -torso(k)->min_m.x());
        return sign * x.x() > side_x + 0.01;
      };
      for (const Triangle& t : surface_.triangles)
        for (int e = 0; e < 3; ++e) {
          const Vec3& p = surface_.vertices_m[t[e]];
          const Vec3& q = surface_.vertices_m[t[(e + 1) % 3]];
          const int n = 1 + static_cast<int>((q - p).norm() / 0.01);
          for (int i = 0; i < n; ++i)
            if (const Vec3 x = p + (static_cast<double>(i) / n) * (q - p); outside(x))
              arm.push_back(x);
        }
      if (arm.size() < 10) throw BodyMeasureError("wrist " + s + ": no arm outside the armpit");
      const FittedLine guess = fit_line(arm, Vec3(sign, 0, 0));
      const Vec3 d = guess.direction;
      const Vec3 start = guess.point_m + (d.dot(armpit) + 0.03 - d.dot(guess.point_m)) * d;
      const LimbTrack track = follow_limb(surface_, start, d, 0.005, 0.05, 0.1, 0.6);
      if (track.sections.size() < 20)
        throw BodyMeasureError("wrist " + s + ": the arm cannot be followed from the armpit (" +
                               std::to_string(track.sections.size()) + " sections)");
      const Vec3 a = track.axis.direction;
      // The shoulder point (acromion): the top of the body above the middle between the armpit
      // and the arm's axis at the armpit's level (an arm within 30 degrees of level: the axis's
      // point nearest the armpit).
      const Vec3 axis_at_armpit = std::abs(a.z()) > 0.5
                                      ? track.axis.at_height(armpit.z())
                                      : track.axis.point_m + a.dot(armpit - track.axis.point_m) * a;
      const double shoulder_x = 0.5 * (armpit.x() + axis_at_armpit.x());
      // Its highest point on the plane x = shoulder_x: the section, not the vertices, so that a
      // coarse mesh's faces count too.
      Vec3 shoulder(shoulder_x, 0, -1e9);
      for (const SectionLoop& l : SectionCutter(surface_, Vec3::UnitX()).cut(shoulder_x))
        for (const Vec3& p : l.points_m)
          if (p.z() > shoulder.z()) shoulder = p;
      if (shoulder.z() < armpit.z())
        throw BodyMeasureError("shoulder point " + s + ": no body above the armpit");
      const double t_shoulder = a.dot(shoulder), t_end = track.sections.back().t_m;
      const double t_armpit = a.dot(armpit);
      int wrist = -1, upper = -1;
      for (std::size_t i = 0; i < track.sections.size(); ++i) {
        const LimbSection& x = track.sections[i];
        const double f = (x.t_m - t_shoulder) / (t_end - t_shoulder);
        // The wrist: from half way out, the smallest girth before the hand (where the girth
        // grows by a fifth again).
        if (f > 0.5 && f < 0.95) {
          const double h = x.loop.hull_perimeter_m;
          if (wrist >= 0 && h > 1.2 * track.sections[wrist].loop.hull_perimeter_m) break;
          if (wrist < 0 || h < track.sections[wrist].loop.hull_perimeter_m)
            wrist = static_cast<int>(i);
        }
        if (x.t_m > t_armpit + 0.03 && x.t_m < t_armpit + 0.15 &&
            (upper < 0 || x.loop.hull_perimeter_m > track.sections[upper].loop.hull_perimeter_m))
          upper = static_cast<int>(i);
      }
      if (wrist < 0)
        throw BodyMeasureError("wrist " + s + ": the arm's track ends before the hand");
      if (upper < 0) throw BodyMeasureError("upper arm " + s + ": no section of the upper arm");
      const SectionLoop& w = track.sections[wrist].loop;
      m_.girths.push_back(girth_of("wrist " + s, w, a, scan_.floor_m));
      m_.girths.push_back(girth_of("upper arm " + s, track.sections[upper].loop, a, scan_.floor_m));
      landmark("shoulder point " + s, shoulder);
      landmark("wrist " + s, w.centroid_m);
      shoulder_[side] = shoulder;
      wrist_[side] = w.centroid_m;
      const Vec3 root = track.axis.point_m + (t_shoulder - a.dot(track.axis.point_m)) * a;
      m_.parts.push_back(frame("arm " + s, root, a, Vec3::UnitZ(), t_end - t_shoulder));
    }
  }

  // The neck: its narrowest section between 3 cm below the shoulder points and 12 % of the height
  // below the top; its base the first level below where the section is 1.5 times as wide.
  void neck() {
    const double shoulders = std::max(shoulder_[0].z(), shoulder_[1].z());
    const int k0 = level_at(scan_.top_m - 0.12 * height()), k1 = level_at(shoulders - 0.03);
    const auto width = [&](int k) { return scan_.core(k).max_m.x() - scan_.core(k).min_m.x(); };
    const int narrowest = extreme_level(
        k0, k1, [&](int k) { return scan_.core(k).perimeter_m; }, false);
    if (narrowest < 0)
      throw BodyMeasureError("neck base: no section between the shoulders and the head");
    int base = narrowest;
    while (base < k1 && width(base) < 1.5 * width(narrowest)) ++base;
    if (base >= k1)
      throw BodyMeasureError(
          "neck base: the neck does not widen into the shoulders above the "
          "shoulder points");
    landmark("neck base", scan_.core(base).centroid_m);
    for (PartFrame& p : m_.parts)
      if (p.name == "torso") p.length_m = scan_.core(base).centroid_m.z() - p.origin_m.z();
  }

  void lengths() {
    length("height", height());
    length("crotch height", scan_.crotch_m.z() - scan_.floor_m);
    length("bust height", m_.girth("bust").level_m);
    length("under-bust height", m_.girth("under-bust").level_m);
    length("waist height", m_.girth("waist").level_m);
    length("hip height", m_.girth("hips").level_m);
    length("shoulder width", (shoulder_[0] - shoulder_[1]).norm());
    for (int side = 0; side < 2; ++side)
      length(std::string("arm length ") + side_name(side), (wrist_[side] - shoulder_[side]).norm());
  }

  const TriangleSurface& surface_;
  SectionCutter horizontal_;
  TorsoScan scan_;
  BodyMeasurements m_;
  FittedLine torso_axis_;
  Vec3 shoulder_[2], wrist_[2];
};

template <typename T>
const T& find(const std::vector<T>& list, const std::string& name, const char* what) {
  for (const T& x : list)
    if (x.name == name) return x;
  throw std::out_of_range(std::string("no ") + what + " '" + name + "' measured");
}

}  // namespace

const BodyLandmark& BodyMeasurements::landmark(const std::string& name) const {
  return find(landmarks, name, "landmark");
}
const BodyGirth& BodyMeasurements::girth(const std::string& name) const {
  return find(girths, name, "girth");
}
const BodyLength& BodyMeasurements::length(const std::string& name) const {
  return find(lengths, name, "length");
}
const PartFrame& BodyMeasurements::part(const std::string& name) const {
  return find(parts, name, "body part");
}

BodyMeasurements measure_body(const TriangleSurface& surface) {
  check_standing_person(body_extent(surface.vertices_m), "the body");
  return Measurer(surface).run();
}

}  // namespace tightfit
