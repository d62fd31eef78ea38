// Per-thread OpenCASCADE state (thread_state.h).
#include "thread_state.h"

#include <BRep_Tool.hxx>
#include <array>
#include <gp_Pnt2d.hxx>

namespace rdmesh::cad {

ThreadState::ThreadState(const CadOracle::Model& m, std::uint64_t serial)
    : model_(&m), serial_(serial), faces_(m.faces.size()) {}

FaceState& ThreadState::face(int i) {
  FaceState& s = faces_[i];
  if (s.query != query_) {
    s.query = query_;
    s.closed_form_done = false;
    s.occt_done = false;
    s.occt_windows = 0;
  }
  return s;
}

const SurfaceEvaluator& ThreadState::surface(int i) {
  std::unique_ptr<SurfaceEvaluator>& s = faces_[i].surface;
  if (!s) s = std::make_unique<SurfaceEvaluator>(model_->faces[i]);
  return *s;
}

const BRepTopAdaptor_FClass2d& ThreadState::classifier(int i) {
  std::unique_ptr<BRepTopAdaptor_FClass2d>& c = faces_[i].classifier;
  if (!c) {
    const TopoDS_Face& f = model_->faces[i].face;
    c = std::make_unique<BRepTopAdaptor_FClass2d>(f, BRep_Tool::Tolerance(f));
  }
  return *c;
}

OcctFaceIntersector& ThreadState::occt(int i) {
  std::unique_ptr<OcctFaceIntersector>& x = faces_[i].occt;
  if (!x) x = std::make_unique<OcctFaceIntersector>(model_->faces[i], model_->tolerance);
  return *x;
}

TopAbs_State ThreadState::classify(int i, double u, double v) {
  return model_->faces[i].cells.classify(
      u, v, [&]() -> const BRepTopAdaptor_FClass2d& { return classifier(i); });
}

ThreadState& thread_state(const CadOracle::Model& m, std::uint64_t serial) {
  // A few oracles per thread; the least recently created slot is replaced.
  thread_local std::array<std::unique_ptr<ThreadState>, 4> slots;
  thread_local std::size_t next = 0;
  for (std::unique_ptr<ThreadState>& s : slots) {
    if (s && s->serial() == serial) return *s;
  }
  std::unique_ptr<ThreadState>& s = slots[next];
  next = (next + 1) % slots.size();
  s = std::make_unique<ThreadState>(m, serial);
  return *s;
}

}  // namespace rdmesh::cad
