// Internal to cad/: CPU-time clocks for the limits on reading and preparing a
// model. A limit in CPU seconds does not depend on how loaded the machine is:
// the same file is accepted or refused whether it is meshed alone or beside
// three other jobs (a wall-clock limit once refused a valid 1.8 MB part under
// load that it prepared in a few seconds on a quiet machine).
#pragma once

#include <ctime>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/types.h>
#endif

namespace rdmesh::cad {

/// CPU seconds the calling thread has used; 0 where the clock is missing.
inline double thread_cpu_seconds() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
  timespec t{};
  if (::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) != 0) return 0;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
#else
  return 0;
#endif
}

#if defined(__unix__) || defined(__APPLE__)
/// CPU seconds process `pid` (a child of ours) has used, or -1 when it cannot
/// be read (the child is gone, or the system has no such clock).
inline double process_cpu_seconds(pid_t pid) {
  clockid_t clock{};
  if (::clock_getcpuclockid(pid, &clock) != 0) return -1;
  timespec t{};
  if (::clock_gettime(clock, &t) != 0) return -1;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
#endif

}  // namespace rdmesh::cad
