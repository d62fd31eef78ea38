// Progress on stderr for every phase longer than a second (reading the input,
// protecting features, refining, exuding, checking, writing): the phase, what it
// counts (refinement: vertices and queues) and its time. On a terminal one line
// is rewritten a few times a second; otherwise (logs, CI) a line every 5 s. A
// phase that took longer than the delay ends with a line "PHASE: done in T s".
// RDMESH_PROGRESS_DELAY (seconds, default 1) sets the delay; 0 shows every phase.
//
// The display's thread is quiet whenever the process forks (reading a CAD file
// forks a child that reads it): the constructor returns once the thread has
// started, and a fork handler holds the display's lock across fork(), so that the
// thread is not inside an allocation or a print when the child is made. An
// allocator that is not fork-safe (the sanitizers') would otherwise leave the
// child waiting forever on a lock taken by a thread the child does not have.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "rdmesh/mesher.h"

namespace rdmesh::cli {

class ProgressDisplay {
 public:
  /// Disabled: prints nothing and starts no thread.
  explicit ProgressDisplay(bool enabled);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  /// A new phase starts now (the previous one ends).
  void phase(const std::string& name);
  /// The mesher's callback: its phases and the refinement counts.
  void operator()(const Progress& p);
  /// Ends the current phase (its line if it was long) and stops the display. Without
  /// it (an error unwinding the run) the destructor stops it without that line and
  /// clears a terminal's progress line, so that the error line stands alone.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  friend struct ForkQuiet;
  void stop(bool completed);
  void run();
  void end_phase_locked();
  void print_locked();
  double elapsed_locked() const;

  bool enabled_;
  bool tty_;
  double delay_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
  bool running_ = false;  ///< the thread has started and waits on `wake_`
  bool stopping_ = false;
  ProgressDisplay* next_ = nullptr;  ///< the next live display with a thread
  std::string phase_;                ///< empty: no phase running
  std::string detail_;               ///< counts of the running phase
  Clock::time_point start_;
  double last_print_ = -1;       ///< elapsed time of the phase's last line, -1 = none
  std::size_t line_length_ = 0;  ///< of the rewritten terminal line
};

}  // namespace rdmesh::cli
