// A body whose surface is a mesh it changes between load steps or dressing frames (a morph, a
// growth, a shrink about its skeleton): every query goes to the MeshBody it holds, which its
// derived class moves with MeshBody::set_vertex_positions. `Interface` is RigidBody or an
// interface derived from it (ShrinkingBody).
#pragma once

#include "bodies/mesh_body.h"

#include <string>
#include <utility>

namespace tightfit {

template <typename Interface>
class ChangingMeshBody : public Interface {
 public:
  SurfacePoint query(const Vec3& x) const override { return mesh_.query(x); }
  SurfacePoint query_near(const Vec3& x, NearFaces& near) const override {
    return mesh_.query_near(x, near);
  }
  SurfacePoint query_parts(const Vec3& x, NearFaces& near, QueryParts parts) const override {
    return mesh_.query_parts(x, near, parts);
  }
  bool costly_queries() const override { return true; }
  DisplayMesh display_mesh() const override { return mesh_.display_mesh(); }
  Vec3 surface_point_m(const SurfaceLocation& l) const override { return mesh_.surface_point_m(l); }
  Vec3 surface_point_near_m(const SurfaceLocation& l, const NearFaces* near) const override {
    return mesh_.surface_point_near_m(l, near);
  }

  const MeshBody& mesh() const { return mesh_; }

 protected:
  // Checks the surface and builds its tree as MeshBody does (and throws as it does).
  ChangingMeshBody(TriangleSurface surface, const MeshBodyOptions& options, const std::string& what)
      : mesh_(std::move(surface), options, what) {}

  MeshBody mesh_;
};

}  // namespace tightfit
