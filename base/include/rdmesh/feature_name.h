// How every message and report names a feature of the input complex: its kind,
// its id (ids start at 1) and, when it has one, its name in parentheses:
// "corner 3", "curve 7 (rim)", "patch 2 (top face)", "subdomain 1 (shell)".
#pragma once

#include <string>
#include <string_view>

#include "rdmesh/geometry.h"

namespace rdmesh {

std::string feature_name(CornerId id);
std::string feature_name(CurveId id, std::string_view name = {});
std::string feature_name(PatchId id, std::string_view name = {});
std::string feature_name(SubdomainId id, std::string_view name = {});

}  // namespace rdmesh
