// Typed exceptions thrown by the rdmesh library.
//
// The library never calls exit/abort; the CLI maps these types to exit codes
// (InputError -> 2) and prints what() as a single line.
#pragma once

#include <stdexcept>
#include <string>

namespace rdmesh {

/// Base class of every rdmesh exception.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The user's input (a file, an option, an expression) is invalid.
/// what() reads "FILE: problem" when a file is involved.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(message) {}
  InputError(const std::string& file, const std::string& problem)
      : Error(file.empty() ? problem : file + ": " + problem), file_(file) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

/// An oracle could not answer a query it is required to answer.
class OracleError : public Error {
 public:
  using Error::Error;
};

/// Writing an output file failed.
class OutputError : public Error {
 public:
  using Error::Error;
};

/// A broken invariant inside rdmesh (a bug): thrown instead of assert.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace rdmesh
