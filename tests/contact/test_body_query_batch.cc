// A frame's body queries shared out to threads (contact/body_query_pool.h) against the same
// queries on one thread, on the MakeHuman female's smooth surface: thousands of points near the
// surface, each with its own kept faces, moved frame after frame as garment vertices are, asked
// what a frame's force asks (query_parts), the whole answer, and friction's anchor point
// (surface_point_near_m). Every answer is the serial one to the last bit: a point's answer
// depends on the point and its own NearFaces only, never on the thread or on which points that
// thread answered before (the blend's per-thread scratch).
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "contact/body_query_pool.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace tightfit {
namespace {

const std::string female =
    std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_female_body_m.obj";

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool same_answer(const SurfacePoint& a, const SurfacePoint& b) {
  return same_bits(a.signed_distance_m, b.signed_distance_m) &&
         same_bits(a.closest_point_m, b.closest_point_m) &&
         same_bits(a.outward_normal, b.outward_normal) &&
         same_bits(a.gap_gradient, b.gap_gradient) &&
         same_bits(a.normal_derivative_per_m, b.normal_derivative_per_m) &&
         a.location.face == b.location.face &&
         same_bits(a.location.coordinates, b.location.coordinates);
}

// Every point's answers at each frame: the force's parts, then the whole answer, then the
// anchor point of the location its first answer found.
struct FrameAnswers {
  std::vector<SurfacePoint> force, whole;
  std::vector<Vec3> anchor_m;
};

std::vector<FrameAnswers> walk(const RigidBody& body, const std::vector<std::vector<Vec3>>& frames,
                               WorkerPool* pool) {
  const std::size_t n = frames.front().size();
  std::vector<NearFaces> near(n), near_whole(n);
  std::vector<SurfaceLocation> anchor(n);
  QueryParts force_parts;
  force_parts.closest_point = force_parts.location = false;
  std::vector<FrameAnswers> answers;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    FrameAnswers a;
    a.force.resize(n);
    a.whole.resize(n);
    a.anchor_m.resize(n);
    for_each_part(pool, n, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const Vec3& x = frames[f][i];
        a.force[i] = body.query_parts(x, near[i], force_parts);
        a.whole[i] = body.query_near(x, near_whole[i]);
        if (f == 0) anchor[i] = a.whole[i].location;
        a.anchor_m[i] = body.surface_point_near_m(anchor[i], &near_whole[i]);
      }
    });
    answers.push_back(std::move(a));
  }
  return answers;
}

// `n` points from 3 mm inside to 3 mm outside the surface near random vertices, each moved by
// up to 0.2 mm a frame (within and beyond the kept faces' reach).
std::vector<std::vector<Vec3>> walks(const MeshBody& body, int n, int n_frames) {
  const auto& surface = body.surface();
  std::mt19937 random(41);
  std::uniform_int_distribution<int> vertex(0, int(surface.vertices_m.size()) - 1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::vector<Vec3>> frames(n_frames, std::vector<Vec3>(n));
  for (int i = 0; i < n; ++i) {
    const int v = vertex(random);
    Vec3 x = surface.vertices_m[v] + 0.003 * unit(random) * body.vertex_normals()[v];
    for (int f = 0; f < n_frames; ++f) {
      frames[f][i] = x;
      x += 2e-4 * Vec3(unit(random), unit(random), unit(random));
    }
  }
  return frames;
}

TEST(BodyQueryBatch, ThreadsGiveTheSerialAnswersOnTheSmoothFemale) {
  MeshBodyOptions options;
  options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  const auto body = load_mesh_body(female, options);
  const auto frames = walks(*body, 3000, 4);
  const std::vector<FrameAnswers> serial = walk(*body, frames, nullptr);
  for (int threads : {2, 3}) {
    const std::unique_ptr<WorkerPool> pool = body_query_pool(body.get(), threads);
    ASSERT_TRUE(pool) << "a mesh body's queries are costly";
    const std::vector<FrameAnswers> parallel = walk(*body, frames, pool.get());
    int differing = 0;
    for (std::size_t f = 0; f < frames.size(); ++f)
      for (std::size_t i = 0; i < frames[f].size(); ++i)
        differing += !same_answer(parallel[f].force[i], serial[f].force[i]) ||
                     !same_answer(parallel[f].whole[i], serial[f].whole[i]) ||
                     !same_bits(parallel[f].anchor_m[i], serial[f].anchor_m[i]);
    EXPECT_EQ(differing, 0) << threads << " threads";
  }
}

TEST(BodyQueryBatch, NoPoolForOneThreadOrAnAnalyticBody) {
  const Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), 0.05);
  EXPECT_FALSE(body_query_pool(&cylinder, 2));
  EXPECT_FALSE(body_query_pool(nullptr, 2));
  MeshBodyOptions options;
  const auto body = load_mesh_body(female, options);
  EXPECT_FALSE(body_query_pool(body.get(), 1));
  EXPECT_FALSE(body_query_pool(body.get(), 0));
  const auto pool = body_query_pool(body.get(), 2);
  ASSERT_TRUE(pool);
  EXPECT_EQ(pool->threads(), 2);
}

}  // namespace
}  // namespace tightfit
