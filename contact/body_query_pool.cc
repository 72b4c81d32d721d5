#include "contact/body_query_pool.h"

namespace tightfit {

std::unique_ptr<WorkerPool> body_query_pool(const RigidBody* body, int threads) {
  if (threads <= 1 || !body || !body->costly_queries()) return nullptr;
  return std::make_unique<WorkerPool>(threads);
}

}  // namespace tightfit
