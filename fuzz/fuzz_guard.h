// The verdict of every fuzz target: InputError is a clean outcome; any other
// exception aborts with its type and message, so libFuzzer records the input
// as a crash (crashes, leaks and undefined behaviour are the sanitizers' part).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <typeinfo>

#include "rdmesh/errors.h"

namespace rdmesh::fuzz {

/// Runs `read`, returning normally when it succeeds or throws InputError.
template <class Read>
void expect_success_or_input_error(Read&& read) {
  try {
    read();
  } catch (const InputError&) {
    // A rejected input: what a reader must do with bad bytes.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rdmesh fuzz: %s escaped the reader: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "rdmesh fuzz: a non-standard exception escaped the reader\n");
    std::abort();
  }
}

}  // namespace rdmesh::fuzz
