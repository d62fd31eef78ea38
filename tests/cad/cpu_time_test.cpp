// The CPU-time clocks behind the limits on reading and preparing a CAD model
// (cad/src/cpu_time.h): waiting costs none of the limit, computing does, and
// the parent can read a child's clock.
#include "cpu_time.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#if defined(__unix__) || defined(__APPLE__)
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace rdmesh::cad {
namespace {

// Spins until this thread has used `cpu` seconds or `wall` seconds have passed;
// returns the CPU seconds used.
double spin(double cpu, double wall) {
  const double start = thread_cpu_seconds();
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(wall);
  volatile double x = 1;
  while (thread_cpu_seconds() - start < cpu && std::chrono::steady_clock::now() < end) {
    for (int i = 0; i < 10000; ++i) x = x * 1.0000001 + 1e-9;
  }
  return thread_cpu_seconds() - start;
}

TEST(CpuTime, WaitingCostsNoneOfTheLimitAndComputingDoes) {
  const double before = thread_cpu_seconds();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_LT(thread_cpu_seconds() - before, 0.05);  // 300 ms asleep
  EXPECT_GE(spin(0.2, 20), 0.2);                   // a loaded machine only makes it slower
}

#if defined(__unix__) || defined(__APPLE__)
TEST(CpuTime, TheParentReadsItsChildsClock) {
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    spin(1e9, 30);
    ::_exit(0);
  }
  double seen = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (seen < 0.2 && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    seen = process_cpu_seconds(pid);
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_GE(seen, 0.2);
  EXPECT_LT(thread_cpu_seconds(), seen + 1000);  // two different clocks, both read
}
#endif

}  // namespace
}  // namespace rdmesh::cad
