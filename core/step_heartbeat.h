// A line now and then while one long load step solves, so that a run is never silent for
// minutes: "    step 3/16 (alpha 1.150): still solving, 2.0 min so far". The load step's own
// progress line follows when it ends (cases/scenario_run.cc).
#pragma once

#include <chrono>
#include <condition_variable>
#include <iosfwd>
#include <mutex>
#include <string>
#include <thread>

namespace tightfit {

// "0.4 s", "45 s", "2.5 min", "1.2 h": a duration as a progress line says it.
std::string duration_text(double seconds);

class StepHeartbeat {
 public:
  // Writes to `log` after `first`, then every `interval`, until destroyed. `log` must not be
  // written by anyone else meanwhile (the backends do not write to it while they solve).
  StepHeartbeat(std::ostream& log, std::string what,
                std::chrono::seconds first = std::chrono::seconds(30),
                std::chrono::seconds interval = std::chrono::seconds(60));
  ~StepHeartbeat();
  StepHeartbeat(const StepHeartbeat&) = delete;
  StepHeartbeat& operator=(const StepHeartbeat&) = delete;

 private:
  void beat(std::chrono::seconds first, std::chrono::seconds interval);
  std::ostream& log_;
  const std::string what_;
  std::mutex mutex_;
  std::condition_variable stop_signal_;
  bool stopped_ = false;
  std::thread thread_;
};

}  // namespace tightfit
