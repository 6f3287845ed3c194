#pragma once
// Import of MeshData (gmsh result) into a deal.II Triangulation<2> with the boundary ids of
// the physical groups and manifolds that follow the exact curves, so that refinement and
// MappingQ(p) place new points on the true boundary, not on the facets.
#include "mesh/domain.h"

#include <deal.II/grid/tria.h>

namespace gearfem::mesh
{
  /// Manifold ids: curved pieces get first_curve_manifold_id + piece index; cells that
  /// touch a curved piece get transfinite_manifold_id (TransfiniteInterpolationManifold);
  /// all other cells and straight pieces stay flat.
  inline constexpr dealii::types::manifold_id transfinite_manifold_id = 1;
  inline constexpr dealii::types::manifold_id first_curve_manifold_id = 100;

  /// Which cells get the transfinite interpolation manifold.
  enum class InteriorManifold
  {
    none,           ///< flat interior: cheapest, fine for Q1
    boundary_layer, ///< only cells touching a curved piece (default)
    all             ///< every cell (best for high-order convergence studies)
  };

  /// Build `tria` from `mesh` (create_triangulation with SubCellData carrying the boundary
  /// ids), attach a ChartManifold per curved piece (pull-back: closest curve parameter,
  /// push-forward: curve point; deal.II 9.4 ChartManifold<2,2,1>) and the transfinite
  /// interpolation manifold inside. `tria` must be empty.
  void create_triangulation(const MeshData &mesh, dealii::Triangulation<2> &tria,
                            InteriorManifold interior = InteriorManifold::boundary_layer);

  /// Largest distance [m] of a vertex on a curved boundary face of `tria` from its exact
  /// curve (for checking refinement and manifolds).
  double max_boundary_vertex_distance(const MeshData &mesh, const dealii::Triangulation<2> &tria);
} // namespace gearfem::mesh
