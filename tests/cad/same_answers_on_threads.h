// Thread safety of an oracle, checked by its answers: a list of queries run
// once alone, then on several threads at once, must give the same results.
#pragma once

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace rdmesh::test {

/// `answers()` returns the results of a fixed list of queries.
template <class Answers>
void expect_same_answers_on_threads(const Answers& answers, int threads) {
  const std::vector<double> serial = answers();
  std::vector<std::vector<double>> results(static_cast<std::size_t>(threads));
  std::vector<std::thread> running;
  for (auto& r : results) running.emplace_back([&r, &answers] { r = answers(); });
  for (auto& t : running) t.join();
  for (const auto& r : results) EXPECT_EQ(r, serial);
}

}  // namespace rdmesh::test
