// Progress on stderr for runs longer than a second: vertices, queue sizes,
// elapsed time. Rewrites one line on a terminal, prints a line every few
// seconds otherwise (logs, CI).
#pragma once

#include <unistd.h>

#include <cstdio>

#include "rdmesh/mesher.h"

namespace rdmesh::cli {

class ProgressDisplay {
 public:
  explicit ProgressDisplay(bool enabled) : enabled_(enabled), tty_(::isatty(STDERR_FILENO) != 0) {}

  void operator()(const Progress& p) {
    if (!enabled_ || p.elapsed_seconds < 1.0) return;
    if (!tty_ && p.elapsed_seconds - last_print_ < 5.0) return;
    last_print_ = p.elapsed_seconds;
    std::fprintf(stderr, "%srefining: %zu vertices, queues %zu edges / %zu facets / %zu cells, %.1f s%s",
                 tty_ ? "\r" : "", p.vertices, p.edge_queue, p.facet_queue, p.cell_queue,
                 p.elapsed_seconds,
                 tty_ ? "   " : "\n");
    printed_ = true;
  }

  /// Ends the rewritten line so that the summary starts on a fresh one.
  void finish() {
    if (printed_ && tty_) std::fputc('\n', stderr);
  }

 private:
  bool enabled_;
  bool tty_;
  bool printed_ = false;
  double last_print_ = -1e9;
};

}  // namespace rdmesh::cli
