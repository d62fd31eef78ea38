// Gmsh MSH ASCII reader, versions 4.1 (what rdmesh and current Gmsh write) and
// 2.2 (the legacy format many tools still write).
//
// Labels: in 4.1 an element takes the first physical tag of its entity, or the
// entity's own tag when it has none (files saved without physical groups); in
// 2.2 its first tag (physical) unless zero, else its second (elementary).
// Higher-order elements keep their corner nodes; quadrangles, hexahedra,
// prisms and pyramids are counted as skipped.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "element_kinds.h"
#include "node_tags.h"
#include "rdmesh/errors.h"
#include "rdmesh/view_mesh.h"
#include "text_scanner.h"

namespace rdmesh::view {
namespace {

using detail::Kind;

struct GmshType {
  int nodes;  ///< 0: unknown type
  Kind kind;
};

/// Node count and kind of Gmsh element types 1..31 (GmshDefines.h).
GmshType gmsh_type(std::int64_t type) {
  static const GmshType kTypes[32] = {
      {0, Kind::kOther},     {2, Kind::kLine},      {3, Kind::kTriangle},  {4, Kind::kOther},
      {4, Kind::kTet},       {8, Kind::kOther},     {6, Kind::kOther},     {5, Kind::kOther},
      {3, Kind::kLine},      {6, Kind::kTriangle},  {9, Kind::kOther},     {10, Kind::kTet},
      {27, Kind::kOther},    {18, Kind::kOther},    {14, Kind::kOther},    {1, Kind::kPoint},
      {8, Kind::kOther},     {20, Kind::kOther},    {15, Kind::kOther},    {13, Kind::kOther},
      {9, Kind::kTriangle},  {10, Kind::kTriangle}, {12, Kind::kTriangle}, {15, Kind::kTriangle},
      {15, Kind::kTriangle}, {21, Kind::kTriangle}, {4, Kind::kLine},      {5, Kind::kLine},
      {6, Kind::kLine},      {20, Kind::kTet},      {35, Kind::kTet},      {56, Kind::kTet}};
  return type >= 1 && type <= 31 ? kTypes[type] : GmshType{0, Kind::kOther};
}

constexpr std::int64_t kMaxInt = 2147483647;

class GmshReader {
 public:
  GmshReader(const std::string& text, const std::string& file) : s_(text, file) {}

  ViewMesh read() {
    s_.expect("$MeshFormat");
    const double version = s_.read_double("the format version");
    const std::int64_t file_type = s_.read_int("the file type");
    s_.read_int("the data size");
    if (file_type != 0) s_.fail("binary .msh files are not supported (save the mesh as ASCII)");
    s_.expect("$EndMeshFormat");
    if (version >= 2 && version < 3) {
      v2_ = true;
    } else if (!(version >= 4.1 && version < 5)) {
      s_.fail("MSH version " + std::to_string(version).substr(0, 3) +
              " is not supported (4.1 and 2.2 are)");
    }
    while (!s_.at_end()) read_section();
    if (!have_nodes_) s_.fail("no $Nodes section");
    for (const auto& [tag, name] : volume_names_) mesh_.subdomain_names[tag] = name;
    return std::move(mesh_);
  }

 private:
  void read_section() {
    const std::string section(s_.next());
    if (section.size() < 2 || section[0] != '$')
      s_.fail("expected a $Section, found '" + section + "'");
    const std::string name = section.substr(1);
    if (name == "PhysicalNames") {
      read_physical_names();
    } else if (name == "Entities" && !v2_) {
      read_entities();
    } else if (name == "Nodes") {
      if (have_nodes_) s_.fail("a second $Nodes section");
      v2_ ? read_nodes_v2() : read_nodes_v41();
      if (!tags_.build(node_tags_)) s_.fail("node tags must be distinct and positive");
      have_nodes_ = true;
    } else if (name == "Elements") {
      if (!have_nodes_) s_.fail("$Elements before $Nodes");
      v2_ ? read_elements_v2() : read_elements_v41();
    } else {
      s_.skip_past("$End" + name);  // $Periodic, $NodeData, ...: nothing to draw
      return;
    }
    s_.expect("$End" + name);
  }

  void read_physical_names() {
    const std::size_t n = s_.read_count("the number of physical names", 6);
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t dim = s_.read_int("a physical dimension", 0, 3);
      const std::int64_t tag = s_.read_int("a physical tag", -kMaxInt, kMaxInt);
      std::string name = s_.read_quoted("a physical name");
      if (dim == 3) volume_names_[static_cast<int>(tag)] = std::move(name);
    }
  }

  /// Reads `n` tags of a list (physical tags, bounding entities); returns the first (or 0).
  std::int64_t read_tag_list(const char* what) {
    const std::size_t n = s_.read_count(what, 2);
    std::int64_t first = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t t = s_.read_int("a tag", -kMaxInt, kMaxInt);
      if (i == 0) first = t;
    }
    return n > 0 ? first : 0;
  }

  void read_entities() {
    std::size_t counts[4];
    for (std::size_t& c : counts) c = s_.read_count("the number of entities", 8);
    for (int dim = 0; dim < 4; ++dim) {
      for (std::size_t i = 0; i < counts[dim]; ++i) {
        const std::int64_t tag = s_.read_int("an entity tag", -kMaxInt, kMaxInt);
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) s_.read_double("a coordinate");
        const std::int64_t physical = read_tag_list("the number of physical tags");
        if (dim > 0) read_tag_list("the number of bounding entities");
        entity_label_[{dim, static_cast<int>(tag)}] =
            static_cast<int>(physical != 0 ? physical : tag);
      }
    }
  }

  Point3 read_point() {
    Point3 p;
    p.x = s_.read_double("a coordinate");
    p.y = s_.read_double("a coordinate");
    p.z = s_.read_double("a coordinate");
    return p;
  }

  void read_nodes_v41() {
    const std::size_t blocks = s_.read_count("the number of node blocks", 8);
    const std::size_t total = s_.read_count("the number of nodes", 8);
    s_.read_int("the smallest node tag");
    s_.read_int("the largest node tag");
    if (total > static_cast<std::size_t>(kMaxInt)) s_.fail("too many nodes");
    mesh_.points.reserve(total);
    node_tags_.reserve(total);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::int64_t dim = s_.read_int("an entity dimension", 0, 3);
      s_.read_int("an entity tag");
      const std::int64_t parametric = s_.read_int("the parametric flag", 0, 1);
      const std::size_t n = s_.read_count("the number of nodes in a block", 8);
      if (node_tags_.size() + n > total) s_.fail("more nodes than the $Nodes header says");
      for (std::size_t i = 0; i < n; ++i) node_tags_.push_back(s_.read_int("a node tag"));
      for (std::size_t i = 0; i < n; ++i) {
        mesh_.points.push_back(read_point());
        for (std::int64_t k = 0; k < (parametric ? dim : 0); ++k) s_.read_double("a parameter");
      }
    }
    if (node_tags_.size() != total) s_.fail("fewer nodes than the $Nodes header says");
  }

  void read_nodes_v2() {
    const std::size_t n = s_.read_count("the number of nodes", 8);
    if (n > static_cast<std::size_t>(kMaxInt)) s_.fail("too many nodes");
    mesh_.points.reserve(n);
    node_tags_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      node_tags_.push_back(s_.read_int("a node tag"));
      mesh_.points.push_back(read_point());
    }
  }

  /// Reads an element's `count` node tags and adds it (or counts it as skipped).
  void read_element(const GmshType& type, int label) {
    int nodes[56];
    for (int k = 0; k < type.nodes; ++k) {
      const std::int64_t tag = s_.read_int("a node tag");
      nodes[k] = tags_.find(tag);
      if (nodes[k] < 0)
        s_.fail("an element refers to node " + std::to_string(tag) + ", not in $Nodes");
    }
    detail::add_element(mesh_, type.kind, nodes, label);
  }

  GmshType checked_type(std::int64_t code) {
    const GmshType type = gmsh_type(code);
    if (type.nodes == 0) s_.fail("element type " + std::to_string(code) + " is not supported");
    return type;
  }

  void read_elements_v41() {
    const std::size_t blocks = s_.read_count("the number of element blocks", 8);
    s_.read_count("the number of elements", 4);
    s_.read_int("the smallest element tag");
    s_.read_int("the largest element tag");
    for (std::size_t b = 0; b < blocks; ++b) {
      const int dim = static_cast<int>(s_.read_int("an entity dimension", 0, 3));
      const int entity = static_cast<int>(s_.read_int("an entity tag", -kMaxInt, kMaxInt));
      const GmshType type = checked_type(s_.read_int("an element type"));
      const std::size_t n =
          s_.read_count("the number of elements in a block", 2 * (type.nodes + 1));
      auto it = entity_label_.find({dim, entity});
      const int label = it != entity_label_.end() ? it->second : entity;
      for (std::size_t i = 0; i < n; ++i) {
        s_.read_int("an element tag");
        read_element(type, label);
      }
    }
  }

  void read_elements_v2() {
    const std::size_t n = s_.read_count("the number of elements", 8);
    for (std::size_t i = 0; i < n; ++i) {
      s_.read_int("an element tag");
      const GmshType type = checked_type(s_.read_int("an element type"));
      const std::size_t ntags = s_.read_count("the number of tags", 2);
      std::int64_t label = 0;
      for (std::size_t k = 0; k < ntags; ++k) {
        const std::int64_t tag = s_.read_int("a tag", -kMaxInt, kMaxInt);
        if (k == 0 || (k == 1 && label == 0)) label = tag;
      }
      read_element(type, static_cast<int>(label));
    }
  }

  detail::TextScanner s_;
  ViewMesh mesh_;
  bool v2_ = false;
  bool have_nodes_ = false;
  std::vector<std::int64_t> node_tags_;
  detail::NodeTags tags_;
  std::map<std::pair<int, int>, int> entity_label_;
  std::map<int, std::string> volume_names_;
};

}  // namespace

ViewMesh parse_gmsh(const std::string& text, const std::string& file) {
  return GmshReader(text, file).read();
}

}  // namespace rdmesh::view
