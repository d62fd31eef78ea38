#include "rdmesh/expression.h"

#include <muParser.h>

#include <atomic>
#include <cctype>
#include <mutex>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include "rdmesh/errors.h"

namespace rdmesh {

namespace {

/// One compiled muparser object bound to its own variables.
struct Compiled {
  double x = 0, y = 0, z = 0;
  mu::Parser parser;
};

// muparser keeps static state (its locale, default operator tables); constructing
// and compiling parsers is serialised, evaluation is not.
std::mutex& compile_mutex() {
  static std::mutex m;
  return m;
}

std::atomic<std::uint64_t> next_id{1};

std::string defined_text(const std::vector<std::string>& variables) {
  std::string out;
  for (std::size_t i = 0; i < variables.size(); ++i) {
    out += (i == 0 ? "" : ", ") + variables[i];
  }
  return out + (variables.size() == 1 ? " is defined" : " are defined");
}

std::string describe(const mu::Parser::exception_type& e, const std::string& text,
                     const std::vector<std::string>& variables) {
  const std::string token = e.GetToken();
  if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && !token.empty()) {
    if (std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '.') {
      return "invalid number '" + token + "' in '" + text + "'";
    }
    std::size_t after = static_cast<std::size_t>(e.GetPos()) + token.size();
    while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after]))) ++after;
    if (after < text.size() && text[after] == '(') {
      return "unknown function '" + token + "' in '" + text + "'";
    }
    return "unknown variable '" + token + "' in '" + text + "' (only " + defined_text(variables) +
           ")";
  }
  return "syntax error in '" + text + "': " + e.GetMsg();
}

/// Compiles `text`; throws InputError. Caller holds compile_mutex().
std::unique_ptr<Compiled> compile(const std::string& text,
                                  const std::vector<std::string>& variables) {
  auto c = std::make_unique<Compiled>();
  double* slots[3] = {&c->x, &c->y, &c->z};
  try {
    for (std::size_t i = 0; i < variables.size(); ++i) c->parser.DefineVar(variables[i], slots[i]);
    c->parser.DefineConst("pi", std::numbers::pi);
    c->parser.SetExpr(text);
    c->parser.Eval();  // muparser parses lazily: force it now
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(describe(e, text, variables));
  }
  return c;
}

}  // namespace

struct Expression::State {
  std::string text;
  std::vector<std::string> variables;
  std::uint64_t id = 0;
  std::mutex mutex;                                   // guards `per_thread`
  std::vector<std::unique_ptr<Compiled>> per_thread;  // one per evaluating thread
};

Expression::Expression(const std::string& text) : Expression(text, {"x", "y", "z"}) {}

Expression::Expression(const std::string& text, const std::vector<std::string>& variables)
    : state_(std::make_shared<State>()) {
  if (variables.empty() || variables.size() > 3) {
    throw InputError("an expression needs one to three variables, got " +
                     std::to_string(variables.size()));
  }
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError("empty expression");
  }
  state_->text = text;
  state_->variables = variables;
  {
    std::lock_guard lock(compile_mutex());
    compile(text, variables);  // validate now, so that evaluation never throws
  }
  state_->id = next_id.fetch_add(1);
}

const std::string& Expression::text() const { return state_->text; }

double Expression::operator()(const Point3& p) const {
  // Per-thread table: expression id -> this thread's compiled object. Entries of
  // destroyed expressions are never looked up again (ids are unique).
  thread_local std::unordered_map<std::uint64_t, Compiled*> table;
  thread_local std::uint64_t last_id = 0;
  thread_local Compiled* last = nullptr;
  Compiled* c;
  if (last_id == state_->id) {
    c = last;
  } else {
    auto it = table.find(state_->id);
    if (it != table.end()) {
      c = it->second;
    } else {
      std::unique_ptr<Compiled> fresh;
      {
        std::lock_guard lock(compile_mutex());
        fresh = compile(state_->text, state_->variables);
      }
      c = fresh.get();
      std::lock_guard lock(state_->mutex);
      state_->per_thread.push_back(std::move(fresh));
      table.emplace(state_->id, c);
    }
    last_id = state_->id;
    last = c;
  }
  c->x = p.x;
  c->y = p.y;
  c->z = p.z;
  return c->parser.Eval();
}

std::function<double(const Point3&)> make_expression_function(const std::string& expr) {
  return Expression(expr);
}

}  // namespace rdmesh
