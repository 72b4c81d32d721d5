#include "fem/node_copies_exchange.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace tightfit {

void merge_repeated_copies(std::vector<NodeCopy>& copies) {
  std::sort(copies.begin(), copies.end(), [](const NodeCopy& a, const NodeCopy& b) {
    return std::tie(a.node, a.dofs) < std::tie(b.node, b.dofs);
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < copies.size(); ++i) {
    if (kept > 0 && copies[kept - 1].node == copies[i].node &&
        copies[kept - 1].dofs == copies[i].dofs) {
      copies[kept - 1].order = std::min(copies[kept - 1].order, copies[i].order);
      copies[kept - 1].rest_area_m2 += copies[i].rest_area_m2;
    } else {
      copies[kept++] = copies[i];
    }
  }
  copies.resize(kept);
}

std::vector<NodeCopy> exchange_node_copies(std::vector<NodeCopy> own, int n_nodes, MPI_Comm comm) {
  const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
  const auto home = [&](int node) {
    return static_cast<unsigned int>(static_cast<long long>(node) * n_ranks / n_nodes);
  };
  merge_repeated_copies(own);
  std::map<unsigned int, std::vector<NodeCopy>> to_home;
  for (const NodeCopy& copy : own) to_home[home(copy.node)].push_back(copy);
  own = std::vector<NodeCopy>();

  // At home: the copies of its nodes from every rank, and which ranks hold each node.
  std::vector<NodeCopy> copies;
  std::vector<std::pair<int, unsigned int>> holders;  // (node, rank)
  for (const auto& [rank, received] : dealii::Utilities::MPI::some_to_some(comm, to_home))
    for (const NodeCopy& copy : received) {
      copies.push_back(copy);
      holders.emplace_back(copy.node, rank);
    }
  to_home.clear();
  merge_repeated_copies(copies);
  std::sort(holders.begin(), holders.end());
  holders.erase(std::unique(holders.begin(), holders.end()), holders.end());

  std::map<unsigned int, std::vector<NodeCopy>> to_holders;
  auto holder = holders.begin();
  for (std::size_t begin = 0, end = 0; begin < copies.size(); begin = end) {
    const int node = copies[begin].node;
    double area_m2 = 0.0;
    while (end < copies.size() && copies[end].node == node) area_m2 += copies[end++].rest_area_m2;
    std::sort(copies.begin() + begin, copies.begin() + end,
              [](const NodeCopy& a, const NodeCopy& b) { return a.order < b.order; });
    for (std::size_t i = begin; i < end; ++i) copies[i].rest_area_m2 = area_m2;
    for (; holder != holders.end() && holder->first == node; ++holder)
      to_holders[holder->second].insert(to_holders[holder->second].end(), copies.begin() + begin,
                                        copies.begin() + end);
  }
  copies = std::vector<NodeCopy>();

  // Each home sends a block of nodes, each node's copies together and in order.
  std::vector<NodeCopy> result;
  for (const auto& [rank, received] : dealii::Utilities::MPI::some_to_some(comm, to_holders))
    result.insert(result.end(), received.begin(), received.end());
  std::stable_sort(result.begin(), result.end(),
                   [](const NodeCopy& a, const NodeCopy& b) { return a.node < b.node; });
  return result;
}

}  // namespace tightfit
