#pragma once
// Plane domains bounded by exact curves, meshed with gmsh into all-quadrilateral meshes.
// This header has no deal.II and no gmsh types: a Domain is a list of closed loops of exact
// curve pieces (first loop outer, counter-clockwise; further loops are holes), and MeshData
// is the gmsh result (vertices, quads, boundary edges with ids) ready for deal.II import
// (mesh/triangulation.h). SI units (m).
#include "base/errors.h"
#include "geometry/curve.h"

#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gearfem::mesh
{
  using Vec2 = geometry::Vec2;

  /// Boundary ids written to the .msh physical groups and carried into deal.II
  /// (documented in meshes/README.md).
  namespace boundary
  {
    inline constexpr unsigned int bore    = 1; ///< inner circle (bore or fixed rim)
    inline constexpr unsigned int cut_cw  = 2; ///< sector cut edge on the clockwise side
    inline constexpr unsigned int cut_ccw = 3; ///< sector cut edge on the counter-clockwise side
    inline constexpr unsigned int outer   = 4; ///< outer boundary of the test domains
    /// Outer circle of a ring between its support arcs (free; ring_domain.h, bolts model).
    /// For a ring, `bore` is its outer support (the whole circle, or the bolt arcs).
    inline constexpr unsigned int ring_free = 5;

    /// Segment codes of a tooth boundary id 1000 (tooth + 1) + code.
    enum Code : unsigned int
    {
      flank_drive      = 1,
      flank_coast      = 2,
      fillet_drive     = 3,
      fillet_coast     = 4,
      tip              = 5,
      tip_round_drive  = 6,
      tip_round_coast  = 7,
      root_drive       = 8,
      root_coast       = 9
    };
    /// Boundary id of segment `code` of tooth `tooth` (0 <= tooth < z).
    inline unsigned int tooth_id(int tooth, Code code)
    {
      return 1000u * static_cast<unsigned int>(tooth + 1) + code;
    }
    /// Tooth index of a boundary id, -1 for non-tooth ids.
    inline int tooth_of(unsigned int id) { return id >= 1000 ? int(id / 1000) - 1 : -1; }
    /// Segment code of a tooth boundary id (0 for non-tooth ids).
    inline unsigned int code_of(unsigned int id) { return id >= 1000 ? id % 1000 : 0; }
    /// "flank_drive", "fillet_coast", ... for a code; "bore", "cut_cw", ... for the others.
    std::string name(unsigned int id);
  } // namespace boundary

  /// An exact parametric curve given by functions (point, first and second derivative
  /// with respect to the parameter t). SI units.
  struct ParametricCurve
  {
    std::function<Vec2(double)> point, d1, d2;
    /// point, d1 and d2 in one call where the curve shares their work (may be empty).
    std::function<void(double, Vec2 &, Vec2 &, Vec2 &)> all;
    /// point, d1 and d2 at t (through `all` when set: the same values).
    void evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const;
    /// Parameter in [lo, hi] of the point closest to q: sampling followed by safeguarded
    /// Newton on (p(t) - q)·p'(t) = 0.
    double closest_parameter(const Vec2 &q, double lo, double hi) const;
    /// The same with the samples given: `samples` holds point(lo + (hi - lo) i / n) for
    /// i = 0..n, n = closest_samples (lo <= hi), e.g. kept by a caller that projects often.
    double closest_parameter(const Vec2 &q, double lo, double hi, const std::vector<Vec2> &samples) const;
    /// The number of intervals of the sampled start of closest_parameter.
    static constexpr int closest_samples = 32;
    /// The same from a start t0 near the answer (a previous projection): safeguarded Newton
    /// in the bracket t0 -/+ (hi - lo)/32, without the sampling (the bracket's ends are
    /// evaluated only where Newton does not converge inside it). `ok` false (and the result
    /// meaningless) when the bracket does not hold the minimum: call closest_parameter.
    double closest_parameter_from(const Vec2 &q, double lo, double hi, double t0, bool &ok) const;
    /// The same, with the point x and the tangent x1 at the result (when ok).
    double closest_parameter_from(const Vec2 &q, double lo, double hi, double t0, bool &ok, Vec2 &x,
                                  Vec2 &x1) const;
    /// A Curve rotated by `angle` [rad] about the origin (curve may be null-free only).
    static ParametricCurve from(const geometry::CurvePtr &curve, double angle = 0.0);
    /// Circle of radius r about c: c + r (cos t, sin t).
    static ParametricCurve circle(const Vec2 &c, double r);
    /// Straight line a + t (b - a).
    static ParametricCurve line(const Vec2 &a, const Vec2 &b);
  };

  /// One piece of a loop: the curve from parameter t0 to t1 (t1 < t0 allowed), with its
  /// boundary id and the target element size on it.
  struct BoundaryPiece
  {
    ParametricCurve curve;
    double t0 = 0.0, t1 = 1.0;
    unsigned int boundary_id = 0;
    double size = 0.0;     ///< target element size on the piece [m]; <= 0: the body size
    bool straight = false; ///< a straight line (flat manifold, no projection needed)
    int tooth = -1;        ///< tooth index for gear outlines, -1 otherwise
    int segment = -1;      ///< index into ToothProfile::segments() for gear outlines
    /// A fixed node distribution (straight pieces only): this many edges, their lengths in
    /// geometric progression by `progression` from start to end; 0: from `size`.
    int edges = 0;
    double progression = 1.0;
    Vec2 start() const { return curve.point(t0); }
    Vec2 end() const { return curve.point(t1); }
  };

  /// A closed chain of pieces: each piece ends where the next one starts.
  struct Loop
  {
    std::vector<BoundaryPiece> pieces;
  };

  /// The region to mesh: loops[0] is the outer boundary, the other loops are holes.
  struct Domain
  {
    std::vector<Loop> loops;
    double h_body = 0.0; ///< element size far from fine boundaries [m]
    double growth = 1.2; ///< bound on the size ratio of neighbouring elements (> 1)
  };

  /// gmsh options that are not geometry.
  struct MeshingOptions
  {
    int algorithm = 6;              ///< gmsh Mesh.Algorithm (8 with recombination segfaults in 4.8)
    int samples_per_piece = 24;     ///< spline points per boundary piece for the gmsh geometry
    int smoothing_steps   = 5;      ///< gmsh Mesh.Smoothing (Laplacian smoothing passes)
    std::filesystem::path msh_file; ///< if not empty, write the mesh here (MSH 4.1, atomic)
    std::string model_name = "gearfem";
    /// When Blossom recombination leaves triangles, also on the mesh graded to short pieces
    /// (mesh_domain): retry, then subdivide (true), or throw RecombinationFailed (false: a
    /// caller that can try other sizes, model_choice/).
    bool fallbacks = true;
    /// When the first recombination leaves triangles and the outline has short pieces, mesh
    /// again with the size field graded to them (mesh_domain) before the retries; false: go
    /// straight to the retries (or RecombinationFailed), as mesh_gear_tiled's first attempts
    /// at a coarse tile do.
    bool grade_short = true;
  };

  /// The first all-quad recombination failed and MeshingOptions::fallbacks was off.
  class RecombinationFailed : public InputError
  {
  public:
    using InputError::InputError;
  };

  /// Result of meshing: an all-quad mesh with boundary edges tagged by piece.
  struct MeshData
  {
    std::vector<Vec2> vertices;
    /// Quads in deal.II (lexicographic) vertex order: 0 1 bottom, 2 3 top; positive area.
    std::vector<std::array<unsigned int, 4>> cells;
    struct Edge
    {
      unsigned int v0, v1;
      unsigned int boundary_id;
      int piece; ///< index into `pieces`
    };
    std::vector<Edge> boundary_edges;
    std::vector<BoundaryPiece> pieces; ///< all pieces of all loops, in loop order
    double mesh_seconds = 0.0;         ///< wall time in gmsh [s]
    bool subdivided     = false;       ///< the all-quad fallback (subdivision) was used
  };

  /// Mesh a domain with gmsh (Frontal-Delaunay + Blossom recombination; even node counts
  /// per loop so that only quads result; subdivision fallback), snap boundary
  /// vertices onto the exact curves, and orient the cells. Throws InputError("Mesh", ...)
  /// when gmsh fails or leaves triangles or inverted cells.
  MeshData mesh_domain(const Domain &domain, const MeshingOptions &options = {});
  /// Write `mesh` as MSH 4.1 through gmsh (atomic): its vertices, quads and boundary edges,
  /// one physical group per boundary id (named as boundary::name).
  void write_mesh_msh(const MeshData &mesh, const std::filesystem::path &file, const std::string &model_name);

  /// Annulus r_inner < r < r_outer about the origin: bore id 1 inside, id 4 outside.
  Domain annulus_domain(double r_inner, double r_outer, double h);
  /// Rectangle [0, L] x [-H/2, H/2]: ids 11 (x = 0), 12 (y = -H/2), 13 (x = L), 14 (y = H/2).
  Domain rectangle_domain(double length, double height, double h);

  /// Mesh quality (angles in degrees).
  struct QualityReport
  {
    std::size_t n_cells = 0, n_vertices = 0;
    double min_angle = 0, max_angle = 0; ///< interior angles of the quads [deg]
    double max_aspect_ratio = 0;          ///< longest / shortest edge of a cell
    double min_edge = 0, max_edge = 0;    ///< [m]
    std::size_t n_inverted = 0;           ///< cells with a non-positive corner Jacobian
  };
  QualityReport quality(const MeshData &mesh);
  /// Where the first inverted cell of `mesh` is, and how many of its vertices lie on the
  /// boundary, as a phrase for an error message ("" when none is inverted).
  std::string inverted_cell_location(const MeshData &mesh);

  /// Untangle the cells that the snap of the boundary vertices onto the exact curves (or
  /// gmsh itself) left inverted: Laplacian smoothing of the interior vertices of inverted
  /// cells, growing to their neighbours when that is not enough, at most `sweeps` times.
  /// Boundary vertices never move (they stay on the exact curves); a mesh with no inverted
  /// cell is not touched. Returns the number of inverted cells left.
  int untangle_inverted_cells(MeshData &mesh, int sweeps = 50);
} // namespace gearfem::mesh
