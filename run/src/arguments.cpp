#include "rdmesh/arguments.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

namespace rdmesh::run {
namespace {

/// What each option accepts, in the words of the error messages.
const std::map<std::string, std::string>& accepted_values() {
  static const std::map<std::string, std::string> values = {
      {"--output", "a file name ending in .msh, .mesh or .vtu"},
      {"--size", "a length > 0"},
      {"--edge-size", "a length > 0"},
      {"--facet-size", "a length > 0"},
      {"--cell-size", "a length > 0"},
      {"--facet-distance", "a length > 0"},
      {"--facet-angle", "an angle in degrees in (0, 30]"},
      {"--radius-edge", "a ratio >= 2"},
      {"--min-size", "a length > 0"},
      {"--max-elements", "a number > 0, such as 1e8"},
      {"--exude-time-limit", "a number of seconds >= 0 (0: no limit)"},
      {"--exude-bound", "an angle in degrees in (0, 90]"},
      {"--time-limit", "a number of seconds >= 0 (0: no limit)"},
      {"--report", "a file name ending in .json"},
      {"--threads", "a number of threads from 0 (all cores) to 1024"},
      {"--features", "protect or refine"},
      {"--feature-angle", "an angle in degrees in [0, 180]"},
      {"--check", "cheap or full"},
      {"--format", "msh41 or msh22"},
      {"--order", "1 or 2"},
      {"--partitions", "a number of partitions from 1 to 1048576"},
      {"--size-on", "KIND:WHICH=SIZE, such as face:12=0.5"},
      {"--sizes", "a .json file of entity sizes"},
      {"--grade", "a growth factor > 1, such as 1.4"},
      {"--curvature", "a number of elements per full turn > 0, such as 16"},
      {"--picture", "a file name ending in .png"},
      {"--view", "iso, x, y or z"},
      {"--picture-size", "WIDTHxHEIGHT, such as 1600x900"},
      {"--cut", "AXIS=VALUE, such as x=0.2"},
  };
  return values;
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  (void)std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

/// The options of `app` named in `text` as whole words (the longest first wins:
/// "--picture-size" is not "--size").
const CLI::Option* option_named_in(const std::string& text, const CLI::App& app) {
  const CLI::Option* best = nullptr;
  std::size_t best_length = 0;
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& name : opt->get_lnames()) {
      const std::string dashed = "--" + name;
      for (std::size_t at = text.find(dashed); at != std::string::npos;
           at = text.find(dashed, at + 1)) {
        const std::size_t after = at + dashed.size();
        const bool word_end = after == text.size() || text[after] == ':' || text[after] == ' ';
        const bool word_start = at == 0 || text[at - 1] == ' ';
        if (word_end && word_start && dashed.size() > best_length) {
          best = opt;
          best_length = dashed.size();
        }
      }
    }
  }
  return best;
}

std::string long_name(const CLI::Option& opt) {
  return opt.get_lnames().empty() ? opt.get_name() : "--" + opt.get_lnames().front();
}

std::string accepted(const CLI::Option& opt) {
  const auto it = accepted_values().find(long_name(opt));
  return it == accepted_values().end() ? std::string("a value") : it->second;
}

std::string help_hint(const std::string& command) { return command + " --help lists the options"; }

}  // namespace

std::optional<std::string> single_dash_option(int argc, const char* const* argv,
                                              const std::string& allowed_short) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") return std::nullopt;
    // A number is a value when it follows an option (--size -1), a flag otherwise (-3).
    const std::string before = i > 1 ? argv[i - 1] : "";
    const bool after_option = before.size() > 1 && before[0] == '-' &&
                              before.find('=') == std::string::npos && !is_number(before);
    if (arg.size() < 2 || arg[0] != '-' || arg[1] == '-' || (is_number(arg) && after_option)) {
      continue;
    }
    if (arg.size() == 2 && allowed_short.find(arg[1]) != std::string::npos) continue;
    return arg;
  }
  return std::nullopt;
}

std::string unknown_single_dash_message(const std::string& arg, const std::string& command) {
  return "unknown option '" + arg + "' (" + command + "'s options start with two dashes, e.g. " +
         (command == "rdmesh" ? "--size" : "--view") + "; the only short ones are -o, -q and -h; " +
         help_hint(command) + ")";
}

std::string parse_error_message(const CLI::ParseError& e, const CLI::App& app,
                                const std::string& command) {
  const std::string what = e.what();
  if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr) {
    return "no input file given (usage: " + command + " INPUT [-o OUTPUT] [options]; " +
           help_hint(command) + ")";
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const std::vector<std::string> extras = app.remaining();
    const std::string first = extras.empty() ? what : extras.front();
    if (first.rfind("--", 0) == 0) {
      return "unknown option '" + first.substr(0, first.find('=')) + "' (" + help_hint(command) +
             ")";
    }
    return "unexpected argument '" + first + "': " + command + " takes one input file (" +
           help_hint(command) + ")";
  }
  if (dynamic_cast<const CLI::ExcludesError*>(&e) != nullptr) return what + ": give only one";
  const CLI::Option* opt = option_named_in(what, app);
  if (opt == nullptr) return what;  // no option to name: CLI11's own words
  const std::string name = long_name(*opt);
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr) {
    if (opt->get_type_size() == 0) return name + " takes no value";
    return name + " needs a value: " + accepted(*opt);
  }
  const std::vector<std::string>& given = opt->results();
  const std::string value = given.empty() ? std::string() : given.back();
  return name + ": '" + value + "' is not allowed; expected " + accepted(*opt);
}

std::string command_line_text(int argc, const char* const* argv) {
  std::string out;
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    bool plain = !arg.empty();
    for (const char c : arg) {
      const bool safe = std::isalnum(static_cast<unsigned char>(c)) ||
                        std::string("-_./=:,+@%").find(c) != std::string::npos;
      plain = plain && safe;
    }
    if (!out.empty()) out += ' ';
    if (plain) {
      out += arg;
      continue;
    }
    out += '\'';
    for (const char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        if (!is_number(v) || !std::isfinite(std::strtod(v.c_str(), nullptr))) {
          return "'" + v + "' is not a number";
        }
        return {};
      },
      "NUMBER");
}

}  // namespace rdmesh::run
