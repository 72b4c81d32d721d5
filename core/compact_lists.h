// Lists of varying length (a node's DoF copies, a vertex's constrained directions) stored one
// after the other in a single block, with each list's start in an offset array (compressed
// sparse rows). A std::vector per list costs a 24-byte header and a heap block of at least 32
// bytes even when empty; on the 96600-vertex tube the per-node vectors of the FE backend's
// pattern held about 8 MB that way (docs/performance.md, "Rank-local nodes").
#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace tightfit {

// A read-only view of one list: iterable, indexable, sized.
template <typename T>
class ListView {
 public:
  ListView(const T* first, const T* last) : first_(first), last_(last) {}
  const T* begin() const { return first_; }
  const T* end() const { return last_; }
  std::size_t size() const { return static_cast<std::size_t>(last_ - first_); }
  bool empty() const { return first_ == last_; }
  const T& operator[](std::size_t k) const { return first_[k]; }
  const T& front() const { return *first_; }

 private:
  const T* first_;
  const T* last_;
};

template <typename T>
class CompactLists {
 public:
  int size() const { return static_cast<int>(offsets_.size()) - 1; }
  ListView<T> operator[](int list) const {
    return ListView<T>(values_.data() + offsets_[list], values_.data() + offsets_[list + 1]);
  }
  // Appends a list (any range of T).
  template <typename Range>
  void push_back(const Range& list) {
    values_.insert(values_.end(), list.begin(), list.end());
    offsets_.push_back(static_cast<Offset>(values_.size()));
  }
  // Returns the capacity left over by the appends.
  void shrink_to_fit() {
    offsets_.shrink_to_fit();
    values_.shrink_to_fit();
  }
  // Whole lists of lists, packed.
  static CompactLists from(const std::vector<std::vector<T>>& lists) {
    CompactLists result;
    std::size_t n_values = 0;
    for (const auto& list : lists) n_values += list.size();
    if (n_values > static_cast<std::size_t>(max_offset))
      throw std::length_error("CompactLists: more values than an offset can count");
    result.offsets_.reserve(lists.size() + 1);
    result.values_.reserve(n_values);
    for (const auto& list : lists) result.push_back(list);
    return result;
  }

 private:
  // 32-bit offsets: a garment's nodes and their copies number far below 2^31.
  using Offset = int;
  static constexpr Offset max_offset = 0x7fffffff;
  std::vector<Offset> offsets_{0};
  std::vector<T> values_;
};

}  // namespace tightfit
