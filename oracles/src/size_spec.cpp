// Sizing objects (rdmesh/size_spec.h): sizing files and the domain file's "sizes".
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "rdmesh/errors.h"
#include "rdmesh/input_file.h"
#include "size_spec_json.h"

namespace rdmesh {

SizeSpec detail::size_spec_from_json(const nlohmann::ordered_json& object) {
  if (!object.is_object()) throw InputError("expected an object of sizes");
  SizeSpec spec;
  for (const auto& [key, value] : object.items()) {
    const double v = value.is_number() ? value.get<double>() : NAN;
    if (!value.is_number() || !std::isfinite(v)) {
      throw InputError("'" + key + "' must be a number");
    }
    if (key == "grade") {
      if (!(v > 1)) throw InputError("'grade' must be a number above 1");
      spec.grade = v;
    } else if (key == "curvature") {
      if (!(v > 0)) throw InputError("'curvature' must be a positive number of elements per turn");
      spec.curvature = v;
    } else if (key.find(':') == std::string::npos) {
      throw InputError("unknown key '" + key +
                       "' (expected KIND:WHICH such as \"face:12\", \"grade\" or \"curvature\")");
    } else {
      if (!(v > 0)) throw InputError("'" + key + "': the size must be a positive number");
      spec.entities.emplace_back(key, v);
    }
  }
  return spec;
}

SizeSpec parse_size_spec(const std::string& text, const std::string& origin) {
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(text, nullptr, /*allow_exceptions=*/true,
                                      /*ignore_comments=*/true);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(origin, std::string("not JSON: ") + e.what());
  }
  try {
    return detail::size_spec_from_json(j);
  } catch (const InputError& e) {
    throw InputError(origin, e.what());
  }
}

SizeSpec read_size_spec(const std::string& path) {
  check_input_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, std::string("cannot read the sizes file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "cannot read the sizes file");
  return parse_size_spec(text.str(), path);
}

}  // namespace rdmesh
