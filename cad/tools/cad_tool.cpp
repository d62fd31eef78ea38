// rdmesh_cad_tool: small helpers around the CAD oracle for benchmarks and samples.
//   rdmesh_cad_tool load isolated|in-process FILE   seconds to load FILE
//   rdmesh_cad_tool faces FILE          per patch: area, box, sides
//   rdmesh_cad_tool info FILE           JSON: solids, patches, curves, corners, bbox, exact
//                                       volume (whole and per subdomain) and area
//   rdmesh_cad_tool thickness FILE      the thickness behind each curved face
//   rdmesh_cad_tool curves FILE         each curve's length, corners and ends
//   rdmesh_cad_tool write SHAPE FILE    writes a test shape (box, cylinder, box_minus_cylinder,
//                                       two_boxes, sphere) as STEP / BREP / IGES
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/curve.h"
#include "rdmesh/errors.h"
#include "rdmesh/stopwatch.h"

int main(int argc, char** argv) {
  using namespace rdmesh;
  try {
    const std::string cmd = argc > 1 ? argv[1] : "";
    if (cmd == "info" && argc == 3) {
      const auto o = load_cad_file(argv[2]);
      const Box3 b = o->bounding_box();
      std::printf(
          "{\"solids\": %d, \"subdomains\": %zu, \"patches\": %zu, \"curves\": %zu, "
          "\"corners\": %zu, \"diagonal\": %.17g, \"volume\": %.17g, \"area\": %.17g, "
          "\"subdomain_volumes\": [",
          o->input_solids(), o->subdomains().size(), o->patches().size(), o->curves().size(),
          o->corners().size(), b.diagonal() / 1.02, o->exact_volume(), o->exact_area());
      for (const SubdomainInfo& s : o->subdomains()) {
        std::printf("%s%.17g", s.id.value == 1 ? "" : ", ", o->exact_volume(s.id));
      }
      std::printf("]}\n");
      return 0;
    }
    if (cmd == "thickness" && argc == 3) {
      const auto o = load_cad_file(argv[2]);
      for (const PatchInfo& p : o->patches()) {
        const auto t = o->curved_thickness(p.id);
        if (t) std::printf("patch %d thickness %.6g\n", p.id.value, *t);
      }
      return 0;
    }
    if (cmd == "load" && argc == 4) {
      // Seconds to load FILE: read (isolated in a child or in this process),
      // sew, check and build the oracle.
      CadOptions options;
      options.isolate = std::string(argv[2]) == "isolated";
      const Stopwatch clock;
      const auto o = load_cad_file(argv[3], options);
      std::printf("%.6f\n", clock.seconds());
      return o->patches().empty() ? 1 : 0;
    }
    if (cmd == "faces" && argc == 3) {
      const auto o = load_cad_file(argv[2]);
      for (const PatchInfo& p : o->patches()) {
        const Box3 b = o->patch_box(p.id);
        std::printf("patch %d area %.6g box (%g %g %g) (%g %g %g) sides %d %d\n", p.id.value,
                    o->exact_area(p.id), b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z,
                    p.side_a.value, p.side_b.value);
      }
      return 0;
    }
    if (cmd == "curves" && argc == 3) {
      const auto o = load_cad_file(argv[2]);
      for (const CurveInfo& c : o->curves()) {
        const Curve& curve = o->curve(c.id);
        const Point3 a = curve.point(c.t_begin), b = curve.point(c.t_end);
        std::printf("curve %d length %.6g corners %d %d from (%g %g %g) to (%g %g %g)\n",
                    c.id.value, curve.length(c.t_begin, c.t_end), c.start.value, c.end.value, a.x,
                    a.y, a.z, b.x, b.y, b.z);
      }
      return 0;
    }
    const std::map<std::string, CadTestShape> shapes = {
        {"box", CadTestShape::box},
        {"cylinder", CadTestShape::cylinder},
        {"box_minus_cylinder", CadTestShape::box_minus_cylinder},
        {"two_boxes", CadTestShape::two_boxes},
        {"sphere", CadTestShape::sphere}};
    if (cmd == "write" && argc == 4 && shapes.count(argv[2])) {
      write_cad_test_shape(shapes.at(argv[2]), argv[3]);
      return 0;
    }
    std::cerr << "usage: rdmesh_cad_tool info FILE | write SHAPE FILE\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "rdmesh_cad_tool: error: " << e.what() << "\n";
    return 2;
  } catch (const Error& e) {
    std::cerr << "rdmesh_cad_tool: error: " << e.what() << "\n";
    return 1;
  }
}
