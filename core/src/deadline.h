// A run's time limit as the meshing phases check it (MeshOptions::
// time_limit_seconds): the clock is read only every `every`-th call, so that a
// tight loop may ask at each step.
#pragma once

#include <chrono>

namespace rdmesh::detail {

/// The run's time limit passed while protecting the features or inserting the
/// initial points; generate_mesh() then returns no mesh.
struct TimeLimitReached {};

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  /// The usual `every` of loops whose step is about one insertion or one
  /// ball-pair test: cheap enough that reading the clock at each step would
  /// show, short enough that a limit is overrun by only a few steps' time.
  static constexpr unsigned kCheckEvery = 256;
  void set(Clock::time_point at) { at_ = at; }
  /// Whether the deadline has passed; only every `every`-th call reads the
  /// clock (the others answer false).
  bool passed(unsigned every) { return ++calls_ % every == 0 && Clock::now() > at_; }
  /// Throws TimeLimitReached when passed(every).
  void check(unsigned every) {
    if (passed(every)) throw TimeLimitReached{};
  }

 private:
  Clock::time_point at_ = Clock::time_point::max();
  unsigned calls_ = 0;
};

}  // namespace rdmesh::detail
