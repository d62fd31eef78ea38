// Wall-clock time of a phase, for the reports and progress lines. Time is never
// an input to a geometric decision (outputs do not depend on the machine's load);
// deadlines, which may stop a run, are core's Deadline.
#pragma once

#include <chrono>

namespace rdmesh {

class Stopwatch {
 public:
  using Clock = std::chrono::steady_clock;

  /// Starts now.
  Stopwatch() : start_(Clock::now()) {}
  /// Seconds since construction or the last restart().
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// seconds(), and starts again from now: consecutive phases timed by one watch.
  double lap() {
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return s;
  }
  void restart() { start_ = Clock::now(); }

 private:
  Clock::time_point start_;
};

}  // namespace rdmesh
