// Internal to cad/: the OpenCASCADE objects one thread uses to answer queries
// on one oracle. Surface adaptors cache B-spline spans, classifiers and
// intersectors keep state: each thread builds its own, lazily, per face, and
// keeps them in a small thread-local cache keyed by the oracle's serial number.
// Nothing here is shared between threads.
#pragma once

#include <BRepTopAdaptor_FClass2d.hxx>
#include <cstdint>
#include <memory>
#include <vector>

#include "cad_model.h"
#include "occt_fallback.h"
#include "surface_evaluator.h"

namespace rdmesh::cad {

/// One face's per-thread objects, and what the current query has done with it.
struct FaceState {
  std::unique_ptr<SurfaceEvaluator> surface;
  std::unique_ptr<BRepTopAdaptor_FClass2d> classifier;
  std::unique_ptr<OcctFaceIntersector> occt;
  std::uint64_t query = 0;        ///< the query the fields below belong to
  bool closed_form_done = false;  ///< the face's closed-form crossings were considered
  bool occt_done = false;         ///< OpenCASCADE intersected the face over the whole query
  /// Windows [w0, w1] of the segment OpenCASCADE intersected the face over.
  static constexpr int kWindows = 4;
  double occt_window[kWindows][2] = {};
  int occt_windows = 0;
};

class ThreadState {
 public:
  ThreadState(const CadOracle::Model& m, std::uint64_t serial);
  std::uint64_t serial() const { return serial_; }
  /// Starts a new query: every face's flags read as cleared.
  void begin_query() { ++query_; }
  /// Face i's state, its flags cleared if they belong to an earlier query.
  FaceState& face(int i);
  const SurfaceEvaluator& surface(int i);
  const BRepTopAdaptor_FClass2d& classifier(int i);
  OcctFaceIntersector& occt(int i);
  /// Where (u, v) lies in face i: the face's cells answer, or its classifier on
  /// a boundary cell (TopAbs_IN, TopAbs_ON or TopAbs_OUT).
  TopAbs_State classify(int i, double u, double v);
  /// Scratch for OpenCASCADE's hits (reused between queries).
  std::vector<OcctFaceIntersector::Hit> occt_hits;

 private:
  const CadOracle::Model* model_;
  std::uint64_t serial_;
  std::uint64_t query_ = 0;
  std::vector<FaceState> faces_;
};

/// This thread's state for the oracle with this model and serial number.
ThreadState& thread_state(const CadOracle::Model& m, std::uint64_t serial);

}  // namespace rdmesh::cad
