// Infix expressions of x, y, z (muparser), usable as implicit functions and sizing fields,
// or of other variable names (e.g. the parameter t of a curve).
//
// Syntax: numbers, x y z, + - * / and ^ (power, right-associative; -x^2 is -(x^2)),
// parentheses, the constant pi (also _pi, _e), and the muparser built-ins,
// among them sqrt sin cos tan exp ln log abs, and min(a, b, ...), max(a, b, ...)
// with any number of arguments.
//
// Thread safety: muparser objects are not thread-safe (evaluation writes to an
// internal stack). An Expression therefore owns one compiled muparser object per
// thread that evaluates it, created on that thread's first call under a mutex;
// later calls find it through a thread_local table keyed by the expression's
// unique id (ids are never reused) and do not lock or allocate. The per-thread
// objects are freed with the last copy of the Expression.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh {

/// A compiled expression of x, y, z. Cheap to copy (copies share the compiled state).
class Expression {
 public:
  /// Compiles `text`. Throws InputError (no file name) naming the problem:
  /// "unknown variable 'w' in 'x + w' (only x, y, z are defined)", "unknown
  /// function 'foo' ...", or "syntax error in '...': <muparser message>".
  explicit Expression(const std::string& text);

  /// Compiles `text` over the given variables (one to three names), bound in
  /// order to the x, y, z slots of operator(): Expression("2*t", {"t"}) evaluates
  /// with e(t, 0, 0) or e.at(t). Errors as above, naming the defined variables
  /// ("unknown variable 'x' in 'x + t' (only t is defined)"). Throws InputError
  /// for an empty list or more than three names.
  Expression(const std::string& text, const std::vector<std::string>& variables);

  /// The value with the first variable set to u (the others 0).
  double at(double u) const { return (*this)(Point3{u, 0, 0}); }

  /// The value at p (NaN or inf are returned as computed).
  double operator()(const Point3& p) const;
  double operator()(double x, double y, double z) const { return (*this)(Point3{x, y, z}); }

  const std::string& text() const;

  struct State;  // implementation detail

 private:
  std::shared_ptr<State> state_;
};

/// `expr` as an implicit function (negative inside) for ImplicitOracle.
/// Throws InputError on bad syntax, like Expression.
std::function<double(const Point3&)> make_expression_function(const std::string& expr);

}  // namespace rdmesh
