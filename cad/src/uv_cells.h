// Internal to cad/: where a point of a face's (u, v) box lies relative to the
// face, mostly without OpenCASCADE's 2D classifier.
//
// The face's boundary is its pcurves, cut into chords until each strays from
// its chord by little; each chord carries a reach: twice the sampled sagitta,
// plus a margin, the widest gap between consecutive pcurves, and the band in
// which OpenCASCADE's face classifier answers with tolerances (twice the
// (u, v) tolerance it is built with, and the edge's 3D tolerance carried into
// (u, v)). The true boundary, and every point that classifier might call ON
// against the geometry, lie within the union of these tubes. Each chord also
// has finer chords of its piece of pcurve, ten times closer to it.
//
// A kd-tree cuts the (u, v) box into cells (built by face_tessellation.cpp).
// A cell no tube meets is wholly inside or wholly outside the face (its centre
// decides). A boundary cell lists the chords meeting it and keeps a reference
// point outside every tube, classified once: a point of the cell that is
// outside every tube has the reference's state flipped by each chord the
// segment between them crosses (exact, since both ends lie on the same side of
// the true boundary as of the chords). A point inside a chord's tube counts
// that chord's finer chords instead, when it lies outside their tubes. Points
// inside a finer tube, or where a chord end lies on that segment, are left to
// the face's classifier.
#pragma once

#include <BRepTopAdaptor_FClass2d.hxx>
#include <cstdint>
#include <gp_Pnt2d.hxx>
#include <vector>

namespace rdmesh::cad {

struct FacePatch;

/// Where a point of a face's (u, v) box lies relative to the face.
enum class UvState : std::uint8_t {
  outside,
  inside,
  boundary,  ///< undecided: ask the face's classifier
};

/// A chord of a pcurve; the pcurve stays within `reach` of it. A chord may
/// have finer chords of the same piece of pcurve (UvCells::fine[fine_first,
/// fine_first + fine_count)), with narrower tubes.
struct UvSegment {
  double au, av, bu, bv;
  double reach;
  int fine_first = 0, fine_count = 0;
};

/// The face's pcurves as chords, and their finer chords (see the file comment);
/// `poles` gets the chords of degenerated edges with a wide tube (UvCells::near_pole).
void boundary_segments(const FacePatch& f, std::vector<UvSegment>& chords,
                       std::vector<UvSegment>& fine, std::vector<UvSegment>& poles);

class UvCells {
 public:
  struct Node {
    double split = 0;       ///< inner node: the cut value along `axis`
    int child = -1;         ///< inner node: the low child (the high one is child + 1); leaf: -1
    std::uint8_t axis = 0;  ///< 0: u, 1: v
    UvState state = UvState::boundary;  ///< leaf only
    /// Boundary leaf: chords segment_refs[first, first + count), and the
    /// reference point (has_reference) with its state.
    int first = 0, count = 0;
    bool has_reference = false, reference_inside = false;
    double ref_u = 0, ref_v = 0;
  };

  /// State of (u, v): inside when one of its representatives shifted by whole
  /// periods (`u_period`, `v_period`, 0 when not periodic) is inside, else
  /// boundary when one is undecided, else outside. Beyond the box by more than
  /// `box_margin`: outside.
  UvState state_at(double u, double v) const;
  /// state_at() as the face classifier would answer it; `classifier()` (the
  /// face's BRepTopAdaptor_FClass2d, perhaps built on demand) is asked only
  /// where the cells leave the point undecided.
  template <class Classifier>
  TopAbs_State classify(double u, double v, Classifier&& classifier) const {
    switch (state_at(u, v)) {
      case UvState::inside:
        return TopAbs_IN;
      case UvState::outside:
        return TopAbs_OUT;
      case UvState::boundary:
        break;
    }
    return classifier().Perform(gp_Pnt2d(u, v));
  }
  /// Makes node `index` (cell [cu0, cu1] x [cv0, cv1]) a boundary leaf with
  /// these chords, and picks and classifies its reference point.
  void set_boundary_leaf(int index, double cu0, double cu1, double cv0, double cv1,
                         const std::vector<int>& chords, const BRepTopAdaptor_FClass2d& c);

  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  double u_period = 0, v_period = 0;
  double box_margin = 0;    ///< the widest chord reach
  std::vector<Node> nodes;  // nodes[0] is the root; empty: everything is boundary
  std::vector<UvSegment> segments;
  std::vector<UvSegment> fine;  ///< finer chords of the segments (UvSegment::fine_first)
  /// Chords of degenerated edges (poles) with wide tubes: see near_pole().
  std::vector<UvSegment> poles;
  /// Whether (u, v) lies in a pole's wide tube, where the parametrization
  /// collapses: the cells classify such points exactly, but a point evaluated
  /// there lies next to the pole's vertex, a poor seed (cad_seeds.cpp).
  bool near_pole(double u, double v) const;
  std::vector<int> segment_refs;

 private:
  UvState state_in_box(double u, double v) const;
  UvState resolve(const Node& leaf, double u, double v) const;
};

}  // namespace rdmesh::cad
