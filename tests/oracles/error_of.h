// The message of an expected exception, for tests that check its text.
#pragma once

#include <string>

#include "rdmesh/errors.h"

namespace rdmesh {

/// what() of the E that f() throws; "no error" when it throws nothing (any
/// other exception propagates and fails the test).
template <class E = InputError, class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace rdmesh
