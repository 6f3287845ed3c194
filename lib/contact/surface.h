#pragma once
// The contact surface of one elastic body: the boundary nodes and faces on a chosen set of
// boundary ids, indexed by the exact curve pieces of the body's mesh, with
//  - closest-point projection onto the exact curves (the same curves the mesh manifolds
//    follow), pruned by per-piece bounding boxes;
//  - interpolation of the displacement along a face from its nodes (the face's Lagrange
//    shape functions in the curve parameter);
//  - consistent nodal weights w_j = integral of N_j ds [m] (for pressure recovery).
// Everything here is in the body frame; the solver places bodies rigidly. SI units.
#include "fem/elastic_body.h"

#include <array>
#include <set>
#include <vector>

namespace gearfem::contact
{
  using Vec2 = mesh::Vec2;

  /// 4-point Gauss rule on [0, 1] (points, weights): exact for degree 7.
  inline constexpr double gauss4_x[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                         0.9305681557970263};
  inline constexpr double gauss4_w[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                         0.1739274225687269};

  /// One boundary node of the surface (both DoFs of one support point).
  struct SurfaceNode
  {
    Vec2 x;                    ///< body frame [m], on the exact curve
    unsigned int dof_x, dof_y; ///< global DoF indices in the body
    int piece;                 ///< index into body.mesh().pieces
    double t;                  ///< curve parameter of the node
    double weight = 0;         ///< integral of the node's shape function over its faces [m]
    unsigned int boundary_id;
    int tooth = -1, segment = -1; ///< from the piece (gear outlines), -1 otherwise
  };

  /// One boundary face: nodes ordered by curve parameter.
  struct SurfaceFace
  {
    int piece;
    double t_lo, t_hi;          ///< parameter range (t_lo < t_hi)
    std::vector<int> nodes;     ///< indices into nodes(), sorted by parameter (p + 1 of them)
    std::vector<double> xi;     ///< reference coordinate of each node in [0, 1]
    std::vector<double> w;      ///< integral of each node's shape function over this face [m]
    double length = 0;          ///< arc length [m]
  };

  /// Result of a closest-point projection onto the surface.
  struct Projection
  {
    int piece = -1, face = -1;
    double t = 0;               ///< curve parameter
    Vec2 point = Vec2::Zero();  ///< closest point [m], body frame
    Vec2 normal = Vec2::Zero(); ///< outward unit normal, body frame
    double signed_distance = 0; ///< (q - point) . normal [m]: < 0 inside the body
    bool corner = false;        ///< at a piece end without a tangent-continuous neighbour
  };

  class ContactSurface
  {
  public:
    /// Surface of `body` on the boundary ids `ids`. Throws InputError when no face has one
    /// of the ids.
    ContactSurface(const fem::ElasticBody &body, const std::set<unsigned int> &ids);

    const fem::ElasticBody &body() const { return *body_; }
    const std::vector<SurfaceNode> &nodes() const { return nodes_; }
    const std::vector<SurfaceFace> &faces() const { return faces_; }
    const std::set<unsigned int> &ids() const { return ids_; }

    /// Closest point of the surface pieces accepted by `use_piece` (all when empty) to q
    /// (body frame), among pieces whose bounding box is within `max_distance` of q.
    /// piece = -1 when none.
    Projection project(const Vec2 &q, double max_distance,
                       const std::vector<bool> &use_piece = {}) const;
    /// The same near a previous projection `hint` (piece and parameter) of a nearby point:
    /// Newton on the hint's piece only, when the closest point is interior to that piece
    /// and within the hint's bracket; otherwise (a piece end, a jump) the full project().
    /// `shape`, when given, receives the shape values of face_at at the projection.
    Projection project_from(const Vec2 &q, double max_distance, const std::vector<bool> &use_piece,
                            const Projection &hint, std::vector<double> *shape = nullptr) const;
    /// A lower bound on the distance from q (body frame) to the surface; only pieces within
    /// `reach` of q are looked at (a value above `reach` when there are none) [m].
    double distance_lower_bound(const Vec2 &q, double reach) const;
    /// Face containing parameter t of `piece` and the shape values of its nodes at t.
    int face_at(int piece, double t, std::vector<double> &shape) const;
    /// Outward unit normal of piece p at parameter t (body frame).
    Vec2 outward_normal(int piece, double t) const;
    /// Pressure [Pa] recovered from nodal normal forces [N] (one per node) on a body of
    /// thickness b: face pressures p_f = sum_j lambda_j (w_jf / w_j) / (b L_f) (exact for a
    /// uniform pressure, and free of the vertex/mid-node alternation of node-to-segment
    /// forces), averaged back to the nodes with the weights w_jf. Conserves the force.
    std::vector<double> recover_pressure(const std::vector<double> &force, double b) const;
    /// Node indices on a given piece, sorted by parameter.
    std::vector<int> nodes_on_piece(int piece) const;

  private:
    const fem::ElasticBody *body_;
    std::set<unsigned int> ids_;
    std::vector<SurfaceNode> nodes_;
    std::vector<SurfaceFace> faces_;
    std::vector<std::vector<int>> piece_faces_; ///< per mesh piece, faces sorted by t_lo
    std::vector<std::array<Vec2, 2>> piece_box_; ///< per mesh piece: lo, hi
    std::vector<bool> surface_piece_;
    /// Per surface piece: the sampled start of the closest-point search
    /// (ParametricCurve::closest_samples + 1 points, the polyline of the lower bound), and
    /// a bound on how far the curve strays from that polyline [m].
    std::vector<std::vector<Vec2>> piece_samples_;
    std::vector<double> piece_sag_;
    /// A lower bound on the distance from q to surface piece p: polyline minus sag [m].
    double distance_bound(int p, const Vec2 &q) const;
    /// A uniform grid over the surface pieces' boxes: per cell, the surface pieces whose box
    /// meets it (ascending), so that a projection looks only at the pieces near q.
    struct PieceGrid
    {
      Vec2 origin = Vec2::Zero();
      double cell = 1;
      int nx = 0, ny = 0;
      std::vector<std::vector<int>> pieces;
    } grid_;
    /// Boxes, samples, sags and the grid of the surface pieces (end of the constructor).
    void index_pieces();
    /// The surface pieces (ascending) whose box may lie within `reach` of q.
    void pieces_near(const Vec2 &q, double reach, std::vector<int> &out) const;
  };
} // namespace gearfem::contact
