#include "progress_display.h"

#include <pthread.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rdmesh::cli {
namespace {

double delay_from_environment() {
  const char* text = std::getenv("RDMESH_PROGRESS_DELAY");
  if (text == nullptr || *text == '\0') return 1.0;
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  return *end == '\0' && std::isfinite(v) && v >= 0 ? v : 1.0;
}

}  // namespace

/// The displays whose thread runs, each locked by the fork handler across fork().
/// Lock order: the list's mutex, then each display's.
struct ForkQuiet {
  static std::mutex& list_mutex() {
    static std::mutex m;
    return m;
  }
  static ProgressDisplay*& head() {
    static ProgressDisplay* h = nullptr;
    return h;
  }
  static void prepare() {
    list_mutex().lock();
    for (ProgressDisplay* d = head(); d != nullptr; d = d->next_) d->mutex_.lock();
  }
  // In the parent and in the child alike: the thread that forked holds the locks.
  static void release() {
    for (ProgressDisplay* d = head(); d != nullptr; d = d->next_) d->mutex_.unlock();
    list_mutex().unlock();
  }
  static void add(ProgressDisplay* d) {
    static const int installed = ::pthread_atfork(&prepare, &release, &release);
    (void)installed;  // without the handler (ENOMEM) the display still works
    std::lock_guard<std::mutex> lock(list_mutex());
    d->next_ = head();
    head() = d;
  }
  static void remove(ProgressDisplay* d) {
    std::lock_guard<std::mutex> lock(list_mutex());
    for (ProgressDisplay** p = &head(); *p != nullptr; p = &(*p)->next_) {
      if (*p == d) {
        *p = d->next_;
        return;
      }
    }
  }
};

ProgressDisplay::ProgressDisplay(bool enabled)
    : enabled_(enabled), tty_(::isatty(STDERR_FILENO) != 0), delay_(delay_from_environment()) {
  if (!enabled_) return;
  thread_ = std::thread([this] { run(); });
  // A thread that is starting allocates (its thread-local storage, the
  // sanitizer's bookkeeping) outside the display's lock: wait until it is done.
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait(lock, [this] { return running_; });
  lock.unlock();
  ForkQuiet::add(this);
}

ProgressDisplay::~ProgressDisplay() {
  stop(false);
  if (enabled_) ForkQuiet::remove(this);
}

double ProgressDisplay::elapsed_locked() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void ProgressDisplay::phase(const std::string& name) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (name == phase_) return;
  end_phase_locked();
  phase_ = name;
  detail_.clear();
  start_ = Clock::now();
  last_print_ = -1;
}

void ProgressDisplay::operator()(const Progress& p) {
  if (!enabled_) return;
  if (p.vertices == 0) {  // a phase announcement; counts keep the phase running
    phase(p.phase);
    return;
  }
  char text[160];
  std::snprintf(text, sizeof text, "%zu vertices, queues %zu edges / %zu facets / %zu cells",
                p.vertices, p.edge_queue, p.facet_queue, p.cell_queue);
  std::lock_guard<std::mutex> lock(mutex_);
  detail_ = text;
}

void ProgressDisplay::finish() { stop(true); }

void ProgressDisplay::stop(bool completed) {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return;
    if (completed) {
      end_phase_locked();
    } else if (tty_ && line_length_ > 0) {
      // An error ends the run: its one line replaces the progress line.
      std::fprintf(stderr, "\r%*s\r", static_cast<int>(line_length_), "");
    }
    phase_.clear();
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ProgressDisplay::end_phase_locked() {
  if (phase_.empty()) return;
  const double t = elapsed_locked();
  if (t < delay_) return;
  if (tty_) std::fputc('\r', stderr);
  const int n = std::fprintf(stderr, t >= 10 ? "%s: done in %.0f s" : "%s: done in %.2g s",
                             phase_.c_str(), t);
  if (tty_ && n >= 0 && static_cast<std::size_t>(n) < line_length_) {
    std::fprintf(stderr, "%*s", static_cast<int>(line_length_ - static_cast<std::size_t>(n)), "");
  }
  std::fputc('\n', stderr);
  line_length_ = 0;
}

void ProgressDisplay::print_locked() {
  const double t = elapsed_locked();
  if (phase_.empty() || t < delay_) return;
  if (!tty_ && last_print_ >= 0 && t - last_print_ < 5.0) return;
  last_print_ = t;
  if (tty_) std::fputc('\r', stderr);
  const int n = std::fprintf(stderr, "%s%s%s, %.1f s", phase_.c_str(), detail_.empty() ? "" : ": ",
                             detail_.c_str(), t);
  if (!tty_) {
    std::fputc('\n', stderr);
    return;
  }
  if (n >= 0 && static_cast<std::size_t>(n) < line_length_) {
    std::fprintf(stderr, "%*s", static_cast<int>(line_length_ - static_cast<std::size_t>(n)), "");
  }
  if (n >= 0) line_length_ = static_cast<std::size_t>(n);
  std::fflush(stderr);
}

void ProgressDisplay::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  running_ = true;
  wake_.notify_all();
  while (!stopping_) {
    wake_.wait_for(lock, std::chrono::milliseconds(tty_ ? 200 : 500));
    if (!stopping_) print_locked();
  }
}

}  // namespace rdmesh::cli
