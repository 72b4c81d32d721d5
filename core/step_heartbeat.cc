#include "core/step_heartbeat.h"

#include <cstdio>
#include <ostream>

namespace tightfit {

std::string duration_text(double seconds) {
  char text[32];
  if (seconds < 10)
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  else if (seconds < 120)
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 7200)
    std::snprintf(text, sizeof text, "%.1f min", seconds / 60);
  else
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
  return text;
}

StepHeartbeat::StepHeartbeat(std::ostream& log, std::string what, std::chrono::seconds first,
                             std::chrono::seconds interval)
    : log_(log), what_(std::move(what)) {
  thread_ = std::thread([this, first, interval] { beat(first, interval); });
}

StepHeartbeat::~StepHeartbeat() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
  }
  stop_signal_.notify_all();
  thread_.join();
}

void StepHeartbeat::beat(std::chrono::seconds first, std::chrono::seconds interval) {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  for (auto wait = first;; wait = interval) {
    if (stop_signal_.wait_for(lock, wait, [this] { return stopped_; })) return;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log_ << "    " << what_ << ": still solving, " << duration_text(seconds) << " so far"
         << std::endl;
  }
}

}  // namespace tightfit
