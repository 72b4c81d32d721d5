// The residual history of one load step's settling, in windows of frames, and the stall test
// that lets a step which cannot meet the stop rule say so early.
//
// Damped RK4 brings every smooth mode of the garment down geometrically, so the smallest
// residual of a window of frames falls by a steady factor from one window to the next. A
// window whose smallest residual is not below `required_fall` times the smallest residual of
// every earlier window (since the last restart) has stalled: the frames go round a limit
// cycle (vertices chattering in and out of contact under a time step too large for the
// penalty's kink) or the step approaches a floor the stop rule sits below. The backend then
// halves its time step and restarts the test; after its last halving a stall ends the step
// with a SolverError quoting text(), which the run also writes to solver.log.
#pragma once

#include <string>
#include <vector>

namespace tightfit {

class ResidualHistory {
 public:
  // `window_frames` > 0; `required_fall` in (0, 1). `counter` and `step` name what the
  // windows count and what record()'s dt_s is, for text(): the defaults read RK4's frames and
  // time step; Newton's method records iterations and its line search's step length.
  ResidualHistory(int window_frames, double required_fall, std::string counter = "frames",
                  std::string step = "time step s");

  // Records the residual (N) of frame `frame`, taken with time step `dt_s`. Returns true when
  // this frame closes a window that has stalled.
  bool record(int frame, double residual_N, double dt_s);
  // Forgets the windows' smallest residuals for the stall test (not for the history): after a
  // contact multiplier update or a time-step halving the residual starts afresh.
  void restart();

  // One line per window, closed ones and the one being filled: first frame, time step,
  // smallest, largest and last residual.
  std::string text() const;
  int windows() const { return static_cast<int>(windows_.size()); }

 private:
  struct Window {
    int first_frame = 0;
    double dt_s = 0.0;
    double smallest_N = 0.0, largest_N = 0.0, last_N = 0.0;
    bool stalled = false;
  };
  int window_frames_;
  double required_fall_;
  std::string counter_, step_;
  std::vector<Window> windows_;  // closed windows
  Window open_;
  int open_frames_ = 0;
  double best_N_ = 0.0;  // smallest residual of the windows closed since the last restart
  bool have_best_ = false;
};

}  // namespace tightfit
