// The threads a solver shares its garment vertices' body queries out to (Problem::threads).
#pragma once

#include "bodies/rigid_body.h"
#include "core/worker_pool.h"

#include <memory>

namespace tightfit {

// A pool of `threads` threads where they pay: more than one thread and a body whose queries are
// costly (RigidBody::costly_queries: a mesh body's tree and smooth field). Null otherwise (an
// analytic body's query costs less than waking a thread, and a run on one starts none).
std::unique_ptr<WorkerPool> body_query_pool(const RigidBody* body, int threads);

}  // namespace tightfit
