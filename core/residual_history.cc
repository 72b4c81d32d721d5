#include "core/residual_history.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace tightfit {

ResidualHistory::ResidualHistory(int window_frames, double required_fall, std::string counter,
                                 std::string step)
    : window_frames_(window_frames),
      required_fall_(required_fall),
      counter_(std::move(counter)),
      step_(std::move(step)) {
  if (window_frames <= 0 || !(required_fall > 0 && required_fall < 1))
    throw std::invalid_argument(
        "residual history: the window must be positive and the fall in (0, 1)");
}

bool ResidualHistory::record(int frame, double residual_N, double dt_s) {
  if (open_frames_ == 0) {
    open_ = Window{frame, dt_s, residual_N, residual_N, residual_N, false};
  } else {
    open_.smallest_N = std::min(open_.smallest_N, residual_N);
    open_.largest_N = std::max(open_.largest_N, residual_N);
    open_.last_N = residual_N;
  }
  if (++open_frames_ < window_frames_) return false;
  open_frames_ = 0;
  open_.stalled = have_best_ && !(open_.smallest_N < required_fall_ * best_N_);
  best_N_ = have_best_ ? std::min(best_N_, open_.smallest_N) : open_.smallest_N;
  have_best_ = true;
  windows_.push_back(open_);
  return open_.stalled;
}

void ResidualHistory::restart() {
  have_best_ = false;
  open_frames_ = 0;
}

std::string ResidualHistory::text() const {
  std::ostringstream out;
  out << "residual history (windows of " << window_frames_ << " " << counter_ << ": first, "
      << step_ << ", smallest / largest / last residual N)";
  const auto line = [&out](const Window& w) {
    out << "\n  " << w.first_frame << "  " << w.dt_s << "  " << w.smallest_N << " / " << w.largest_N
        << " / " << w.last_N << (w.stalled ? "  stalled" : "");
  };
  for (const Window& w : windows_) line(w);
  // The last records, in a window not yet full: where a failed step ended.
  if (open_frames_ > 0) {
    line(open_);
    out << "  (" << open_frames_ << " " << counter_ << ")";
  }
  return out.str();
}

}  // namespace tightfit
