#include "rdmesh/mesh_run.h"

#include <future>

#include "model_measures.h"
#include "rdmesh/atomic_file.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/number_text.h"
#include "rdmesh/parallel_for.h"
#include "rdmesh/stopwatch.h"

namespace rdmesh::run {

namespace {
/// Whether the mesh file can be written while the mesh is checked: a thread
/// to spare, and the mesh written is the mesh generated (no second order, no
/// partitions added after the check).
bool stage_while_checking(const Options& opt) {
  return !opt.output.empty() && resolve_threads(opt.threads) > 1 && opt.fem.order != 2 &&
         opt.fem.partitions == 0;
}
}  // namespace

MeshRun mesh_loaded(const Options& opt, const LoadedInput& input, const Criteria& criteria,
                    MeshOptions base) {
  MeshRun run;
  run.criteria = criteria;
  base.exudation = exudation_options(opt);
  base.improvement = improvement_options(opt);
  base.features = opt.features;
  base.surface_only = opt.surface_only;
  base.time_limit_seconds = opt.time_limit;
  base.threads = opt.threads;
  run.result = generate_mesh(*input.oracle, criteria, base);

  // The cheap measures and the fidelity check: a mesh that does not match the
  // model is not written (unless asked). With a thread to spare the file is
  // written meanwhile, under a temporary name: the check decides whether it
  // replaces opt.output (write_outputs). The task ends before this function
  // returns, so the mesh it reads stays where it is.
  std::future<StagedMesh> staging;
  if (stage_while_checking(opt)) {
    staging = std::async(std::launch::async, [&opt, &mesh = run.result.mesh] {
      StagedMesh s;
      const Stopwatch clock;
      try {
        s.file.emplace(stage_mesh(mesh, opt.output, opt.write));
      } catch (...) {
        s.error = std::current_exception();
      }
      s.seconds = clock.seconds();
      return s;
    });
  }
  const Stopwatch clock;
  announce(base, staging.valid()
                     ? "checking the mesh against the model, writing " + printable(opt.output)
                     : "checking the mesh against the model");
  const bool full = opt.full_check || !opt.report.empty();
  // The check takes every thread, the writer's too: its chunks go to whichever
  // thread is free, so that the two end about together. (1.18 M-tet sphere on
  // 2 threads: leaving the writer a core of its own, the check took 0.195 s
  // beside a 0.105 s write; sharing, 0.15-0.16 s beside a 0.17-0.19 s write.)
  run.quality = measure_quality(run.result.mesh, full ? input.oracle.get() : nullptr, opt.threads);
  if (const auto model = model_measures(*input.oracle, opt.surface_only)) {
    run.fidelity =
        check_fidelity(run.quality, *model, input.oracle->patches(), input.oracle->curves(),
                       patch_facet_distances(run.result.mesh, criteria.facet_distance),
                       run.result.stats.curves_below_min_size);
  }
  run.times.report = clock.seconds();
  if (staging.valid()) run.staged = staging.get();
  return run;
}

std::string failure_reason(const Options& opt, const MeshRun& run) {
  const RefinementStats& stats = run.result.stats;
  if (stats.time_limit_reached && stats.stopped_in != MeshingPhase::refinement) {
    return "the time limit (" + short_number(opt.time_limit) + " s) stopped the run in its " +
           phase_name(stats.stopped_in) + " phase, before any mesh";
  }
  if (stats.time_limit_reached) {
    return "refinement stopped at the time limit (" + short_number(opt.time_limit) + " s) with " +
           std::to_string(stats.elements_left) + " elements still queued";
  }
  std::string reason;
  if (run.quality.inverted_tets > 0) {
    const std::size_t n = run.quality.inverted_tets;
    reason = std::to_string(n) + (n == 1 ? " tetrahedron is" : " tetrahedra are") +
             " inverted or flat (signed volume <= 0)";
  }
  if (run.fidelity && !run.fidelity->passed) {
    if (!reason.empty()) reason += "; ";
    reason += "the mesh does not match the model: " + summarize_problems(*run.fidelity);
  }
  return reason;
}

nlohmann::json run_report(const Options& opt, const DomainOracle& oracle, const MeshRun& run) {
  nlohmann::json j =
      report_json(opt, run.criteria, oracle, run.result.stats, run.result.exudation,
                  run.result.improvement, run.quality, run.fidelity, run.times, run.fem);
  const std::string reason = failure_reason(opt, run);
  j["failure"] = reason.empty() ? nlohmann::json(nullptr) : nlohmann::json(reason);
  return j;
}

void apply_fem(const Options& opt, const AppliedSizes& sizes, const DomainOracle& oracle,
               const MeshOptions& options, MeshRun& run) {
  if (opt.fem.order == 2) announce(options, "making second-order elements");
  if (opt.fem.order != 2 && opt.fem.partitions > 0) announce(options, "partitioning");
  run.fem = apply_fem_options(opt.fem, sizes, run.result.mesh, oracle, run.criteria.min_size);
}

void write_outputs(const Options& opt, const DomainOracle& oracle, const MeshOptions& options,
                   bool write_mesh_too, MeshRun& run) {
  const Stopwatch clock;
  const bool staged = run.staged.started();
  if (write_mesh_too) {
    if (staged) {
      if (run.staged.error) std::rethrow_exception(run.staged.error);
      run.staged.file->commit();
    } else if (!opt.output.empty()) {
      announce(options, "writing " + printable(opt.output));
      write_mesh(run.result.mesh, opt.output, opt.write);
    }
    if (!opt.picture.path.empty()) {
      announce(options, "drawing " + printable(opt.picture.path));
      write_picture(run.result.mesh, opt.picture, opt.input);
    }
  }
  run.staged.file.reset();  // not wanted: its temporary file goes
  run.times.write = clock.seconds() + (staged ? run.staged.seconds : 0.0);
  if (!opt.report.empty()) {
    announce(options, "writing " + printable(opt.report));
    const nlohmann::json report = run_report(opt, oracle, run);
    write_file_atomically(opt.report, [&](std::ostream& out) { out << report.dump(2) << '\n'; });
  }
}

void announce(const MeshOptions& options, const std::string& phase) {
  if (!options.progress) return;
  Progress p;
  p.phase = phase.c_str();
  options.progress(p);
}

}  // namespace rdmesh::run
