// Per-cell arrays of one fixed length (a cell's DoFs, its quadrature weights, its shape
// gradients), stored one cell after the other in a single block. A std::vector per cell costs a
// heap block and a vector header besides its values: on the 96600-vertex tube, one block per
// kind lowered the resident set after the FE backend's setup from 349 to 319 MB serially and
// from 285 to 268 MB per rank on two (docs/performance.md, MPI).
#pragma once

#include <deal.II/base/array_view.h>

#include <stdexcept>
#include <vector>

namespace tightfit {

template <typename T>
class CellTable {
 public:
  // Forgets every cell; each cell added from now on has `per_cell` values.
  void reset(unsigned int per_cell) {
    per_cell_ = per_cell;
    values_.clear();
  }
  int size() const { return per_cell_ == 0 ? 0 : static_cast<int>(values_.size() / per_cell_); }
  unsigned int per_cell() const { return per_cell_; }

  // Appends one cell's values (a range of exactly per_cell() of them).
  template <typename Range>
  void push_back(const Range& cell_values) {
    if (static_cast<unsigned int>(cell_values.size()) != per_cell_)
      throw std::logic_error("CellTable: a cell with the wrong number of values");
    values_.insert(values_.end(), cell_values.begin(), cell_values.end());
  }
  // Returns the capacity left over by the appends (the vector doubles as it grows).
  void shrink_to_fit() { values_.shrink_to_fit(); }

  dealii::ArrayView<const T> operator[](int cell) const {
    return dealii::ArrayView<const T>(values_.data() + static_cast<std::size_t>(cell) * per_cell_,
                                      per_cell_);
  }

 private:
  unsigned int per_cell_ = 0;
  std::vector<T> values_;
};

}  // namespace tightfit
