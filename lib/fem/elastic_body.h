#pragma once
// One linear-elastic body in its own body frame: Triangulation<2> with exact-curve
// manifolds, FE_Q(p)^2 with MappingQ(p) (cached), the assembled stiffness matrix, a
// factorisation reused for any number of load cases, boundary conditions, reactions and
// stress recovery. Plane stress (thickness = face width) or plane strain. SI units:
// forces [N], tractions [Pa], displacements [m], stresses [Pa], torques [N m].
//
// The stiffness is rotation-invariant, so a contact solver places bodies rigidly and
// rotates displacements; it never re-assembles per mesh position.
#include "fem/direct_solver.h"
#include "fem/elasticity.h"
#include "mesh/domain.h"
#include "mesh/triangulation.h"

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace gearfem::fem
{
  using Point2  = dealii::Point<2>;
  using Tensor2 = dealii::Tensor<1, 2>;
  /// Vector field x -> value (displacement [m] or traction [Pa]).
  using VectorFunction = std::function<Tensor2(const Point2 &)>;

  /// Finite-element options of a body (the `Finite elements` section).
  struct FeOptions
  {
    unsigned int degree = 2;                   ///< p of FE_Q(p)^2 and MappingQ(p), {1, 2}
    unsigned int refinements = 0;              ///< global refinements of the gmsh mesh
    SolverKind solver = SolverKind::automatic; ///< direct solver
    unsigned int umfpack_max_dofs = 20000;     ///< automatic: UMFPACK up to this many DoFs
    /// Cells with a transfinite-interpolation manifold. Default none: MappingQ then
    /// places interior support points by Gordon-Hall interpolation of the exact boundary,
    /// which is robust on strongly curved coarse cells (the TFI manifold can fail there).
    mesh::InteriorManifold interior = mesh::InteriorManifold::none;
    /// Throws InputError for p not in {1, 2} or more than 6 refinements.
    void validate() const;
  };

  /// Stress state at one point [Pa].
  struct StressPoint
  {
    Point2 x;
    double sxx = 0, syy = 0, sxy = 0, szz = 0;
    double s1 = 0, s2 = 0, von_mises = 0;
  };

  /// One sample of a boundary stress profile (fillet extractor).
  struct BoundaryStressSample
  {
    StressPoint stress;
    double arc_length = 0; ///< from the start of the boundary piece chain [m]
    double parameter  = 0; ///< exact-curve parameter t
    int piece         = -1;
  };

  /// The stress along one boundary as linear functionals of the displacement: the samples
  /// of ElasticBody::boundary_stress (same points, same order, same arc length; stresses
  /// left zero) and, per sample, three sparse rows (sigma_xx, sigma_yy, sigma_xy) with
  /// sigma = sum_d row_d u_d [Pa per m]. Applied to the columns of K^-1 they give the
  /// stress influence coefficients of nodal forces (unit-load solves).
  struct BoundaryStressFunctionals
  {
    std::vector<BoundaryStressSample> samples;
    /// rows[3 i + c]: component c (xx, yy, xy) of sample i, as (DoF, coefficient).
    std::vector<std::vector<std::pair<unsigned int, double>>> rows;
  };

  /// Peak of the maximum principal stress along one boundary (e.g. a fillet).
  struct StressPeak
  {
    double value      = 0; ///< max sigma_1 [Pa]
    double arc_length = 0; ///< [m] along the boundary from its start
    double radius     = 0; ///< |x| [m] in the body frame
    double angle      = 0; ///< polar angle of x [rad] in the body frame
    Point2 x;
  };

  /// Discretisation errors against an exact solution.
  struct ErrorNorms
  {
    double l2_displacement = 0; ///< ||u - u_h||_L2 [m^2]
    double h1_displacement = 0; ///< |u - u_h|_H1 seminorm [m]
    double l2_stress       = 0; ///< ||sigma - sigma_h||_L2 [Pa m]
  };

  /// A boundary DoF pair (x and y component) with its location on the exact outline.
  struct BoundaryNode
  {
    Point2 x;
    unsigned int dof_x = 0, dof_y = 0;
    dealii::types::boundary_id boundary_id = 0;
    int piece        = -1; ///< index into mesh().pieces (tooth, segment, curve)
    double parameter = 0;  ///< exact-curve parameter of the node
  };

  class ElasticBody
  {
  public:
    /// Build the triangulation from `mesh` (refined `options.refinements` times), the FE
    /// space and the mapping. Throws InputError for bad options or material.
    ElasticBody(const mesh::MeshData &mesh, const Elasticity &material, const FeOptions &options);
    ~ElasticBody();

    /// Prescribe the selected displacement components on boundary `id` (values are given
    /// per solve). Must be called before assemble().
    void constrain(dealii::types::boundary_id id, bool x = true, bool y = true);
    /// Assemble the body-frame stiffness (WorkStream, multithreaded) and factorise it with
    /// the Dirichlet rows and columns eliminated. Throws SolverError for a singular system
    /// (e.g. no Dirichlet boundary).
    void assemble_and_factorize();

    /// Load vector [N] of the traction t(x) [Pa] on the faces with id in `ids` for which
    /// `where(x)` is true (all when null). Thickness b included.
    dealii::Vector<double> traction_load(const VectorFunction &traction,
                                         const std::set<dealii::types::boundary_id> &ids,
                                         const std::function<bool(const Point2 &)> &where = {}) const;
    /// Solve K u = f with u = g(x) on the constrained boundaries (g = 0 when null).
    dealii::Vector<double> solve(const dealii::Vector<double> &f,
                                 const VectorFunction &g = {}) const;

    /// Flexibility columns: for each DoF d = dofs[j], u = K^{-1} e_d with homogeneous
    /// Dirichlet data (zero for a constrained d), at its own rows `rows[j]` [m/N]. One
    /// selected-entries request (DirectSolver::inverse_entries).
    std::vector<std::vector<double>> compliance_columns(const std::vector<unsigned int> &dofs,
                                                        const std::vector<std::vector<unsigned int>> &rows) const;
    /// Reaction force vector r = K u - f [N] (nonzero on constrained DoFs only).
    dealii::Vector<double> reactions(const dealii::Vector<double> &u,
                                     const dealii::Vector<double> &f) const;
    /// Displacement u_h(x) [m] at a point of the body (cell search + mapping inverse).
    Tensor2 displacement_at(const dealii::Vector<double> &u, const Point2 &x) const;
    /// The moment about `centre` of the reactions on the constrained DoFs, K u - f there, as a
    /// linear functional of u (sparse row over the DoFs; f has no entries on constrained DoFs
    /// for surface loads): moment(reactions(u, f)) = sum row_j u_j.
    std::vector<std::pair<unsigned int, double>> reaction_moment_functional(const Point2 &centre = {}) const;
    /// Moment about `centre` of a nodal force vector (sum x_i × F_i) [N m].
    double moment(const dealii::Vector<double> &nodal_forces, const Point2 &centre = {}) const;
    /// Sum of a nodal force vector [N].
    Tensor2 resultant(const dealii::Vector<double> &nodal_forces) const;

    /// Stresses at the quadrature points (QGauss(p+1)) of every cell.
    std::vector<StressPoint> quadrature_stresses(const dealii::Vector<double> &u) const;
    /// Stress along the boundary with id `id`: `per_face` equally spaced points on each face,
    /// sorted along the exact curve, with arc length.
    std::vector<BoundaryStressSample> boundary_stress(const dealii::Vector<double> &u,
                                                      dealii::types::boundary_id id,
                                                      unsigned int per_face = 8) const;
    /// The same samples as linear functionals of u (BoundaryStressFunctionals).
    BoundaryStressFunctionals boundary_stress_functionals(dealii::types::boundary_id id,
                                                          unsigned int per_face = 8) const;
    /// The stress state of components (sxx, syy, sxy) [Pa] at x: szz, principal stresses
    /// and von Mises of this body's material (as boundary_stress reports them).
    StressPoint stress_point(double sxx, double syy, double sxy, const Point2 &x) const;
    /// Fillet extractor: the peak of sigma_1 along boundary `id`.
    StressPeak peak_principal_stress(const dealii::Vector<double> &u,
                                     dealii::types::boundary_id id,
                                     unsigned int per_face = 8) const;
    /// Errors of u against u_exact and its stress sigma_exact (QGauss(p+2)).
    ErrorNorms errors(const dealii::Vector<double> &u, const VectorFunction &u_exact,
                      const std::function<dealii::SymmetricTensor<2, 2>(const Point2 &)>
                        &stress_exact) const;
    /// DoFs on the boundaries `ids` with position and exact-curve parameter.
    std::vector<BoundaryNode> boundary_nodes(const std::set<dealii::types::boundary_id> &ids) const;

    /// Write the deformed configuration (displacement scaled by `scale`) with u, sigma_xx,
    /// sigma_yy, sigma_xy, sigma_1, sigma_2, von Mises [MPa] and boundary ids to a VTU file,
    /// atomically. Returns the path written.
    void write_vtu(const dealii::Vector<double> &u, const std::filesystem::path &file,
                   double scale = 1.0) const;

    const dealii::Triangulation<2> &triangulation() const { return tria_; }
    const dealii::DoFHandler<2> &dof_handler() const { return dof_handler_; }
    const dealii::Mapping<2> &mapping() const { return *mapping_; }
    const dealii::FESystem<2> &fe() const { return fe_; }
    const dealii::SparseMatrix<double> &stiffness() const { return stiffness_; }
    const mesh::MeshData &mesh() const { return mesh_; }
    const Elasticity &material() const { return material_; }
    const FeOptions &options() const { return options_; }
    unsigned int n_dofs() const { return dof_handler_.n_dofs(); }
    /// Support point of each DoF [m] and its component (0 = x, 1 = y).
    const std::vector<Point2> &dof_points() const { return dof_points_; }
    const std::vector<unsigned char> &dof_components() const { return dof_component_; }
    const std::vector<bool> &constrained_dofs() const { return constrained_; }
    /// Wall times [s] of the phases.
    double assemble_seconds() const { return t_assemble_; }
    double factorize_seconds() const { return t_factorize_; }
    SolverKind solver_used() const { return solver_.kind(); }

  private:
    StressPoint stress_at(const std::vector<dealii::Tensor<1, 2>> &grad_u, const Point2 &x) const;
    std::vector<int> pieces_with_id(dealii::types::boundary_id id) const;
    /// `per_face` equally spaced points on a face (the boundary stress samples).
    static dealii::Quadrature<1> boundary_samples(unsigned int per_face);
    /// Exact-curve piece and parameter of boundary sample `s` (nearest of `pieces`).
    void locate_on_pieces(BoundaryStressSample &s, const std::vector<int> &pieces) const;
    /// The permutation that orders boundary samples along the outline (by piece, then
    /// along the piece), and their arc lengths in that order.
    std::vector<std::size_t> order_along_outline(std::vector<BoundaryStressSample> &samples) const;

    mesh::MeshData mesh_;
    Elasticity material_;
    FeOptions options_;
    dealii::Triangulation<2> tria_;
    dealii::FESystem<2> fe_;
    std::unique_ptr<dealii::MappingQCache<2>> mapping_;
    dealii::DoFHandler<2> dof_handler_;
    dealii::SparsityPattern sparsity_;
    dealii::SparseMatrix<double> stiffness_, reduced_;
    DirectSolver solver_;
    std::map<dealii::types::boundary_id, std::pair<bool, bool>> dirichlet_;
    std::vector<bool> constrained_;
    std::vector<Point2> dof_points_;
    std::vector<unsigned char> dof_component_;
    double diagonal_scale_ = 1.0;
    double t_assemble_ = 0, t_factorize_ = 0;
  };
} // namespace gearfem::fem
