// rdmesh vs CGAL Mesh_3: same domains, same criteria, same run. Prints Markdown tables.
//
// Each side of each case runs in its own forked child process (unless --no-fork):
// a crash or a hang of one side (rdmesh is young) is reported in the table
// instead of ending the run, each side starts from a fresh heap, and the
// child's peak RSS is that side's own peak memory.
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cgal_anchor.h"
#include "polyhedral_anchor.h"
#include "rdmesh_side.h"
#include "shapes.h"

namespace {

struct Case {
  std::string name;
  std::string shape;
  double h;
  bool quick;  ///< part of --quick
};

const std::vector<Case>& all_cases() {
  static const std::vector<Case> cases = {
      {"sphere-0.1", "sphere", 0.1, true},
      {"sphere-0.05", "sphere", 0.05, false},
      {"sphere-0.025", "sphere", 0.025, false},
      {"torus-0.05", "torus", 0.05, true},
      {"torus-0.025", "torus", 0.025, false},
      // Triangle meshes (h as a fraction of the box diagonal), Mesh_3 with features at 60 degrees.
      {"fandisk-0.03", "mesh:cgal_fandisk.off", 0.03, true},
      {"anchor-0.03", "mesh:cgal_anchor.off", 0.03, false},
      {"joint-0.03", "mesh:cgal_joint.off", 0.03, false},
      {"part-0.03", "mesh:cgal_part.off", 0.03, false},
      {"pinion-0.025", "mesh:cgal_pinion.off", 0.025, false},
      {"spool-0.03", "mesh:cgal_spool.off", 0.03, false},
      {"tripod-0.03", "mesh:cgal_tripod.off", 0.03, false},
      {"part1-0.03", "mesh:netgen_part1.stl", 0.03, false},
      {"hinge-0.03", "mesh:netgen_hinge.stl", 0.03, false},
  };
  return cases;
}

/// One side's run, in a form that crosses a pipe (trivially copyable).
struct Wire {
  int ok = 0;
  std::uint64_t tets = 0, vertices = 0, non_positive = 0, guard_rejections = 0;
  double seconds = 0, setup_seconds = 0, min_dihedral_deg = 0, max_radius_edge = 0, volume = 0;
  // --optimize: quality before the optimizers, their times.
  std::uint64_t below_10 = 0, below_10_before = 0;
  double min_dihedral_before_deg = 0, min_dihedral_perturbed_deg = -1;
  double refine_seconds = 0, perturb_seconds = 0, exude_seconds = 0;
  char error[400] = {};
};

struct Outcome {
  Wire w;
  std::string error;      ///< empty when ok
  long peak_rss_kb = -1;  ///< -1 when unknown (--no-fork)
};

enum class Side { kRdmesh, kCgal };

double g_cgal_relative_error = 1e-3;  // --cgal-relative-error
bool g_optimize = false;              // --optimize

Wire run_side_inline(Side side, const Case& c) {
  Wire w;
  try {
    if (side == Side::kRdmesh) {
      const RdmeshResult r = is_polyhedral_shape(c.shape)
                                 ? run_rdmesh_polyhedral(c.shape, c.h, g_optimize)
                                 : run_rdmesh(c.shape, c.h, g_optimize);
      w.tets = r.tets;
      w.vertices = r.vertices;
      w.seconds = r.seconds;
      w.setup_seconds = r.setup_seconds;
      w.min_dihedral_deg = r.min_dihedral_deg;
      w.max_radius_edge = r.max_radius_edge;
      w.volume = r.volume;
      w.non_positive = r.non_positive;
      w.guard_rejections = r.guard_rejections;
      w.below_10 = r.below_10_deg;
      w.below_10_before = r.below_10_deg_before;
      w.min_dihedral_before_deg = r.min_dihedral_before_deg;
      w.refine_seconds = r.refine_seconds;
      w.exude_seconds = r.optimize_seconds;
    } else {
      const AnchorResult r = is_polyhedral_shape(c.shape)
                                 ? run_cgal_polyhedral(c.shape, c.h, g_optimize)
                                 : run_cgal_anchor(c.shape, c.h, g_cgal_relative_error, g_optimize);
      w.tets = r.tets;
      w.vertices = r.vertices;
      w.seconds = r.seconds;
      w.min_dihedral_deg = r.min_dihedral_deg;
      w.max_radius_edge = r.max_radius_edge;
      w.volume = r.volume;
      w.non_positive = r.non_positive;
      w.below_10 = r.below_10_deg;
      w.below_10_before = r.below_10_deg_before;
      w.min_dihedral_before_deg = r.min_dihedral_before_deg;
      w.min_dihedral_perturbed_deg = r.min_dihedral_perturbed_deg;
      w.refine_seconds = r.refine_seconds;
      w.perturb_seconds = r.perturb_seconds;
      w.exude_seconds = r.exude_seconds;
    }
    w.ok = 1;
    if (w.tets == 0) {
      w.ok = 0;
      std::snprintf(w.error, sizeof w.error, "empty mesh (0 tetrahedra)");
    }
  } catch (const std::exception& e) {
    std::snprintf(w.error, sizeof w.error, "%s", e.what());
  } catch (...) {
    std::snprintf(w.error, sizeof w.error, "unknown exception");
  }
  return w;
}

Outcome run_side(Side side, const Case& c, bool fork_side, int timeout_s) {
  Outcome out;
  if (!fork_side) {
    out.w = run_side_inline(side, c);
    if (!out.w.ok) out.error = out.w.error;
    return out;
  }
  int fds[2];
  if (pipe(fds) != 0) {
    out.error = std::string("pipe: ") + std::strerror(errno);
    return out;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) {
    out.error = std::string("fork: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return out;
  }
  if (pid == 0) {  // child
    close(fds[0]);
    if (timeout_s > 0) alarm(static_cast<unsigned>(timeout_s));
    const Wire w = run_side_inline(side, c);
    const char* p = reinterpret_cast<const char*>(&w);
    std::size_t left = sizeof w;
    while (left > 0) {
      const ssize_t n = write(fds[1], p, left);
      if (n <= 0) _exit(3);
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  Wire w;
  char* p = reinterpret_cast<char*>(&w);
  std::size_t got = 0;
  while (got < sizeof w) {
    const ssize_t n = read(fds[0], p + got, sizeof w - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  close(fds[0]);
  int status = 0;
  struct rusage ru {};
  while (wait4(pid, &status, 0, &ru) < 0 && errno == EINTR) {
  }
  out.peak_rss_kb = ru.ru_maxrss;  // kilobytes on Linux
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    out.error = sig == SIGALRM
                    ? "timeout after " + std::to_string(timeout_s) + " s"
                    : "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
  } else if (got != sizeof w) {
    out.error = "child exited with status " + std::to_string(WEXITSTATUS(status));
  } else {
    out.w = w;
    if (!w.ok) out.error = w.error;
  }
  return out;
}

/// The run with the median time among the successful ones (the first failure if none).
Outcome median_outcome(std::vector<Outcome> runs) {
  std::vector<Outcome> ok;
  for (const Outcome& o : runs)
    if (o.error.empty()) ok.push_back(o);
  if (ok.empty()) return runs.front();
  std::sort(ok.begin(), ok.end(),
            [](const Outcome& a, const Outcome& b) { return a.w.seconds < b.w.seconds; });
  return ok[(ok.size() - 1) / 2];  // lower median for an even count: an actual run
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string cell_error(const std::string& e) {
  std::string s = e;
  std::replace(s.begin(), s.end(), '|', '/');
  std::replace(s.begin(), s.end(), '\n', ' ');
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return "failed: " + s;
}

struct Row {
  Case c;
  std::optional<Outcome> r, cg;
};

bool succeeded(const std::optional<Outcome>& o) { return o && o->error.empty(); }

/// --optimize: smallest dihedral angle and tets below 10 degrees before and
/// after each side's optimizers, and the optimizers' times.
void print_optimize_table(const std::vector<Row>& rows, int repeat) {
  std::printf(
      "Sliver removal: rdmesh sliver exudation vs CGAL %s perturb_mesh_3 + exude_mesh_3 as\n"
      "make_mesh_3(perturb(), exude()) runs them (default bounds, time limit = refine time\n"
      "each); same criteria as the refinement table (cell radius-edge 3); %d run(s) per side,\n"
      "median total time; CGAL relative_error_bound %g. Angles in degrees, min over all tets;\n"
      "'<10' = tets with a dihedral angle below 10 degrees.\n\n",
      cgal_anchor_version().c_str(), repeat, g_cgal_relative_error);
  std::printf(
      "| case | tets (r / C) | min dihedral before (r / C) | rdmesh after exude | CGAL after "
      "perturb | CGAL after exude | <10 before (r / C) | <10 after (r / C) | refine s (r / C) "
      "| optimize s (r / C) | CGAL perturb s + exude s | optimize time ratio r/C |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& row : rows) {
    const bool rok = succeeded(row.r), cok = succeeded(row.cg);
    const Wire* r = rok ? &row.r->w : nullptr;
    const Wire* c = cok ? &row.cg->w : nullptr;
    auto num = [](const Wire* w, const char* f, double v) {
      return w ? fmt(f, v) : std::string("-");
    };
    auto cnt = [](const Wire* w, std::uint64_t v) {
      return w ? std::to_string(v) : std::string("-");
    };
    const std::string rt = rok ? std::to_string(r->tets) : row.r ? cell_error(row.r->error) : "-";
    const std::string ct = cok ? std::to_string(c->tets) : row.cg ? cell_error(row.cg->error) : "-";
    const double c_opt = c ? c->perturb_seconds + c->exude_seconds : 0;
    std::printf(
        "| %s | %s / %s | %s / %s | %s | %s | %s | %s / %s | %s / %s | %s / %s | %s / %s | %s + %s "
        "| %s |\n",
        row.c.name.c_str(), rt.c_str(), ct.c_str(),
        num(r, "%.2f", r ? r->min_dihedral_before_deg : 0).c_str(),
        num(c, "%.2f", c ? c->min_dihedral_before_deg : 0).c_str(),
        num(r, "%.2f", r ? r->min_dihedral_deg : 0).c_str(),
        num(c, "%.2f", c ? c->min_dihedral_perturbed_deg : 0).c_str(),
        num(c, "%.2f", c ? c->min_dihedral_deg : 0).c_str(),
        cnt(r, r ? r->below_10_before : 0).c_str(), cnt(c, c ? c->below_10_before : 0).c_str(),
        cnt(r, r ? r->below_10 : 0).c_str(), cnt(c, c ? c->below_10 : 0).c_str(),
        num(r, "%.2f", r ? r->refine_seconds : 0).c_str(),
        num(c, "%.2f", c ? c->refine_seconds : 0).c_str(),
        num(r, "%.2f", r ? r->exude_seconds : 0).c_str(), num(c, "%.2f", c_opt).c_str(),
        num(c, "%.2f", c ? c->perturb_seconds : 0).c_str(),
        num(c, "%.2f", c ? c->exude_seconds : 0).c_str(),
        r && c && c_opt > 0 ? fmt("%.2f", r->exude_seconds / c_opt).c_str() : "-");
  }
}

void usage(const char* argv0) {
  std::fprintf(stderr,
               "usage: %s [--quick] [--case NAME]... [--repeat N] [--side both|rdmesh|cgal]\n"
               "          [--timeout SECONDS] [--no-fork] [--cgal-relative-error E] [--optimize]\n"
               "cases:",
               argv0);
  for (const Case& c : all_cases()) std::fprintf(stderr, " %s", c.name.c_str());
  std::fprintf(stderr,
               "\n--quick: sphere-0.1 and torus-0.05. Default: all cases, once per side.\n"
               "--optimize: sliver removal table (rdmesh exudation vs CGAL perturb + exude);\n"
               "  default cases sphere-0.025 and torus-0.05.\n");
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, fork_side = true;
  int repeat = 1, timeout_s = 1800;
  std::string sides = "both";
  std::vector<std::string> selected;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        usage(argv[0]);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--quick") {
      quick = true;
    } else if (a == "--case") {
      selected.push_back(value());
    } else if (a == "--repeat") {
      repeat = std::atoi(value().c_str());
    } else if (a == "--timeout") {
      timeout_s = std::atoi(value().c_str());
    } else if (a == "--side") {
      sides = value();
    } else if (a == "--cgal-relative-error") {
      g_cgal_relative_error = std::atof(value().c_str());
    } else if (a == "--optimize") {
      g_optimize = true;
    } else if (a == "--no-fork") {
      fork_side = false;
    } else if (a == "-h" || a == "--help") {
      usage(argv[0]);
      return 0;
    } else {
      std::fprintf(stderr, "unknown argument: %s\n", a.c_str());
      usage(argv[0]);
      return 2;
    }
  }
  if (repeat < 1 || !(g_cgal_relative_error > 0) ||
      (sides != "both" && sides != "rdmesh" && sides != "cgal")) {
    usage(argv[0]);
    return 2;
  }
  std::vector<Case> cases;
  for (const Case& c : all_cases()) {
    const bool default_pick = g_optimize
                                  ? (quick ? c.name == "sphere-0.1" || c.name == "torus-0.05"
                                           : c.name == "sphere-0.025" || c.name == "torus-0.05")
                                  : (!quick || c.quick);
    const bool picked = selected.empty()
                            ? default_pick
                            : std::find(selected.begin(), selected.end(), c.name) != selected.end();
    if (picked) cases.push_back(c);
  }
  for (const std::string& s : selected) {
    if (std::none_of(all_cases().begin(), all_cases().end(),
                     [&](const Case& c) { return c.name == s; })) {
      std::fprintf(stderr, "unknown case: %s\n", s.c_str());
      usage(argv[0]);
      return 2;
    }
  }
  const bool run_r = sides != "cgal", run_c = sides != "rdmesh";

  std::vector<Row> rows;
  for (const Case& c : cases) {
    std::vector<Outcome> rr, cc;
    for (int k = 0; k < repeat; ++k) {
      // Alternate which side goes first, so that neither always meets a warm (or hot) CPU.
      const bool rdmesh_first = k % 2 == 0;
      for (int s = 0; s < 2; ++s) {
        const Side side = (s == 0) == rdmesh_first ? Side::kRdmesh : Side::kCgal;
        if ((side == Side::kRdmesh && !run_r) || (side == Side::kCgal && !run_c)) continue;
        std::fprintf(stderr, "[%s] %s run %d/%d ...\n", c.name.c_str(),
                     side == Side::kRdmesh ? "rdmesh" : "CGAL", k + 1, repeat);
        Outcome o = run_side(side, c, fork_side, timeout_s);
        if (o.error.empty())
          std::fprintf(stderr, "[%s]   %zu tets in %.3f s\n", c.name.c_str(),
                       static_cast<std::size_t>(o.w.tets), o.w.seconds);
        else
          std::fprintf(stderr, "[%s]   %s\n", c.name.c_str(), o.error.c_str());
        (side == Side::kRdmesh ? rr : cc).push_back(std::move(o));
      }
    }
    Row row{c, {}, {}};
    if (!rr.empty()) row.r = median_outcome(rr);
    if (!cc.empty()) row.cg = median_outcome(cc);
    rows.push_back(std::move(row));
  }

  if (g_optimize) {
    print_optimize_table(rows, repeat);
    bool all_ok = true;
    for (const Row& row : rows)
      all_ok = all_ok && (!row.r || succeeded(row.r)) && (!row.cg || succeeded(row.cg));
    return all_ok ? 0 : 1;
  }
  std::printf(
      "rdmesh vs CGAL %s Mesh_3 (sequential), criteria: facet angle 25, facet size = cell size = "
      "h,\n"
      "facet distance h/10, cell radius-edge 3, no perturb, no exude; %d run(s) per side, median "
      "time;\n"
      "CGAL relative_error_bound %g.\n\n",
      cgal_anchor_version().c_str(), repeat, g_cgal_relative_error);
  std::printf(
      "| case | h | rdmesh tets | rdmesh s | rdmesh tets/s | CGAL tets | CGAL s | CGAL tets/s "
      "| time ratio rdmesh/CGAL | min dihedral (r / C) | max radius-edge (r / C) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  auto ok = [](const std::optional<Outcome>& o) { return o && o->error.empty(); };
  for (const Row& row : rows) {
    std::string rt = "-", rs = "-", rtps = "-", ct = "-", cs = "-", ctps = "-", ratio = "-";
    std::string rdih = "-", cdih = "-", rre = "-", cre = "-";
    if (ok(row.r)) {
      const Wire& w = row.r->w;
      rt = std::to_string(w.tets);
      rs = fmt("%.3f", w.seconds);
      rtps = fmt("%.0f", w.tets / w.seconds);
      rdih = fmt("%.2f", w.min_dihedral_deg);
      rre = fmt("%.3f", w.max_radius_edge);
    } else if (row.r) {
      rt = cell_error(row.r->error);
    }
    if (ok(row.cg)) {
      const Wire& w = row.cg->w;
      ct = std::to_string(w.tets);
      cs = fmt("%.3f", w.seconds);
      ctps = fmt("%.0f", w.tets / w.seconds);
      cdih = fmt("%.2f", w.min_dihedral_deg);
      cre = fmt("%.3f", w.max_radius_edge);
    } else if (row.cg) {
      ct = cell_error(row.cg->error);
    }
    if (ok(row.r) && ok(row.cg)) ratio = fmt("%.2f", row.r->w.seconds / row.cg->w.seconds);
    std::printf("| %s | %g | %s | %s | %s | %s | %s | %s | %s | %s / %s | %s / %s |\n",
                row.c.name.c_str(), row.c.h, rt.c_str(), rs.c_str(), rtps.c_str(), ct.c_str(),
                cs.c_str(), ctps.c_str(), ratio.c_str(), rdih.c_str(), cdih.c_str(), rre.c_str(),
                cre.c_str());
  }

  std::printf(
      "\nSanity and memory: vertices, total volume of the tets (exact volume of the smooth "
      "domain in brackets),\nrdmesh oracle setup time (box sampling, not in 'rdmesh s'), "
      "minimum-size guard rejections,\npeak RSS of each side's own process.\n\n");
  std::printf(
      "| case | vertices (r / C) | volume (r / C) [exact] | rdmesh oracle setup s | rdmesh guard "
      "rejections | peak RSS MB (r / C) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const Row& row : rows) {
    const rdmesh_bench::Shape* shape = rdmesh_bench::find_shape(row.c.shape);
    std::string rv = "-", cv = "-", rvol = "-", cvol = "-", setup = "-", guard = "-", rm = "-",
                cm = "-";
    if (ok(row.r)) {
      const Wire& w = row.r->w;
      rv = std::to_string(w.vertices);
      rvol = fmt("%.4f", w.volume);
      setup = fmt("%.3f", w.setup_seconds);
      guard = std::to_string(w.guard_rejections);
    }
    if (ok(row.cg)) {
      cv = std::to_string(row.cg->w.vertices);
      cvol = fmt("%.4f", row.cg->w.volume);
    }
    if (row.r && row.r->peak_rss_kb >= 0) rm = fmt("%.0f", row.r->peak_rss_kb / 1024.0);
    if (row.cg && row.cg->peak_rss_kb >= 0) cm = fmt("%.0f", row.cg->peak_rss_kb / 1024.0);
    std::printf("| %s | %s / %s | %s / %s [%.4f] | %s | %s | %s / %s |\n", row.c.name.c_str(),
                rv.c_str(), cv.c_str(), rvol.c_str(), cvol.c_str(),
                shape ? shape->exact_volume : 0.0, setup.c_str(), guard.c_str(), rm.c_str(),
                cm.c_str());
  }
  for (const Row& row : rows) {
    if (ok(row.r) && row.r->w.non_positive > 0)
      std::printf("\nWARNING: %s: rdmesh output has %zu tets that are not positively oriented.\n",
                  row.c.name.c_str(), static_cast<std::size_t>(row.r->w.non_positive));
    if (ok(row.cg) && row.cg->w.non_positive > 0)
      std::printf("\nWARNING: %s: CGAL output has %zu cells that are not positively oriented.\n",
                  row.c.name.c_str(), static_cast<std::size_t>(row.cg->w.non_positive));
  }
  bool all_ok = true;
  for (const Row& row : rows) all_ok = all_ok && (!row.r || ok(row.r)) && (!row.cg || ok(row.cg));
  return all_ok ? 0 : 1;
}
